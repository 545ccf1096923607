#include "solvers/stability/strong_stability.h"

#include <gtest/gtest.h>

#include <random>

#include "checker/stability_check.h"
#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/rational_text.h"
#include "geometry/nnc_cone.h"
#include "geometry/scene_json.h"
#include "geometry/span_cone.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/stability/stable_region.h"
#include "solvers/wrench_cone/wrench_cone.h"
#include "tests/solvers/scene_fixtures.h"

namespace contactcert::solvers {
namespace {

using exact::Q;
using exact::Vec;
using exact::Z;

using testing::random_wrench;
using testing::wrench;

geometry::PlanarScene section7(const char* mu) { return testing::scene_with_mu("bt2002_section7_disk.json", mu); }

TEST(StrongStability, Section7DiskPushedStraightDownIsStronglyStable) {
  // A moving solution from rest has vdot^T M vdot = a^T c + vdot^T g <= vdot^T g (friction opposes
  // sliding, separating contacts carry no force). For g = (0,-1,0), vdot^T g = -ydd, and the bottom
  // fixel's normal acceleration is a_1n = ydd >= 0, so vdot = 0: no solution moves.
  const auto scene = section7("1.2");
  for (exact::Arith arith : {exact::Arith::kExact, exact::Arith::kVerified}) {
    const auto r = strong_stability<Q>(scene, wrench(0, -1, 0), {arith});
    EXPECT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
    // 9 feasible moving modes, each with a proof for g; the 6 others end in a dead prefix (the 4^2 - 1 strings).
    EXPECT_EQ(r.modes_kinematically_feasible, 9);
    EXPECT_EQ(r.proofs.size(), 9u + static_cast<std::size_t>(r.dead_prefixes));
    EXPECT_EQ(checker::check_stability(scene, wrench(0, -1, 0), r), "");
  }
  EXPECT_EQ(strong_stability<double>(scene, exact::to_double(wrench(0, -1, 0))).verdict,
            StabilityVerdict::kStronglyStable);
}

TEST(StrongStability, PushIntoTheSideFixelIsStronglyStable) {
  // Same energy argument with g = (1,0,0): a_2n = -xdd >= 0 at the fixel at (1,0).
  const auto scene = section7("1.2");
  const auto r = strong_stability<Q>(scene, wrench(1, 0, 0));
  EXPECT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
  EXPECT_EQ(checker::check_stability(scene, wrench(1, 0, 0), r), "");
}

TEST(StrongStability, DownLeftPushIsOnlyWeaklyStableAndUnstableWithLowFriction) {
  // Down-left through the centre: with mu = 1.2 the bottom fixel alone can hold it (|c_t|/c_n = 1 <= 1.2),
  // but the disk may also roll on the bottom fixel away from the side fixel.
  const auto scene = section7("1.2");
  const auto r = strong_stability<Q>(scene, wrench(-1, -1, 0));
  EXPECT_EQ(r.verdict, StabilityVerdict::kWeaklyStable);
  ASSERT_TRUE(r.has_moving);
  EXPECT_EQ(checker::check_stability(scene, wrench(-1, -1, 0), r), "");
  // With mu = 0.3 nothing holds it: the side fixel can only push left, the bottom one needs mu >= 1.
  const auto low = section7("0.3");
  const auto u = strong_stability<Q>(low, wrench(-1, -1, 0));
  EXPECT_EQ(u.verdict, StabilityVerdict::kUnstable);
  EXPECT_FALSE(u.has_resting);
  EXPECT_EQ(checker::check_stability(low, wrench(-1, -1, 0), u), "");
}

TEST(StrongStability, PullingAwayIsWeaklyStableOnlyUnderForceClosure) {
  // g = (0,1,0) lifts the disk. With mu = 1.2 each fixel lies in the other's friction cone (force
  // closure, section 7): the disk can wedge, c = (5, 6, -6, 6) balances g, yet it may also just lift off.
  const auto scene = section7("1.2");
  const auto r = strong_stability<Q>(scene, wrench(0, 1, 0));
  EXPECT_EQ(r.verdict, StabilityVerdict::kWeaklyStable);
  EXPECT_EQ(checker::check_stability(scene, wrench(0, 1, 0), r), "");
  // With mu = 0.3: x balance gives c_2n = -c_1t <= 0.3 c_1n, y balance c_2t = c_1n + 1 <= 0.3 c_2n
  // <= 0.09 c_1n: impossible, so nothing holds it.
  const auto low = section7("0.3");
  const auto u = strong_stability<Q>(low, wrench(0, 1, 0));
  EXPECT_EQ(u.verdict, StabilityVerdict::kUnstable);
  EXPECT_EQ(checker::check_stability(low, wrench(0, 1, 0), u), "");
}

TEST(StrongStability, CorruptedEvidenceIsRejected) {
  const auto scene = section7("1.2");
  auto r = strong_stability<Q>(scene, wrench(0, -1, 0));
  ASSERT_EQ(r.verdict, StabilityVerdict::kStronglyStable);
  auto wrong_verdict = r;
  wrong_verdict.verdict = StabilityVerdict::kWeaklyStable;
  EXPECT_NE(checker::check_stability(scene, wrench(0, -1, 0), wrong_verdict), "");
  // Change one number in a dynamic proof (one that is not all zeros).
  bool corrupted = false;
  ModeProofs<Q> bad;
  for (const auto& p : r.proofs) {
    ModeProof<Q> q = p;
    for (Eigen::Index i = 0; i < q.motzkin.size() && !corrupted && !q.kinematic; ++i)
      if (sgn(q.motzkin(i)) != 0) {
        q.motzkin(i) = -q.motzkin(i) - 1;
        corrupted = true;
      }
    bad.push_back(q);
  }
  ASSERT_TRUE(corrupted);
  r.proofs = bad;
  EXPECT_NE(checker::check_stability(scene, wrench(0, -1, 0), r), "");
  // The same evidence does not prove stability under another wrench.
  auto w = strong_stability<Q>(scene, wrench(0, -1, 0));
  EXPECT_NE(checker::check_stability(scene, wrench(-1, -1, 0), w), "");
}

// A unit disk touching fixels at (0,-1), (1,0) and (-4/5,-3/5), mu = 1/2 (the benchmark's three-fixel scene).
const char* const kThreeFixelDisk =
    R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"mass":1,"inertia":1},
        "fixels":[{"position":[0,-1]},{"position":[1,0]},{"position":["-4/5","-3/5"]}],
        "mu_s":"1/2","mu_k":"1/2"})";
