#include "solvers/design/evaluate.h"

#include <optional>

#include "geometry/double_description.h"
#include "geometry/set_ops.h"
#include "geometry/sphere_arrangement.h"
#include "solvers/insertion/insertion.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/stable_region.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::solvers {
namespace {

using exact::Mat;
using exact::Q;
using exact::Vec;

/// Does pos(generators) meet the cone at a point other than 0?
bool meets_beyond_origin(const geometry::FaceCone<Q>& generated, const geometry::FaceCone<Q>& cone) {
  const geometry::NncForm<Q> both = geometry::nnc_form<Q>(geometry::intersection<Q>(generated, cone));
  return both.status == geometry::NncStatus::kNonEmpty && both.dimension() > 0;
}

/// Is g in cone? Read off the signs of g at the arrangement's planes: rows [r, ...) of the arrangement's input
/// are the cone's inequalities, equalities and strict rows (cone_rows' order); r moves past them.
bool in_cone(const geometry::FaceCone<Q>& cone, const geometry::SphereArrangement<Q>& arrangement,
             const std::vector<int>& signs, std::size_t& r) {
  bool inside = true;
  auto row_sign = [&]() {
    const Eigen::Index j = arrangement.row_plane[r];
    const int s = j < 0 ? 0 : arrangement.row_orientation[r] * signs[static_cast<std::size_t>(j)];
    ++r;
    return s;
  };
  for (Eigen::Index i = 0; i < cone.inequalities.rows(); ++i) inside = row_sign() <= 0 && inside;
  for (Eigen::Index i = 0; i < cone.equalities.rows(); ++i) inside = row_sign() == 0 && inside;
  for (Eigen::Index i = 0; i < cone.strict.rows(); ++i) inside = row_sign() < 0 && inside;
  return inside;
}

/// Is G_goal (the complement of the union of the insertion cones) non-empty? G_goal is a union of cells of the
/// arrangement of the cones' planes, so one point per cell decides it, by the cell's signs (the cones contained in
/// another, left out of the arrangement, add no point to the union). With `witness`, the point of the first such
/// cell, highest dimension first. Runs the containment pass if insertion() left it.
bool goal_nonempty(Insertion<Q>& ins, Vec<Q>* witness) {
  // A cone of no rows is all of R^3: it covers every cell.
  for (const auto& c : ins.cones)
    if (c.inequalities.rows() + c.equalities.rows() + c.strict.rows() == 0 && !is_empty_cone<Q>(c)) return false;
  if (ins.redundant.empty()) find_redundant(ins);
  std::vector<const geometry::FaceCone<Q>*> cones;
  for (std::size_t i = 0; i < ins.cones.size(); ++i)
    if (!ins.redundant[i] && !is_empty_cone<Q>(ins.cones[i])) cones.push_back(&ins.cones[i]);
  const std::vector<Vec<Q>> rows = cone_rows<Q>(cones);
  Mat<Q> normals(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t r = 0; r < rows.size(); ++r) normals.row(static_cast<Eigen::Index>(r)) = rows[r].transpose();
  const auto arrangement = geometry::sphere_arrangement<Q>(
      normals, {}, witness ? geometry::CellPoints::kPoints : geometry::CellPoints::kSigns);
  for (int dimension = 3; dimension >= 1; --dimension)
    for (const auto& cell : arrangement.cells) {
      if (cell.dimension != dimension) continue;
      std::size_t r = 0;
      bool in_goal = true;
      for (const auto* c : cones) in_goal = !in_cone(*c, arrangement, cell.signs, r) && in_goal;
      if (!in_goal) continue;
      if (witness) *witness = cell.point;
      return true;
    }
  return false;
}

Vec<Q> row_vector(const Mat<Q>& M, Eigen::Index r) { return M.row(r).transpose(); }

}  // namespace

const char* placement_status_name(PlacementStatus s) {
  switch (s) {
    case PlacementStatus::kAccepted:
      return "accepted";
    case PlacementStatus::kSymmetricDuplicate:
      return "symmetric_duplicate";
    case PlacementStatus::kNotWeaklyStable:
      return "not_weakly_stable";
    case PlacementStatus::kNotStronglyStable:
      return "not_strongly_stable";
    case PlacementStatus::kConeMeetsMovingMode:
      return "cone_meets_moving_mode";
    case PlacementStatus::kNotInsertable:
      return "not_insertable";
    case PlacementStatus::kGoalMissesWrench:
      return "goal_misses_wrench";
    case PlacementStatus::kNoPushInGoal:
      return "no_push_in_goal";
  }
  return "?";
}

