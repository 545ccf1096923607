// The query of `contactcert cone FILE --mode MODE`: the wrench cone of an augmented contact mode (Balkcom, Trinkle
// 2002, eqs. 13-17: { g : K z = P g, z >= 0, z_j > 0 on the strict components }), exactly (the exact and verified
// paths: the cone's combinatorics are decided in rationals) or in unchecked doubles (--arith float); with a
// certificate (a Motzkin vector for an empty cone, a witness wrench otherwise) and a picture.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "queries/json_out.h"
#include "queries/limit.h"
#include "queries/options.h"
#include "queries/scene_input.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::queries {

struct ConeOptions {
  CommonOptions common;  ///< the time limit stops the double description and the LPs of route project
  std::string mode;      ///< one Table 2 letter per fixel
  solvers::Route route = solvers::Route::kPaper;
  Table2 table2 = Table2::kStrict;
  std::string certificate;  ///< the file the certificate is written to ("" = none)
  std::string svg;          ///< the file the picture is written to ("" = none)
};

/// A witness of a non-empty cone as a person reads it: the wrench g and the contact forces c of the touching fixels
/// that its z applies (solvers::contact_forces).
struct ConeWitness {
  std::vector<Eigen::Index> touching;
  exact::Vec<exact::Q> g, c;
};

struct ConeAnswer {
  geometry::PlanarScene scene;
  ConeOptions options;
  solvers::ModeString mode;                               ///< as read under options.table2
  std::optional<solvers::WrenchCone<exact::Q>> cone;      ///< the exact and verified paths
  std::optional<solvers::WrenchCone<double>> cone_float;  ///< --arith float
  std::optional<ConeWitness> witness;                     ///< with a certificate of a non-empty cone
  std::string certificate_text;                           ///< the certificate written ("" = none)
  bool empty() const;
};

/// The mode `text` names in `scene` (InputError naming `file` and --mode otherwise); with `printed_separation`, `s`
/// at a touching fixel as Table 2 prints it (a_n >= 0).
solvers::ModeString cone_mode(const geometry::PlanarScene& scene, const std::string& file, const std::string& text,
                              bool printed_separation = false);

/// The wrench cone of options.mode, its certificate and picture written where asked (InputError for a
/// certificate or picture of the float path; a Limit past the time limit).
Limited<ConeAnswer> run_cone(const SceneInput& input, const ConeOptions& options);

/// The object `cone --json` prints: the cone's keys sorted, then "certificate" and "witness" where written.
json to_json(const ConeAnswer& answer);

/// The picture of an exact cone: the workpiece, the fixels, their friction cones and the generators as lines of
/// force.
std::string cone_svg(const ConeAnswer& answer);

/// "force along (fx, fy) through (x, y)", "pure moment, clockwise" or "zero wrench": the line of force of g.
std::string line_of_force_text(const exact::Vec<exact::Q>& g, const geometry::Point2& com);

}  // namespace contactcert::queries
