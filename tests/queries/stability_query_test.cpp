#include "queries/stability_query.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "queries/finger_query.h"
#include "queries/json_out.h"
#include "queries/region_query.h"
#include "queries/wrenches_query.h"
#include "runtime/scenes.h"

namespace contactcert::queries {
namespace {

using exact::Q;
using exact::Vec;

SceneInput scene(const std::string& name) { return load_scene(runtime::bundled_scenes_dir() + "/" + name); }

Vec<Q> wrench(const std::string& text) { return parse_number_list(text, "--wrench", 3); }

const char* const kWrenches[] = {"0,-1,0", "1,-2,0", "-1,-1,0", "0,0,1", "1/3,-7/5,1/10", "0,0,0"};

/// The field the InputError `f` throws names ("" if it throws none).
template <class F>
std::string refused(F f) {
  try {
    f();
  } catch (const exact::InputError& e) {
    return e.json_path;
  }
  return "";
}

TEST(StabilityQuery, FloatPathRefusesWhatOnlyExactnessGives) {
  const SceneInput disk = scene("bt2002_section7_disk.json");
  StabilityQueryOptions o{{exact::Arith::kFloat, 0}, wrench("0,-1,0"), false, "c.json"};
  EXPECT_EQ(refused([&] { run_stability(disk, o); }), "--certificate");
  o.certificate = "";
  o.margin = true;
  EXPECT_EQ(refused([&] { run_stability(disk, o); }), "--margin");
  EXPECT_EQ(refused([&] { run_region(disk, {{exact::Arith::kFloat, 0}, std::nullopt, ""}); }), "--arith");
  EXPECT_EQ(refused([&] { run_finger(disk, {{exact::Arith::kFloat, 0}, ""}); }), "--arith");
}

TEST(StabilityQuery, AdaptiveRunsAndIsReportedAsVerified) {
  const SceneInput disk = scene("bt2002_section7_disk.json");
  const CommonOptions adaptive{exact::Arith::kAdaptive, 0}, verified{exact::Arith::kVerified, 0};
  const StabilityAnswer a = *run_stability(disk, {adaptive, wrench("1,-2,0"), true, ""});
  EXPECT_EQ(a.arith, exact::Arith::kVerified);
  EXPECT_EQ(to_json(a), to_json(*run_stability(disk, {verified, wrench("1,-2,0"), true, ""})));
  EXPECT_EQ(to_json(a)["arith"], "verified");
  ASSERT_TRUE(a.margin.has_value());
  EXPECT_GT(a.margin->squared_radius, 0);
}

// The oracle's answer is the single run's except for what the prepared tree counts differently.
TEST(StabilityQuery, OracleAnswersEqualSingleRuns) {
  for (const char* name : {"bt2002_section7_disk.json", "bt2002_fig4a_lla.json", "bt2002_fig10_pentagon_insert.json"})
    for (const exact::Arith& arith : {exact::Arith::kExact, exact::Arith::kFloat, exact::Arith::kVerified}) {
      const SceneInput in = scene(name);
      const StabilityVerdicts oracle(in.scene, {arith, 0});
      for (const char* w : kWrenches) {
        json batch = to_json(oracle.answer(wrench(w)));
        json single = to_json(*run_stability(in, {{arith, 0}, wrench(w), false, ""}));
        for (const char* key : {"lps", "mode_tree", "modes_kinematically_feasible"}) {
          batch.erase(key);
          single.erase(key);
        }
        EXPECT_EQ(batch, single) << name << " " << w << " " << exact::arith_name(arith);
      }
    }
}

// The region labels every wrench as the verdict does (section 7: g strongly stable iff in no moving mode's cone
// and in the weakly stable cone), and the batch counts what it labels.
TEST(StabilityQuery, RegionLabelsAgreeWithVerdictsAndBatchCounts) {
  for (const char* name : {"bt2002_section7_disk.json", "bt2002_fig4b_nnn.json", "bt2002_fig4c_peg_lra.json"}) {
    const SceneInput in = scene(name);
    std::array<long, 3> counts{};
    for (const char* w : kWrenches) {
      const RegionAnswer region = *run_region(in, {{}, wrench(w), ""});
      const StabilityAnswer single = *run_stability(in, {{}, wrench(w), false, ""});
      const auto verdict = std::get<solvers::StabilityResult<Q>>(single.outcome).verdict;
      EXPECT_EQ(region.wrench_label, verdict) << name << " " << w;
      ++counts[static_cast<int>(verdict)];
    }
    std::string file = testing::TempDir() + "/wrenches.txt", text;
    for (const char* w : kWrenches) text += std::string(w) + "\n";
    write_text_file(file, text);
    const WrenchesAnswer batch = *run_wrenches(in, {{}, file});
    EXPECT_EQ(batch.counts, counts) << name;
    EXPECT_EQ(to_json(batch)["wrenches"].size(), std::size(kWrenches));
  }
}

/// The text of the limit that stopped `run` (a query's Limited answer) at a budget, else "".
template <class A>
std::string budget_text(const Limited<A>& run) {
  return !run && run.limit().kind == Limit::Kind::kBudget ? run.limit().text() : "";
}

// One deadline for the whole run: far too short a limit stops each query with a status saying what was covered.
TEST(StabilityQuery, TimeLimitStopsEveryQuery) {
  const SceneInput disk48 = load_scene(DISK48_SCENE);  // 48 touching fixels
  const CommonOptions short_limit{exact::Arith::kVerified, 1e-6};
  const std::string file = testing::TempDir() + "/one_wrench.txt";
  write_text_file(file, "0,-1,0\n");
  const std::string texts[] = {budget_text(run_stability(disk48, {short_limit, wrench("0,-1,0"), true, ""})),
                               budget_text(run_region(disk48, {short_limit, std::nullopt, ""})),
                               budget_text(run_finger(disk48, {short_limit, ""})),
                               budget_text(run_wrenches(disk48, {short_limit, file}))};
  for (const std::string& text : texts)
    EXPECT_NE(text.find("time limit of 1e-06 s reached (covered: "), std::string::npos) << text;
  EXPECT_THROW(StabilityVerdicts(disk48.scene, short_limit), exact::BudgetExceeded);  // for with_limits to catch
}

/// A certificate that `check` could not read back (more than kMaxInputBytes) is refused with a budget, not written.
TEST(CertificateFile, LargerThanCheckReadsIsNotWritten) {
  const std::string file = testing::TempDir() + "/too_large.cert.json";
  std::remove(file.c_str());
  try {
    write_certificate_file("stability", file, std::string(exact::kMaxInputBytes + 1, ' '), "the verdict is unstable");
    FAIL() << "no budget";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("stability --certificate: the certificate would take 33554433 bytes"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::ifstream(file).good());
  write_certificate_file("stability", file, std::string(exact::kMaxInputBytes, ' '), "");
  EXPECT_TRUE(std::ifstream(file).good());
  std::remove(file.c_str());
}

}  // namespace
}  // namespace contactcert::queries
