// The hard-case families of `contactcert bench`: deterministic per seed, valid instances, the verified rung
// never disagreeing with the exact one, and error measures that are zero exactly when they should be.
#include "queries/bench/families.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "exact/rational_text.h"
#include "geometry/contact_frame.h"
#include "queries/bench/rungs.h"

namespace contactcert::bench {
namespace {

std::string text(const geometry::Point2& p) { return exact::to_string(p.x) + "," + exact::to_string(p.y); }

/// Everything an instance holds, as text.
std::string fingerprint(const Instance& inst) {
  std::ostringstream s;
  s << family_name(inst.family) << "|" << inst.knob << "|" << question_kind(inst.question) << "|";
  std::visit(
      [&](const auto& q) {
        using X = std::decay_t<decltype(q)>;
        if constexpr (std::is_same_v<X, UcpQuestion>) {
          s << solvers::ucp::to_json_text(q.problem);
        } else {
          if (const auto* poly = std::get_if<geometry::PolygonShape>(&q.scene.workpiece.shape))
            for (const auto& v : poly->vertices) s << text(v) << ";";
          for (const auto& f : q.scene.fixels)
            s << text(f.frame.point) << "/" << text(f.frame.normal) << "/" << exact::to_string(f.mu_s) << ";";
          if constexpr (std::is_same_v<X, StabilityQuestion>)
            for (Eigen::Index i = 0; i < 3; ++i) s << exact::to_string(q.wrench(i)) << ",";
          else
            s << q.mode.text();
        }
      },
      inst.question);
  return s.str();
}

std::vector<Instance> all_at(double difficulty, std::uint64_t seed) {
  std::vector<Instance> out;
  for (Family f : all_families())
    for (Instance& i : generate(f, difficulty, seed)) out.push_back(std::move(i));
  return out;
}

TEST(BenchFamilies, DeterministicPerSeedAndDifferentAcrossSeeds) {
  for (double d : {0.0, 0.5, 1.0}) {
    const auto a = all_at(d, 7), b = all_at(d, 7), c = all_at(d, 8);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(fingerprint(a[i]), fingerprint(b[i]));
      EXPECT_NE(fingerprint(a[i]), fingerprint(c[i])) << fingerprint(a[i]);
    }
  }
}

TEST(BenchFamilies, NamesRoundTripAndBadDifficultyIsRejected) {
  for (Family f : all_families()) {
    EXPECT_EQ(parse_family(family_name(f)), f);
    EXPECT_GE(family_levels(f), f == Family::kPaper ? 1 : 2);
  }
  EXPECT_FALSE(parse_family("nope"));
  EXPECT_THROW(generate(Family::kParallel, 1.5, 1), std::invalid_argument);
  EXPECT_THROW(generate(Family::kPaper, -1, 1), std::invalid_argument);
  EXPECT_EQ(generate(Family::kPaper, 0, 1).size(), 12u);
  EXPECT_TRUE(generate(Family::kPaper, 0, 2).empty());
}

TEST(BenchFamilies, InstancesAreValid) {
  for (double d : {0.0, 0.5, 1.0})
    for (std::uint64_t seed : {1, 2, 3})
      for (const Instance& inst : all_at(d, seed)) {
        SCOPED_TRACE(fingerprint(inst));
        if (const auto* u = std::get_if<UcpQuestion>(&inst.question)) {
          const auto& X = u->problem.ucp().X;
          const auto& Y = u->problem.ucp().Y;
          EXPECT_EQ(X.A.cols(), Y.A.cols());
          EXPECT_EQ(X.A.rows(), X.b.size());
          EXPECT_EQ(Y.A.rows(), Y.b.size());
          if (u->problem.quasistatic) {
            EXPECT_NO_THROW(solvers::ucp::validate(*u->problem.quasistatic));
          }
          EXPECT_EQ(inst.family == Family::kReduction, u->known_solvable.has_value());
          continue;
        }
        const geometry::PlanarScene& scene = std::visit(
            [](const auto& q) -> const geometry::PlanarScene& {
              if constexpr (std::is_same_v<std::decay_t<decltype(q)>, UcpQuestion>)
                throw std::logic_error("not a scene");
              else
                return q.scene;
            },
            inst.question);
        if (const auto* poly = std::get_if<geometry::PolygonShape>(&scene.workpiece.shape)) {
          EXPECT_EQ(geometry::check_polygon(poly->vertices).defect, geometry::PolygonDefect::kNone);
        }
        std::vector<bool> touching;
        for (const auto& f : scene.fixels) {
          const auto r = geometry::frame_from_contact(scene.workpiece.shape, f.frame.point, f.frame.normal, 0);
          EXPECT_EQ(r.status, geometry::FrameStatus::kOk) << r.message;
          EXPECT_GE(sgn(f.mu_s), 0);
          touching.push_back(f.frame.touching());
        }
        if (const auto* c = std::get_if<ConeQuestion>(&inst.question)) {
          EXPECT_EQ(solvers::parse_mode(c->mode.text(), touching).status, solvers::ModeStatus::kValid);
        } else {
          EXPECT_EQ(std::get<StabilityQuestion>(inst.question).wrench.size(), 3);
        }
      }
}

TEST(BenchFamilies, KnobReachesTheIssueRanges) {
  EXPECT_EQ(generate(Family::kParallel, 1, 1).front().knob, "angle 1e-12");
  EXPECT_EQ(generate(Family::kLever, 1, 1).front().knob, "arms 1e-6..1e6");
  EXPECT_EQ(generate(Family::kLarge, 1, 1).front().knob, "nc 40, 8 fixels");
  const std::vector<Instance> large = generate(Family::kLarge, 1, 1);
  EXPECT_EQ(std::get<ConeQuestion>(large.back().question).scene.fixels.size(), 8u);
  EXPECT_EQ(std::get<UcpQuestion>(large.front().question).problem.quasistatic->nc, 40);
}

/// The verified rung must give the exact rung's verdict on every family (small difficulties and seeds), and
/// its point must satisfy the constraints exactly.
TEST(BenchRungs, VerifiedAgreesWithExactOnEveryFamily) {
  const auto& rungs = default_rungs();
  ASSERT_EQ(rungs.back().arith, exact::Arith::kExact);
  const Rung& verified = rungs[1];
  ASSERT_EQ(verified.arith, exact::Arith::kVerified);
  for (Family f : all_families())
    for (double d : {0.0, 0.2})
      for (std::uint64_t seed : {1, 2, 3})
        for (const Instance& inst : generate(f, d, seed)) {
          SCOPED_TRACE(fingerprint(inst));
          const Answer x = run_rung(inst.question, rungs.back());
          const Answer v = run_rung(inst.question, verified);
          ASSERT_TRUE(x.failure.empty()) << x.failure;
          EXPECT_EQ(v.verdict, x.verdict);
          const Errors e = measure(inst.question, v, x);
          EXPECT_FALSE(e.wrong_verdict);
          EXPECT_EQ(worst_error(e), 0.0);
          if (const auto* u = std::get_if<UcpQuestion>(&inst.question); u && u->known_solvable) {
            EXPECT_EQ(x.verdict, *u->known_solvable ? "solvable" : "jammed");
          }
        }
}

// Issue 9 item 3: every rung of the ladder answers every question kind on small seeds. MPFR floats are unchecked
// and may be wrong, so only the checked rungs (verified, adaptive) are held to the exact verdict everywhere, and
// an interval rung that decides is never wrong (it proves every sign). On the scene families (stability and
// cone questions, easiest and hardest knob) 1024 bits give the exact verdict and generators.
TEST(BenchRungs, LadderRungsAnswerAndCheckedRungsAgreeWithExact) {
  const std::vector<Rung> rungs = parse_rungs("float,interval,mpfr113,mpfr256,mpfr1024,verified,adaptive");
  ASSERT_EQ(rungs.size(), all_rungs().size());
  ASSERT_EQ(rungs.back().arith, exact::Arith::kExact);
  EXPECT_THROW(parse_rungs("float,mpfr99"), std::invalid_argument);
  EXPECT_EQ(parse_rungs("mpfr256").size(), 2u);  // + exact
  for (Family f : all_families())
    for (double d : {0.0, 1.0})
      for (std::uint64_t seed : {1, 2})
        for (const Instance& inst : generate(f, d, seed)) {
          SCOPED_TRACE(fingerprint(inst));
          const bool ucp = std::holds_alternative<UcpQuestion>(inst.question);
          if (ucp && d > 0) continue;  // the hardest UCPs are the bench's, not a unit test's
          const Answer x = run_rung(inst.question, rungs.back());
          ASSERT_TRUE(x.failure.empty()) << x.failure;
          for (std::size_t k = 0; k + 1 < rungs.size(); ++k) {
            SCOPED_TRACE(rungs[k].name);
            const Answer a = run_rung(inst.question, rungs[k]);
            EXPECT_FALSE(a.verdict.empty());
            const Errors e = measure(inst.question, a, x);
            if (rungs[k].arith != exact::Arith::kFloat) {
              EXPECT_EQ(a.verdict, x.verdict);
            }
            if (rungs[k].number.kind == exact::Rung::Kind::kInterval) {
              EXPECT_FALSE(e.wrong_verdict);
              if (a.verdict == "unknown" && !ucp) {
                EXPECT_EQ(a.failure, "an interval sign is uncertain");
              }
            }
            if (rungs[k].name == "mpfr1024" && !ucp) {
              EXPECT_EQ(a.verdict, x.verdict) << a.failure;
              EXPECT_LT(worst_error(e), 1e-12);
            }
          }
        }
}

TEST(BenchRungs, ErrorMeasures) {
  const Instance inst = generate(Family::kBoundary, 0, 1).back();  // a cone question
  const Answer x = run_rung(inst.question, default_rungs().back());
  ASSERT_EQ(x.verdict, "non_empty");
  EXPECT_EQ(measure(inst.question, x, x).generator_distance, 0.0);
  Answer empty;
  empty.verdict = "empty";
  const Errors e = measure(inst.question, empty, x);
  EXPECT_TRUE(e.wrong_verdict);
  EXPECT_EQ(e.generator_distance, 2.0);
  EXPECT_EQ(worst_error(e), 1.0);
  Answer failed;
  failed.verdict = "failed";
  EXPECT_TRUE(measure(inst.question, failed, x).undecided);
  // Resting forces moved off equilibrium by 1/1000 in one entry: the violation is at least that, relative to g.
  const Instance st = generate(Family::kBoundary, 0, 1).front();
  Answer r = run_rung(st.question, default_rungs().back());
  ASSERT_GT(r.forces.size(), 0);
  EXPECT_TRUE(std::isnan(measure(st.question, r, r).xTy));
  EXPECT_EQ(measure(st.question, r, r).violation, 0.0);
  r.forces(0) += Q(1, 1000);
  EXPECT_GT(measure(st.question, r, r).violation, 0.0);
}

}  // namespace
}  // namespace contactcert::bench
