#include "solvers/spatial/spatial_cone_certificate.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "exact/input_error.h"
#include "exact/json_input.h"
#include "exact/strict_feasibility.h"
#include "geometry/cone_json.h"
#include "solvers/spatial/spatial_stability.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/stability/stability_certificate.h"

namespace contactcert::solvers::spatial {
namespace {

using Index = Eigen::Index;
using json = nlohmann::ordered_json;
using System = exact::SparseStrictSystem<Q>;

/// The mode's system with sigma > 0 (`open`) or sigma >= 0, g's six free columns after x's (A x - (0; g) = 0), and
/// with a row `a` one more row a . g - t = 0: t > 0 beside sigma >= 0, t >= 0 beside sigma > 0.
System with_wrench(System sys, bool open, const Vec<Q>& a = {}) {
  if (!open) sys.strict.assign(sys.strict.size(), false);
  auto column = [&](bool free, bool strict) {
    sys.is_free.push_back(free);
    sys.strict.push_back(strict);
    return sys.cols++;
  };
  const Index g = sys.cols;
  for (Index d = 0; d < 6; ++d) sys.entries.push_back({sys.rows - 6 + d, column(true, false), Q(-1)});
  if (a.size() == 0) return sys;
  for (Index d = 0; d < 6; ++d)
    if (sgn(a(d)) != 0) sys.entries.push_back({sys.rows, g + d, a(d)});
  sys.entries.push_back({sys.rows, column(false, !open), Q(-1)});
  ++sys.rows;
  return sys;
}

class Prover {
 public:
  Prover(System sys, const exact::Deadline& deadline) : sys_(std::move(sys)), deadline_(deadline) {}

  /// The Motzkin vector that a . g <= 0 on the closure (open: a . g < 0 on the cone), written sparse.
  json row(const Vec<Q>& a, bool open) {
    const exact::StrictFeasibility<Q> f = solve(with_wrench(sys_, open, a), {});
    if (f.status != exact::StrictStatus::kInfeasible)
      throw std::logic_error("spatial cone certificate: a row of the face form fails on the cone");
    return sparse_motzkin_json(f.motzkin);
  }
  json rows(const exact::Mat<Q>& M, bool open, int sign = 1) {
    json out = json::array();
    for (Index r = 0; r < M.rows(); ++r) out.push_back(row(Q(sign) * Vec<Q>(M.row(r).transpose()), open));
    return out;
  }
  /// A point x of the closure's system for g (sigma >= 0).
  json point(const Vec<Q>& g) {
    System closed = sys_;
    closed.strict.assign(closed.strict.size(), false);
    Vec<Q> b = Vec<Q>::Zero(sys_.rows);
    b.tail(6) = g;
    const exact::StrictFeasibility<Q> f = solve(closed, b);
    if (f.status != exact::StrictStatus::kFeasible)
      throw std::logic_error("spatial cone certificate: a generator of the span form is not in the cone");
    return exact_strings(f.x);
  }
  json points(const exact::Mat<Q>& M) {
    json out = json::array();
    for (Index r = 0; r < M.rows(); ++r) out.push_back(point(M.row(r).transpose()));
    return out;
  }
  /// A point x with sigma > 0 for g, or (empty cone, g empty: any g) the Motzkin vector of the rows that none exists.
  exact::StrictFeasibility<Q> strict_point(const Vec<Q>& g = {}) {
    if (g.size() == 0) return solve(with_wrench(sys_, true), {});
    Vec<Q> b = Vec<Q>::Zero(sys_.rows);
    b.tail(6) = g;
    exact::StrictFeasibility<Q> f = solve(sys_, b);
    if (f.status != exact::StrictStatus::kFeasible)
      throw std::logic_error("spatial cone certificate: a face of the face form is not in the cone");
    return f;
  }
  Index kinematic_rows() const { return sys_.rows - 6; }

