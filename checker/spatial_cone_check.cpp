#include "checker/spatial_cone_check.h"

#include <algorithm>
#include <functional>
#include <set>

#include "checker/sparse_motzkin_reader.h"
#include "checker/spatial_rows.h"
#include "exact/input_error.h"
#include "exact/linalg.h"

namespace contactcert::checker {
namespace {

using exact::Mat;
using exact::Q;
using exact::Vec;
using Index = Eigen::Index;
using namespace spatial_check;  // the checker's own reading of a body in space
using table2_check::Rows;

/// The cone as written (docs/formats.md section 4): the face form's rows, the span form's generators, the open
/// faces (rays' indices).
struct Written {
  bool empty = true;
  Mat<Q> A = Mat<Q>(0, 6), S = Mat<Q>(0, 6), E = Mat<Q>(0, 6), rays = Mat<Q>(0, 6), lines = Mat<Q>(0, 6);
  long dimension = -1;
  std::vector<std::vector<Index>> open;
};

Mat<Q> matrix(const exact::JsonInput& node, std::string_view key) {
  const exact::JsonInput m = node.at(key);
  if (!m.is_array()) m.fail("expected an array of rows of 6 numbers");
  return m.size() == 0 ? Mat<Q>(0, 6) : m.rational_matrix(std::nullopt, 6);
}

Written read_written(const exact::JsonInput& cone) {
  cone.expect_keys({"dim", "dimension", "empty", "face", "span", "closed", "open_faces"});
  cone.at("dim").integer(6, 6);
  const exact::JsonInput face = cone.at("face");
  face.at("dim").integer(6, 6);
  Written w;
  w.empty = cone.at("empty").boolean();
  if (face.at("empty").boolean() != w.empty) face.at("empty").fail(w.empty ? "expected true" : "expected false");
  if (w.empty) {
    face.expect_keys({"dim", "empty"});
    cone.expect_keys({"dim", "dimension", "empty", "face"});
    cone.at("dimension").integer(-1, -1);
    return w;
  }
  face.expect_keys({"dim", "empty", "inequalities", "strict", "equalities"});
  w.A = matrix(face, "inequalities"), w.S = matrix(face, "strict"), w.E = matrix(face, "equalities");
  const exact::JsonInput span = cone.at("span");
  span.expect_keys({"dim", "rays", "lines"});
  span.at("dim").integer(6, 6);
  w.rays = matrix(span, "rays"), w.lines = matrix(span, "lines");
  w.dimension = cone.at("dimension").integer(0, 6);
  for (const exact::JsonInput& f : cone.at("open_faces").elements()) {
    std::vector<Index> rays;
    for (const exact::JsonInput& r : f.elements()) rays.push_back(r.integer(0, static_cast<long>(w.rays.rows()) - 1));
    w.open.push_back(std::move(rays));
  }
  if (cone.at("closed").boolean() != w.open.empty()) cone.at("closed").fail("expected closed = no open faces");
  return w;
}

Vec<Q> row(const Mat<Q>& M, Index r) { return M.row(r).transpose(); }

/// The rows `pick` of M, then every row of below.
Mat<Q> stacked(const Mat<Q>& M, const std::vector<Index>& pick, const Mat<Q>& below) {
  Mat<Q> out(static_cast<Index>(pick.size()) + below.rows(), 6);
  for (std::size_t i = 0; i < pick.size(); ++i) out.row(static_cast<Index>(i)) = M.row(pick[i]);
  for (Index i = 0; i < below.rows(); ++i) out.row(static_cast<Index>(pick.size()) + i) = below.row(i);
  return out;
}

/// 0, 1, ..., n - 1.
std::vector<Index> first(Index n) {
  std::vector<Index> v(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = i;
  return v;
}

Index rank_of(const Mat<Q>& M) { return M.rows() == 0 ? 0 : exact::rank(M); }

/// The rays on which the row a . g vanishes.
std::vector<Index> tight(const Mat<Q>& rays, const Vec<Q>& a) {
  std::vector<Index> t;
  for (Index r = 0; r < rays.rows(); ++r)
    if (sgn(a.dot(row(rays, r))) == 0) t.push_back(r);
  return t;
}

/// Why some generator breaks a row of the face form, or "".
std::string generators_fault(const Written& w) {
  const std::pair<const Mat<Q>*, const char*> forms[] = {
      {&w.A, "inequality"}, {&w.S, "strict row"}, {&w.E, "equality"}};
  for (const auto& [M, name] : forms)
    for (Index i = 0; i < M->rows(); ++i) {
      for (Index r = 0; r < w.rays.rows(); ++r)
        if (const int s = sgn(row(*M, i).dot(row(w.rays, r))); s > 0 || (s < 0 && M == &w.E))
          return "ray " + std::to_string(r) + " breaks " + name + " " + std::to_string(i);
      for (Index l = 0; l < w.lines.rows(); ++l)
        if (sgn(row(*M, i).dot(row(w.lines, l))) != 0)
          return "line " + std::to_string(l) + " breaks " + name + " " + std::to_string(i);
    }
  return {};
}

/// The subsets of rays that the facet enumeration visits at most (each a rank of at most 6 rows).
constexpr long kMaxSubsets = 4'000'000;

/// Why pos(rays) + span(lines) has a facet that no row of the face form is tight on, or "": every p = D - 1 - l
/// rays that with the lines span D - 1 dimensions (chosen in index order, each raising the rank) span, with the
/// lines, a hyperplane of the generators' span, whose normal h there is orthogonal to them and to the equalities; it
/// is a facet iff no ray lies strictly on one side of h while another lies strictly on the other.
std::string missing_facet(const Written& w, Index D) {
  const Index l = w.lines.rows(), p = D - 1 - l;
  if (p < 0) return {};
  const Mat<Q> lines_and_E = stacked(w.lines, first(l), w.E);
  std::vector<Index> chosen;
  long visited = 0;
  std::string fault;
  std::function<void(Index)> extend = [&](Index from) {
    if (!fault.empty()) return;
    if (++visited > kMaxSubsets)  // no verdict: a limit (exit 3), not an invalid certificate
      throw exact::BudgetExceeded("spatial cone check: over " + std::to_string(kMaxSubsets) +
                                      " subsets of rays in the facet enumeration",
                                  "every row and generator verified; the facets of " +
                                      std::to_string(w.rays.rows()) + " rays not all enumerated");
    if (static_cast<Index>(chosen.size()) == p) {
      const Mat<Q> N = exact::null_space(stacked(w.rays, chosen, lines_and_E));
      if (N.cols() != 1) {
        fault = "the equalities are not independent of the generators";
        return;
      }
      bool above = false, below = false;
      for (Index r = 0; r < w.rays.rows(); ++r) {
        const int s = sgn(N.col(0).dot(row(w.rays, r)));
        above = above || s > 0, below = below || s < 0;
      }
      if (above && below) return;  // not a supporting hyperplane
      for (const Mat<Q>* M : {&w.A, &w.S})
        for (Index i = 0; i < M->rows(); ++i) {
          const std::vector<Index> t = tight(w.rays, row(*M, i));
          if (std::includes(t.begin(), t.end(), chosen.begin(), chosen.end())) return;
        }
      fault = "the facet of the span form through rays";
      for (const Index r : chosen) fault += " " + std::to_string(r);
      fault +=
          (chosen.empty() ? " (none) and the lines" : " and the lines") + std::string(" is no row of the face form");
      return;
    }
    for (Index r = from; r < w.rays.rows() && fault.empty(); ++r) {
      chosen.push_back(r);
      if (rank_of(stacked(w.rays, chosen, w.lines)) == l + static_cast<Index>(chosen.size())) extend(r + 1);
      chosen.pop_back();
    }
  };
  extend(0);
  return fault;
}

/// Why the written forms are not one cone, pos(rays) + span(lines) = { A, S <= 0, E = 0 } of the written dimension
/// with its inequalities facets and its open faces the strict rows' tight rays, or "".
std::string forms_fault(const Written& w) {
  if (std::string why = generators_fault(w); !why.empty()) return why;
  const Index l = w.lines.rows(), D = rank_of(stacked(w.rays, first(w.rays.rows()), w.lines));
  if (D != w.dimension) return "the generators span dimension " + std::to_string(D) + ", not the written dimension";
  if (rank_of(w.lines) != l) return "the lines are not independent";
  if (rank_of(w.E) != w.E.rows() || w.E.rows() + D != 6)
    return "the equalities are not a basis of the complement of the generators' span";
  for (Index i = 0; i < w.A.rows(); ++i)
    if (rank_of(stacked(w.rays, tight(w.rays, row(w.A, i)), w.lines)) != D - 1)
      return "inequality " + std::to_string(i) + " is not a facet (tight on generators of rank other than " +
             std::to_string(D - 1) + ")";
  std::vector<std::vector<Index>> strict_faces, open = w.open;
  for (Index i = 0; i < w.S.rows(); ++i) {
    strict_faces.push_back(tight(w.rays, row(w.S, i)));
    if (static_cast<Index>(strict_faces.back().size()) == w.rays.rows())
      return "strict row " + std::to_string(i) + " vanishes on the whole closure";
  }
  if (std::string why = missing_facet(w, D); !why.empty()) return why;
  for (auto& f : open) std::sort(f.begin(), f.end());
  std::sort(open.begin(), open.end());
  std::sort(strict_faces.begin(), strict_faces.end());
  if (open != strict_faces) return "the open faces are not the rays the strict rows are tight on";
  return {};
}

/// Whether x solves the rows for the right-hand side (0; g) with the rows' signs.
bool solves(const Rows& R, const Vec<Q>& x, const Vec<Q>& g) {
  for (std::size_t j = 0; j < R.columns.size(); ++j) {
    const int s = sgn(x(static_cast<Index>(j)));
    if ((R.columns[j] == Rows::Sign::kNonNegative && s < 0) || (R.columns[j] == Rows::Sign::kPositive && s <= 0))
      return false;
  }
  const std::size_t first = R.rows.size() - 6;
  for (std::size_t i = 0; i < R.rows.size(); ++i) {
    Q sum = i < first ? Q(0) : Q(-g(static_cast<Index>(i - first)));
    for (const Rows::Entry& e : R.rows[i]) sum += e.value * x(static_cast<Index>(e.col));
    if (sgn(sum) != 0) return false;
  }
  return true;
}

/// The closure's rows: sigma >= 0 in place of sigma > 0.
Rows closed(Rows R) {
  for (Rows::Sign& c : R.columns)
    if (c == Rows::Sign::kPositive) c = Rows::Sign::kNonNegative;
  return R;
}

/// The mode's rows with g free, A x - (0; g) = 0 (g's six columns after x's), and one more row a . g - t = 0;
/// `open`: sigma > 0 and t >= 0 (infeasible iff a . g < 0 on the cone), else sigma >= 0 and t > 0 (iff a . g <= 0 on
/// the closure).
Rows with_wrench(const Rows& mode_rows, bool open, const Vec<Q>& a) {
  Rows R = open ? mode_rows : closed(mode_rows);
  const std::size_t first = R.rows.size() - 6, g = R.columns.size();
  for (std::size_t d = 0; d < 6; ++d) {
    R.columns.push_back(Rows::Sign::kFree);
    R.rows[first + d].push_back({g + d, Q(-1)});
  }
  R.rows.emplace_back();
  for (std::size_t d = 0; d < 6; ++d)
    if (sgn(a(static_cast<Index>(d))) != 0) R.rows.back().push_back({g + d, a(static_cast<Index>(d))});
  R.columns.push_back(open ? Rows::Sign::kNonNegative : Rows::Sign::kPositive);
  R.rows.back().push_back({g + 6, Q(-1)});
  R.b = Vec<Q>();  // zero
  return R;
}

/// Why a row's proofs (one per row of M; `pairs`: two per row, for a and -a) fail, or "".
std::string proofs_fault(const Rows& mode_rows, const Mat<Q>& M, const exact::JsonInput& proofs, bool open, bool pairs,
                         const char* name) {
  if (proofs.size() != static_cast<std::size_t>(M.rows()))
    proofs.fail("expected one proof per " + std::string(name) + " (" + std::to_string(M.rows()) + ")");
  for (Index i = 0; i < M.rows(); ++i) {
    const exact::JsonInput p = proofs.at(static_cast<std::size_t>(i));
    if (pairs && p.size() != 2) p.fail("expected two proofs: for e . g <= 0 and for -e . g <= 0");
    for (std::size_t k = 0; k < (pairs ? 2u : 1u); ++k) {
      const Rows R = with_wrench(mode_rows, open, (k == 0 ? Q(1) : Q(-1)) * row(M, i));
      if (!table2_check::motzkin_holds(R, read_sparse_motzkin(pairs ? p.at(k) : p, R.rows.size())))
        return std::string("the proof of ") + name + " " + std::to_string(i) + " does not verify";
    }
  }
  return {};
}

/// Why a generator's points (one per row of M; `pairs`: for the line and its opposite) are not in the closure.
std::string points_fault(const Rows& mode_rows, const Mat<Q>& M, const exact::JsonInput& points, bool pairs,
                         const char* name) {
  if (points.size() != static_cast<std::size_t>(M.rows()))
    points.fail("expected one point per " + std::string(name) + " (" + std::to_string(M.rows()) + ")");
  const Rows R = closed(mode_rows);
  for (Index i = 0; i < M.rows(); ++i) {
    const exact::JsonInput p = points.at(static_cast<std::size_t>(i));
    if (pairs && p.size() != 2) p.fail("expected two points: for the line and its opposite");
    for (std::size_t k = 0; k < (pairs ? 2u : 1u); ++k)
      if (!solves(R, (pairs ? p.at(k) : p).rational_vector(R.columns.size()), (k == 0 ? Q(1) : Q(-1)) * row(M, i)))
        return std::string("the point of ") + name + " " + std::to_string(i) + " is not a solution of the mode";
  }
  return {};
}

/// The faces of the closure (by their rays' indices) that lie in no strict row's hyperplane and contain no other
/// such face: every face of pos(rays) + span(lines) is the closure or an intersection of facets, all of which are
/// written rows (forms_fault), so the faces are the closure of {all rays} under intersection with the rows' tight
/// sets. exact::BudgetExceeded past kMaxFaces.
constexpr std::size_t kMaxFaces = 200'000;
std::vector<std::set<Index>> minimal_faces(const Written& w) {
  std::vector<std::set<Index>> rows, strict, faces, out;
  for (const Mat<Q>* M : {&w.A, &w.S})
    for (Index i = 0; i < M->rows(); ++i) {
      const std::vector<Index> t = tight(w.rays, row(*M, i));
      rows.emplace_back(t.begin(), t.end());
      if (M == &w.S) strict.push_back(rows.back());
    }
  std::set<std::set<Index>> known;
  std::set<Index> all;
  for (Index r = 0; r < w.rays.rows(); ++r) all.insert(r);
  faces.push_back(all);
  known.insert(all);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (const std::set<Index>& t : rows) {
      std::set<Index> f;
      std::set_intersection(faces[i].begin(), faces[i].end(), t.begin(), t.end(), std::inserter(f, f.end()));
      if (!known.insert(f).second) continue;
      if (faces.size() == kMaxFaces)  // no verdict: a limit (exit 3), not an invalid certificate
        throw exact::BudgetExceeded(
            "spatial cone check: the closure has more than " + std::to_string(kMaxFaces) + " faces",
            "both forms verified equal; the faces that no strict row vanishes on not all enumerated");
      faces.push_back(std::move(f));
    }
  auto kept = [&](const std::set<Index>& f) {
    return std::none_of(strict.begin(), strict.end(), [&](const std::set<Index>& s) {
      return std::includes(s.begin(), s.end(), f.begin(), f.end());
    });
  };
  // A kept face with a kept proper face has one among its intersections with the rows (the facets through the
  // smaller face do not all contain it), and a face holding a kept face is kept.
  for (const std::set<Index>& f : faces) {
    if (!kept(f)) continue;
    const bool minimal = std::none_of(rows.begin(), rows.end(), [&](const std::set<Index>& t) {
      std::set<Index> g;
      std::set_intersection(f.begin(), f.end(), t.begin(), t.end(), std::inserter(g, g.end()));
      return g.size() < f.size() && kept(g);
    });
    if (minimal) out.push_back(f);
  }
  return out;
}

/// Why the points "faces" do not show every point of the face form with its strict rows in the cone, or "": each
/// is a point of the cone (sigma > 0), and each minimal face of the closure in no strict row's hyperplane holds one
/// (every row that vanishes on the face's rays vanishes on it). The cone holds the relative interior of each face of
/// the closure that it meets, and each point of the face form lies in the relative interior of a face that no strict
/// row vanishes on, which contains a minimal one.
std::string faces_fault(const Written& w, const Rows& mode_rows, const exact::JsonInput& points) {
  std::vector<Vec<Q>> g;
  for (const exact::JsonInput& p : points.elements()) {
    p.expect_keys({"wrench", "x"});
    g.push_back(p.at("wrench").rational_vector(6));
    if (!solves(mode_rows, p.at("x").rational_vector(mode_rows.columns.size()), g.back()))
      return "the point of face " + std::to_string(g.size() - 1) + " is not a solution of the mode with sigma > 0";
  }
  for (const std::set<Index>& f : minimal_faces(w)) {
    const bool met = std::any_of(g.begin(), g.end(), [&](const Vec<Q>& p) {
      for (const Mat<Q>* M : {&w.A, &w.S})
        for (Index i = 0; i < M->rows(); ++i) {
          const std::vector<Index> t = tight(w.rays, row(*M, i));
          if (std::includes(t.begin(), t.end(), f.begin(), f.end()) && sgn(row(*M, i).dot(p)) != 0) return false;
        }
      return true;
    });
    if (!met) {
      std::string fault = "no point of the cone is given on the face of the closure through rays";
      for (const Index r : f) fault += " " + std::to_string(r);
      return fault + (f.empty() ? " (none): the lineality space" : "") + ", which no strict row vanishes on";
    }
  }
  return {};
}

}  // namespace

SpatialConeCheck check_spatial_cone_certificate(const exact::JsonInput& c) {
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const geometry::SpatialScene scene = geometry::read_spatial_scene(embedded);
  const std::vector<Seen> cs = seen(scene);
  const Written w = read_written(c.at("cone"));
  if (w.empty)
    c.expect_keys({"kind", "mode", "cone", "motzkin", "scene", "problem_sha256"});
  else
    c.expect_keys({"kind", "mode", "cone", "rays", "lines", "faces", "inequalities", "strict", "equalities", "scene",
                   "problem_sha256"});
  if (c.at("problem_sha256").string() != embedded.canonical_sha256())
    return {false, "problem_sha256 is not the digest of the embedded scene"};
  if (const std::string fault = frame_fault(cs); !fault.empty()) return {false, fault};
  const std::string mode = read_letters(c.at("mode"), cs, true);
  if (w.empty) {
    const Rows kinematic = prefix_rows(cs, mode);
    if (!table2_check::motzkin_holds(kinematic, read_sparse_motzkin(c.at("motzkin"), kinematic.rows.size())))
      return {false, "the Motzkin vector does not prove mode " + mode + " kinematically infeasible"};
    return {true, "the Motzkin vector proves that no acceleration realises mode " + mode + ": its cone is empty"};
  }
  if (std::string why = forms_fault(w); !why.empty()) return {false, "the written cone: " + why};
  const Rows rows = motion_rows(scene.body, cs, mode, Vec<Q>::Zero(6), false);
  std::string why = points_fault(rows, w.rays, c.at("rays"), false, "ray");
  if (why.empty()) why = points_fault(rows, w.lines, c.at("lines"), true, "line");
  if (why.empty()) why = proofs_fault(rows, w.A, c.at("inequalities"), false, false, "inequality");
  if (why.empty()) why = proofs_fault(rows, w.S, c.at("strict"), true, false, "strict row");
  if (why.empty()) why = proofs_fault(rows, w.E, c.at("equalities"), false, true, "equality");
  if (!why.empty()) return {false, why};
  if (std::string why = faces_fault(w, rows, c.at("faces")); !why.empty()) return {false, why};
  SpatialConeCheck out{true, "mode " + mode + "'s cone is the written cone: its closure in both forms, the cone " +
                                 "its face form with the strict rows"};
  out.dimension = w.dimension;
  out.rays = static_cast<long>(w.rays.rows()), out.lines = static_cast<long>(w.lines.rows());
  out.inequalities = static_cast<long>(w.A.rows()), out.strict = static_cast<long>(w.S.rows());
  return out;
}

}  // namespace contactcert::checker
