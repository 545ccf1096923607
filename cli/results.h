// The JSON results the subcommands print with --json, built apart from the printing so that the Python module
// (python/) returns the same objects from the same code.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "geometry/planar_scene.h"
#include "queries/json_out.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::cli {

using namespace queries;  // the front end names the query layer's writers unqualified

// stability.cpp: `stability --wrench` (T = Q on the exact and verified paths, double with --arith float),
// `--region` and `--finger`, and the --finger picture.
// The witness's contact forces are also given in world coordinates (solvers/stability/world_forces.h), which
// needs the scene.
template <class T>
json stability_json(const geometry::PlanarScene& scene, const exact::Vec<exact::Q>& g,
                    const solvers::StabilityResult<T>& r, const std::string& arith, const std::string& certificate,
                    const std::optional<solvers::Margin<exact::Q>>& margin);
/// The `stability` certificate file (solvers/stability/stability_certificate.h) with its readable part: the
/// witness's world forces under "resting"/"contacts" and "moving"/"contacts" (contacts_json, queries/contact_forces.h).
/// The checker verifies the raw "forces"; `check` recomputes the contacts from them and compares.
std::string stability_certificate_file(const std::string& scene_text, const geometry::PlanarScene& scene,
                                       const exact::Vec<exact::Q>& g, const solvers::StabilityResult<exact::Q>& r);
json region_json(const solvers::StableRegion<exact::Q>& region);
json finger_json(const solvers::FingerPushes<exact::Q>& pushes);
std::string finger_svg(const geometry::PlanarScene& scene, const solvers::FingerPushes<exact::Q>& pushes);

// modes.cpp: the feasible contact modes of a scene (arith, table2, unions and the budgets as `modes` reads
// them: with --unions or a printed `s` a time limit of 0 means the default budget kModesDefaultSeconds) and
// the JSON of `modes --json`.
inline constexpr double kModesDefaultSeconds = 60;
solvers::ContactModes modes_of(const geometry::PlanarScene& scene, const std::string& arith, const std::string& table2,
                               bool unions, long max_nodes, double time_limit,
                               long max_modes = solvers::ModeTreeOptions{}.max_modes);
json modes_json(const solvers::ContactModes& m, bool kinematic, const std::string& certificate);

// cone.cpp: the mode named by --mode (InputError naming `file` and --mode otherwise), the exact and the
// float cone, and the --svg picture.
solvers::ModeString cone_mode(const geometry::PlanarScene& scene, const std::string& file, const std::string& text,
                              bool printed_separation = false);
nlohmann::json cone_json(const geometry::PlanarScene& scene, const solvers::ModeString& mode,
                         const solvers::WrenchCone<exact::Q>& c, const std::string& route, const std::string& arith);
nlohmann::json cone_json(const solvers::ModeString& mode, const solvers::WrenchCone<double>& c,
                         const std::string& route);
std::string cone_svg(const geometry::PlanarScene& scene, const solvers::ModeString& mode,
                     const solvers::WrenchCone<exact::Q>& c);

// insert.cpp: G_goal of the scene read from `file` (an InputError names the file), G_goal without --sweep-mu, the
// values of --sweep-mu (InputError unless each is >= 0), the sweep's entry for one mu (every fixel's mu_s = mu_k =
// mu), and the --svg picture.
solvers::Insertion<exact::Q> insertion_of(const geometry::PlanarScene& scene, const std::string& file);
json insertion_json(const geometry::PlanarScene& scene, const solvers::Insertion<exact::Q>& ins,
                    const solvers::BoundaryPieces<exact::Q, bool>& pushes);
std::vector<exact::Q> sweep_mus(const std::string& text);
json sweep_entry_json(const geometry::PlanarScene& scene, const exact::Q& mu);
std::string insertion_svg(const geometry::PlanarScene& scene, const solvers::BoundaryPieces<exact::Q, bool>& pushes);

}  // namespace contactcert::cli
