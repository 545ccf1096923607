#include "solvers/stability/mode_tree.h"

#include <deque>
#include <string_view>

#include "exact/input_error.h"
#include "exact/ladder_numbers.h"
#include "solvers/stability/mode_tree_cone.h"

namespace contactcert::solvers {

using Index = Eigen::Index;
namespace ring = exact::ring;

std::vector<Interaction> ModeAlphabet::letters(std::size_t fixel) const {
  using I = Interaction;
  if (rules.touches(fixel)) {
    if (unions) return {I::kSeparate, I::kSlideLeft, I::kSlideRight, I::kRoll, I::kMaintain};
    return {I::kSeparate, I::kSlideLeft, I::kSlideRight, I::kRoll};
  }
  if (unions) return {I::kSeparate, I::kApproach, I::kUnconstrained};
  return {I::kSeparate, I::kApproach};
}

namespace {

// Whether acceleration vdot meets letter L's rows at fixel i (Table 2), by the sign test of T.
template <class T>
bool meets(const MotionModel<T>& model, const KinematicRules& rules, const Vec<T>& vdot, std::size_t i, Interaction L) {
  const Index k = model.J.cols() / 2, c = static_cast<Index>(i);
  const T a_n = model.J.col(c).dot(vdot);
  const int n = exact::sign(a_n);
  auto t = [&] { return exact::sign(T(model.J.col(k + c).dot(vdot))); };
  switch (L) {
    case Interaction::kSeparate:
      return n > 0 || (n == 0 && (!rules.touches(i) || rules.printed_separation));
    case Interaction::kSeparatePrinted:
      return n >= 0;
    case Interaction::kApproach:
      return n < 0;
    case Interaction::kUnconstrained:
      return true;
    case Interaction::kSlideLeft:
      return n == 0 && t() > 0;
    case Interaction::kSlideRight:
      return n == 0 && t() < 0;
    case Interaction::kRoll:
      return n == 0 && t() == 0;
    case Interaction::kMaintain:
      return n == 0;
  }
  return false;
}

// What row a letter puts on a fixel's a_n and on its a_t (kinematic_system): a Motzkin certificate that weighs
// only rows of the same kinds is one for any prefix with those kinds at those fixels.
enum class RowKind : char { kNone, kZero, kSlackMinus, kSlackMinusStrict, kSlackPlusStrict };

RowKind normal_row(Interaction L, bool strict_s) {
  switch (L) {
    case Interaction::kSeparate:
      return strict_s ? RowKind::kSlackMinusStrict : RowKind::kSlackMinus;
    case Interaction::kSeparatePrinted:
      return RowKind::kSlackMinus;
    case Interaction::kApproach:
      return RowKind::kSlackPlusStrict;
    case Interaction::kUnconstrained:
      return RowKind::kNone;
    default:
      return RowKind::kZero;
  }
}

RowKind tangent_row(Interaction L) {
  switch (L) {
    case Interaction::kSlideLeft:
      return RowKind::kSlackMinusStrict;
    case Interaction::kSlideRight:
      return RowKind::kSlackPlusStrict;
    case Interaction::kRoll:
      return RowKind::kZero;
    default:
      return RowKind::kNone;
  }
}

// A dead prefix's certificate by the rows it weighs: per fixel of its support, the kinds and the weights.
template <class T>
struct KnownProof {
  struct Weight {
    std::size_t fixel;
    RowKind normal, tangent;  // kNone where the certificate does not weigh the row
    T y_normal, y_tangent;
  };
  std::vector<Weight> support;  // in fixel order; the last is the prefix's last fixel
};

template <class T>
class Walker {
 public:
  Walker(const MotionModel<T>& model, const ModeAlphabet& alphabet, const ModeTreeOptions& options,
         const OnMode<T>& on_mode, ModeTree<T>& out, bool by_cones = false)
      : model_(model),
        alphabet_(alphabet),
        options_(options),
        on_mode_(on_mode),
        out_(out),
        k_(static_cast<std::size_t>(model.J.cols() / 2)),
        known_(k_) {
    for (std::size_t i = 0; i < k_; ++i)
      (alphabet.rules.touches(i) ? touching_letters_ : gap_letters_) = alphabet.letters(i);
    if constexpr (std::is_same_v<T, Q>)
      if (by_cones) integer_columns();
  }

