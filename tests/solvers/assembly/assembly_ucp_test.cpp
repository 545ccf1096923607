// Pang-Trinkle-Lo's quasistatic problem for several bodies (eqs. (1)-(10)), built exactly from an assembly: one body
// rebuilds the one-workpiece builder's matrices entry for entry; two boxes pushed by a finger are solved, and
// pushed against a wall they are proven jammed with a certificate the UCP checker accepts.
#include "solvers/assembly/assembly_ucp.h"

#include <gtest/gtest.h>

#include "checker/ucp_check.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/scene_builder.h"
#include "solvers/ucp/solve.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

using exact::Q;
using exact::Vec;
using testing::body;
using testing::box;
using testing::obstacle;
using testing::point;
using testing::SceneText;

TEST(AssemblyUcp, OneBodyRebuildsTheOneWorkpieceBuilder) {
  // docs/formats.md section 2's example, once as a workpiece and once as an assembly of one body of mass 1.
  const std::string one = R"({"kind": "quasistatic_scene",
    "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "com": ["1/2", "1/2"]},
    "gravity": [0, -1],
    "contacts": [
      {"point": ["1/2", 0], "normal": [0, 1], "mu": "0.3"},
      {"position": [0, "1/2"], "mu": "1/5", "finger": {"axes": "world", "force": ["3/10", 0]}},
      {"point": [1, "1/2"], "normal": [-1, 0], "mu": "0.5", "finger": {"velocity": ["-0.1", 0]}}]})";
  const std::string many = R"({"kind": "quasistatic_scene",
    "bodies": [{"shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [1, 1], [0, 1]]}, "com": ["1/2", "1/2"],
                "mass": 1}],
    "fixels": [{"position": ["1/2", 0]}],
    "fingers": [{"position": [0, "1/2"], "axes": "world", "force": ["3/10", 0]},
                {"position": [1, "1/2"], "velocity": ["-0.1", 0]}],
    "gravity": [0, -1],
    "contacts": [
      {"from": {"fixel": 0}, "to": {"body": 0}, "mu": "0.3"},
      {"from": {"finger": 0}, "to": {"body": 0}, "mu": "1/5"},
      {"from": {"finger": 1}, "to": {"body": 0}, "point": [1, "1/2"], "normal": [-1, 0], "mu": "0.5"}]})";
  const ucp::QuasistaticProblem p = ucp::build_quasistatic_scene(exact::JsonInput::parse(one, "one.json"));
  const ucp::QuasistaticProblem q =
      assembly_quasistatic(geometry::read_assembly(exact::JsonInput::parse(many, "many.json")));
  EXPECT_EQ(q.nc, p.nc);
  EXPECT_EQ(q.nq, p.nq);
  EXPECT_EQ(q.ntheta, p.ntheta);
  EXPECT_EQ(q.P, p.P);
  EXPECT_EQ(q.Jn, p.Jn);
  EXPECT_EQ(q.Jt, p.Jt);
  EXPECT_EQ(q.theta_dot, p.theta_dot);
  EXPECT_EQ(q.alpha, p.alpha);
  EXPECT_EQ(q.abar, p.abar);
  EXPECT_EQ(q.d, p.d);
  EXPECT_EQ(q.mu, p.mu);
}

/// Boxes A = [0,1]^2 and B = [1,2] x [0,1] on the ground (mu 3/10), touching along x = 1 (contacts at heights 1/4
/// and 3/4, normal (1, 0) from A into B, mu 1/5), a finger at (0, 1/2) on A with frame axes and velocity
/// (v_n, 0); with `wall`, a fixed wall [2,3] x [0,2] touches B at heights 1/4 and 3/4.
ucp::UcpProblem pushed_boxes(const char* v_n, bool wall) {
  SceneText s;
  s.kind = "quasistatic_scene";
  const std::size_t g = testing::ground(s);
  s.body(box(0, 0, 1, 1));
  s.body(box(1, 0, 2, 1));
  for (const Q& x : {Q(0), Q(1)}) s.contact(obstacle(g), body(0), point(x, 0), "[0, 1]", testing::mu("3/10"));
  for (const Q& x : {Q(1), Q(2)}) s.contact(obstacle(g), body(1), point(x, 0), "[0, 1]", testing::mu("3/10"));
  for (const Q& y : {Q(1, 4), Q(3, 4)}) s.contact(body(0), body(1), point(1, y), "[1, 0]", testing::mu("1/5"));
  if (wall) {
    const std::size_t w = s.obstacle(box(2, 0, 3, 2));
    for (const Q& y : {Q(1, 4), Q(3, 4)}) s.contact(obstacle(w), body(1), point(2, y), "[-1, 0]", testing::mu("1/5"));
  }
  s.fingers.push_back(std::string("{\"position\": [0, \"1/2\"], \"velocity\": [\"") + v_n + "\", 0]}");
  s.contacts.push_back("{\"from\": {\"finger\": 0}, \"to\": {\"body\": 0}, \"mu\": \"1/2\"}");
  ucp::UcpProblem p;
  p.quasistatic = assembly_quasistatic(s.read(), "pushed.json");
  p.set(ucp::build_ucp(*p.quasistatic));
  return p;
}

// Pushed (the finger's joint along n at +1: the finger moves along n, into A, as a velocity along n does for one
// workpiece) the pair slides: solvable, and the recovered physics satisfies (2)-(10).
// Against the wall nothing can move right, so no solution exists: jammed, with a checked certificate.
TEST(AssemblyUcp, TwoBoxesPushedByAFinger) {
  const ucp::UcpProblem free = pushed_boxes("1", false);
  EXPECT_EQ(free.quasistatic->nq, 6);
  EXPECT_EQ(free.quasistatic->nc, 7);
  const ucp::UcpReport r = ucp::solve_ucp(free, {});
  ASSERT_EQ(r.status, ucp::UcpStatus::kSolvable);
  ASSERT_TRUE(r.physical && r.conditions);
  EXPECT_EQ(r.conditions->status, ucp::ConditionsStatus::kSatisfied);
  const Vec<Q> q_dot = r.physical->q_dot.to_q();
  EXPECT_GE(q_dot(0), 1);  // A moves right at least at the finger's speed
  EXPECT_GE(q_dot(3), 1);  // and pushes B (rotation about the origin aside, B's frame moves right too)
  const std::string solvable = ucp::certificate_text(free, r);
  EXPECT_EQ(checker::check_ucp_certificate(exact::JsonInput::parse(solvable, "s.json")).verdict,
            checker::CertificateVerdict::kValid);

  const ucp::UcpProblem blocked = pushed_boxes("1", true);
  const ucp::UcpReport j = ucp::solve_ucp(blocked, {});
  ASSERT_EQ(j.status, ucp::UcpStatus::kJammed);
  const std::string jammed = ucp::certificate_text(blocked, j);
  const checker::CertificateCheck c = checker::check_ucp_certificate(exact::JsonInput::parse(jammed, "j.json"));
  EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << c.reason;

  // Withdrawn (-1), the finger leaves the boxes at rest even against the wall.
  const ucp::UcpReport away = ucp::solve_ucp(pushed_boxes("-1", true), {});
  ASSERT_EQ(away.status, ucp::UcpStatus::kSolvable);
  EXPECT_TRUE(away.physical->q_dot.to_q().isZero());
}

}  // namespace
}  // namespace contactcert::solvers::assembly
