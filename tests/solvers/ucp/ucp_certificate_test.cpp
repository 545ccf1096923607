#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

#include "checker/ucp_check.h"
#include "exact/json_input.h"
#include "runtime/scenes.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/generate.h"
#include "solvers/ucp/search.h"

namespace contactcert::solvers::ucp {
namespace {

std::string scene(int k) {
  return contactcert::runtime::bundled_scenes_dir() + "/pang1994_dataset" + std::to_string(k) + ".json";
}

checker::CertificateCheck check_text(const std::string& text) {
  return checker::check_ucp_certificate(exact::JsonInput::parse(text, "certificate"));
}

std::string jammed_text(const UcpProblem& p) {
  std::mt19937_64 rng(1);
  const SearchResult<Q> s = complete_search(p.ucp(), SearchOptions{}, rng);
  EXPECT_EQ(s.status, UcpStatus::kJammed);
  return jammed_certificate(p, s);
}

/// Adds 1 to the integer string at j[path...].
void bump(nlohmann::json& v) { v = exact::Z(exact::Z(v.get<std::string>(), 10) + 1).get_str(); }

TEST(UcpCertificate, DataSet4JammedCertificateIsAcceptedAndEveryFarkasEntryMatters) {
  const std::string text = jammed_text(load_ucp_problem(scene(4)));
  const checker::CertificateCheck ok = check_text(text);
  ASSERT_EQ(ok.verdict, checker::CertificateVerdict::kValid) << ok.reason;
  EXPECT_GT(ok.leaves, 1);
  const nlohmann::json j = nlohmann::json::parse(text);
  int changed_x = 0, rejected_x = 0, changed_y = 0, rejected_y = 0;
  for (std::size_t k = 0; k < j["nodes"].size(); ++k) {
    if (!j["nodes"][k].contains("farkas")) continue;
    const bool x_side = j["nodes"][k]["empty"] == "X";
    for (std::size_t e = 0; e < j["nodes"][k]["farkas"].size(); ++e) {
      nlohmann::json t = j;
      bump(t["nodes"][k]["farkas"][e]);
      const bool rejected = check_text(t.dump()).verdict == checker::CertificateVerdict::kInvalid;
      (x_side ? changed_x : changed_y)++;
      (x_side ? rejected_x : rejected_y) += rejected;
    }
  }
  // X-side vectors must satisfy w^T P = 0 exactly, so any change breaks them. A Y-side inequality with
  // slack may survive a small change (the certificate then still proves the leaf empty).
  EXPECT_GT(changed_x, 0);
  EXPECT_EQ(rejected_x, changed_x);
  EXPECT_GT(2 * rejected_y, changed_y);
}

TEST(UcpCertificate, ChangingTheProblemOrTheTreeIsRejected) {
  const std::string text = jammed_text(load_ucp_problem(scene(4)));
  const nlohmann::json j = nlohmann::json::parse(text);
  // A certificate stays valid for nearby problems that are jammed for the same reasons (e.g. another
  // theta_dot), so the changes below are ones that must break it.
  {  // a wrench entry: the X-side vectors w satisfy w^T P = 0 only for the original P
    nlohmann::json t = j;
    t["problem"]["P"][0][0] = "0.805";
    EXPECT_EQ(check_text(t.dump()).verdict, checker::CertificateVerdict::kInvalid);
  }
  {  // no gravity: y = 0 is in Y and the problem becomes solvable, so no proof of jamming can pass
    nlohmann::json t = j;
    t["problem"]["d"][4] = "0";
    EXPECT_EQ(check_text(t.dump()).verdict, checker::CertificateVerdict::kInvalid);
  }
  {  // a branch index
    nlohmann::json t = j;
    t["nodes"][0]["branch"] = (t["nodes"][0]["branch"].get<int>() + 1) % 9;
    EXPECT_EQ(check_text(t.dump()).verdict, checker::CertificateVerdict::kInvalid);
  }
  {  // a child reference that makes a node unreachable / reached twice
    nlohmann::json t = j;
    t["nodes"][0]["y_zero"] = t["nodes"][0]["x_zero"];
    EXPECT_EQ(check_text(t.dump()).verdict, checker::CertificateVerdict::kInvalid);
  }
  {  // the root alone is not a proof
    nlohmann::json t = j;
    t["nodes"] = nlohmann::json::array({j["nodes"][1]});
    EXPECT_EQ(check_text(t.dump()).verdict, checker::CertificateVerdict::kInvalid);
  }
}

TEST(UcpCertificate, SolvableCertificatesOfDataSets1To3AreAcceptedAndTamperingIsRejected) {
  for (int k = 1; k <= 3; ++k) {
    const UcpProblem p = load_ucp_problem(scene(k));
    std::mt19937_64 rng(1);
    const SearchResult<Q> s = complete_search(p.ucp(), SearchOptions{}, rng);
    ASSERT_EQ(s.status, UcpStatus::kSolvable);
    const std::string text = solvable_certificate(p, s.x, s.y);
    EXPECT_EQ(check_text(text).verdict, checker::CertificateVerdict::kValid);
    nlohmann::json t = nlohmann::json::parse(text);
    for (std::size_t e = 0; e < t["y"].size(); ++e)
      if (t["y"][e] != "0") {
        t["y"][e] = "1";
        break;
      }
    EXPECT_EQ(check_text(t.dump()).verdict, checker::CertificateVerdict::kInvalid);
  }
}

TEST(UcpCertificate, RandomAndReductionJammedCertificatesVerify) {
  int checked = 0;
  for (int seed = 0; seed < 16; ++seed) {
    std::mt19937_64 gen(seed);
    UcpProblem p;
    if (seed % 2 == 0) {
      RandomProblemOptions o;
      o.nc = 3 + seed % 3;
      o.mu_max = Q(3, 2);
      o.abar_size = seed % 4;
      p = generate_random_problem(o, gen);
    } else {
      p = reduction_problem(random_zero_one(2, 4, false, gen));
    }
    std::mt19937_64 rng(seed);
    const SearchResult<Q> s = complete_search(p.ucp(), SearchOptions{}, rng);
    if (s.status != UcpStatus::kJammed) continue;
    ++checked;
    const checker::CertificateCheck c = check_text(jammed_certificate(p, s));
    EXPECT_EQ(c.verdict, checker::CertificateVerdict::kValid) << "seed " << seed << ": " << c.reason;
  }
  EXPECT_GE(checked, 4);
}

}  // namespace
}  // namespace contactcert::solvers::ucp