 private:
  exact::StrictFeasibility<Q> solve(const System& s, const Vec<Q>& b) {
    if (deadline_.expired())
      throw exact::BudgetExceeded("cone: " + deadline_.reached_text(), "the cone, not its certificate");
    return exact::StrictSolver<Q>(s).solve(b.size() ? b : Vec<Q>::Zero(s.rows));
  }
  System sys_;
  const exact::Deadline& deadline_;
};

/// The rays of the closure on which row a vanishes, as a mask.
std::vector<bool> vanishing(const exact::Mat<Q>& rays, const Vec<Q>& a) {
  std::vector<bool> m;
  for (Index r = 0; r < rays.rows(); ++r) m.push_back(sgn(a.dot(Vec<Q>(rays.row(r).transpose()))) == 0);
  return m;
}

/// The minimal faces of the closure (by their rays) inside no open face, found from the closure down: a face is
/// minimal when each of its intersections with a closure facet lies inside an open face (or is the face itself).
/// The cone holds the relative interior of each face it meets, so a point of the cone on each of these shows that
/// it holds every point of the face form with its strict rows.
std::vector<std::vector<bool>> minimal_kept_faces(const geometry::NncForm<Q>& cone) {
  const exact::Mat<Q>& rays = cone.closure.rays;
  std::vector<std::vector<bool>> facets, open, out;
  for (Index r = 0; r < cone.closure_face.inequalities.rows(); ++r)
    facets.push_back(vanishing(rays, cone.closure_face.inequalities.row(r).transpose()));
  for (const std::vector<Index>& f : cone.open_faces) {
    open.emplace_back(static_cast<std::size_t>(rays.rows()), false);
    for (const Index r : f) open.back()[static_cast<std::size_t>(r)] = true;
  }
  auto inside = [](const std::vector<bool>& a, const std::vector<bool>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i] && !b[i]) return false;
    return true;
  };
  auto in_open = [&](const std::vector<bool>& f) {
    return std::any_of(open.begin(), open.end(), [&](const std::vector<bool>& o) { return inside(f, o); });
  };
  std::set<std::vector<bool>> seen;
  std::vector<std::vector<bool>> todo{std::vector<bool>(static_cast<std::size_t>(rays.rows()), true)};
  while (!todo.empty()) {
    std::vector<bool> face = std::move(todo.back());
    todo.pop_back();
    if (!seen.insert(face).second) continue;
    bool minimal = true;
    for (const std::vector<bool>& f : facets) {
      std::vector<bool> sub = face;
      for (std::size_t i = 0; i < sub.size(); ++i) sub[i] = sub[i] && f[i];
      if (sub == face || in_open(sub)) continue;
      minimal = false;
      todo.push_back(std::move(sub));
    }
    if (minimal) out.push_back(std::move(face));
  }
  return out;
}

}  // namespace

std::string spatial_cone_certificate(const std::string& scene_text, const geometry::SpatialScene& scene,
                                     const std::string& mode, const geometry::NncForm<Q>& cone,
                                     const exact::Deadline& deadline) {
  Prover p(spatial_motion_system(scene.body, spatial_model(scene), mode), deadline);
  json j;
  j["kind"] = "spatial_cone";
  j["mode"] = mode;
  j["cone"] = json::parse(geometry::nnc_to_json(cone).dump());
  if (cone.status == geometry::NncStatus::kEmpty) {
    // No x with sigma > 0 for any g: the free g columns give the six dynamics rows weight 0.
    const exact::StrictFeasibility<Q> f = p.strict_point();
    if (f.status != exact::StrictStatus::kInfeasible)
      throw std::logic_error("spatial cone certificate: the empty cone's mode is kinematically feasible");
    j["motzkin"] = sparse_motzkin_json(f.motzkin.head(p.kinematic_rows()));
  } else {
    const geometry::FaceCone<Q>& face = cone.face;
    j["rays"] = p.points(cone.closure.rays);
    j["lines"] = json::array();
    for (Index r = 0; r < cone.closure.lines.rows(); ++r) {
      const Vec<Q> l = cone.closure.lines.row(r).transpose();
      j["lines"].push_back({p.point(l), p.point(-l)});
    }
    j["faces"] = json::array();
    for (const std::vector<bool>& f : minimal_kept_faces(cone)) {
      Vec<Q> g = Vec<Q>::Zero(6);  // the sum of the face's rays: in its relative interior
      for (Index r = 0; r < cone.closure.rays.rows(); ++r)
        if (f[static_cast<std::size_t>(r)]) g += cone.closure.rays.row(r).transpose();
      j["faces"].push_back({{"wrench", exact_strings(g)}, {"x", exact_strings(p.strict_point(g).x)}});
    }
    j["inequalities"] = p.rows(face.inequalities, false);
    j["strict"] = p.rows(face.strict, true);
    j["equalities"] = json::array();
    const json plus = p.rows(face.equalities, false), minus = p.rows(face.equalities, false, -1);
    for (std::size_t e = 0; e < plus.size(); ++e) j["equalities"].push_back({plus[e], minus[e]});
  }
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers::spatial
