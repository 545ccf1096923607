// The checker of a step's uniqueness certificate (checker/uniqueness_check.h) on Data Set 2 over a grid of friction
// coefficients: every decided verdict's certificate checks, and a certificate with a dead prefix dropped or a Farkas
// vector negated is refused.
#include "checker/uniqueness_check.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "runtime/scenes.h"
#include "solvers/motion/uniqueness_certificate.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using solvers::motion::MotionUniqueness;
using solvers::motion::UniquenessStatus;

UniquenessCertificateCheck checked(const std::string& text) {
  return check_uniqueness_certificate(exact::JsonInput::parse(text, "uniqueness.json"));
}

TEST(UniquenessCertificate, DataSet2MuGridCertificatesCheckAndForgedTreesAreRefused) {
  const solvers::ucp::UcpProblem base =
      solvers::ucp::load_ucp_problem(runtime::bundled_scenes_dir() + "/pang1994_dataset2.json");
  int unique = 0, not_unique = 0;
  for (int a = 0; a <= 4; a += 2)
    for (int b = 0; b <= 4; b += 2) {
      solvers::ucp::UcpProblem p = base;
      p.quasistatic->mu << Q(a, 4), Q(b, 4), Q(1, 2);
      p.set(solvers::ucp::build_ucp(*p.quasistatic));
      const MotionUniqueness u = solvers::motion::motion_uniqueness(p, exact::Arith::kVerified, 1L << 12, true);
      const std::string text = solvers::motion::uniqueness_certificate(p, u);
      if (text.empty()) continue;  // undecided, or no solution (a ucp_jammed certificate's question)
      const UniquenessCertificateCheck c = checked(text);
      EXPECT_TRUE(c.valid) << "mu " << a << "/4, " << b << "/4: " << c.reason;
      EXPECT_EQ(c.verdict, solvers::motion::uniqueness_name(u.status));
      if (u.status == UniquenessStatus::kNotUnique) {
        ++not_unique;
        continue;
      }
      ++unique;
      if (c.dead == 0) continue;
      nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
      nlohmann::ordered_json dropped = j, changed = j;
      dropped["dead"].erase(dropped["dead"].begin());
      const UniquenessCertificateCheck d = checked(dropped.dump());
      EXPECT_FALSE(d.valid);
      EXPECT_NE(d.reason.find("prefix tree"), std::string::npos) << d.reason;
      for (auto& f : changed["dead"][0]["farkas"]) f = Q(-Q(f.get<std::string>())).get_str();
      const UniquenessCertificateCheck w = checked(changed.dump());
      EXPECT_FALSE(w.valid);
      EXPECT_NE(w.reason.find("Farkas"), std::string::npos) << w.reason;
    }
  EXPECT_GT(unique + not_unique, 0);
  EXPECT_GT(unique, 0);
}

}  // namespace
}  // namespace contactcert::checker