Evaluation evaluate_placement(const DesignProblem& problem, const CandidateSymmetry& symmetry,
                              const Placement& placement, PlacementEvidence* evidence, InsertionCones<Q>* cones) {
  Evaluation out;
  auto reject = [&](PlacementStatus s) {
    out.status = s;
    return out;
  };
  if (!symmetry.is_canonical(placement)) return reject(PlacementStatus::kSymmetricDuplicate);
  const geometry::PlanarScene scene = placement_scene(problem, placement);
  const Mat<Q>& W = problem.wrenches.rows;
  const bool stable_under = problem.wrenches.kind != WrenchSet::Kind::kNone;
  std::optional<StabilityOracle<Q>> oracle;  // its mode tree also gives the moving modes' cones
  std::optional<StableRegion<Q>> region;     // the moving modes' cones, for a cone of wrenches and the margin
  if (stable_under) {
    const geometry::FaceCone<Q> weak = weakly_stable_cone<Q>(scene);
    for (Eigen::Index r = 0; r < W.rows(); ++r)
      if (!geometry::contains_point<Q>(weak, row_vector(W, r))) return reject(PlacementStatus::kNotWeaklyStable);
    oracle.emplace(scene, StabilityOptions{exact::Arith::kVerified});
    out.lps += oracle->preparation_lps();
    for (Eigen::Index r = 0; r < W.rows(); ++r) {
      StabilityResult<Q> v = oracle->verdict(row_vector(W, r));
      out.lps += v.lps;
      if (v.verdict != StabilityVerdict::kStronglyStable) return reject(PlacementStatus::kNotStronglyStable);
      if (evidence) evidence->stability.push_back(std::move(v));
    }
    if (problem.wrenches.kind == WrenchSet::Kind::kCone) {
      region = mode_cones<Q>(scene, oracle->mode_tree());
      const geometry::FaceCone<Q> generated =
          geometry::to_face<Q>(geometry::SpanCone<Q>::from_rows(3, W, Mat<Q>(0, 3)));
      for (const auto& c : region->cones)
        if (meets_beyond_origin(generated, c)) return reject(PlacementStatus::kConeMeetsMovingMode);
    }
  }
  if (problem.insertable) {
    Insertion<Q> ins = insertion<Q>(scene, Route::kPaper, cones, Redundancy::kDeferred);
    long in_goal = 0, first = -1;
    Vec<Q> push_witness;
    for (std::size_t i = 0; i < problem.pushes.size(); ++i) {
      const Candidate& c = problem.pushes[i];
      Vec<Q> p(2), n(2);
      p << c.point.x, c.point.y;
      n << c.normal.x, c.normal.y;
      const Vec<Q> g = push_wrench<Q>(problem.workpiece.com, p, n);
      if (!ins.in_goal(g)) continue;
      if (in_goal++ == 0) {
        push_witness = g;
        first = static_cast<long>(i);
      }
    }
    const bool wrench_in_goal = problem.goal_wrench.size() > 0 && ins.in_goal(problem.goal_wrench);
    // G_goal != {}: a push or the required wrench in it shows it; otherwise a cell of the arrangement decides
    // (and gives the witness the evidence shows when no push is in G_goal).
    Vec<Q> witness;
    if (in_goal == 0 && (evidence || !wrench_in_goal) && !goal_nonempty(ins, evidence ? &witness : nullptr))
      return reject(PlacementStatus::kNotInsertable);
    if (problem.goal_wrench.size() > 0 && !wrench_in_goal) return reject(PlacementStatus::kGoalMissesWrench);
    if (problem.goal_push && in_goal == 0) return reject(PlacementStatus::kNoPushInGoal);
    if (problem.rank == Rank::kGoalFraction) {
      out.figure = Q(in_goal, static_cast<long>(problem.pushes.size()));
      out.figure.canonicalize();
    }
    if (evidence) {
      evidence->goal_witness = in_goal > 0 ? push_witness : witness;  // a finger push reads better
      evidence->goal_pushes = in_goal;
      evidence->goal_push_point = first;
    }
  }
  // The margin last: it rejects nothing, so a placement rejected above needs none.
  if (stable_under && problem.rank == Rank::kMargin) {
    if (!region) region = mode_cones<Q>(scene, oracle->mode_tree());
    for (Eigen::Index r = 0; r < W.rows(); ++r) {
      const Margin<Q> m = stability_margin<Q>(*region, row_vector(W, r));
      if (r == 0 || m.squared_radius < out.figure) out.figure = m.squared_radius;
      if (evidence) evidence->margins.push_back(m);
    }
  }
  return out;
}

}  // namespace contactcert::solvers
