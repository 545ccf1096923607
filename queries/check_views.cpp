#include "queries/check_views.h"

#include <optional>
#include <string>

#include "checker/frame_check.h"
#include "checker/world_forces.h"
#include "queries/contact_forces.h"

namespace contactcert::queries {
namespace {

/// INVALID unless the certificate's readable copy `given` (if any) of the view `view` is exactly it.
void require_view(const std::optional<exact::JsonInput>& given, const json& view, const std::string& what,
                  const std::string& reason, CheckResult& c) {
  if (given && given->canonical_text() != exact::JsonInput::parse(view.dump(), what).canonical_text()) {
    c.verdict = CheckVerdict::kInvalid;
    c.reason = reason;
  }
}

/// The contact forces of a checked stability witness as a person reads them (queries/contact_forces.h), recomputed
/// from the verified raw vector `forces` of `evidence` (the witness under `key`) with the checker's own Jacobian.
void add_contacts(const exact::JsonInput& evidence, const std::string& key, const geometry::PlanarScene& scene,
                  const std::vector<Eigen::Index>& touching, CheckResult& c, json& view, std::string& text) {
  const exact::Vec<exact::Q> forces = evidence.at("forces").rational_vector(2 * touching.size());
  const auto world = checker::checked_world_forces(scene, touching, forces);
  view = forces_json(world, "fixel");
  text = forces_text(world, "fixel", "    ");
  require_view(evidence.find("contacts"), view, "contacts",
               key + ".contacts are not the world forces of the checked " + key + ".forces", c);
}

}  // namespace

void stability_view(const exact::JsonInput& cert, const exact::JsonInput& embedded, CheckResult& c) {
  const geometry::PlanarScene scene = checker::frame_check::read_checked_scene(embedded).scene;
  std::vector<Eigen::Index> touching;  // the fixels strong stability considers: those touching, in scene order
  for (std::size_t i = 0; i < scene.fixels.size(); ++i)
    if (scene.fixels[i].frame.touching()) touching.push_back(static_cast<Eigen::Index>(i));
  const exact::Vec<exact::Q> g = cert.at("wrench").rational_vector(3);
  c.details["wrench"] = exact_json(g);
  c.text = "  wrench g = " + tuple_text(g) + "\n";
  if (cert.at("resting").find("forces")) {
    json view;
    std::string lines;
    add_contacts(cert.at("resting"), "resting", scene, touching, c, view, lines);
    c.details["resting_contacts"] = view;
    c.text += "  at rest with contact forces (world coordinates; they balance g):\n" + lines;
  } else {
    c.text += "  at rest: no contact forces in the friction cones balance g (Motzkin vector checked)\n";
  }
  if (auto moving = cert.find("moving")) {
    json view;
    std::string lines;
    add_contacts(*moving, "moving", scene, touching, c, view, lines);
    const auto a = moving->at("acceleration").rational_vector(3);
    c.details["moving"] = {{"mode", moving->at("mode").string()}, {"acceleration", exact_json(a)}, {"contacts", view}};
    c.text += "  moves in mode '" + moving->at("mode").string() + "' with acceleration " + tuple_text(a) +
              ", contact forces (world coordinates):\n" + lines;
  }
}

void cone_view(const exact::JsonInput& cert, const exact::JsonInput& embedded,
               const std::vector<Eigen::Index>& touching, const exact::Vec<exact::Q>& forces, CheckResult& c) {
  const geometry::PlanarScene scene = checker::frame_check::read_checked_scene(embedded).scene;
  const exact::Vec<exact::Q> g = cert.at("wrench").rational_vector(3);
  const auto world = checker::checked_world_forces(scene, touching, forces);
  const json view = witness_json(scene, world, g);
  c.details["witness"] = view;
  c.text = witness_text(scene, world, g, "  ");
  for (const char* key : {"contacts", "acceleration"})
    require_view(cert.find(key), view.at(key), key, std::string(key) + " is not the view of the checked witness", c);
}

}  // namespace contactcert::queries
