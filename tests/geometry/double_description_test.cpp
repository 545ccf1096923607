// Span <-> face conversion: round trips, degenerate cones, and cddlib (GMP) as the reference.
#include "geometry/double_description.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "exact/fraction_free.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/linalg.h"
#include "geometry/canonical.h"
#include "geometry/scene_json.h"
#include "solvers/wrench_cone/cone_form.h"
#include "solvers/wrench_cone/contact_model.h"
#include "solvers/wrench_cone/mode.h"
#include "tests/geometry/polytope_cones.h"
#include "tests/geometry/random_cones.h"
#include "tests/reference/cdd_cone.h"

namespace contactcert::geometry {
namespace {

using testing::random_face;
using testing::random_span;

// Every generator satisfies every row, and every facet is tight on dim - 1 - (#equalities) independent rays.
void expect_valid_pair(const SpanCone<Q>& S, const FaceCone<Q>& F) {
  for (Eigen::Index f = 0; f < F.inequalities.rows(); ++f) {
    Mat<Q> tight(0, S.dim);
    for (Eigen::Index r = 0; r < S.rays.rows(); ++r) {
      const Q v = F.inequalities.row(f).dot(S.rays.row(r));
      ASSERT_LE(v, 0);
      if (v == 0) {
        tight.conservativeResize(tight.rows() + 1, S.dim);
        tight.row(tight.rows() - 1) = S.rays.row(r);
      }
    }
    for (Eigen::Index l = 0; l < S.lines.rows(); ++l) ASSERT_EQ(F.inequalities.row(f).dot(S.lines.row(l)), 0);
    Mat<Q> all(tight.rows() + S.lines.rows(), S.dim);
    all << tight, S.lines;
    // A facet of a cone of dimension d contains a (d-1)-dimensional face.
    const Eigen::Index d = S.dim - F.equalities.rows();
    EXPECT_EQ(exact::rank<Q>(all), d - 1);
  }
  for (Eigen::Index e = 0; e < F.equalities.rows(); ++e) {
    for (Eigen::Index r = 0; r < S.rays.rows(); ++r) ASSERT_EQ(F.equalities.row(e).dot(S.rays.row(r)), 0);
    for (Eigen::Index l = 0; l < S.lines.rows(); ++l) ASSERT_EQ(F.equalities.row(e).dot(S.lines.row(l)), 0);
  }
}

void check_span_cone(const SpanCone<Q>& C) {
  const FaceCone<Q> F = canonical(to_face(C));
  const FaceCone<Q> F_cdd = canonical(reference::cdd_to_face(C));
  ASSERT_TRUE(identical(F, F_cdd)) << "dim " << C.dim << " rays\n"
                                   << C.rays << "\nlines\n"
                                   << C.lines << "\nours\n"
                                   << F.inequalities << "\ncdd\n"
                                   << F_cdd.inequalities;
  const SpanCone<Q> S = canonical(to_span(F));
  const SpanCone<Q> S_cdd = canonical(reference::cdd_to_span(F));
  ASSERT_TRUE(identical(S, S_cdd)) << "ours\n" << S.rays << "\ncdd\n" << S_cdd.rays;
  expect_valid_pair(S, F);
  // Round trip: the minimal span form converts back to the same face form.
  ASSERT_TRUE(identical(canonical(to_face(S)), F));
  // Every input generator lies in the cone.
  for (Eigen::Index r = 0; r < C.rays.rows(); ++r)
    for (Eigen::Index f = 0; f < F.inequalities.rows(); ++f) ASSERT_LE(F.inequalities.row(f).dot(C.rays.row(r)), 0);
  // Float path: same number of facets on these small integer inputs.
  SpanCone<double> Cd = SpanCone<double>::from_rows(C.dim, exact::to_double(C.rays), exact::to_double(C.lines));
  const FaceCone<double> Fd = to_face(Cd);
  EXPECT_EQ(Fd.inequalities.rows(), F.inequalities.rows());
  EXPECT_EQ(Fd.equalities.rows(), F.equalities.rows());
}

TEST(DoubleDescription, RandomConesAgainstCddlib) {
  std::mt19937_64 rng(20261123);
  int count = 0;
  for (Eigen::Index dim = 3; dim <= 8; ++dim)
    for (int rep = 0; rep < 60; ++rep) {
      std::uniform_int_distribution<int> n(1, static_cast<int>(dim + 5));
      SpanCone<Q> C = random_span(rng, dim, n(rng), 0);
      // Half of them pointed (a cone over a polytope), where facets are many.
      if (rep % 2 == 0)
        for (Eigen::Index r = 0; r < C.rays.rows(); ++r) C.rays(r, 0) = abs(C.rays(r, 0)) + 1;
      check_span_cone(C);
      ++count;
    }
  EXPECT_GE(count, 300);
}

TEST(DoubleDescription, DegenerateConesAgainstCddlib) {
  std::mt19937_64 rng(7);
  int count = 0;
  for (Eigen::Index dim = 3; dim <= 8; ++dim)
    for (int rep = 0; rep < 20; ++rep) {
      // Many generators on one facet.
      check_span_cone(random_span(rng, dim, dim + 4, 0, dim + 1));
      // Lineality.
      check_span_cone(random_span(rng, dim, dim, 1 + rep % (dim - 1)));
      count += 2;
    }
  EXPECT_GE(count, 200);
}

TEST(DoubleDescription, RandomFaceConesAgainstCddlib) {
  std::mt19937_64 rng(99);
  for (Eigen::Index dim = 3; dim <= 7; ++dim)
    for (int rep = 0; rep < 20; ++rep) {
      const FaceCone<Q> F = random_face(rng, dim, dim + rep % 6, rep % 3 == 0 ? 1 : 0, 0);
      const SpanCone<Q> S = canonical(to_span(F));
      const SpanCone<Q> S_cdd = canonical(reference::cdd_to_span(F));
      ASSERT_TRUE(identical(S, S_cdd)) << "ours\n" << S.rays << "\ncdd\n" << S_cdd.rays;
    }
}

Mat<Q> rows(std::initializer_list<std::initializer_list<long>> r) {
  Mat<Q> M(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(r.begin()->size()));
  Eigen::Index i = 0;
  for (auto& row : r) {
    Eigen::Index j = 0;
    for (long v : row) M(i, j++) = v;
    ++i;
  }
  return M;
}

TEST(DoubleDescription, SpecialCones) {
  // The origin: no rays -> equalities span everything.
  const FaceCone<Q> origin = canonical(to_face(SpanCone<Q>::from_rows(3, Mat<Q>(0, 3), Mat<Q>(0, 3))));
  EXPECT_EQ(origin.inequalities.rows(), 0);
  EXPECT_EQ(origin.equalities, rows({{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}));  // sorted lexicographically
  // The whole space from lines: no rows at all.
  const FaceCone<Q> whole =
      canonical(to_face(SpanCone<Q>::from_rows(3, Mat<Q>(0, 3), rows({{1, 2, 0}, {0, 1, 1}, {1, 0, 0}}))));
  EXPECT_EQ(whole.inequalities.rows(), 0);
  EXPECT_EQ(whole.equalities.rows(), 0);
  // The whole space from rays (positively spanning).
  const FaceCone<Q> whole2 = canonical(
      to_face(SpanCone<Q>::from_rows(3, rows({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}}), Mat<Q>(0, 3))));
  EXPECT_EQ(whole2.inequalities.rows() + whole2.equalities.rows(), 0);
  // A half-space: z <= 0 is { (0,0,1) . g <= 0 }.
  const FaceCone<Q> half =
      canonical(to_face(SpanCone<Q>::from_rows(3, rows({{0, 0, -1}}), rows({{1, 0, 0}, {0, 1, 0}}))));
  EXPECT_EQ(half.inequalities, rows({{0, 0, 1}}));
  EXPECT_EQ(half.equalities.rows(), 0);
  // A line: two equalities.
  const FaceCone<Q> line = canonical(to_face(SpanCone<Q>::from_rows(3, Mat<Q>(0, 3), rows({{2, 4, 6}}))));
  EXPECT_EQ(line.inequalities.rows(), 0);
  EXPECT_EQ(line.equalities.rows(), 2);
  const SpanCone<Q> line_back = canonical(to_span(line));
  EXPECT_EQ(line_back.lines, rows({{1, 2, 3}}));
  EXPECT_EQ(line_back.rays.rows(), 0);
  // A ray: face form has 2 equalities and 1 inequality.
  const FaceCone<Q> ray = canonical(to_face(SpanCone<Q>::from_rows(3, rows({{0, 0, 3}}), Mat<Q>(0, 3))));
  EXPECT_EQ(ray.inequalities, rows({{0, 0, -1}}));
  EXPECT_EQ(ray.equalities, rows({{0, 1, 0}, {1, 0, 0}}));
  // The paper's section 4 cone G (mu_s = 1/5, scaled by 5): three generators, three facets.
  const SpanCone<Q> G = SpanCone<Q>::from_rows(3, rows({{5, 0, -5}, {-1, -5, -1}, {1, -5, 1}}), Mat<Q>(0, 3));
  const FaceCone<Q> GF = canonical(to_face(G));
  EXPECT_EQ(GF.inequalities.rows(), 3);
  EXPECT_TRUE(identical(GF, canonical(reference::cdd_to_face(G))));
  for (const auto& c : {origin, whole, whole2, half, line, ray})
    EXPECT_TRUE(identical(canonical(to_face(canonical(to_span(c)))), c));
}

TEST(DoubleDescription, CanonicalFormIsInvariant) {
  // Same cone from permuted, scaled, duplicated and redundant generators prints identically.
  std::mt19937_64 rng(5);
  for (int rep = 0; rep < 50; ++rep) {
    SpanCone<Q> C = random_span(rng, 4, 7, rep % 2);
    SpanCone<Q> D = C;
    D.rays = Mat<Q>(C.rays.rows() + 1, 4);
    for (Eigen::Index i = 0; i < C.rays.rows(); ++i) D.rays.row(i) = C.rays.row(C.rays.rows() - 1 - i) * (Q(i + 1) / 3);
    D.rays.row(C.rays.rows()) = C.rays.row(0) + C.rays.row(1);  // redundant
    if (D.lines.rows() > 0) D.lines.row(0) *= Q(-2);
    EXPECT_TRUE(identical(canonical(to_face(C)), canonical(to_face(D))));
    EXPECT_TRUE(identical(canonical(to_span(to_face(C))), canonical(to_span(to_face(D)))));
  }
}

// The fixed-width ring of exact/fraction_free.h: every overflow is caught, and with_exact_ring then
// restarts in Z.
TEST(FractionFree, MachineIntegerOverflowRestartsInZ) {
  namespace rg = exact::ring;
  const std::int64_t big = std::int64_t{1} << 62;
  EXPECT_THROW(rg::mul(big, 2), exact::RingOverflow);
  EXPECT_THROW(rg::add(big, big), exact::RingOverflow);
  EXPECT_THROW(rg::sub(-big, big), exact::RingOverflow);  // INT64_MIN itself is excluded
  EXPECT_EQ(rg::mul(-(big / 2), 2), -big);
  // Primitive rows: the same in both rings; a row that does not fit throws.
  const std::vector<Q> row = {Q(6, 35), Q(-4, 21), Q(0), Q(2, 15)};
  std::vector<std::int64_t> small(row.size());
  std::vector<Z> exact(row.size());
  rg::to_ring(row.data(), 4, small.data());
  rg::to_ring(row.data(), 4, exact.data());
  EXPECT_EQ(small, (std::vector<std::int64_t>{9, -10, 0, 7}));  // 105 row / 2
  for (std::size_t i = 0; i < row.size(); ++i) EXPECT_EQ(Z(static_cast<long>(small[i])), exact[i]);
  const std::vector<Q> huge = {Q(Z("123456789012345678901234567890")), Q(1, 7)};
  EXPECT_THROW(rg::to_ring(huge.data(), 2, small.data()), exact::RingOverflow);
  const bool restarted = exact::with_exact_ring<Q>([&]<class R>() {
    std::vector<R> r(2);
    rg::to_ring(huge.data(), 2, r.data());
    return std::is_same_v<R, Z>;
  });
  EXPECT_TRUE(restarted);
}

// Coordinates that overflow 64-bit products part way through the iteration (2^20), at the first
// product (2^40) or already in the input (2^62): the restart in Z gives cddlib's cone.
TEST(DoubleDescription, HugeCoordinatesAgainstCddlib) {
  std::mt19937_64 rng(20261124);
  for (long range : {long{1} << 20, long{1} << 40, long{1} << 62})
    for (Eigen::Index dim = 3; dim <= 6; ++dim)
      for (int rep = 0; rep < 6; ++rep) {
        SpanCone<Q> C = random_span(rng, dim, dim + 3, rep % 3 == 2 ? 1 : 0, 0, range);
        if (rep % 3 == 0)
          for (Eigen::Index r = 0; r < C.rays.rows(); ++r) C.rays(r, 0) = abs(C.rays(r, 0)) + 1;
        const FaceCone<Q> F = canonical(to_face(C));
        ASSERT_TRUE(identical(F, canonical(reference::cdd_to_face(C)))) << "range " << range << " dim " << dim;
        const SpanCone<Q> S = canonical(to_span(F));
        ASSERT_TRUE(identical(S, canonical(reference::cdd_to_span(F)))) << "range " << range << " dim " << dim;
        expect_valid_pair(S, F);
      }
}

// Every row order gives the same cone: byte-identical canonical forms, both ways, on seeded random
// (pointed or not), degenerate (many generators on one facet), lineality, lower-dimensional, cube and
// cross-polytope inputs, and on coordinates whose products overflow 64 bits part way (the run goes on
// in GMP with the same order); the same row counts in the float path; the default order agrees with cddlib.
TEST(DoubleDescription, EveryRowOrderGivesTheSameCone) {
  std::mt19937_64 rng(20261202);
  std::vector<SpanCone<Q>> inputs = {testing::cube_span(4), testing::cross_polytope_span(5)};
  for (Eigen::Index dim = 3; dim <= 7; ++dim) {
    SpanCone<Q> pointed = random_span(rng, dim, dim + 6, 0);
    for (Eigen::Index r = 0; r < pointed.rays.rows(); ++r) pointed.rays(r, 0) = abs(pointed.rays(r, 0)) + 1;
    SpanCone<Q> flat = random_span(rng, dim, dim + 3, 0);
    for (Eigen::Index r = 0; r < flat.rays.rows(); ++r) flat.rays(r, dim - 1) = flat.rays(r, 0);
    inputs.insert(inputs.end(),
                  {pointed, flat, random_span(rng, dim, dim + 4, 0, dim + 1), random_span(rng, dim, dim, 1)});
  }
  const std::size_t small = inputs.size();  // (float row counts are compared on these)
  for (Eigen::Index dim = 3; dim <= 6; ++dim) inputs.push_back(random_span(rng, dim, dim + 3, 0, 0, long{1} << 20));
  const RowOrder orders[] = {RowOrder::kLexMin, RowOrder::kLexMax, RowOrder::kMinCutoff, RowOrder::kMaxCutoff};
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const SpanCone<Q>& C = inputs[i];
    const FaceCone<Q> F = canonical(to_face(C));
    ASSERT_TRUE(identical(F, canonical(reference::cdd_to_face(C))));
    const SpanCone<Q> S = canonical(to_span(F));
    const auto Cd = SpanCone<double>::from_rows(C.dim, exact::to_double(C.rays), exact::to_double(C.lines));
    for (RowOrder order : orders) {
      DdBudget budget;
      budget.order = order;
      ASSERT_TRUE(identical(canonical(to_face(C, budget)), F)) << static_cast<int>(order) << "\n" << C.rays;
      ASSERT_TRUE(identical(canonical(to_span(F, budget)), S)) << static_cast<int>(order) << "\n" << C.rays;
      if (i < small) {
        EXPECT_EQ(to_face(Cd, budget).inequalities.rows(), F.inequalities.rows());
      }
    }
  }
  for (const FaceCone<Q>& F : {testing::cube_face(5), testing::cross_polytope_face(4)}) {
    const SpanCone<Q> S = canonical(to_span(F));
    for (RowOrder order : orders) {
      DdBudget budget;
      budget.order = order;
      ASSERT_TRUE(identical(canonical(to_span(F, budget)), S)) << static_cast<int>(order);
    }
  }
}

TEST(DoubleDescription, BudgetIsEnforced) {
  std::mt19937_64 rng(3);
  const SpanCone<Q> C = random_span(rng, 8, 30, 0);
  DdBudget budget;
  budget.max_rays = 10;
  EXPECT_THROW(to_face(C, budget), exact::BudgetExceeded);
}

// The 30-dimensional cross-polytope and cube (2^30 facets / rays): the work budget and the deadline
// are checked inside the iteration, so both limits bite within a fraction of a second of being reached.
TEST(DoubleDescription, GrowthBudgetsBiteOnThirtyDimensions) {
  using Clock = std::chrono::steady_clock;
  auto seconds_of = [](auto&& f) {
    const auto start = Clock::now();
    EXPECT_THROW(f(), exact::BudgetExceeded);
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  DdBudget timed;
  timed.deadline = exact::Deadline::after(0.2);
  EXPECT_LT(seconds_of([&] { to_face(testing::cross_polytope_span(30), timed); }), 2.0);
  timed.deadline = exact::Deadline::after(0.2);
  EXPECT_LT(seconds_of([&] { to_span(testing::cube_face(30), timed); }), 2.0);
  DdBudget work;
  work.max_work = std::uint64_t{1} << 24;
  EXPECT_LT(seconds_of([&] { to_face(testing::cross_polytope_span(30), work); }), 2.0);
  EXPECT_LT(seconds_of([&] { to_span(testing::cube_face(30), work); }), 2.0);
  DdBudget rays;
  rays.max_rays = 1000;
  EXPECT_LT(seconds_of([&] { to_span(testing::cube_face(30), rays); }), 2.0);
}

// The degenerate polytope families both ways against cddlib: cubes and cross-polytopes of dimension
// 2-6 (up to 64 rays / facets, many rows through every vertex).
TEST(DoubleDescription, CubesAndCrossPolytopesAgainstCddlib) {
  for (Eigen::Index n = 2; n <= 6; ++n) {
    for (const SpanCone<Q>& C : {testing::cube_span(n), testing::cross_polytope_span(n)}) {
      const FaceCone<Q> F = canonical(to_face(C));
      ASSERT_TRUE(identical(F, canonical(reference::cdd_to_face(C)))) << "n " << n;
      EXPECT_EQ(F.inequalities.rows(), C.rays.rows() == 2 * n ? Eigen::Index{1} << n : 2 * n);
    }
    for (const FaceCone<Q>& F : {testing::cube_face(n), testing::cross_polytope_face(n)}) {
      const SpanCone<Q> S = canonical(to_span(F));
      ASSERT_TRUE(identical(S, canonical(reference::cdd_to_span(F)))) << "n " << n;
    }
  }
}

// Lower-dimensional and non-pointed inputs (equalities, lines, rays in a hyperplane, implicit
// equalities from opposite rows) are converted by one run in the ring; both_forms' second side (picked
// by incidence) is the canonical form of the other conversion, and cddlib agrees.
TEST(DoubleDescription, BothFormsFromOneConversionAgainstCddlib) {
  std::mt19937_64 rng(20261201);
  for (Eigen::Index dim = 3; dim <= 7; ++dim)
    for (int rep = 0; rep < 12; ++rep) {
      SpanCone<Q> C = random_span(rng, dim, dim + 3, rep % 3, rep % 2 == 0 ? dim + 3 : 0);
      if (rep % 4 == 1)  // every generator in x_last = x_0: a lower-dimensional cone
        for (Eigen::Index r = 0; r < C.rays.rows(); ++r) C.rays(r, dim - 1) = C.rays(r, 0);
      const ConePair<Q> pair = both_forms(C);
      const FaceCone<Q> F = canonical(pair.face);
      ASSERT_TRUE(identical(F, canonical(reference::cdd_to_face(C))));
      const SpanCone<Q> S = canonical(to_span(F));
      ASSERT_TRUE(identical(canonical(pair.span), S));
      FaceCone<Q> G = random_face(rng, dim, dim + rep % 5, rep % 3 == 0 ? 1 : 0, 0);
      if (rep % 2 == 1 && G.inequalities.rows() > 1) G.inequalities.row(1) = -G.inequalities.row(0);
      const ConePair<Q> back = both_forms(G);
      const SpanCone<Q> GS = canonical(back.span);
      ASSERT_TRUE(identical(GS, canonical(reference::cdd_to_span(G))));
      ASSERT_TRUE(identical(canonical(back.face), canonical(to_face(GS))));
    }
}

// The K matrices of the wrench cone algorithm (eq. 15), pos(K) often not full-dimensional: a unit disk
// with 1-6 fixels, every mode of one letter and a seeded mixed mode each.
TEST(DoubleDescription, WrenchConeKMatricesAgainstCddlib) {
  const char* points[] = {"[0, -1]", "[1, 0]", "[0, 1]", "[-1, 0]", "[\"3/5\", \"4/5\"]", "[\"-4/5\", \"-3/5\"]"};
  std::mt19937_64 rng(15);
  const auto letters = solvers::letters_for(true);
  for (int fixels = 1; fixels <= 6; ++fixels) {
    std::string text = R"({"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1},
        "mass": 1, "inertia": "1/2"}, "mu_s": "1/5", "mu_k": "1/5", "fixels": [)";
    for (int i = 0; i < fixels; ++i) text += std::string(i ? ", " : "") + "{\"position\": " + points[i] + "}";
    const auto scene = read_planar_scene(exact::JsonInput::parse(text + "]}", "test"));
    const auto model = solvers::contact_model<Q>(scene);
    std::vector<std::string> modes;
    for (solvers::Interaction c : letters) modes.emplace_back(static_cast<std::size_t>(fixels), static_cast<char>(c));
    std::string mixed;
    for (int i = 0; i < fixels; ++i) mixed += static_cast<char>(letters[rng() % letters.size()]);
    modes.push_back(mixed);
    for (const std::string& mode : modes) {
      const auto parsed = solvers::parse_mode(mode, std::vector<bool>(static_cast<std::size_t>(fixels), true));
      if (parsed.status != solvers::ModeStatus::kValid) continue;
      const SpanCone<Q> K = SpanCone<Q>::from_columns(solvers::cone_form<Q>(scene, model, parsed.mode).K);
      ASSERT_TRUE(identical(canonical(to_face(K)), canonical(reference::cdd_to_face(K)))) << mode;
    }
  }
}

}  // namespace
}  // namespace contactcert::geometry
