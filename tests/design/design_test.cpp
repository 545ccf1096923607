// The pieces of fixture design: candidates exactly on the boundary, lexicographic placements, the total order
// of the top K (independent of how the placements were split), symmetry, chunk results as text.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "exact/input_error.h"
#include "geometry/canonical.h"
#include "geometry/set_ops.h"
#include "geometry/sphere_arrangement.h"
#include "solvers/design/candidates.h"
#include "solvers/design/ranking.h"
#include "solvers/design/symmetry.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_stability.h"

namespace contactcert::solvers {
namespace {

using geometry::Point2;
using geometry::PolygonShape;
using geometry::Q;

geometry::Shape pawl() { return PolygonShape{{{0, 0}, {7, 0}, {10, -2}, {9, 1}, {7, 2}, {1, 2}, {0, 1}}}; }

TEST(DesignCandidates, ArcLengthPointsLieOnTheBoundaryWithInwardNormals) {
  for (const geometry::Shape& shape : {pawl(), geometry::Shape(geometry::DiskShape{{Q(1), Q(-2)}, Q(3)}),
                                       geometry::Shape(PolygonShape{{{0, 0}, {3, 0}, {3, 4}, {0, 4}}})}) {
    const auto c = arc_length_candidates(shape, 36);
    EXPECT_EQ(c.size(), 36u);
    for (const auto& k : c) {
      EXPECT_EQ(geometry::locate_in_shape(shape, k.point), geometry::ShapeLocation::kBoundary);
      const CandidateCheck again = candidate_at(shape, k.point);
      ASSERT_TRUE(again.message.empty()) << again.message;
      EXPECT_EQ(geometry::cross(again.candidate.normal, k.normal), 0);  // the same inward direction
      EXPECT_GT(geometry::dot(again.candidate.normal, k.normal), 0);
    }
  }
}

TEST(DesignCandidates, RationalPerimeterIsSplitExactly) {
  // A 3 x 4 rectangle, perimeter 14: points at arc lengths 1/2, 3/2, ... (half a step from (0, 0)); with 7
  // points, arc lengths 3 and 7 are the vertices (3, 0) and (3, 4) and are dropped.
  const PolygonShape rectangle{{{0, 0}, {3, 0}, {3, 4}, {0, 4}}};
  const auto c = arc_length_candidates(rectangle, 14);
  ASSERT_EQ(c.size(), 14u);
  EXPECT_EQ(c[0].point, (Point2{Q(1, 2), 0}));
  EXPECT_EQ(c[3].point, (Point2{3, Q(1, 2)}));
  EXPECT_EQ(arc_length_candidates(rectangle, 7).size(), 5u);
}

TEST(DesignCandidates, OffBoundaryAndVertexPointsAreRejected) {
  EXPECT_FALSE(candidate_at(pawl(), {Q(1), Q(1)}).message.empty());  // inside
  EXPECT_FALSE(candidate_at(pawl(), {Q(7), Q(0)}).message.empty());  // a vertex
  EXPECT_TRUE(candidate_at(pawl(), {Q(7, 2), Q(0)}).message.empty());
}

TEST(DesignCandidates, LatticePointsOfACircle) {
  // x^2 + y^2 = 25 has 12 integer points.
  const auto c = lattice_candidates(geometry::DiskShape{{Q(0), Q(0)}, Q(5)}, Q(1));
  EXPECT_EQ(c.size(), 12u);
  EXPECT_EQ(c[0].point, (Point2{5, 0}));  // counter-clockwise from angle 0
  EXPECT_EQ(c[1].point, (Point2{4, 3}));
}

TEST(DesignCandidates, LatticeCountIsTheCandidatesWithoutStoringThem) {
  const geometry::Shape disk = geometry::DiskShape{{Q(0), Q(0)}, Q(5)};
  EXPECT_EQ(lattice_candidate_count(disk, Q(1)), 12);
  for (const Q& pitch : {Q(1), Q(1, 2), Q(1, 3), Q(2, 7)}) {
    const auto c = lattice_candidates(pawl(), pitch);
    EXPECT_EQ(lattice_candidate_count(pawl(), pitch), static_cast<long>(c.size())) << pitch;
    for (std::size_t i = 0; i < c.size(); ++i) EXPECT_TRUE(candidate_at(pawl(), c[i].point).message.empty());
  }
  // Points in boundary order along each edge: on the bottom edge (0, 0) -> (7, 0), x increases.
  const auto c = lattice_candidates(pawl(), Q(1));
  EXPECT_EQ(c[0].point, (Point2{1, 0}));
  EXPECT_EQ(c[5].point, (Point2{6, 0}));
  EXPECT_THROW(lattice_candidate_count(pawl(), Q(1, 1000000), 1000), exact::BudgetExceeded);
}

TEST(DesignPlacements, UnrankingIsLexicographic) {
  EXPECT_EQ(placement_count(100, 3), 161700);
  EXPECT_EQ(placement_count(5, 6), 0);
  EXPECT_EQ(placement_count(5000000, 3), -1);
  long i = 0;
  for (int a = 0; a < 7; ++a)
    for (int b = a + 1; b < 7; ++b)
      for (int c = b + 1; c < 7; ++c) EXPECT_EQ(placement_at(i++, 7, 3), (Placement{a, b, c}));
}

TEST(DesignRanking, TopKIsTheSameForEverySplit) {
  std::vector<Ranked> all;
  for (int i = 0; i < 40; ++i) {
    Q figure(i % 7, 3);
    figure.canonicalize();
    all.push_back({{i, i + 1}, figure});
  }
  TopK whole(5);
  for (const auto& r : all) whole.offer(r);
  TopK merged(5);
  for (int part = 0; part < 4; ++part) {
    TopK t(5);
    for (int i = part; i < 40; i += 4) t.offer(all[static_cast<std::size_t>(i)]);
    merged.merge(t);
  }
  ASSERT_EQ(whole.items().size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(whole.items()[i].placement, merged.items()[i].placement);
  EXPECT_EQ(whole.items()[0].figure, Q(2));
  EXPECT_EQ(whole.items()[0].placement, (Placement{6, 7}));  // ties: the least indices first
}

TEST(DesignRanking, ChunkResultTextRoundTrips) {
  ChunkResult r{TopK(3), {}};
  r.top.offer({{1, 4, 9}, Q(-7, 20)});
  r.statistics.by_status = {1, 2, 3, 4, 5, 6, 7, 8};
  r.statistics.lps = 99;
  const ChunkResult back = parse_chunk_result(chunk_result_text(r), 3);
  ASSERT_EQ(back.top.items().size(), 1u);
  EXPECT_EQ(back.top.items()[0].figure, Q(-7, 20));
  EXPECT_EQ(back.statistics.by_status, r.statistics.by_status);
  EXPECT_EQ(back.statistics.lps, 99);
}

TEST(DesignSymmetry, SquareUnderGravityHasOnlyTheMirror) {
  DesignProblem p;
  p.workpiece.shape = PolygonShape{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  p.workpiece.com = {0, 0};
  p.candidates = arc_length_candidates(p.workpiece.shape, 8);
  EXPECT_EQ(candidate_symmetry(p).permutations.size(), 7u);  // the dihedral group of order 8, no wrenches
  p.wrenches.kind = WrenchSet::Kind::kList;
  p.wrenches.rows = exact::Mat<Q>(1, 3);
  p.wrenches.rows << 0, -1, 0;
  const CandidateSymmetry s = candidate_symmetry(p);
  ASSERT_EQ(s.permutations.size(), 1u);  // x -> -x maps (0, -1, 0) to itself
  // Candidates 0 (-1/2, -1) and 1 (1/2, -1) are mirror images: {1, 2} is the image of {0, 7}.
  EXPECT_TRUE(s.is_canonical({0, 7}));
  EXPECT_FALSE(s.is_canonical({1, 2}));
}

}  // namespace
}  // namespace contactcert::solvers

namespace contactcert::solvers {
namespace {

/// The pentagon of Figure 10 with mu = 1/5 and 8 candidates, strongly stable under gravity required.
DesignProblem pentagon_problem() {
  DesignProblem p;
  const std::vector<geometry::Point2> V{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 2}};
  p.workpiece.shape = geometry::PolygonShape{V};
  p.workpiece.com = geometry::polygon_centroid(V);
  p.workpiece.inertia_per_mass = geometry::polygon_inertia_per_mass(V, p.workpiece.com);
  p.mu_s = p.mu_k = geometry::Q(1, 5);
  p.candidates = arc_length_candidates(p.workpiece.shape, 8);
  p.wrenches.kind = WrenchSet::Kind::kList;
  p.wrenches.rows = exact::Mat<geometry::Q>(1, 3);
  p.wrenches.rows << 0, -1, 0;
  return p;
}

TEST(DesignEvaluate, VerdictsAgreeWithStrongStabilityOnEveryPlacement) {
  const DesignProblem p = pentagon_problem();
  const CandidateSymmetry none;
  exact::Vec<geometry::Q> g(3);
  g << 0, -1, 0;
  int accepted = 0, pruned_weak = 0;
  for (long i = 0; i < placement_count(8, 3); ++i) {
    const Placement pl = placement_at(i, 8, 3);
    const Evaluation e = evaluate_placement(p, none, pl);
    const auto direct = strong_stability<geometry::Q>(placement_scene(p, pl), g);
    EXPECT_EQ(e.status == PlacementStatus::kAccepted, direct.verdict == StabilityVerdict::kStronglyStable) << i;
    // The cheap weak-cone test only rejects placements that have no resting solution at all.
    if (e.status == PlacementStatus::kNotWeaklyStable) {
      EXPECT_EQ(direct.verdict, StabilityVerdict::kUnstable) << i;
      ++pruned_weak;
    }
    accepted += e.status == PlacementStatus::kAccepted;
    if (e.status == PlacementStatus::kAccepted) {
      EXPECT_GT(e.figure, 0);  // a strongly stable g has a margin
    }
  }
  EXPECT_GT(accepted, 0);
  EXPECT_GT(pruned_weak, 0);
}

TEST(DesignEvaluate, AcceptedConesAreStronglyStableInside) {
  DesignProblem p = pentagon_problem();
  p.wrenches.kind = WrenchSet::Kind::kCone;
  p.wrenches.rows = exact::Mat<geometry::Q>(2, 3);
  p.wrenches.rows << 0, -1, 0, 1, -6, 0;
  const CandidateSymmetry none;
  int accepted = 0;
  for (long i = 0; i < placement_count(8, 3); ++i) {
    const Placement pl = placement_at(i, 8, 3);
    if (evaluate_placement(p, none, pl).status != PlacementStatus::kAccepted) continue;
    ++accepted;
    for (int w : {1, 3}) {  // interior wrenches g1 + w g2 of the cone
      const exact::Vec<geometry::Q> g = (p.wrenches.rows.row(0) + w * p.wrenches.rows.row(1)).transpose();
      EXPECT_EQ(strong_stability<geometry::Q>(placement_scene(p, pl), g).verdict, StabilityVerdict::kStronglyStable)
          << i;
    }
  }
  EXPECT_GT(accepted, 0);
}

}  // namespace
TEST(DesignEvaluate, InsertableVerdictsAreTheSameWithAndWithoutEvidence) {
  DesignProblem p = pentagon_problem();
  p.insertable = true;
  for (const long pushes : {0L, 20L}) {  // without pushes every verdict comes from the arrangement
    p.pushes = pushes > 0 ? arc_length_candidates(p.workpiece.shape, pushes) : std::vector<Candidate>{};
    const CandidateSymmetry none;
    int accepted = 0, not_insertable = 0;
    for (long i = 0; i < placement_count(8, 3); ++i) {
      const Placement pl = placement_at(i, 8, 3);
      PlacementEvidence ev;
      const Evaluation fast = evaluate_placement(p, none, pl), full = evaluate_placement(p, none, pl, &ev);
      EXPECT_EQ(fast.status, full.status) << i;
      EXPECT_EQ(fast.figure, full.figure) << i;
      not_insertable += fast.status == PlacementStatus::kNotInsertable;
      if (full.status != PlacementStatus::kAccepted) continue;
      ++accepted;
      EXPECT_TRUE(insertion<geometry::Q>(placement_scene(p, pl)).in_goal(ev.goal_witness)) << i;
    }
    EXPECT_GT(accepted, 0);
    EXPECT_GT(not_insertable, 0);
  }
}

TEST(DesignEvaluate, ArrangementSignsAloneGiveTheSameCells) {
  exact::Mat<geometry::Q> normals(7, 3);  // parallel rows, three planes through one line, a zero row, fractions
  normals << 1, 0, 0, -2, 0, 0, 0, 1, 0, 1, 1, 0, geometry::Q(1, 3), -1, geometry::Q(7, 5), 0, 0, 0, 3, -5, 1;
  const auto full = geometry::sphere_arrangement<geometry::Q>(normals);
  const auto signs = geometry::sphere_arrangement<geometry::Q>(normals, {}, geometry::CellPoints::kSigns);
  ASSERT_EQ(full.cells.size(), signs.cells.size());
  for (std::size_t c = 0; c < full.cells.size(); ++c) {
    EXPECT_EQ(full.cells[c].dimension, signs.cells[c].dimension) << c;
    EXPECT_EQ(full.cells[c].signs, signs.cells[c].signs) << c;
    EXPECT_EQ(signs.cells[c].point.size(), 0) << c;
    for (Eigen::Index j = 0; j < full.planes.rows(); ++j) {  // the point's signs are the cell's
      EXPECT_EQ(exact::sign(geometry::Q(full.planes.row(j).dot(full.cells[c].point))),
                full.cells[c].signs[static_cast<std::size_t>(j)]);
    }
  }
}

TEST(DesignEvaluate, ArrangementSignsAloneGiveTheSameCellsOnRandomPlanes) {
  // Small integer normals: simple vertices (two planes, the shortcut without points) and vertices of three or more.
  std::mt19937 rng(12345);
  std::uniform_int_distribution<long> entry(-3, 3);
  auto next = [&]() { return entry(rng); };
  for (int trial = 0; trial < 40; ++trial) {
    exact::Mat<geometry::Q> normals(4 + trial % 9, 3);
    for (Eigen::Index r = 0; r < normals.rows(); ++r)
      for (Eigen::Index j = 0; j < 3; ++j) normals(r, j) = geometry::Q(next(), 1 + trial % 4);
    const auto full = geometry::sphere_arrangement<geometry::Q>(normals);
    const auto signs = geometry::sphere_arrangement<geometry::Q>(normals, {}, geometry::CellPoints::kSigns);
    ASSERT_EQ(full.cells.size(), signs.cells.size()) << trial;
    for (std::size_t c = 0; c < full.cells.size(); ++c) {
      EXPECT_EQ(full.cells[c].dimension, signs.cells[c].dimension) << trial << " " << c;
      EXPECT_EQ(full.cells[c].signs, signs.cells[c].signs) << trial << " " << c;
    }
  }
}

// f(i, scene of placement i) for every step-th placement of 3 fixels among the pentagon's 8 candidates.
template <class F>
void each_pentagon_placement(long step, F f) {
  const DesignProblem p = pentagon_problem();
  for (long i = 0; i < placement_count(8, 3); i += step) f(i, placement_scene(p, placement_at(i, 8, 3)));
}

TEST(DesignEvaluate, ModeConesFromTheOraclesTreeAreTheWalkedOnes) {
  int compared = 0;
  each_pentagon_placement(3, [&](long i, const geometry::PlanarScene& scene) {
    const StabilityOracle<geometry::Q> oracle(scene);
    const auto walked = mode_cones<geometry::Q>(scene), reused = mode_cones<geometry::Q>(scene, oracle.mode_tree());
    ASSERT_EQ(walked.modes.size(), reused.modes.size()) << i;
    for (std::size_t m = 0; m < walked.modes.size(); ++m) {
      EXPECT_EQ(walked.modes[m].text(), reused.modes[m].text()) << i;
      EXPECT_TRUE(geometry::identical(walked.cones[m], reused.cones[m])) << i;
    }
    compared += static_cast<int>(walked.modes.size());
  });
  EXPECT_GT(compared, 0);
}

TEST(DesignEvaluate, SharedInsertionConesAreTheConesOfEachPlacement) {
  const DesignProblem p = pentagon_problem();
  InsertionCones<geometry::Q> shared(40);  // small: the cache is also emptied on the way
  for (long i = 0; i < placement_count(8, 3); ++i) {
    const geometry::PlanarScene scene = placement_scene(p, placement_at(i, 8, 3));
    const auto fresh = insertion<geometry::Q>(scene), kept = insertion<geometry::Q>(scene, Route::kPaper, &shared);
    ASSERT_EQ(fresh.cones.size(), kept.cones.size());
    EXPECT_EQ(fresh.redundant, kept.redundant) << i;
    for (std::size_t c = 0; c < fresh.cones.size(); ++c) {
      EXPECT_EQ(fresh.cones[c].inequalities, kept.cones[c].inequalities) << i << " " << c;
      EXPECT_EQ(fresh.cones[c].equalities, kept.cones[c].equalities) << i << " " << c;
      EXPECT_EQ(fresh.cones[c].strict, kept.cones[c].strict) << i << " " << c;
    }
  }
}

TEST(DesignEvaluate, DeferredContainmentFindsTheRedundantConesOfTheExactTest) {
  // find_redundant (float filter, then geometry::contains) against the exact test alone, pair by pair.
  int redundant = 0;
  each_pentagon_placement(7, [&](long i, const geometry::PlanarScene& scene) {
    Insertion<geometry::Q> ins = insertion<geometry::Q>(scene, Route::kPaper, nullptr, Redundancy::kDeferred);
    EXPECT_TRUE(ins.redundant.empty());
    find_redundant(ins);
    std::vector<bool> expected(ins.cones.size(), false);
    for (std::size_t a = 0; a < ins.cones.size(); ++a) {
      const bool empty = is_empty_cone<geometry::Q>(ins.cones[a]);
      for (std::size_t b = 0; b < ins.cones.size() && !expected[a]; ++b)
        if (a != b && !expected[b] &&
            (empty || geometry::contains<geometry::Q>(ins.cones[b], ins.cones[a]).status ==
                          geometry::ContainmentStatus::kContained))
          expected[a] = true;
    }
    EXPECT_EQ(ins.redundant, expected) << i;
    redundant += static_cast<int>(std::count(expected.begin(), expected.end(), true));
  });
  EXPECT_GT(redundant, 0);
}

}  // namespace contactcert::solvers