geometry::PlanarScene three_fixel_disk() {
  return geometry::read_planar_scene(exact::JsonInput::parse(kThreeFixelDisk, "three_fixel_disk.json"));
}

TEST(StabilityOracle, FloatFirstVerdictEqualsTheExactVerdictIncludingConeFaces) {
  // The prepared, float-first (verified) oracle must give the exact verdict with verifying evidence, on random
  // wrenches and on the representatives of every cell of the region: those of dimension 1 and 2 lie exactly
  // on faces of the weak cone or of a moving-mode cone, where a float LP cannot tell the sides apart.
  for (const char* mu : {"1.2", "0.3"}) {
    const auto scene = section7(mu);
    const StabilityOracle<Q> oracle(scene);
    const auto region = stable_region<Q>(scene);
    std::vector<Vec<Q>> wrenches;
    for (const auto& cell : region.cells) wrenches.push_back(cell.point);
    std::mt19937_64 rng(17);
    std::uniform_int_distribution<int> d(-5, 5);
    for (int t = 0; t < 100; ++t) wrenches.push_back(random_wrench(d, rng));
    long lps = 0, from_float = 0;
    for (const Vec<Q>& g : wrenches) {
      const auto r = oracle.verdict(g);
      EXPECT_EQ(r.verdict, strong_stability<Q>(scene, g, {exact::Arith::kExact}).verdict)
          << "mu " << mu << " g = " << g.transpose();
      EXPECT_EQ(r.verdict, region.label(g));
      EXPECT_EQ(checker::check_stability(scene, g, r), "") << "mu " << mu << " g = " << g.transpose();
      lps += r.lps;
      from_float += r.lps_checked_from_float;
    }
    // The point of the float-first path: nearly every LP is decided by a rounded float answer.
    EXPECT_GT(from_float * 10, lps * 9) << from_float << " of " << lps;
  }
}

