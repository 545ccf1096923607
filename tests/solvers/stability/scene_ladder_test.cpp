// The scene algorithms on the precision ladder (issue 9): strong stability and the wrench cone (paper route)
// instantiated for MPFR floats and double intervals, against the exact answers on the papers' scenes.
// MPFR at 1024 bits must give the exact verdicts and generators; an interval run must either give the exact
// verdict or stop at an uncertain sign (exact::UncertainSign), never a different verdict.
#include "solvers/scene_ladder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "runtime/scenes.h"
#include "tests/solvers/scene_fixtures.h"

namespace contactcert::solvers {
namespace {

using exact::Interval;
using exact::Mpfr;
using testing::wrench;

template <class T>
Vec<T> in(const Vec<Q>& g) {
  return g.unaryExpr([](const Q& q) { return from_exact<T>(q); });
}

/// The interval verdict, or nullopt if the interval run stopped at an uncertain sign.
std::optional<StabilityVerdict> interval_verdict(const geometry::PlanarScene& scene, const Vec<Q>& g) {
  try {
    return strong_stability<Interval>(scene, in<Interval>(g), {exact::Arith::kFloat}).verdict;
  } catch (const exact::UncertainSign&) {
    return std::nullopt;
  }
}

/// The Hausdorff distance between the generators of two closures (rays, and both signs of the lines), each
/// scaled to unit length in double: 0 when they are the same cone.
template <class T>
double generator_distance(const geometry::SpanCone<Q>& x, const geometry::SpanCone<T>& a) {
  const auto units = [](const auto& cone) {
    std::vector<Vec<double>> out;
    const auto add = [&](const auto& M, double s) {
      for (Eigen::Index r = 0; r < M.rows(); ++r) {
        Vec<double> v(M.cols());
        for (Eigen::Index c = 0; c < M.cols(); ++c)
          v(c) = s * exact::NumberTraits<std::decay_t<decltype(M(r, c))>>::to_double(M(r, c));
        out.push_back(v / v.norm());
      }
    };
    add(cone.rays, 1);
    add(cone.lines, 1);
    add(cone.lines, -1);
    return out;
  };
  const std::vector<Vec<double>> X = units(x), A = units(a);
  if (X.empty() != A.empty()) return 2;
  const auto directed = [](const std::vector<Vec<double>>& P, const std::vector<Vec<double>>& R) {
    double d = 0;
    for (const Vec<double>& p : P) {
      double best = 2;
      for (const Vec<double>& r : R) best = std::min(best, (p - r).norm());
      d = std::max(d, best);
    }
    return d;
  };
  return std::max(directed(X, A), directed(A, X));
}

TEST(SceneLadder, Section7DiskStabilityAtEveryRung) {
  const auto scene = testing::scene_with_mu("bt2002_section7_disk.json", "1.2");
  const auto low = testing::scene_with_mu("bt2002_section7_disk.json", "0.3");
  int decided_by_intervals = 0, cases = 0;
  for (const auto* s : {&scene, &low})
    for (const Vec<Q>& g : {wrench(0, -1, 0), wrench(1, 0, 0), wrench(-1, -1, 0), wrench(1, -2, 0), wrench(0, 1, 0)}) {
      SCOPED_TRACE(::testing::PrintToString(g.transpose()));
      ++cases;
      const StabilityResult<Q> x = strong_stability<Q>(*s, g, {exact::Arith::kExact});
      {
        const exact::MpfrPrecision bits(1024);
        const StabilityResult<Mpfr> m = strong_stability<Mpfr>(*s, in<Mpfr>(g), {exact::Arith::kFloat});
        EXPECT_EQ(m.verdict, x.verdict);
        ASSERT_EQ(m.has_resting, x.has_resting);
        // The run is at 1024 bits: its resting forces balance g to 1e-100, far below double precision.
        if (m.has_resting) {
          const Vec<Q> c = m.resting_forces.unaryExpr([](const Mpfr& v) { return exact::to_rational(v); });
          const Vec<Q> residual = jacobian(touching_scene(*s)) * c + g;
          const Q tiny(exact::Z(1), exact::Z("1" + std::string(100, '0')));  // 1e-100
          for (Eigen::Index i = 0; i < 3; ++i) EXPECT_LT(abs(residual(i)), tiny);
        }
      }
      if (const auto v = interval_verdict(*s, g)) {
        EXPECT_EQ(*v, x.verdict);
        ++decided_by_intervals;
      }
    }
  RecordProperty("interval_decided", std::to_string(decided_by_intervals) + " of " + std::to_string(cases));
}

TEST(SceneLadder, PapersConesAtEveryRung) {
  const std::pair<const char*, const char*> cones[] = {{"bt2002_section4_disk.json", "na"},
                                                       {"bt2002_fig4a_lla.json", "lla"},
                                                       {"bt2002_fig4b_nnn.json", "nnn"},
                                                       {"bt2002_fig4c_peg_lra.json", "lra"},
                                                       {"bt2002_fig4d_peg_nn.json", "nn"}};
  for (const auto& [file, text] : cones) {
    SCOPED_TRACE(file);
    const auto scene = geometry::load_planar_scene((contactcert::runtime::bundled_scenes_dir() + "/") + file);
    std::vector<bool> touching;
    for (const auto& f : scene.fixels) touching.push_back(f.frame.touching());
    const ModeParse p = parse_mode(text, touching);
    ASSERT_EQ(p.status, ModeStatus::kValid) << p.message;
    const WrenchCone<Q> x = wrench_cone<Q>(scene, p.mode, Route::kPaper);
    {
      const exact::MpfrPrecision bits(1024);
      const WrenchCone<Mpfr> m = wrench_cone<Mpfr>(scene, p.mode, Route::kPaper);
      EXPECT_EQ(m.status, x.status);
      EXPECT_LT(generator_distance(x.cone.closure, m.cone.closure), 1e-15);
      EXPECT_EQ(m.cone.face.strict.rows(), x.cone.face.strict.rows());
    }
    try {
      const WrenchCone<Interval> i = wrench_cone<Interval>(scene, p.mode, Route::kPaper);
      EXPECT_EQ(i.status, x.status);
      EXPECT_LT(generator_distance(x.cone.closure, i.cone.closure), 1e-9);
    } catch (const exact::UncertainSign&) {  // undecided: allowed, never a wrong cone
    }
  }
}

}  // namespace
}  // namespace contactcert::solvers
