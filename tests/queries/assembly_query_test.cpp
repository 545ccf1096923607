// The assembly queries (queries/assembly_query.h) on the bundled assemblies: the world forces they report balance
// every body's load exactly (at rest: Newton-Euler with vdot = 0; the quasistatic solution: eq. (1), W c + g = 0),
// the moving witness's forces give M vdot, and the certificate a run writes is VALID for the checker.
#include "queries/assembly_query.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "checker/assembly_check.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "queries/assembly_svg.h"
#include "runtime/scenes.h"
#include "solvers/assembly/assembly_certificate.h"

namespace contactcert::queries {
namespace {

using exact::Q;
using geometry::Point2;

AssemblyInput bundled(const std::string& name) {
  return load_assembly(runtime::bundled_scenes_dir() + "/" + name + ".json");
}

/// Per body, load + the contact forces acting on it: (f_x, f_y, torque about `about(b)`).
std::vector<std::array<Q, 3>> net_wrenches(const geometry::Assembly& a, const std::vector<AssemblyContactForce>& fs,
                                           bool torque_about_origin) {
  std::vector<std::array<Q, 3>> net;
  for (const geometry::Body& b : a.bodies) {
    const Point2 f{b.load_fx, b.load_fy};
    net.push_back({f.x, f.y, b.load_torque + (torque_about_origin ? geometry::cross(b.com, f) : Q(0))});
  }
  for (const AssemblyContactForce& c : fs)
    for (const auto& [party, sign] : {std::pair{c.to, 1}, std::pair{c.from, -1}}) {
      if (!party.movable()) continue;
      const Point2 r = torque_about_origin ? c.point : c.point - a.bodies[party.index].com;
      auto& w = net[party.index];
      w[0] += sign * c.force.x;
      w[1] += sign * c.force.y;
      w[2] += sign * geometry::cross(r, c.force);
    }
  return net;
}

TEST(AssemblyQuery, WitnessForcesBalanceTheLoadsAndCertificatesCheck) {
  const std::vector<std::pair<std::string, const char*>> scenes = {
      {"assembly_two_boxes", "strongly_stable"},   {"assembly_two_boxes_pushed", "strongly_stable"},
      {"assembly_overhang", "unstable"},           {"assembly_corbel", "strongly_stable"},
      {"assembly_corbel_arch", "strongly_stable"}, {"assembly_pushed_box_weak", "weakly_stable"}};
  const std::string certificate = (std::filesystem::temp_directory_path() / "assembly_query_test.json").string();
  for (const auto& [name, verdict] : scenes) {
    const AssemblyInput in = bundled(name);
    AssemblyStabilityOptions o;
    o.certificate = certificate;
    const AssemblyStabilityAnswer ans = *run_assembly_stability(in, o);
    ASSERT_TRUE(ans.decided()) << name;
    EXPECT_EQ(to_json(ans)["verdict"], verdict) << name;
    const auto& r = ans.result;
    if (r.has_resting) {
      for (const auto& w : net_wrenches(in.assembly, ans.resting, false)) {
        EXPECT_TRUE(w[0] == 0 && w[1] == 0 && w[2] == 0) << name;
      }
    }
    if (r.has_moving) {
      const auto net = net_wrenches(in.assembly, ans.moving, false);
      for (std::size_t b = 0; b < net.size(); ++b) {
        const geometry::Body& body = in.assembly.bodies[b];
        const auto i = static_cast<Eigen::Index>(3 * b);
        EXPECT_EQ(net[b][0], body.mass * r.moving.acceleration(i)) << name;
        EXPECT_EQ(net[b][1], body.mass * r.moving.acceleration(i + 1)) << name;
        EXPECT_EQ(net[b][2], body.inertia * r.moving.acceleration(i + 2)) << name;
      }
    }
    const auto check = checker::check_assembly_certificate(
        exact::JsonInput::parse(exact::JsonInput::read_text(certificate), certificate));
    EXPECT_TRUE(check.valid) << name << ": " << check.reason;
    EXPECT_EQ(ans.certificate_text, exact::JsonInput::read_text(certificate)) << name;
  }
  std::filesystem::remove(certificate);
}

// The solution's contact forces hold each body in quasistatic equilibrium (eq. (1), torques about the origin).
TEST(AssemblyQuery, QuasistaticForcesBalanceEveryBody) {
  const AssemblyInput in = bundled("assembly_pushed_boxes");
  const AssemblyUcpAnswer ans = *run_assembly_ucp(in, {});
  ASSERT_EQ(ans.report.status, solvers::ucp::UcpStatus::kSolvable);
  ASSERT_EQ(ans.forces.size(), in.assembly.contacts.size());
  for (const auto& w : net_wrenches(in.assembly, ans.forces, true)) {
    EXPECT_TRUE(w[0] == 0 && w[1] == 0 && w[2] == 0);
  }
  for (const BodyVelocity& v : ans.bodies) {
    EXPECT_EQ(v.com_velocity.x, Q(1));  // both pushed at the finger's speed
  }
  EXPECT_EQ(run_assembly_ucp(bundled("assembly_pushed_boxes_wall"), {})->report.status,
            solvers::ucp::UcpStatus::kJammed);
}

// A certificate larger than `check` reads is refused naming the command that ran: `ucp ASSEMBLY` says `ucp`.
TEST(AssemblyQuery, ATooLargeCertificateNamesTheCommandThatRan) {
  const std::string file = testing::TempDir() + "/too_large_assembly.cert.json";
  for (const auto command : {AssemblyUcpOptions::Command::kUcp, AssemblyUcpOptions::Command::kAssembly}) {
    AssemblyUcpOptions o;
    o.command = command;
    o.certificate = file;
    AssemblyUcpAnswer ans;
    ans.certificate_text = std::string(exact::kMaxInputBytes + 1, ' ');
    const std::string expected = command_name(o) + " --certificate: the certificate would take";
    try {
      write_files(AssemblyInput{}, o, ans);
      FAIL() << "no budget";
    } catch (const exact::BudgetExceeded& e) {
      EXPECT_EQ(std::string(e.what()).rfind(expected, 0), 0u) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(file));
  }
  EXPECT_EQ(command_name(AssemblyUcpOptions{}), "assembly");
}

TEST(AssemblyQuery, RefusesWhatItWouldNotAnswerExactly) {
  EXPECT_THROW(bundled("bt2002_section7_disk"), exact::InputError);  // no bodies
  AssemblyStabilityOptions o;
  o.common.arith = exact::Arith::kFloat;
  EXPECT_THROW(run_assembly_stability(bundled("assembly_two_boxes"), o), exact::InputError);
}

}  // namespace
}  // namespace contactcert::queries