TEST(StabilityOracle, ThreeFixelsAgreeWithTheCellLabelsAndTheColdVerdict) {
  const auto scene = three_fixel_disk();
  const StabilityOracle<Q> oracle(scene);
  const StabilityOracle<double> floats(scene);
  const auto region = stable_region<Q>(scene);
  std::mt19937_64 rng(23);
  for (std::size_t c = 0; c < region.cells.size(); c += 1 + rng() % 6) {
    const Vec<Q>& g = region.cells[c].point;
    const auto r = oracle.verdict(g);
    EXPECT_EQ(r.verdict, region.cells[c].label) << g.transpose();
    EXPECT_EQ(checker::check_stability(scene, g, r), "") << g.transpose();
    const auto cold = strong_stability<Q>(scene, g);
    EXPECT_EQ(cold.verdict, r.verdict);
    EXPECT_EQ(checker::check_stability(scene, g, cold), "") << g.transpose();
    // Cold prepares only the modes the verdict reaches: all of them unless some mode moves.
    if (r.has_moving) {
      EXPECT_LE(cold.lps, r.lps + oracle.preparation_lps());
      EXPECT_EQ(cold.moving.mode.text(), r.moving.mode.text());
    } else {
      EXPECT_EQ(cold.lps, r.lps + oracle.preparation_lps());
    }
    if (region.cells[c].dimension == 3) {  // off every face the float oracle agrees too
      EXPECT_EQ(floats.verdict(exact::to_double(g)).verdict, r.verdict) << g.transpose();
    }
  }
}

TEST(StabilityOracle, SharedKinematicProofsOutliveTheOracleAndEqualTheColdOnes) {
  // A verdict refers to the oracle's kinematic proofs instead of copying them: they must still verify (also
  // through the certificate file) after the oracle is gone, in copies of the result, and equal the proofs that
  // the cold path computes for itself.
  const auto scene = three_fixel_disk();
  const Vec<Q> g = wrench(0, -1, 0);
  StabilityResult<Q> warm;
  long shared = 0;
  {
    const StabilityOracle<Q> oracle(scene);
    warm = oracle.verdict(g);
    for (const auto& p : warm.proofs) shared += p.kinematic;
    // Some kinematic proofs were reused from an earlier mode (fewer LPs than moving modes), and still verify below.
    EXPECT_LT(oracle.preparation_lps(), 63);
  }
  ASSERT_EQ(warm.verdict, StabilityVerdict::kStronglyStable);
  ASSERT_EQ(warm.proofs.size(), static_cast<std::size_t>(warm.modes_kinematically_feasible + warm.dead_prefixes));
  EXPECT_EQ(shared, warm.dead_prefixes);
  EXPECT_GT(shared, 10);
  const StabilityResult<Q> copy = warm;
  warm = StabilityResult<Q>();  // the copy alone keeps the shared proofs now
  EXPECT_EQ(checker::check_stability(scene, g, copy), "");
  const auto checked = checker::check_stability_certificate(
      exact::JsonInput::parse(stability_certificate(kThreeFixelDisk, g, copy), "certificate.json"));
  EXPECT_TRUE(checked.valid) << checked.reason;
  const auto cold = strong_stability<Q>(scene, g);
  ASSERT_EQ(cold.proofs.size(), copy.proofs.size());
  for (std::size_t i = 0; i < cold.proofs.size(); ++i) {
    EXPECT_EQ(cold.proofs[i].mode.text(), copy.proofs[i].mode.text());
    EXPECT_EQ(cold.proofs[i].kinematic, copy.proofs[i].kinematic);
    EXPECT_EQ(cold.proofs[i].motzkin, copy.proofs[i].motzkin) << cold.proofs[i].mode.text();
  }
}

