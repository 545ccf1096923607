// The geometric front end (solvers/ucp/scene_builder.h): Data Sets 1-4 written as geometry give the paper's
// matrices exactly; force-controlled and world-axis fingers and obstacles give the J_abar columns, d and J rows
// of section 2; bad fields are named.
#include "solvers/ucp/scene_builder.h"

#include <gtest/gtest.h>

#include <string>

#include "exact/input_error.h"
#include "runtime/scenes.h"

namespace contactcert::solvers::ucp {
namespace {

const std::string kScenes = contactcert::runtime::bundled_scenes_dir() + "/";

TEST(SceneBuilder, DataSetsOneToFourAsGeometryGiveThePapersMatrices) {
  for (int ds = 1; ds <= 4; ++ds) {
    SCOPED_TRACE("Data Set " + std::to_string(ds));
    const auto paper = load_ucp_problem(kScenes + "pang1994_dataset" + std::to_string(ds) + ".json");
    const auto built = load_ucp_problem(kScenes + "pang1994_dataset" + std::to_string(ds) + "_geometry.json");
    ASSERT_TRUE(paper.quasistatic && built.quasistatic);
    const QuasistaticProblem &a = *paper.quasistatic, &b = *built.quasistatic;
    EXPECT_EQ(a.nc, b.nc);
    EXPECT_EQ(a.nq, b.nq);
    EXPECT_EQ(a.ntheta, b.ntheta);
    EXPECT_EQ(a.P, b.P);
    EXPECT_EQ(a.Jn, b.Jn);
    EXPECT_EQ(a.Jt, b.Jt);
    EXPECT_EQ(a.theta_dot, b.theta_dot);
    EXPECT_EQ(a.alpha, b.alpha);
    EXPECT_EQ(a.abar, b.abar);
    EXPECT_EQ(a.d, b.d);
    EXPECT_EQ(a.mu, b.mu);
    EXPECT_EQ(paper.ucp().X.A, built.ucp().X.A);
    EXPECT_EQ(paper.ucp().Y.b, built.ucp().Y.b);
  }
}

/// A unit square resting on an obstacle at (1/2, 0), pushed by a force-controlled finger at (0, 1/2) with
/// world axes and touched by a velocity-controlled finger at (1, 1/2) with frame axes.
const char* kBox = R"({"kind": "quasistatic_scene",
  "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}},
  "gravity": [0, "-2"],
  "contacts": [
    {"point": ["1/2", 0], "normal": [0, 1], "mu": "0.3"},
    {"position": [0, "1/2"], "mu": "1/5", "finger": {"axes": "world", "force": ["3/10", 0]}},
    {"point": [1, "1/2"], "normal": [-1, 0], "mu": "0.5", "finger": {"velocity": ["-0.1", 0]}}]})";

QuasistaticProblem build(const std::string& text) {
  return build_quasistatic_scene(exact::JsonInput::parse(text, "box.json"));
}

TEST(SceneBuilder, ObstaclesForceAndVelocityControlledFingers) {
  const QuasistaticProblem p = build(kBox);
  EXPECT_EQ(p.nc, 3);
  EXPECT_EQ(p.ntheta, 4);
  EXPECT_EQ(p.alpha, (std::vector<int>{2, 3}));
  EXPECT_EQ(p.abar, (std::vector<int>{0, 1}));
  // The obstacle has no joints; the world-axis finger's rows are n^T and t^T on joints 0, 1.
  EXPECT_EQ(p.Jn.row(0), Mat<Q>::Zero(1, 4));
  const struct { Q x, y; } n = {p.Jn(1, 0), p.Jn(1, 1)};
  EXPECT_GT(n.x, Q(0));
  EXPECT_EQ(n.y, Q(0));
  EXPECT_EQ(p.Jt(1, 0), Q(0));
  EXPECT_EQ(p.Jt(1, 1), n.x);
  EXPECT_EQ(p.Jn(2, 2), Q(1));
  EXPECT_EQ(p.Jt(2, 3), Q(1));
  // P = [W^T  J_abar]: the obstacle's normal row (0, 1, r x n) = (0, 1, 1/2).
  EXPECT_EQ(p.P.cols(), 5);
  EXPECT_EQ(p.P(0, 0), Q(0));
  EXPECT_EQ(p.P(0, 1), Q(1));
  EXPECT_EQ(p.P(0, 2), Q(1, 2));
  EXPECT_EQ(p.P(1, 3), n.x);  // J_abar column of joint 0 at the finger's normal row
  // d = [0 0 0; g_obj = (0, -2, com x (0, -2)) with com (1/2, 1/2); -tau_abar].
  Vec<Q> d(8);
  d << 0, 0, 0, 0, -2, -1, Q(-3, 10), 0;
  EXPECT_EQ(p.d, d);
  EXPECT_EQ(p.theta_dot(2), Q(-1, 10));
}

void expect_error(const std::string& text, const std::string& path) {
  try {
    build(text);
    ADD_FAILURE() << "accepted: expected an error at " << path;
  } catch (const exact::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(SceneBuilder, ErrorsNameTheField) {
  const std::string box = kBox;
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = box;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  expect_error(with(R"("mu": "0.3")", R"("mu": "-1")"), "$.contacts[0].mu");
  expect_error(with(R"("point": ["1/2", 0])", R"("point": ["1/2", "1/3"])"), "$.contacts[0].point");
  expect_error(with(R"("normal": [0, 1])", R"("normal": [1, 0])"), "$.contacts[0].normal");
  expect_error(with(R"({"axes": "world", "force": ["3/10", 0]})", R"({"axes": "world"})"), "$.contacts[1].finger");
  expect_error(with(R"("axes": "world")", R"("axes": "joint")"), "$.contacts[1].finger.axes");
  expect_error(with(R"("position": [0, "1/2"])", R"("position": ["-1", "1/2"])"), "$.contacts[1].position");
  expect_error(with(R"("gravity")", R"("gravty")"), "gravty");
}

}  // namespace
}  // namespace contactcert::solvers::ucp
