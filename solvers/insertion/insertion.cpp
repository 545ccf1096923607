#include "solvers/insertion/insertion.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "exact/input_error.h"
#include "geometry/nnc_cone.h"
#include "geometry/set_ops.h"

namespace contactcert::solvers {

std::string InsertionSet::state_text() const {
  std::string s;
  for (bool b : state) s += b ? '1' : '0';
  return s;
}

namespace {

InsertionSet set_of(const char* state, const char* mode) {
  InsertionSet s;
  for (const char* c = state; *c; ++c) s.state.push_back(*c == '1');
  for (const char* c = mode; *c; ++c) s.mode.letters.push_back(static_cast<Interaction>(*c));
  return s;
}

}  // namespace

std::vector<InsertionSet> insertion_sets(std::size_t fixels) {
  if (fixels == 2)  // eq. (21): G_goal = complement of (G_su u G_us u G_sm u G_ms)
    return {set_of("10", "su"), set_of("10", "ms"), set_of("01", "us"), set_of("01", "sm")};
  if (fixels == 3)  // Table 5 (its state 111 row lists "mss" twice; the second is ssm by symmetry)
    return {set_of("000", "sss"), set_of("100", "suu"), set_of("100", "mss"), set_of("010", "usu"),
            set_of("010", "sms"), set_of("001", "uus"), set_of("001", "ssm"), set_of("110", "ssu"),
            set_of("110", "msu"), set_of("110", "smu"), set_of("110", "mms"), set_of("101", "sus"),
            set_of("101", "mus"), set_of("101", "sum"), set_of("101", "msm"), set_of("011", "uss"),
            set_of("011", "ums"), set_of("011", "usm"), set_of("011", "smm"), set_of("111", "sss"),
            set_of("111", "mss"), set_of("111", "sms"), set_of("111", "ssm"), set_of("111", "mms"),
            set_of("111", "smm"), set_of("111", "msm")};
  return {};
}

geometry::PlanarScene scene_in_state(const geometry::PlanarScene& goal, const std::vector<bool>& touching) {
  geometry::PlanarScene s = goal;
  for (std::size_t i = 0; i < s.fixels.size(); ++i)
    if (!touching[i]) s.fixels[i].frame.gap_squared = 1;  // any positive gap: only touching() is read
  return s;
}

template <class T>
bool Insertion<T>::in_goal(const Vec<T>& g) const {
  for (const auto& c : cones)
    if (geometry::contains_point<T>(c, g)) return false;
  return true;
}

namespace {

/// G of one set in the goal scene: the wrench cone of the set's mode in the set's contact state.
template <class T>
geometry::FaceCone<T> set_cone(const geometry::PlanarScene& goal, const InsertionSet& set, Route route) {
  const geometry::PlanarScene s = scene_in_state(goal, set.state);
  return wrench_cone_face<T>(s, contact_model<T>(s), set.mode, route);
}

bool unconstrained(Interaction letter) { return letter == Interaction::kUnconstrained; }

}  // namespace

template <class T>
const SetCone<T>& InsertionCones<T>::cone(const geometry::PlanarScene& goal, std::size_t index, const InsertionSet& set,
                                          Route route) {
  std::vector<Q> key{Q(static_cast<long>(index)), Q(static_cast<int>(route))};
  for (std::size_t i = 0; i < goal.fixels.size(); ++i) {
    if (unconstrained(set.mode.letters[i])) continue;
    const geometry::Fixel& f = goal.fixels[i];
    key.insert(key.end(), {f.frame.point.x, f.frame.point.y, f.frame.normal.x, f.frame.normal.y, f.mu_s, f.mu_k});
  }
  const auto known = cones_.find(key);
  if (known != cones_.end()) return known->second;
  if (cones_.size() >= capacity_) cones_.clear();
  SetCone<T> c{set_cone<T>(goal, set, route), std::nullopt};
  if (!is_empty_cone<T>(c.cone)) c.form = geometry::nnc_form<T>(c.cone);
  return cones_.emplace(std::move(key), std::move(c)).first->second;
}

namespace {

// A float filter for "c is not in the cone" (the first test of geometry::contains, c the sum of the inner cone's
// closure rays): rows and point rounded to doubles once; sign(row . c) taken from the float dot when it clears its
// error bound (each operand within 2^-52 relative, three products, two sums: under 8 u sum |row_k c_k|; taken as
// 1e-14), else unknown. Unusable (every sign unknown) when a non-zero rational rounds to 0, a subnormal or infinity.
struct FloatRows {
  std::vector<std::array<double, 3>> equalities, inequalities, strict;
  bool usable = true;
};

bool rounds_well(const Q& x, double& d) {
  d = x.get_d();
  return sgn(x) == 0 ? d == 0 : std::isnormal(d);
}

template <class M>
std::vector<std::array<double, 3>> float_rows(const M& rows, bool& usable) {
  std::vector<std::array<double, 3>> out(static_cast<std::size_t>(rows.rows()));
  for (Eigen::Index r = 0; r < rows.rows(); ++r)
    for (Eigen::Index k = 0; k < 3; ++k)
      usable = rounds_well(rows(r, k), out[static_cast<std::size_t>(r)][k]) && usable;
  return out;
}

FloatRows float_rows(const geometry::FaceCone<Q>& cone) {
  FloatRows f;
  if (cone.dim != 3) return f.usable = false, f;
  f.equalities = float_rows(cone.equalities, f.usable);
  f.inequalities = float_rows(cone.inequalities, f.usable);
  f.strict = float_rows(cone.strict, f.usable);
  return f;
}

// sign(row . c): -1, 0 (never: a zero is always unknown), 1, or 2 for unknown.
int filtered_sign(const std::array<double, 3>& row, const std::array<double, 3>& c) {
  double s = 0, m = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    s += row[k] * c[k];
    m += std::abs(row[k] * c[k]);
  }
  if (std::abs(s) > 1e-14 * m) return s > 0 ? 1 : -1;
  return 2;
}

// True when c is certainly not in the cone of `f` (as contains_point would find); false when in or unknown.
bool certainly_outside(const FloatRows& f, const std::array<double, 3>& c) {
  if (!f.usable) return false;
  for (const auto& row : f.equalities)
    if (filtered_sign(row, c) != 2) return true;  // a certain non-zero sign
  for (const auto& row : f.inequalities)
    if (filtered_sign(row, c) == 1) return true;
  for (const auto& row : f.strict)
    if (filtered_sign(row, c) == 1) return true;
  return false;
}

}  // namespace