TEST(StabilityOracle, ReusedCertificatesGiveTheSameVerdictsWitnessesAndCounts) {
  // A batch decides a system by a certificate kept from an earlier wrench where it proves infeasibility for g:
  // every verdict, witness and count must be verdict(g)'s, the proofs (some now reused) must verify, and some
  // systems must indeed be decided without their LP. The wrenches: the cells' representatives (on the faces, where
  // y_dyn . g = 0), random ones, and all of them again.
  for (const geometry::PlanarScene& scene : {section7("1.2"), section7("0.3"), three_fixel_disk()}) {
    const StabilityOracle<Q> oracle(scene);
    std::vector<Vec<Q>> wrenches;
    for (const auto& cell : stable_region<Q>(scene).cells) wrenches.push_back(cell.point);
    std::mt19937_64 rng(31);
    std::uniform_int_distribution<int> d(-4, 4);
    for (int t = 0; t < 60; ++t) wrenches.push_back(random_wrench(d, rng));
    const std::size_t n = wrenches.size();
    for (std::size_t i = 0; i < n; ++i) wrenches.push_back(wrenches[i]);
    ReusedCertificates<Q> reuse;
    long reused = 0;
    for (const Vec<Q>& g : wrenches) {
      const auto r = oracle.verdict(g, reuse);
      const auto alone = oracle.verdict(g);
      EXPECT_EQ(r.verdict, alone.verdict) << g.transpose();
      EXPECT_EQ(r.has_resting, alone.has_resting);
      EXPECT_EQ(r.resting_forces, alone.resting_forces) << g.transpose();
      EXPECT_EQ(r.has_moving, alone.has_moving);
      EXPECT_EQ(r.moving.mode.text(), alone.moving.mode.text());
      EXPECT_EQ(r.moving.forces, alone.moving.forces);
      EXPECT_EQ(r.moving.acceleration, alone.moving.acceleration);
      EXPECT_EQ(r.lps, alone.lps);
      EXPECT_EQ(r.modes_checked, alone.modes_checked);
      EXPECT_EQ(r.proofs.size(), alone.proofs.size());
      EXPECT_EQ(alone.lps_reused, 0);
      EXPECT_EQ(checker::check_stability(scene, g, r), "") << g.transpose();
      reused += r.lps_reused;
    }
    EXPECT_GT(reused, static_cast<long>(n));  // the second pass at least reuses
  }
  // Float certificates are never reused (a float dot product proves nothing).
  const StabilityOracle<double> floats(section7("1.2"));
  ReusedCertificates<double> none;
  for (int t = 0; t < 3; ++t) EXPECT_EQ(floats.verdict(exact::to_double(wrench(0, -1, 0)), none).lps_reused, 0);
}

TEST(StabilityOracle, CorruptedFloatFirstEvidenceIsRejected) {
  const auto scene = section7("1.2");
  const StabilityOracle<Q> oracle(scene);
  // A kinematic proof turned into nonsense, and one made non-zero off the kinematic rows.
  auto strong = oracle.verdict(wrench(0, -1, 0));
  ASSERT_EQ(strong.verdict, StabilityVerdict::kStronglyStable);
  ASSERT_EQ(checker::check_stability(scene, wrench(0, -1, 0), strong), "");
  // The list with proof i replaced by `q` (the others still shared with the oracle).
  auto with = [&strong](std::size_t i, const ModeProof<Q>& q) {
    auto bad = strong;
    bad.proofs = ModeProofs<Q>();
    for (std::size_t j = 0; j < strong.proofs.size(); ++j) bad.proofs.push_back(j == i ? q : strong.proofs[j]);
    return bad;
  };
  for (std::size_t i = 0; i < strong.proofs.size(); ++i) {
    const ModeProof<Q>& p = strong.proofs[i];
    if (!p.kinematic) continue;
    ModeProof<Q> q = p;
    q.motzkin = -q.motzkin;
    EXPECT_NE(checker::check_stability(scene, wrench(0, -1, 0), with(i, q)), "") << p.mode.text();
    q.motzkin = p.motzkin;
    q.motzkin(q.motzkin.size() - 1) += 1;
    EXPECT_NE(checker::check_stability(scene, wrench(0, -1, 0), with(i, q)), "") << p.mode.text();
  }
  EXPECT_EQ(checker::check_stability(scene, wrench(0, -1, 0), strong), "");  // the shared set itself is unchanged
  // A moving witness with a changed acceleration, and resting forces that no longer balance g.
  auto weak = oracle.verdict(wrench(-1, -1, 0));
  ASSERT_EQ(weak.verdict, StabilityVerdict::kWeaklyStable);
  ASSERT_EQ(checker::check_stability(scene, wrench(-1, -1, 0), weak), "");
  auto moved = weak;
  moved.moving.acceleration(0) += Q(1, 7);
  EXPECT_NE(checker::check_stability(scene, wrench(-1, -1, 0), moved), "");
  auto resting = weak;
  resting.resting_forces(0) += 1;
  EXPECT_NE(checker::check_stability(scene, wrench(-1, -1, 0), resting), "");
}

