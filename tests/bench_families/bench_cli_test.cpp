// `contactcert bench` end to end: a quick run of one family writes its report files and JSON that parses, with
// a record per rung for every instance and no disagreement between the verified and exact rungs. Bad options
// exit 2 with a message naming the option.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

namespace {

/// Runs a shell command; returns its exit code and stdout + stderr.
std::pair<int, std::string> run(const std::string& args) {
  const std::string cmd = std::string(CONTACTCERT_EXE) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(BenchCli, QuickSuiteWritesReportAndValidJson) {
  const std::string dir = BENCH_OUT_DIR;
  std::filesystem::remove_all(dir);
  const auto [code, out] = run("bench --quick --suite reduction --json --out " + dir);
  ASSERT_EQ(code, 0) << out;
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j["suite"], "reduction");
  ASSERT_EQ(j["rungs"].size(), 4u);
  EXPECT_EQ(j["rungs"][0]["name"], "float");
  EXPECT_EQ(j["rungs"][3]["arith"], "exact");
  EXPECT_EQ(j["instances"].size(), 15u);  // 3 difficulties x 5 seeds, one UCP each
  for (const auto& inst : j["instances"]) {
    EXPECT_EQ(inst["family"], "reduction");
    for (const char* r : {"float", "verified", "adaptive", "exact"}) {
      EXPECT_TRUE(inst["rungs"][r]["median_seconds"].is_number());
      EXPECT_GE(inst["rungs"][r]["repeats"].get<int>(), 1);
    }
    EXPECT_EQ(inst["rungs"]["verified"]["verdict"], inst["rungs"]["exact"]["verdict"]);
    EXPECT_EQ(inst["rungs"]["adaptive"]["verdict"], inst["rungs"]["exact"]["verdict"]);
  }
  EXPECT_EQ(j["totals"]["verified"]["disagreements_with_exact"], 0);
  EXPECT_EQ(j["totals"]["adaptive"]["disagreements_with_exact"], 0);
  ASSERT_EQ(j["families"].size(), 1u);
  EXPECT_EQ(j["families"][0]["name"], "reduction");
  for (const char* f : {"report.txt", "report.md", "time_vs_error.svg", "bench.json", "index.html"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / f)) << f;
  std::ifstream file(std::filesystem::path(dir) / "bench.json");
  EXPECT_EQ(nlohmann::json::parse(file)["instances"], j["instances"]);
}

// Issue 9 item 3: --rungs adds the interval and MPFR rungs (exact is always added, last); each family gets a
// precision-ladder row per rung, and the ladder plot is written.
TEST(BenchCli, RungsOptionAddsThePrecisionLadder) {
  const std::string dir = std::string(BENCH_OUT_DIR) + "-ladder";
  std::filesystem::remove_all(dir);
  const auto [code, out] = run("bench --quick --suite reduction --rungs interval,mpfr113 --json --out " + dir);
  ASSERT_EQ(code, 0) << out;
  const nlohmann::json j = nlohmann::json::parse(out);
  ASSERT_EQ(j["rungs"].size(), 3u);
  EXPECT_EQ(j["rungs"][0]["name"], "interval");
  EXPECT_EQ(j["rungs"][1]["name"], "mpfr113");
  EXPECT_EQ(j["rungs"][2]["name"], "exact");
  for (const char* r : {"interval", "mpfr113", "exact"}) {
    const auto& cell = j["precision_ladder"]["reduction"][r];
    ASSERT_TRUE(cell.is_object()) << r;
    EXPECT_EQ(cell["n"], 15);
  }
  EXPECT_EQ(j["precision_ladder"]["reduction"]["interval"]["wrong_verdicts"], 0);
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / "precision_ladder.svg"));
}

TEST(BenchCli, BadOptionsExitTwoNamingTheOption) {
  int code = 0;
  std::string out;
  std::tie(code, out) = run("bench --suite nope");
  EXPECT_EQ(code, 2);
  EXPECT_NE(out.find("--suite"), std::string::npos) << out;
  std::tie(code, out) = run("bench --suite reduction --rungs float,mpfr99");
  EXPECT_EQ(code, 2);
  EXPECT_NE(out.find("--rungs"), std::string::npos) << out;
  std::tie(code, out) = run("bench --repeats 3");
  EXPECT_EQ(code, 2);
  std::tie(code, out) = run("bench --suite reduction --quick --out /proc/no-such-dir/x");
  EXPECT_EQ(code, 2);
  EXPECT_NE(out.find("--out"), std::string::npos) << out;
}

}  // namespace