  // Walks the subtree of the empty prefix depth first, letters in alphabet order, with an explicit stack (one
  // frame per live prefix on the current path: its realising vdot and its next letter), so the depth of the
  // walk - up to the number of fixels - never becomes call depth. False once on_mode stopped the walk.
  bool walk() {
    struct Frame {
      Vec<T> vdot;                     // realises the live prefix of this depth
      std::size_t next = 0;            // the index of the next letter to try at the following fixel
      std::optional<PrefixCone> cone;  // walk_modes_by_cones: the closure cone of the prefix's rows, if it fits
    };
    ModeString prefix;
    std::vector<Frame> path;
    path.push_back({Vec<T>::Zero(model_.J.rows()), 0, std::nullopt});  // the empty prefix: no rows, vdot = 0
    if (!columns_.empty()) path.back().cone.emplace();
    while (!path.empty()) {
      const std::size_t i = path.size() - 1;  // == prefix.letters.size()
      if (i == k_) {
        count_mode();
        out_.modes.push_back(prefix);
        out_.accelerations.push_back(path.back().vdot);
        if (on_mode_ && !on_mode_(prefix, path.back().vdot)) return false;
      }
      if (i == k_ || path.back().next == letters_of(i).size()) {  // the subtree of this prefix is done
        path.pop_back();
        if (!prefix.letters.empty()) prefix.letters.pop_back();
        continue;
      }
      const Interaction L = letters_of(i)[path.back().next++];
      count_node();
      prefix.letters.push_back(L);
      if (meets(model_, alphabet_.rules, path.back().vdot, i, L)) {
        Vec<T> vdot = path.back().vdot;  // copied before push_back can move the frames
        std::optional<PrefixCone> cone = child_cone(path.back().cone, prefix);
        path.push_back({std::move(vdot), 0, std::move(cone)});
        continue;
      }
      if (Vec<T> y = reuse(prefix); y.size()) {
        dead_.push_back({prefix, std::move(y)});
        prefix.letters.pop_back();
        continue;
      }
      if constexpr (std::is_same_v<T, Q>) {
        if (std::optional<PrefixCone> cone = child_cone(path.back().cone, prefix)) {
          ++out_.lps;
          ++out_.lps_by_cones;
          if (const std::optional<Int3> v = cone->point_meeting(rows_of(prefix))) {
            Vec<Q> vdot(3);
            for (Index d = 0; d < 3; ++d)
              ring::to_rational((*v)[static_cast<std::size_t>(d)], exact::Int128(1), vdot(d));
            path.push_back({std::move(vdot), 0, std::move(cone)});
            continue;
          }
          Vec<Q> first_found;  // when y replaced it: remembered too, so that its reuses are not lost
          if (Vec<Q> y = cone_certificate(prefix, *path.back().cone, *cone, first_found); y.size()) {
            remember(prefix, y);
            if (first_found.size()) remember(prefix, first_found);
            dead_.push_back({prefix, std::move(y)});
            prefix.letters.pop_back();
            continue;
          }
          --out_.lps;
          --out_.lps_by_cones;
        }
      }
      auto kin = exact::strict_feasibility(kinematic_system(model_, prefix, alphabet_.rules), options_.arith);
      out_.lps += kin.lps;
      if (kin.rounded_float_checked) out_.lps_checked_from_float += kin.lps;
      if (kin.status == exact::StrictStatus::kFeasible) {
        path.push_back({Vec<T>(kin.x.head(model_.J.rows())), 0, std::nullopt});
        continue;
      }
      remember(prefix, kin.motzkin);
      dead_.push_back({prefix, std::move(kin.motzkin)});
      prefix.letters.pop_back();
    }
    return true;
  }

  // Moves the dead prefixes into the result, each once.
  void finish() {
    out_.dead.reserve(dead_.size());
    for (DeadPrefix<T>& d : dead_) out_.dead.push_back(std::move(d));
    dead_.clear();
  }