TEST(StrictSolver, FallsBackToTheExactLpWhenTheRoundedAnswerDoesNotCheck) {
  // x1 - p x2 = b <= 0 with x1, x2 >= 0, x1 > 0, p = 1 + 2^-31: the LP's only optimal vertex has x1 = 1 and
  // x2 = (1 - b) / p, whose denominator 2^31 + 1 is beyond the rounding's 2^30, so the rounded point fails the
  // exact check and the exact route decides.
  const Q p = 1 + 1 / Q(Z(1) << 31);
  exact::StrictSystem<Q> sys;
  sys.A = exact::Mat<Q>(1, 2);
  sys.A << 1, -p;
  sys.strict = {true, false};
  const exact::StrictSolver<Q> solver(sys);
  for (const Q& b : {Q(0), Q(-1), Q(-3)}) {
    const Vec<Q> rhs = Vec<Q>::Constant(1, b);
    const auto r = solver.solve(rhs);
    sys.b = rhs;
    ASSERT_EQ(r.status, exact::StrictStatus::kFeasible) << b;  // x2 large enough always works
    EXPECT_TRUE(exact::verify_strict_point(sys, r.x)) << b;
    EXPECT_FALSE(r.rounded_float_checked) << b;
  }
  // Infeasible with a certificate: x1 + x2 = -1.
  exact::StrictSystem<Q> neg{exact::Mat<Q>::Ones(1, 2), Vec<Q>::Constant(1, Q(-1)), {}, {}};
  const auto r = exact::strict_feasibility(neg);
  ASSERT_EQ(r.status, exact::StrictStatus::kInfeasible);
  EXPECT_TRUE(r.rounded_float_checked);
  EXPECT_TRUE(exact::verify_motzkin(neg, r.motzkin));
}

TEST(StrictSolver, RowsBeyondSixtyFourBitsAreSolvedInRationals) {
  // 2^-62 x1 + (2^62 - 1)^-1 x2 = b: the row's common denominator 2^62 (2^62 - 1) does not fit in 64 bits, so
  // the solver keeps the rational row (dense or sparse input alike) and every answer comes from the verified LP.
  const Q a = 1 / Q(Z(1) << 62), c = 1 / Q((Z(1) << 62) - 1);
  exact::SparseStrictSystem<Q> sparse{1, 2, {{0, 0, a}, {0, 1, c}}, {}, {true, false}};
  for (const Q& b : {Q(1), Q(-1)}) {
    const Vec<Q> rhs = Vec<Q>::Constant(1, b);
    const exact::StrictSystem<Q> dense = sparse.dense(rhs);
    for (const auto& r : {exact::StrictSolver<Q>(sparse).solve(rhs), exact::StrictSolver<Q>(dense).solve(rhs)}) {
      EXPECT_FALSE(r.rounded_float_checked);
      if (b > 0) {
        ASSERT_EQ(r.status, exact::StrictStatus::kFeasible);
        EXPECT_TRUE(exact::verify_strict_point(dense, r.x));
      } else {
        ASSERT_EQ(r.status, exact::StrictStatus::kInfeasible);
        EXPECT_TRUE(exact::verify_motzkin(dense, r.motzkin));
      }
    }
  }
}

TEST(MotionSystem, KinematicRowsAndIntegerRowsEqualTheRationalSystem) {
  // Every mode of the three-fixel disk: kinematic_system is the kinematic rows of motion_system on the vdot and
  // sigma columns, motion_system_rows its row count, and the verified solver built from the sparse rational
  // entries (rows scaled to 64-bit integers) answers as the exact LP on the dense rational system.
  const auto scene = three_fixel_disk();
  const auto model = motion_model<Q>(scene);
  std::vector<ModeString> modes = moving_modes(3);
  modes.push_back(ModeString{std::vector<Interaction>(3, Interaction::kRoll)});
  const Vec<Q> g = wrench(1, -3, 1);
  for (const ModeString& mode : modes) {
    const auto ms = motion_system(model, mode);
    const exact::StrictSystem<Q> full = ms.with_wrench(g);
    ASSERT_EQ(motion_system_rows(mode), full.A.rows()) << mode.text();
    const exact::StrictSystem<Q> kin = kinematic_system(model, mode).dense();
    ASSERT_EQ(kin.A.rows(), ms.kinematic_rows);
    std::vector<Eigen::Index> columns{0, 1, 2};
    for (Eigen::Index j = 3; j < full.A.cols(); ++j)
      if (full.strict[static_cast<std::size_t>(j)]) columns.push_back(j);
    ASSERT_EQ(kin.A.cols(), static_cast<Eigen::Index>(columns.size())) << mode.text();
    for (Eigen::Index c = 0; c < kin.A.cols(); ++c) {
      const Eigen::Index j = columns[static_cast<std::size_t>(c)];
      EXPECT_EQ(kin.is_free[static_cast<std::size_t>(c)], full.is_free[static_cast<std::size_t>(j)]);
      EXPECT_EQ(kin.strict[static_cast<std::size_t>(c)], full.strict[static_cast<std::size_t>(j)]);
      for (Eigen::Index i = 0; i < kin.A.rows(); ++i) EXPECT_EQ(kin.A(i, c), full.A(i, j)) << mode.text();
    }
    for (Eigen::Index i = 0; i < kin.A.rows(); ++i)  // the kinematic rows involve no other column
      EXPECT_EQ(kin.A.row(i).cwiseAbs().sum(), full.A.row(i).cwiseAbs().sum()) << mode.text();
    const auto fast = exact::StrictSolver<Q>(ms.system).solve(ms.rhs(g));
    const auto exact_lp = exact::strict_feasibility(full, exact::Arith::kExact);
    ASSERT_EQ(fast.status, exact_lp.status) << mode.text();
    EXPECT_TRUE(fast.rounded_float_checked) << mode.text();
    EXPECT_TRUE(fast.status == exact::StrictStatus::kFeasible ? exact::verify_strict_point(full, fast.x)
                                                              : exact::verify_motzkin(full, fast.motzkin))
        << mode.text();
  }
}

