#include "geometry/set_ops.h"

#include <algorithm>
#include <type_traits>
#include <vector>

#include "geometry/canonical.h"

namespace contactcert::geometry {
namespace {

using Index = Eigen::Index;
using exact::is_zero;
using exact::sign;

template <class T>
Mat<T> stack(const Mat<T>& a, const Mat<T>& b, Index dim) {
  Mat<T> M(a.rows() + b.rows(), dim);
  for (Index i = 0; i < a.rows(); ++i) M.row(i) = a.row(i);
  for (Index i = 0; i < b.rows(); ++i) M.row(a.rows() + i) = b.row(i);
  return M;
}

// A point of the cone near v (v in its closure, c in the cone) that still has f . w > 0, given f . v > 0:
// w = v + t c is in the cone for every t > 0 (segment from a closure point to a point of the cone).
template <class T>
Vec<T> push_inside(const Vec<T>& v, const Vec<T>& c, const Vec<T>& f) {
  const T fv = f.dot(v), fc = f.dot(c);
  const T t = sign(fc) < 0 ? T(fv / (T(-2) * fc)) : T(1);
  return v + t * c;
}

// A row of `outer` (non-strict reading) that v (or, for a line, v or -v) violates, as a normal f with
// f . v' > 0 for the violating v' = +-v.
template <class T>
bool violated_row(const FaceCone<T>& outer, const Vec<T>& v, bool is_line, Vec<T>& f) {
  for (Index i = 0; i < outer.equalities.rows(); ++i) {
    const int s = dot_sign(outer.equalities, i, v);
    if (s != 0) {
      f = s > 0 ? Vec<T>(outer.equalities.row(i).transpose()) : Vec<T>(-outer.equalities.row(i).transpose());
      return true;
    }
  }
  for (const Mat<T>* M : {&outer.inequalities, &outer.strict})
    for (Index i = 0; i < M->rows(); ++i) {
      const int s = dot_sign(*M, i, v);
      if (s > 0 || (is_line && s < 0)) {  // a line violates the row on one side (-v when s < 0)
        f = M->row(i).transpose();
        return true;
      }
    }
  return false;
}

}  // namespace

template <class T>
FaceCone<T> intersection(const FaceCone<T>& a, const FaceCone<T>& b) {
  const Index d = a.dim;
  return FaceCone<T>::from_rows(d, stack<T>(a.inequalities, b.inequalities, d), stack<T>(a.equalities, b.equalities, d),
                                stack<T>(a.strict, b.strict, d));
}

template <class T>
Containment<T> contains(const FaceCone<T>& outer, const FaceCone<T>& inner, const DdBudget& budget) {
  return contains(outer, inner, nnc_form(inner, budget));
}

template <class T>
Containment<T> contains(const FaceCone<T>& outer, const FaceCone<T>& inner, const NncForm<T>& in) {
  Containment<T> out;
  if (in.status == NncStatus::kEmpty) return out;
  const Index d = inner.dim;
  const Mat<T>& R = in.closure.rays;
  // c: a relative interior point of inner's closure, which lies in inner (every face it is
  // relatively interior to is the whole closure, which is in inner when inner is not empty).
  Vec<T> c = Vec<T>::Zero(d);
  for (Index r = 0; r < R.rows(); ++r) c += R.row(r).transpose();
  if (!contains_point(outer, c)) {
    out.status = ContainmentStatus::kNotContained;
    out.witness = c;
    return out;
  }
  // Closure of inner inside the closure of outer (generator by generator).
  Vec<T> f;
  for (Index r = 0; r < R.rows(); ++r)
    if (violated_row<T>(outer, R.row(r).transpose(), false, f)) {
      out.status = ContainmentStatus::kNotContained;
      out.witness = push_inside<T>(R.row(r).transpose(), c, f);
      return out;
    }
  for (Index l = 0; l < in.closure.lines.rows(); ++l)
    if (violated_row<T>(outer, in.closure.lines.row(l).transpose(), true, f)) {
      const Vec<T> v = sign(T(f.dot(in.closure.lines.row(l).transpose()))) > 0
                           ? Vec<T>(in.closure.lines.row(l).transpose())
                           : Vec<T>(-in.closure.lines.row(l).transpose());
      out.status = ContainmentStatus::kNotContained;
      out.witness = push_inside<T>(v, c, f);
      return out;
    }
  // Each strict row s of outer vanishes on a face Z of inner's closure; Z must be missing from inner.
  for (Index s = 0; s < outer.strict.rows(); ++s) {
    std::vector<Index> Z;
    for (Index r = 0; r < R.rows(); ++r)
      if (is_zero(T(outer.strict.row(s).dot(R.row(r))))) Z.push_back(r);
    bool missing = false;
    for (const auto& open : in.open_faces) {
      bool inside = true;
      for (Index r : Z) inside = inside && std::find(open.begin(), open.end(), r) != open.end();
      if (inside) missing = true;
    }
    if (!missing) {
      Vec<T> w = Vec<T>::Zero(d);
      for (Index r : Z) w += R.row(r).transpose();
      out.status = ContainmentStatus::kNotContained;
      out.witness = w;
      return out;
    }
  }
  return out;
}

template <class T>
bool equal(const FaceCone<T>& a, const FaceCone<T>& b, const DdBudget& budget) {
  if (a.dim != b.dim) return false;
  if constexpr (std::is_same_v<T, Q>) {
    return identical(nnc_form(a, budget).face, nnc_form(b, budget).face);
  } else {
    return contains(a, b, budget).status == ContainmentStatus::kContained &&
           contains(b, a, budget).status == ContainmentStatus::kContained;
  }
}

#define CONTACTCERT_SETOPS_INSTANTIATE(T)                                                         \
  template FaceCone<T> intersection<T>(const FaceCone<T>&, const FaceCone<T>&);                   \
  template Containment<T> contains<T>(const FaceCone<T>&, const FaceCone<T>&, const DdBudget&);   \
  template Containment<T> contains<T>(const FaceCone<T>&, const FaceCone<T>&, const NncForm<T>&); \
  template bool equal<T>(const FaceCone<T>&, const FaceCone<T>&, const DdBudget&);
CONTACTCERT_SETOPS_INSTANTIATE(double)
CONTACTCERT_SETOPS_INSTANTIATE(Q)
#undef CONTACTCERT_SETOPS_INSTANTIATE

}  // namespace contactcert::geometry