  void count_node() {
    ++out_.nodes;
    if (out_.nodes > options_.max_nodes || options_.deadline.expired())
      throw exact::BudgetExceeded(
          out_.nodes > options_.max_nodes
              ? "mode enumeration: node budget of " + std::to_string(options_.max_nodes) + " prefixes exhausted"
              : "mode enumeration: " + options_.deadline.reached_text(),
          covered());
  }

  // Before listing a mode beyond options.max_modes: BudgetExceeded (the output of --unions or a printed `s` can
  // be exponential in the fixels).
  void count_mode() const {
    if (static_cast<long>(out_.modes.size()) >= options_.max_modes)
      throw exact::BudgetExceeded(
          "mode enumeration: output budget of " + std::to_string(options_.max_modes) + " modes exhausted", covered());
  }

 private:
  std::string covered() const {
    return std::to_string(out_.nodes - 1) + " prefixes visited, " + std::to_string(out_.modes.size()) +
           " feasible modes found";
  }

  // The letters of fixel i (alphabet.letters), kept once per kind of fixel.
  const std::vector<Interaction>& letters_of(std::size_t i) const {
    return alphabet_.rules.touches(i) ? touching_letters_ : gap_letters_;
  }

  bool strict_s(std::size_t fixel) const {
    return alphabet_.rules.touches(fixel) && !alphabet_.rules.printed_separation;
  }

  // The first row of each fixel of the prefix in kinematic_system's layout, and the row count.
  static std::vector<Index> first_rows(const ModeString& prefix, Index& rows) {
    std::vector<Index> first;
    rows = 0;
    for (Interaction L : prefix.letters) {
      first.push_back(rows);
      rows += normal_row(L, true) != RowKind::kNone;
      rows += tangent_row(L) != RowKind::kNone;
    }
    return first;
  }

  // Keeps the rows a new dead prefix's certificate weighs, under its last fixel (every certificate weighs it:
  // else the parent prefix would be dead).
  void remember(const ModeString& prefix, const Vec<T>& y) {
    Index rows = 0;
    const std::vector<Index> first = first_rows(prefix, rows);
    KnownProof<T> known;
    for (std::size_t f = 0; f < prefix.letters.size(); ++f) {
      const Interaction L = prefix.letters[f];
      typename KnownProof<T>::Weight w{f, RowKind::kNone, RowKind::kNone, T(0), T(0)};
      Index r = first[f];
      if (normal_row(L, true) != RowKind::kNone) {
        if (!exact::is_zero(y(r))) w.normal = normal_row(L, strict_s(f)), w.y_normal = y(r);
        ++r;
      }
      if (tangent_row(L) != RowKind::kNone && !exact::is_zero(y(r))) w.tangent = tangent_row(L), w.y_tangent = y(r);
      if (w.normal != RowKind::kNone || w.tangent != RowKind::kNone) known.support.push_back(std::move(w));
    }
    if (!known.support.empty()) known_[known.support.back().fixel].push_back(std::move(known));
  }

  // A certificate for the prefix moved from a known one that weighs only rows of the same kinds, or empty.
  Vec<T> reuse(const ModeString& prefix) const {
    const std::size_t last = prefix.letters.size() - 1;
    for (const KnownProof<T>& known : known_[last]) {
      bool same = true;
      for (const auto& w : known.support) {
        const Interaction L = prefix.letters[w.fixel];
        same = same && (w.normal == RowKind::kNone || w.normal == normal_row(L, strict_s(w.fixel))) &&
               (w.tangent == RowKind::kNone || w.tangent == tangent_row(L));
      }
      if (!same) continue;
      Index rows = 0;
      const std::vector<Index> first = first_rows(prefix, rows);
      Vec<T> y = Vec<T>::Zero(rows);
      for (const auto& w : known.support) {
        if (w.normal != RowKind::kNone) y(first[w.fixel]) = w.y_normal;
        if (w.tangent != RowKind::kNone) y(first[w.fixel] + 1) = w.y_tangent;  // l r n: after the a_n row
      }
      return y;
    }
    return Vec<T>();
  }