TEST(StrongStability, MembershipLpsAgreeWithTheWrenchConeAlgorithm) {
  // Each moving mode's LP answer must equal membership in the cone of the wrench cone algorithm
  // (an independent route: K z = P g, conversion, strict limits). Random small integer wrenches.
  const auto scene = section7("1.2");
  const auto model = contact_model<Q>(scene);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> d(-3, 3);
  std::vector<geometry::FaceCone<Q>> cones;
  const auto modes = moving_modes(2);
  for (const auto& m : modes) cones.push_back(wrench_cone_face<Q>(scene, model, m, Route::kPaper));
  for (int t = 0; t < 60; ++t) {
    const Vec<Q> g = random_wrench(d, rng);
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const auto ms = motion_system(motion_model<Q>(scene), modes[i]);
      const bool lp =
          exact::strict_feasibility(ms.with_wrench(g), exact::Arith::kExact).status == exact::StrictStatus::kFeasible;
      EXPECT_EQ(lp, geometry::contains_point<Q>(cones[i], g)) << "mode " << modes[i].text() << " g = " << g.transpose();
    }
  }
}

TEST(StableRegion, EveryCellLabelEqualsTheOneWrenchVerdict) {
  // The cells come from the cones' planes; each cell's label (from the cones) must equal the LP verdict
  // at its representative, exactly, for both friction values.
  for (const char* mu : {"1.2", "0.3"}) {
    const auto scene = section7(mu);
    const auto region = stable_region<Q>(scene);
    int strong = 0, weak = 0, unstable = 0;
    for (const auto& cell : region.cells) {
      const auto r = strong_stability<Q>(scene, cell.point, {exact::Arith::kExact});
      EXPECT_EQ(r.verdict, cell.label) << "mu " << mu << " cell at " << cell.point.transpose();
      (cell.label == StabilityVerdict::kStronglyStable ? strong
       : cell.label == StabilityVerdict::kWeaklyStable ? weak
                                                       : unstable)++;
    }
    EXPECT_GT(strong, 0);  // e.g. pushing straight down
    if (std::string(mu) == "0.3") {
      EXPECT_GT(unstable, 0);
    } else {
      EXPECT_GT(weak, 0) << "e.g. the down-left push";
      EXPECT_EQ(unstable, 0) << "force closure: every wrench can be resisted";
    }
  }
}

TEST(StableRegion, SignVectorLabelsEqualTheConeLabelsOnThreeFixels) {
  // Cells are labelled from their sign vectors (integer arrangement, rows mapped to planes with an
  // orientation): each sign must be the exact sign of plane . point, and each label that of label(point).
  const auto scene = three_fixel_disk();
  const auto region = stable_region<Q>(scene);
  ASSERT_GT(region.cells.size(), 100u);
  const auto arr = geometry::sphere_arrangement<Q>(region.planes);
  ASSERT_EQ(arr.cells.size(), region.cells.size());
  for (const auto& cell : arr.cells)
    for (Eigen::Index j = 0; j < region.planes.rows(); ++j)
      ASSERT_EQ(cell.signs[static_cast<std::size_t>(j)], sgn(Q(region.planes.row(j).dot(cell.point))));
  for (Eigen::Index j = 0; j < region.planes.rows(); ++j) {  // every plane given itself: orientation +1
    EXPECT_EQ(arr.row_plane[static_cast<std::size_t>(j)], j);
    EXPECT_EQ(arr.row_orientation[static_cast<std::size_t>(j)], 1);
  }
  for (const auto& cell : region.cells) ASSERT_EQ(cell.label, region.label(cell.point)) << cell.point.transpose();
  // A negated, rescaled copy of a plane maps to it with orientation -1.
  exact::Mat<Q> two(2, 3);
  two.row(0) = region.planes.row(0);
  two.row(1) = Q(-3, 7) * region.planes.row(0);
  const auto pair = geometry::sphere_arrangement<Q>(two);
  EXPECT_EQ(pair.planes.rows(), 1);
  EXPECT_EQ(pair.row_plane, (std::vector<Eigen::Index>{0, 0}));
  EXPECT_EQ(pair.row_orientation, (std::vector<int>{1, -1}));
}

