#include "queries/ucp_query.h"

#include <gtest/gtest.h>

#include "exact/input_error.h"
#include "runtime/scenes.h"

namespace contactcert::queries {
namespace {

namespace ucp = solvers::ucp;

std::string scene(const std::string& name) { return runtime::bundled_scenes_dir() + "/" + name; }

/// The message of the InputError `f` throws, or "" if it throws none.
template <class F>
std::string message(F f) {
  try {
    f();
  } catch (const exact::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(UcpQuery, RefusesWhatTheRunWouldIgnore) {
  UcpQueryOptions o;
  o.method = ucp::Method::kPaper;
  o.max_nodes = 5;
  EXPECT_NE(message([&] { check_ucp_options(o); }).find("--max-nodes"), std::string::npos);
  o = {};
  o.method = ucp::Method::kEnumerate;
  o.max_bases = 5;
  EXPECT_NE(message([&] { check_ucp_options(o); }).find("--max-bases"), std::string::npos);
  o = {};
  o.common.arith = exact::Arith::kFloat;
  o.certificate = "c.json";
  EXPECT_NE(message([&] { check_ucp_options(o); }).find("a certificate needs --arith exact or verified"),
            std::string::npos);
  o = {};
  o.max_nodes = 5;
  o.max_bases = 5;
  EXPECT_EQ(message([&] { check_ucp_options(o); }), "");  // the complete search uses both
  EXPECT_EQ(parse_method("enumerate", "--method"), ucp::Method::kEnumerate);
  EXPECT_NE(message([] { parse_method("best", "--method"); }).find("--method"), std::string::npos);
}

TEST(UcpQuery, UnsetBudgetsAreTheSolversDefaults) {
  const UcpInput in = load_ucp(scene("pang1994_dataset4.json"));
  UcpQueryOptions o;
  const UcpAnswer unset = *run_ucp(in, o);
  o.max_nodes = ucp::UcpOptions{}.max_nodes;
  o.max_bases = ucp::UcpOptions{}.max_bases;
  const UcpAnswer given = *run_ucp(in, o);
  EXPECT_EQ(unset.report.status, ucp::UcpStatus::kJammed);
  EXPECT_EQ(unset.report.nodes, given.report.nodes);
  o.max_nodes = 1;
  EXPECT_EQ(run_ucp(in, o)->report.status, ucp::UcpStatus::kUnknown);
}

TEST(UcpQuery, SceneContactsInTheJson) {
  const UcpAnswer scene_answer = *run_ucp(load_ucp(scene("pang1994_dataset1_geometry.json")), {});
  const UcpAnswer matrices = *run_ucp(load_ucp(scene("pang1994_dataset1.json")), {});
  ASSERT_EQ(scene_answer.report.status, ucp::UcpStatus::kSolvable);
  const json j = to_json(scene_answer);
  EXPECT_EQ(j["physical"]["contacts"].size(), j["physical"]["c_n"].size());
  EXPECT_FALSE(to_json(matrices)["physical"].contains("contacts"));  // a problem given by matrices states no geometry
}

TEST(UcpQuery, GeneratorsCheckTheirRanges) {
  UcpGenerateOptions o;
  o.abar = 7;  // > 2 nc
  EXPECT_NE(message([&] { generate_ucp(o); }).find("--nc/--abar/--mu-max"), std::string::npos);
  o = {};
  o.generator = UcpGenerator::kReduction;
  o.cols = 61;
  EXPECT_NE(message([&] { generate_ucp(o); }).find("--rows/--cols"), std::string::npos);
  o.cols = 4;
  o.seed = 5;
  EXPECT_NE(generate_ucp(o).source.find(", seed 5"), std::string::npos);
  EXPECT_EQ(parse_exact_option("1/2", "--mu-max"), exact::Q(1, 2));
  EXPECT_NE(message([] { parse_exact_option("1+", "--mu-max"); }).find("--mu-max"), std::string::npos);
  EXPECT_EQ(parse_generator("reduction", "--generate"), UcpGenerator::kReduction);
}

// `--all` (issue 32): the unique motion of Data Set 2 is the solve's own q_dot; a jammed problem (Data Set 4) has no
// motion: `no_motion` without a tree walked, as the prefix tree itself finds (no solution mode); the prefix tree's
// budget is the run's Limit with the LPs covered; its options without --all are refused.
TEST(UcpQuery, AllDecidesTheUniquenessOfTheInstant) {
  UcpQueryOptions o;
  o.uniqueness.all = true;
  const UcpAnswer unique = *run_ucp(load_ucp(scene("pang1994_dataset2.json")), o);
  ASSERT_TRUE(unique.uniqueness);
  EXPECT_EQ(unique.uniqueness->verdict.status, solvers::motion::UniquenessStatus::kUnique);
  ASSERT_EQ(unique.uniqueness->verdict.motions.size(), 1u);
  EXPECT_EQ(unique.uniqueness->verdict.motions[0], unique.report.physical->q_dot.to_q());
  EXPECT_EQ(to_json(unique)["uniqueness"]["status"], "unique");
  const UcpInput jammed = load_ucp(scene("pang1994_dataset4.json"));
  const UcpAnswer none = *run_ucp(jammed, o);
  ASSERT_TRUE(none.uniqueness);
  EXPECT_EQ(none.uniqueness->verdict.status, solvers::motion::UniquenessStatus::kNoMotion);
  EXPECT_EQ(none.uniqueness->verdict.lps, 0);
  EXPECT_EQ(to_json(none)["uniqueness"]["status"], "no_motion");
  EXPECT_NE(to_text(*none.uniqueness, 0).find("uniqueness: no motion"), std::string::npos);
  const solvers::motion::MotionUniqueness tree =
      solvers::motion::motion_uniqueness(jammed.problem, exact::Arith::kVerified, 4096);
  EXPECT_EQ(tree.status, solvers::motion::UniquenessStatus::kNoMotion);
  EXPECT_GT(tree.lps, 0);
  o.uniqueness.max_modes = 2;
  const Limited<UcpAnswer> limited = run_ucp(load_ucp(scene("pang1994_dataset2.json")), o);
  ASSERT_FALSE(limited);
  EXPECT_NE(limited.limit().what.find("(--max-modes 2) ran out"), std::string::npos) << limited.limit().what;
  o.uniqueness.all = false;
  EXPECT_NE(message([&] { check_ucp_options(o); }).find("--max-modes"), std::string::npos);
}

}  // namespace
}  // namespace contactcert::queries