  // walk_modes_by_cones: J's columns a_n and a_t of each fixel as integer rows (times a positive scale each);
  // none if a scale or an entry outgrows 64 bits, or if vdot is not in R^3 (several bodies): every prefix then
  // goes to its LP.
  void integer_columns() {
    if (model_.J.rows() != 3) return;
    const Index k = static_cast<Index>(k_);
    std::vector<IntColumn> columns(2 * k_);
    try {
      for (Index c = 0; c < 2 * k; ++c) {
        std::int64_t entries[3];
        const std::int64_t scale = ring::to_common_denominator<std::int64_t>(
            3, [&](Index d) -> const Q& { return model_.J(d, c); }, entries);
        columns[static_cast<std::size_t>(c)] = {{entries[0], entries[1], entries[2]}, scale};
      }
    } catch (const exact::RingOverflow&) {
      return;
    }
    columns_ = std::move(columns);
  }

  // The prefix's rows in kinematic_system's order as sign conditions f . vdot (f = the row's a_n or a_t part
  // times -c, c the coefficient of its slack, so that f . vdot is the slack; f = the row itself where there is no
  // slack), with the factor y_i = factor_i w_i that turns a weight w_i on f into the row's Motzkin entry
  // (mode_tree_cone.h).
  std::vector<ConeRow> rows_of(const ModeString& prefix, std::vector<std::int64_t>* factors = nullptr) const {
    std::vector<ConeRow> rows;
    for (std::size_t u = 0; u < prefix.letters.size(); ++u) letter_rows(u, prefix.letters[u], rows, factors);
    return rows;
  }

  // The rows of letter L at fixel u, appended (rows_of).
  void letter_rows(std::size_t u, Interaction L, std::vector<ConeRow>& rows, std::vector<std::int64_t>* factors) const {
    auto add = [&](std::size_t column, int c, RowSign sign) {  // c = the slack's coefficient, 0 if none
      const IntColumn& col = columns_[column];
      const int orient = c == 0 ? 1 : -c;
      rows.push_back({{orient * col.f[0], orient * col.f[1], orient * col.f[2]}, sign});
      if (factors) factors->push_back(c == 0 ? -col.scale : c * col.scale);
    };
    const std::size_t n = u, t = k_ + u;
    switch (L) {
      case Interaction::kSeparate:  // a_n - sigma = 0
        add(n, -1, strict_s(u) ? RowSign::kPositive : RowSign::kNonNegative);
        break;
      case Interaction::kSeparatePrinted:
        add(n, -1, RowSign::kNonNegative);
        break;
      case Interaction::kApproach:  // a_n + sigma = 0, sigma > 0
        add(n, 1, RowSign::kPositive);
        break;
      case Interaction::kUnconstrained:
        break;
      case Interaction::kSlideLeft:  // a_n = 0, a_t - sigma = 0, sigma > 0
        add(n, 0, RowSign::kZero);
        add(t, -1, RowSign::kPositive);
        break;
      case Interaction::kSlideRight:  // a_n = 0, a_t + sigma = 0, sigma > 0
        add(n, 0, RowSign::kZero);
        add(t, 1, RowSign::kPositive);
        break;
      case Interaction::kRoll:  // a_n = 0, a_t = 0
        add(n, 0, RowSign::kZero);
        add(t, 0, RowSign::kZero);
        break;
      case Interaction::kMaintain:  // a_n = 0
        add(n, 0, RowSign::kZero);
        break;
    }
  }

  // The parent's cone cut by the rows of the prefix's last letter; none without the parent's or on RingOverflow.
  std::optional<PrefixCone> child_cone(const std::optional<PrefixCone>& parent, const ModeString& prefix) const {
    if (!parent) return std::nullopt;
    std::optional<PrefixCone> cone = parent;
    try {
      std::vector<ConeRow> rows;
      letter_rows(prefix.letters.size() - 1, prefix.letters.back(), rows, nullptr);
      for (const ConeRow& row : rows) cone->cut(row);
    } catch (const exact::RingOverflow&) {
      return std::nullopt;
    }
    return cone;
  }