TEST(StableRegion, TheArrangementHonoursItsBudget) {
  // The arrangement stops in its own loops (issue 17): past the deadline, or past its sign budget, with what it
  // covered; the whole region stops at the tree options' deadline too.
  const auto region = stable_region<Q>(three_fixel_disk());
  const auto full = geometry::sphere_arrangement<Q>(region.planes);
  geometry::ArrangementBudget expired{exact::Deadline::after(1e-9)};
  try {
    geometry::sphere_arrangement<Q>(region.planes, expired);
    ADD_FAILURE() << "no BudgetExceeded past the deadline";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("time limit of"), std::string::npos) << e.what();
    EXPECT_NE(e.covered.find("planes"), std::string::npos) << e.covered;
  }
  geometry::ArrangementBudget small;
  small.max_signs = full.cells.size() * static_cast<std::size_t>(region.planes.rows()) / 2;
  try {
    geometry::sphere_arrangement<Q>(region.planes, small);
    ADD_FAILURE() << "no BudgetExceeded past the sign budget";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("cell signs"), std::string::npos) << e.what();
    EXPECT_NE(e.covered.find("vertices visited"), std::string::npos) << e.covered;
  }
  small.max_signs = full.cells.size() * static_cast<std::size_t>(region.planes.rows());
  EXPECT_EQ(geometry::sphere_arrangement<Q>(region.planes, small).cells.size(), full.cells.size());
  ModeTreeOptions late;
  late.deadline = exact::Deadline::after(1e-9);
  EXPECT_THROW(stable_region<Q>(three_fixel_disk(), Route::kPaper, late), exact::BudgetExceeded);
  // The finger pushes after the region stop at the same deadline, before labelling a piece.
  try {
    finger_pushes<Q>(three_fixel_disk(), region, late.deadline);
    ADD_FAILURE() << "no BudgetExceeded in the finger pushes past the deadline";
  } catch (const exact::BudgetExceeded& e) {
    EXPECT_NE(e.covered.find("0 boundary pieces labelled"), std::string::npos) << e.covered;
  }
}

TEST(StableRegion, SixtyRandomWrenchesAgreeWithTheirCellLabel) {
  const auto scene = section7("0.5");
  const auto region = stable_region<Q>(scene);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> d(-4, 4);
  for (int t = 0; t < 60; ++t) {
    const Vec<Q> g = random_wrench(d, rng);
    EXPECT_EQ(region.label(g), strong_stability<Q>(scene, g).verdict) << g.transpose();
  }
}

TEST(FingerPushes, SquareWithTwoFrictionlessFixelsByHand) {
  // Square [0,2]^2 (com (1,1)), frictionless fixels under the bottom midpoint and left of the left
  // midpoint. Their contact wrenches are (0,1,0) and (1,0,0), so a resting solution needs zero torque
  // and f_x, f_y <= 0. A push on the top edge at (x,2) gives g = (0,-1,1-x): only x = 1 rests, and there
  // a moving solution would have vdot^T M vdot <= vdot^T g = -ydd <= 0 (a_1n = ydd >= 0): strongly stable.
  // The right edge at (2,y) gives (-1,0,y-1): the same at y = 1. Bottom and left pushes pull the square
  // off a fixel: unstable.
  const auto scene = geometry::read_planar_scene(exact::JsonInput::parse(R"({"kind": "planar",
      "workpiece": {"shape": {"type": "polygon", "vertices": [[0,0],[2,0],[2,2],[0,2]]}},
      "fixels": [{"position": [1, 0]}, {"position": [0, 1]}], "mu_s": 0, "mu_k": 0})",
                                                                         "square.json"));
  const auto region = stable_region<Q>(scene);
  const auto pushes = finger_pushes<Q>(scene, region);
  std::vector<std::string> got;
  for (const auto& p : pushes.edges)
    got.push_back(std::to_string(p.edge) + (p.from_closed ? "[" : "(") + exact::to_string(p.from) + "," +
                  exact::to_string(p.to) + (p.to_closed ? "]" : ")") + verdict_name(p.label));
  const std::vector<std::string> expected{"0(0,1)unstable",   "1(0,1/2)unstable", "1[1/2,1/2]strongly_stable",
                                          "1(1/2,1)unstable", "2(0,1/2)unstable", "2[1/2,1/2]strongly_stable",
                                          "2(1/2,1)unstable", "3(0,1)unstable"};
  EXPECT_EQ(got, expected);
}

