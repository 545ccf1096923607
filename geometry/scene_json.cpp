#include "geometry/scene_json.h"

namespace contactcert::geometry {
Point2 read_point(const exact::JsonInput& node) {
  const exact::Vec<Q> v = node.rational_vector(2);
  return {v(0), v(1)};
}

Q read_positive(const exact::JsonInput& node) {
  Q x = node.rational();
  if (sgn(x) <= 0) node.fail("a positive number");
  return x;
}

Q read_nonnegative(const exact::JsonInput& node) {
  Q x = node.rational();
  if (sgn(x) < 0) node.fail("a number >= 0");
  return x;
}

namespace {

using exact::JsonInput;

}  // namespace

Shape read_shape(const JsonInput& node) {
  const std::string type = node.at("type").string();
  if (type == "polygon") {
    node.expect_keys({"type", "vertices"});
    const JsonInput vs = node.at("vertices");
    if (vs.size() > kMaxPolygonVertices)  // before reading them
      vs.fail(PolygonCheck{PolygonDefect::kTooManyVertices, vs.size()}.message());
    PolygonShape poly;
    for (const JsonInput& v : vs.elements()) poly.vertices.push_back(read_point(v));
    const PolygonCheck check = check_polygon(poly.vertices);
    if (check.defect != PolygonDefect::kNone) vs.fail(check.message());
    return poly;
  }
  if (type == "disk") {
    node.expect_keys({"type", "center", "radius"});
    return DiskShape{read_point(node.at("center")), read_positive(node.at("radius"))};
  }
  node.at("type").fail("\"polygon\" or \"disk\"");
}

Workpiece read_workpiece(const JsonInput& node) {
  node.expect_keys({"shape", "com", "mass", "inertia"});
  Workpiece w;
  w.shape = read_shape(node.at("shape"));
  const auto com = node.find("com");
  w.com = com ? read_point(*com) : centroid(w.shape);
  const auto mass = node.find("mass");
  const auto inertia = node.find("inertia");
  if (inertia) {
    if (!mass) node.fail("a \"mass\" beside \"inertia\" (only I/m matters)");
    w.inertia_per_mass = read_positive(*inertia) / read_positive(*mass);
  } else {
    if (mass) read_positive(*mass);
    w.inertia_per_mass = inertia_per_mass(w.shape, w.com);
  }
  return w;
}

PlanarSceneInput read_planar_scene_input(const JsonInput& root) {
  if (root.at("kind").string() != "planar") root.at("kind").fail("\"planar\" (a planar fixture scene)");
  root.expect_keys({"kind", "name", "description", "workpiece", "fixels", "mu_s", "mu_k"});
  PlanarSceneInput scene;
  scene.workpiece = read_workpiece(root.at("workpiece"));
  const auto mu_s = root.find("mu_s");
  const auto mu_k = root.find("mu_k");
  const std::optional<Q> global_s = mu_s ? std::optional<Q>(read_nonnegative(*mu_s)) : std::nullopt;
  const std::optional<Q> global_k = mu_k ? std::optional<Q>(read_nonnegative(*mu_k)) : std::nullopt;
  const JsonInput fixels = root.at("fixels");
  for (const JsonInput& f : fixels.elements()) {
    f.expect_keys({"name", "position", "point", "normal", "gap", "mu_s", "mu_k"});
    FixelInput fixel;
    if (const auto pos = f.find("position")) {
      if (f.find("point") || f.find("normal") || f.find("gap"))
        f.fail("either \"position\" or an explicit contact {point, normal, gap}, not both");
      fixel.given.position = read_point(*pos);
    } else {
      fixel.given.point = read_point(f.at("point"));
      fixel.given.normal = read_point(f.at("normal"));
      const auto gap_node = f.find("gap");
      fixel.given.gap = gap_node ? read_nonnegative(*gap_node) : Q(0);
    }
    const auto s = f.find("mu_s");
    const auto k = f.find("mu_k");
    if (s) {
      fixel.mu_s = read_nonnegative(*s);
    } else if (global_s) {
      fixel.mu_s = *global_s;
    } else {
      f.fail("a friction coefficient \"mu_s\", here or at the top level");
    }
    fixel.mu_k = k ? read_nonnegative(*k) : (global_k ? *global_k : fixel.mu_s);
    scene.fixels.push_back(fixel);
  }
  if (scene.fixels.empty()) fixels.fail("at least one fixel");
  return scene;
}

PlanarScene read_planar_scene(const JsonInput& root) {
  const PlanarSceneInput in = read_planar_scene_input(root);
  const std::vector<JsonInput> nodes = root.at("fixels").elements();
  PlanarScene scene{in.workpiece, {}};
  for (std::size_t i = 0; i < in.fixels.size(); ++i) {
    const FixelInput& f = in.fixels[i];
    const FrameResult frame = frame_of(in.workpiece.shape, f.given);
    if (frame.status != FrameStatus::kOk) (f.given.position ? nodes[i].at("position") : nodes[i]).fail(frame.message);
    scene.fixels.push_back({frame.frame, f.mu_s, f.mu_k, f.given.position});
  }
  return scene;
}

PlanarScene load_planar_scene(const std::string& path) { return read_planar_scene(JsonInput::load(path)); }

}  // namespace contactcert::geometry