template <class T>
void find_redundant(Insertion<T>& ins) {
  const std::size_t n = ins.cones.size();
  ins.forms.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    if (!ins.forms[i] && !is_empty_cone<T>(ins.cones[i])) ins.forms[i] = geometry::nnc_form<T>(ins.cones[i]);
  // Exact cones: each outer cone's rows and each inner cone's point c in doubles, so that most pairs are told apart
  // without the exact test.
  std::vector<FloatRows> outer;
  std::vector<std::optional<std::array<double, 3>>> point(n);
  if constexpr (std::is_same_v<T, Q>) {
    for (std::size_t i = 0; i < n; ++i) {
      outer.push_back(float_rows(ins.cones[i]));
      const auto& form = ins.forms[i];
      if (!form || form->status == geometry::NncStatus::kEmpty || form->closure.rays.cols() != 3) continue;
      Vec<Q> c = Vec<Q>::Zero(3);
      for (Eigen::Index r = 0; r < form->closure.rays.rows(); ++r) c += form->closure.rays.row(r).transpose();
      std::array<double, 3> d{};
      bool usable = true;
      for (Eigen::Index k = 0; k < 3; ++k) usable = rounds_well(c(k), d[static_cast<std::size_t>(k)]) && usable;
      if (usable) point[i] = d;
    }
  }
  ins.redundant.assign(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const bool empty = is_empty_cone<T>(ins.cones[i]);
    for (std::size_t j = 0; j < n && !ins.redundant[i]; ++j) {
      if (i == j || ins.redundant[j]) continue;
      if (!empty && point[i] && certainly_outside(outer[j], *point[i])) continue;  // contains() would say so
      if (empty || geometry::contains<T>(ins.cones[j], ins.cones[i], *ins.forms[i]).status ==
                       geometry::ContainmentStatus::kContained)
        ins.redundant[i] = true;
    }
  }
}

template <class T>
Insertion<T> insertion(const geometry::PlanarScene& goal, Route route, InsertionCones<T>* cones,
                       Redundancy redundancy) {
  const std::size_t k = goal.fixels.size();
  if (k != 2 && k != 3)
    throw exact::InputError("", "$.fixels", "insertion needs 2 or 3 fixels, found " + std::to_string(k));
  for (std::size_t i = 0; i < k; ++i)
    if (!goal.fixels[i].frame.touching())
      throw exact::InputError("", "$.fixels[" + std::to_string(i) + "]",
                              "insertion takes the goal configuration: every fixel must touch the workpiece");
  Insertion<T> out;
  out.sets = insertion_sets(k);
  for (std::size_t i = 0; i < out.sets.size(); ++i) {
    const auto& letters = out.sets[i].mode.letters;
    if (cones && std::any_of(letters.begin(), letters.end(), unconstrained)) {
      const SetCone<T>& c = cones->cone(goal, i, out.sets[i], route);
      out.cones.push_back(c.cone);
      out.forms.push_back(c.form);
    } else {
      out.cones.push_back(set_cone<T>(goal, out.sets[i], route));
      out.forms.emplace_back();
    }
  }
  if (redundancy == Redundancy::kFound) find_redundant(out);
  return out;
}

template <class T>
BoundaryPieces<T, bool> insertion_pushes(const geometry::PlanarScene& goal, const Insertion<T>& ins) {
  std::vector<const geometry::FaceCone<T>*> cones;
  for (std::size_t i = 0; i < ins.cones.size(); ++i)
    if (!ins.redundant[i]) cones.push_back(&ins.cones[i]);
  return boundary_pieces<T, bool>(goal, cone_rows<T>(cones), [&](const Vec<T>& g) { return ins.in_goal(g); });
}

#define CONTACTCERT_INSERTION_INSTANTIATE(T)                                                               \
  template struct Insertion<T>;                                                                            \
  template class InsertionCones<T>;                                                                        \
  template void find_redundant<T>(Insertion<T>&);                                                          \
  template Insertion<T> insertion<T>(const geometry::PlanarScene&, Route, InsertionCones<T>*, Redundancy); \
  template BoundaryPieces<T, bool> insertion_pushes<T>(const geometry::PlanarScene&, const Insertion<T>&);
CONTACTCERT_INSERTION_INSTANTIATE(double)
CONTACTCERT_INSERTION_INSTANTIATE(Q)

}  // namespace contactcert::solvers