  // A Motzkin certificate of the prefix's kinematic system from its cone (cone_motzkin), or empty.
  Vec<Q> cone_certificate(const ModeString& prefix, const PrefixCone& parent, const PrefixCone& cone,
                          Vec<Q>& first_found) const {
    std::vector<std::int64_t> factors;
    const std::vector<ConeRow> rows = rows_of(prefix, &factors);
    ModeString head = prefix;
    head.letters.pop_back();
    auto motzkin = [&](const std::vector<exact::Int128>& w) {
      Vec<Q> y = Vec<Q>::Zero(static_cast<Index>(rows.size()));
      for (std::size_t i = 0; i < rows.size(); ++i)
        if (w[i] != 0)
          ring::to_rational(ring::mul(w[i], exact::Int128(factors[i])), exact::Int128(1), y(static_cast<Index>(i)));
      return y;
    };
    try {
      const std::size_t first_new = rows_of(head).size();
      std::vector<exact::Int128> first;
      const auto w = cone_motzkin(rows, cone, certificate_candidates(rows, first_new, parent), kCertificateBudget,
                                  &factors, &first);
      if (!w) return Vec<Q>();
      if (!first.empty()) first_found = motzkin(first);
      return motzkin(*w);
    } catch (const exact::RingOverflow&) {
      return Vec<Q>();
    }
  }

  struct IntColumn {
    std::array<std::int64_t, 3> f;
    std::int64_t scale = 1;  // f = scale * (the column of J)
  };
  static constexpr long kCertificateBudget = 20000;  // subsets of candidate rows tried per dead prefix

  const MotionModel<T>& model_;
  const ModeAlphabet& alphabet_;
  const ModeTreeOptions& options_;
  const OnMode<T>& on_mode_;
  ModeTree<T>& out_;
  std::size_t k_;
  std::vector<std::vector<KnownProof<T>>> known_;  ///< by the last fixel of their support
  std::vector<Interaction> touching_letters_, gap_letters_;
  std::vector<IntColumn> columns_;  ///< walk_modes_by_cones: J's columns in integers (empty: by LPs)
  /// The dead prefixes as found: a deque, which never moves them (a vector of them grows by copying every Q).
  std::deque<DeadPrefix<T>> dead_;
};

}  // namespace

template <class T>
bool realises(const MotionModel<T>& model, const KinematicRules& rules, const Vec<T>& vdot, const ModeString& mode) {
  if (vdot.size() != model.J.rows() || static_cast<Eigen::Index>(mode.letters.size()) > model.J.cols() / 2)
    return false;
  for (std::size_t i = 0; i < mode.letters.size(); ++i)
    if (!meets(model, rules, vdot, i, mode.letters[i])) return false;
  return true;
}

template <class T>
ModeTree<T> walk_modes(const MotionModel<T>& model, const ModeAlphabet& alphabet, const ModeTreeOptions& options,
                       const OnMode<T>& on_mode) {
  ModeTree<T> out;
  Walker<T> walker(model, alphabet, options, on_mode, out);
  walker.count_node();  // the empty prefix
  out.complete = walker.walk();
  walker.finish();
  return out;
}

ModeTree<Q> walk_modes_by_cones(const MotionModel<Q>& model, const ModeAlphabet& alphabet,
                                const ModeTreeOptions& options, const OnMode<Q>& on_mode) {
  ModeTree<Q> out;
  Walker<Q> walker(model, alphabet, options, on_mode, out, /*by_cones=*/true);
  walker.count_node();  // the empty prefix
  out.complete = walker.walk();
  walker.finish();
  return out;
}

#define CONTACTCERT_MODE_TREE_INSTANTIATE(T)                                                             \
  template ModeTree<T> walk_modes<T>(const MotionModel<T>&, const ModeAlphabet&, const ModeTreeOptions&, \
                                     const OnMode<T>&);                                                  \
  template bool realises<T>(const MotionModel<T>&, const KinematicRules&, const Vec<T>&, const ModeString&);
CONTACTCERT_MODE_TREE_INSTANTIATE(double)
CONTACTCERT_MODE_TREE_INSTANTIATE(Q)
CONTACTCERT_MODE_TREE_INSTANTIATE(exact::Mpfr)
CONTACTCERT_MODE_TREE_INSTANTIATE(exact::Interval)
#undef CONTACTCERT_MODE_TREE_INSTANTIATE

}  // namespace contactcert::solvers