TEST(Margin, SquaredDistanceToAQuarterPlaneByHand) {
  geometry::SpanCone<Q> c;
  c.dim = 3;
  c.rays = exact::Mat<Q>(2, 3);
  c.rays << 1, 0, 0, 0, 1, 0;
  c.lines = exact::Mat<Q>(0, 3);
  EXPECT_EQ(squared_distance<Q>(wrench(-1, -1, 5), c), 27);  // nearest point: the apex
  EXPECT_EQ(squared_distance<Q>(wrench(1, -1, 2), c), 5);    // nearest point: (1,0,0) on a ray
  EXPECT_EQ(squared_distance<Q>(wrench(1, 1, 1), c), 1);     // nearest point: (1,1,0) inside the sector
  EXPECT_EQ(squared_distance<Q>(wrench(2, 3, 0), c), 0);
}

TEST(Margin, ExactSquaredDistanceAgreesWithTheFloatOneOnRandomCones) {
  // The exact path solves its faces in closed form, the float path by the Gram matrix's inverse.
  std::uint32_t state = 99;
  auto next = [&]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<int>((state >> 16) % 9) - 4;
  };
  for (int trial = 0; trial < 60; ++trial) {
    geometry::SpanCone<Q> c;
    c.dim = 3;
    c.rays = exact::Mat<Q>(2 + trial % 3, 3);
    c.lines = exact::Mat<Q>(trial % 5 == 0 ? 1 : 0, 3);
    for (Eigen::Index r = 0; r < c.rays.rows(); ++r)
      for (Eigen::Index j = 0; j < 3; ++j) c.rays(r, j) = next();
    for (Eigen::Index r = 0; r < c.lines.rows(); ++r)
      for (Eigen::Index j = 0; j < 3; ++j) c.lines(r, j) = next();
    geometry::SpanCone<double> f;
    f.dim = 3;
    f.rays = c.rays.unaryExpr([](const Q& x) { return x.get_d(); });
    f.lines = c.lines.unaryExpr([](const Q& x) { return x.get_d(); });
    const Vec<Q> g = wrench(next(), next(), next());
    const Vec<double> gd = g.unaryExpr([](const Q& x) { return x.get_d(); });
    EXPECT_NEAR(squared_distance<Q>(g, c).get_d(), squared_distance<double>(gd, f), 1e-9) << trial;
  }
}

TEST(Margin, BallOfTheMarginStaysStronglyStable) {
  // Section 8: every wrench within the margin of a strongly stable biasing wrench is strongly stable.
  const auto scene = section7("1.2");
  const auto region = stable_region<Q>(scene);
  const Vec<Q> g = wrench(1, -2, 0);
  ASSERT_EQ(region.label(g), StabilityVerdict::kStronglyStable);
  const auto m = stability_margin<Q>(region, g);
  ASSERT_GT(m.squared_radius, 0);
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> d(-20, 20);
  for (int t = 0; t < 200; ++t) {
    Vec<Q> delta = random_wrench(d, rng);
    const Q n2 = delta.dot(delta);
    if (n2 == 0) continue;
    // Scale delta to squared length just below the margin: |delta|^2 = margin * 99/100 (a rational factor
    // on the squared length is enough to stay inside: scale by s with s^2 <= 99/100 * margin / n2).
    Q s2 = m.squared_radius * Q(99, 100) / n2, s = 1;
    while (s * s > s2) s /= 2;
    EXPECT_EQ(region.label(Vec<Q>(g + s * delta)), StabilityVerdict::kStronglyStable);
  }
}

}  // namespace
}  // namespace contactcert::solvers
