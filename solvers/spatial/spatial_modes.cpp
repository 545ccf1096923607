#include "solvers/spatial/spatial_modes.h"

#include <algorithm>
#include <optional>

#include "exact/input_error.h"
#include "exact/strict_feasibility.h"

namespace contactcert::solvers::spatial {

using Index = Eigen::Index;
using geometry::Vec3;

std::string letters(std::size_t m) {
  std::string s = "sf";
  for (std::size_t j = 0; j < 2 * m; ++j) s += static_cast<char>('A' + j);
  return s;
}

SpatialModel spatial_model(const geometry::SpatialScene& scene) {
  SpatialModel model;
  for (const geometry::SpatialContact& c : scene.contacts) {
    Vec3 r;
    for (std::size_t i = 0; i < 3; ++i) r[i] = c.point[i] - scene.body.com[i];
    auto w = [&](const Vec3& u) {  // w_u = (u, r x u): u . (a + alpha x r) = w_u . (a, alpha)
      const Vec3 m = geometry::cross(r, u);
      Vec<Q> f(6);
      f << u[0], u[1], u[2], m[0], m[1], m[2];
      return f;
    };
    SpatialModel::Contact k{w(c.normal), w(c.t1), w(c.t2), {}};
    for (std::size_t j = 0; j < c.edges.size(); ++j) k.d.push_back(w(c.edge(j)));
    model.contacts.push_back(std::move(k));
  }
  return model;
}

namespace {

using RowKey = SpatialRowKey;  // two prefixes with one letter each at a contact share the rows of equal functionals

// The keys of letter L with m pyramid edges (the header's table, in its order); empty if L is not a letter.
std::vector<RowKey> letter_keys(std::size_t m, char L) {
  const RowKey n{-1, 0, false};
  if (L == 's') return {{-1, 0, true}};
  if (L == 'f') return {n, {-1, 1, false}, {-1, 2, false}};
  if (L < 'A' || static_cast<std::size_t>(L - 'A') >= 2 * m) return {};
  const int M = static_cast<int>(m), j = (L - 'A') / 2;
  const int prev = (j + M - 1) % M, next = (j + 1) % M, after = (j + 2) % M;
  if ((L - 'A') % 2 == 0) return {n, {prev, j, true}, {next, j, true}};
  return {n, {next, j, false}, {prev, j, true}, {after, next, true}};
}

// The row a_n >= 0 of a contact after a prefix's letters: the only row there of a prefix's system (prefix_system).
const std::vector<RowKey>& later_keys() {
  static const std::vector<RowKey> keys{{-1, 0, false, true}};
  return keys;
}

// The row of `ks` with key's functional: (its index, reversed) where reversed means the edge difference d_b - d_a
// of key's d_a - d_b (the same row with the sign flipped); nullopt if `ks` has none.
std::optional<std::pair<std::size_t, bool>> find_key(const std::vector<RowKey>& ks, const RowKey& key) {
  for (std::size_t r = 0; r < ks.size(); ++r) {
    if (ks[r].a == key.a && ks[r].b == key.b) return std::pair{r, false};
    if (key.a >= 0 && ks[r].a == key.b && ks[r].b == key.a) return std::pair{r, true};
  }
  return std::nullopt;
}

SignRow key_row(const SpatialModel::Contact& c, const RowKey& key) {
  if (key.a >= 0) return {c.d[static_cast<std::size_t>(key.a)] - c.d[static_cast<std::size_t>(key.b)], key.strict};
  return {key.b == 0 ? c.n : key.b == 1 ? c.t1 : c.t2, key.strict};
}

// Whether vdot meets every row (f . vdot = 0, or > 0 if strict).
bool meets(const std::vector<SignRow>& rows, const Vec<Q>& vdot) {
  for (const SignRow& r : rows) {
    Q dot(0);
    for (Index c = 0; c < 6; ++c)
      if (sgn(r.f(c)) != 0) dot += r.f(c) * vdot(c);
    const int s = sgn(dot);
    if (r.strict ? s <= 0 : s != 0) return false;
  }
  return true;
}

// The index of letter L in letters(m): s, f, then 'A' + j.
std::size_t letter_index(char L) { return L == 's' ? 0 : L == 'f' ? 1 : 2 + static_cast<std::size_t>(L - 'A'); }

// Where each weight of `proof` lands on a prefix whose rows at contact c have the keys keys_at(c) (its letter's, or
// later_keys past its letters): per weight the row of its functional there (its index in the contact's rows,
// reversed as find_key); false if one has none.
template <class KeysAt>
bool land(const SpatialProof& proof, const KeysAt& keys_at, std::vector<std::pair<std::size_t, bool>>& at) {
  at.clear();
  for (const SpatialProof::Weight& w : proof.support) {
    const auto found = find_key(keys_at(w.contact), w.key);
    if (!found) return false;
    at.push_back(*found);
  }
  return true;
}

// The weighed rows of y, a vector over the rows of a prefix of a scene of `contacts` contacts whose rows at contact c
// have the keys keys_at(c) (prefix_system's layout), as a proof.
template <class KeysAt>
SpatialProof proof_of(std::size_t contacts, const KeysAt& keys_at, const Vec<Q>& y) {
  SpatialProof proof;
  Index row = 0;
  for (std::size_t c = 0; c < contacts; ++c)
    for (const RowKey& key : keys_at(c))
      if (const Q& w = y(row++); sgn(w) != 0) proof.support.push_back({c, key, w});
  return proof;
}

// The rows of a prefix of a scene of `contacts` contacts whose rows at contact c have the keys keys_at(c).
template <class KeysAt>
Index row_count(std::size_t contacts, const KeysAt& keys_at) {
  Index count = 0;
  for (std::size_t c = 0; c < contacts; ++c) count += static_cast<Index>(keys_at(c).size());
  return count;
}

// The proof's weights moved onto the rows of such a prefix: put(row, weight) for each, in contact order (an edge
// difference reversed with its weight negated); false, at the first weight with no row there (those before it put).
template <class KeysAt, class Put>
bool move_proof(const SpatialProof& proof, const KeysAt& keys_at, const Put& put) {
  Index first = 0;  // the first row of contact c
  std::size_t c = 0;
  for (const SpatialProof::Weight& w : proof.support) {
    for (; c < w.contact; ++c) first += static_cast<Index>(keys_at(c).size());
    const auto found = find_key(keys_at(c), w.key);
    if (!found) return false;
    put(first + static_cast<Index>(found->first), found->second ? Q(-w.y) : w.y);
  }
  return true;
}

// The keys of a dead prefix of `tree` per contact: its letter's, then later_keys.
auto dead_keys(const SpatialModeTree& tree, const SpatialDeadPrefix& dead) {
  return [t = &tree, d = &dead](std::size_t c) -> const std::vector<RowKey>& {
    return c < d->prefix.size() ? t->row_keys[c][letter_index(d->prefix[c])] : later_keys();
  };
}

}  // namespace

std::vector<SignRow> letter_rows(const SpatialModel::Contact& c, char L) {
  std::vector<SignRow> rows;
  for (const RowKey& key : letter_keys(c.d.size(), L)) rows.push_back(key_row(c, key));
  return rows;
}

bool realises(const SpatialModel& model, const std::string& prefix, const Vec<Q>& vdot) {
  if (vdot.size() != 6 || prefix.size() > model.contacts.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    const std::vector<SignRow> rows = letter_rows(model.contacts[i], prefix[i]);
    if (rows.empty() || !meets(rows, vdot)) return false;
  }
  return true;
}

namespace {

// The contacts whose rows a_n >= 0 a prefix's system carries when they come after its letters: all but those whose
// w_n is a non-negative combination of the others' kept (tried from the last contact back, one LP each, so that the
// kept ones come early). Every letter implies a_n >= 0, so a prefix's letters with the kept later rows imply
// a_n >= 0 at every contact: the same solutions as with every later row, in fewer rows (a box on a plane with k rim
// contacts keeps its 4 corners, a peg in a hole with 4 walls at k / 4 heights the 8 contacts of its first two).
std::vector<bool> kept_normals(const SpatialModel& model, exact::Arith arith, long& lps) {
  const std::size_t k = model.contacts.size();
  std::vector<bool> kept(k, true);
  for (std::size_t c = k; c-- > 0;) {
    exact::StrictSystem<Q> cone;  // sum_r lambda_r w_n(r) = w_n(c), lambda >= 0, over the kept r != c
    cone.b = model.contacts[c].n;
    cone.A = exact::Mat<Q>::Zero(6, 0);
    for (std::size_t r = 0; r < k; ++r)
      if (kept[r] && r != c) {
        cone.A.conservativeResize(6, cone.A.cols() + 1);
        cone.A.col(cone.A.cols() - 1) = model.contacts[r].n;
      }
    if (cone.A.cols() == 0) continue;
    const auto f = exact::strict_feasibility(cone, arith);
    lps += f.lps;
    kept[c] = f.status != exact::StrictStatus::kFeasible;
  }
  return kept;
}

// The strict-feasibility system of a prefix by its non-zero entries: its letters' rows, then a_n >= 0 at each later
// contact that `later` names (SpatialDeadPrefix's layout without the other later contacts). A row has at most six
// entries on vdot and one on its slack, so a deep prefix's system stays linear in its rows.
exact::SparseStrictSystem<Q> prefix_system(const SpatialModel& model, const std::string& prefix,
                                           const std::vector<bool>& later) {
  exact::SparseStrictSystem<Q> sys;
  sys.cols = 6;
  sys.is_free.assign(6, true);
  sys.strict.assign(6, false);
  auto put = [&sys](const Vec<Q>& f, bool slack, bool strict) {  // f . vdot - sigma = 0 (sigma > 0 or >= 0), or = 0
    for (Index c = 0; c < 6; ++c)
      if (sgn(f(c)) != 0) sys.entries.push_back({sys.rows, c, f(c)});
    if (slack) {
      sys.entries.push_back({sys.rows, sys.cols++, Q(-1)});
      sys.is_free.push_back(false);
      sys.strict.push_back(strict);
    }
    ++sys.rows;
  };
  for (std::size_t i = 0; i < prefix.size(); ++i)
    for (const SignRow& row : letter_rows(model.contacts[i], prefix[i])) put(row.f, row.strict, row.strict);
  for (std::size_t j = prefix.size(); j < model.contacts.size(); ++j)
    if (later[j]) put(model.contacts[j].n, true, false);
  return sys;
}

class Walker {
 public:
  Walker(const SpatialModel& model, const SpatialModeOptions& options, SpatialModeTree& out)
      : model_(model),
        options_(options),
        out_(out),
        known_(model.contacts.size()),
        kept_(kept_normals(model, options.arith, out.lps)) {
    for (std::size_t i = 0; i < model.contacts.size(); ++i) {
      const SpatialModel::Contact& c = model.contacts[i];
      alphabets_.push_back(letters(c.d.size()));
      out_.row_keys.emplace_back();
      rows_.emplace_back();
      for (char L : alphabets_.back()) {
        out_.row_keys[i].push_back(letter_keys(c.d.size(), L));
        rows_[i].push_back(letter_rows(c, L));
      }
    }
  }

  // Depth first with an explicit stack: per live prefix its realising vdot and the next letter to try below it. A
  // child is live without an LP when the parent's vdot meets its letter, dead without one when a known certificate
  // moves to it (reuse, as the planar tree's certificates reused by row kind); else one LP decides it.
  void walk() {
    struct Frame {
      Vec<Q> vdot;
      std::size_t next = 0;
    };
    const std::size_t k = model_.contacts.size();
    std::string prefix;
    std::vector<Frame> path{{Vec<Q>::Zero(6), 0}};
    count_node();
    while (!path.empty()) {
      const std::size_t i = path.size() - 1;
      if (i == k) {
        if (static_cast<long>(out_.modes.size()) >= options_.max_modes)
          throw exact::BudgetExceeded(
              "spatial modes: output budget of " + std::to_string(options_.max_modes) + " modes exhausted", covered());
        out_.modes.push_back(prefix);
        out_.accelerations.push_back(path.back().vdot);
      }
      if (i == k || path.back().next == alphabets_[i].size()) {
        path.pop_back();
        if (!prefix.empty()) prefix.pop_back();
        continue;
      }
      const std::size_t letter = path.back().next++;
      prefix.push_back(alphabets_[i][letter]);
      at_.resize(i);
      at_.push_back(letter);
      count_node();
      if (meets(rows_[i][letter], path.back().vdot)) {
        Vec<Q> vdot = path.back().vdot;
        path.push_back({std::move(vdot), 0});
        continue;
      }
      if (const std::optional<std::size_t> proof = reuse()) {
        out_.dead.push_back({prefix, *proof});
        prefix.pop_back();
        continue;
      }
      // The prefix's LP with the kept later rows its points push into, added until its point meets them all (each
      // round adds one at least) or it has none: the same verdict as with every kept row, in smaller LPs.
      in_lp_.assign(k, false);
      exact::StrictFeasibility<Q> kin;
      do {
        kin = exact::strict_feasibility(prefix_system(model_, prefix, in_lp_), options_.arith);
        out_.lps += kin.lps;
      } while (kin.status == exact::StrictStatus::kFeasible && pushed_into(kin.x.head(6)));
      if (kin.status == exact::StrictStatus::kFeasible) {
        path.push_back({Vec<Q>(kin.x.head(6)), 0});
        continue;
      }
      out_.dead.push_back({prefix, remember(kin.motzkin)});
      prefix.pop_back();
    }
  }

 private:
  // The keys of the current prefix's system's rows at contact i (its letter's, later_keys if kept, else none); and
  // keys_at as a function (for proof_of, land).
  const std::vector<RowKey>& keys_at(std::size_t i) const {
    static const std::vector<RowKey> none;
    return i < at_.size() ? out_.row_keys[i][at_[i]] : kept_[i] ? later_keys() : none;
  }
  auto prefix_keys() const {
    return [this](std::size_t i) -> const std::vector<RowKey>& { return keys_at(i); };
  }

  // Whether vdot has a_n < 0 at a kept later contact not yet in the LP (in_lp_); those put in.
  bool pushed_into(const Vec<Q>& vdot) {
    bool pushed = false;
    for (std::size_t j = at_.size(); j < model_.contacts.size(); ++j)
      if (kept_[j] && !in_lp_[j] && sgn(Q(model_.contacts[j].n.dot(vdot))) < 0) pushed = in_lp_[j] = true;
    return pushed;
  }

  // Keeps the rows a new dead prefix's certificate weighs as a proof, listed under the prefix's last contact (it
  // weighs a row of that letter: the parent's system, live, has the other rows); returns its index.
  std::size_t remember(const Vec<Q>& y) {
    static const std::vector<RowKey> none;
    known_[at_.size() - 1].push_back(out_.proofs.size());
    out_.proofs.push_back(proof_of(
        model_.contacts.size(),
        [this](std::size_t i) -> const std::vector<RowKey>& {
          return i < at_.size() ? keys_at(i) : in_lp_[i] ? later_keys() : none;
        },
        y));
    return out_.proofs.size() - 1;
  }

  // A known proof that the current prefix is dead, or nullopt: one found for a prefix of the same length, so its
  // weights past the letters land on the same rows a_n >= 0. Each weighed row moves to the prefix's row of the same
  // functional at its contact (the same direction, or the reversed d_b - d_a with the weight negated), so
  // sum y_r f_r = 0 still holds; it is a Motzkin certificate again (exact/strict_feasibility.h: y_r <= 0 on strict
  // and a_n >= 0 rows, some strict y_r < 0, any sign on equalities) if every row it lands on as strict or a_n >= 0
  // weighs <= 0 and a strict one < 0.
  std::optional<std::size_t> reuse() {
    for (const std::size_t p : known_[at_.size() - 1]) {
      const SpatialProof& known = out_.proofs[p];
      if (!land(known, prefix_keys(), landed_)) continue;
      bool strict_negative = false, signs = true;
      for (std::size_t r = 0; r < landed_.size() && signs; ++r) {
        const SpatialProof::Weight& w = known.support[r];
        const RowKey& on = keys_at(w.contact)[landed_[r].first];
        if (!on.strict && !on.at_least) continue;
        const int s = landed_[r].second ? -sgn(w.y) : sgn(w.y);
        signs = s <= 0;
        strict_negative = strict_negative || (on.strict && s < 0);
      }
      if (signs && strict_negative) return p;
    }
    return std::nullopt;
  }

  void count_node() {
    ++out_.nodes;
    if (out_.nodes > options_.max_nodes || options_.deadline.expired())
      throw exact::BudgetExceeded(
          out_.nodes > options_.max_nodes
              ? "spatial modes: node budget of " + std::to_string(options_.max_nodes) + " prefixes exhausted"
              : "spatial modes: " + options_.deadline.reached_text(),
          covered());
  }

  std::string covered() const {
    return std::to_string(out_.nodes - 1) + " prefixes visited, " + std::to_string(out_.modes.size()) +
           " feasible modes found";
  }

  const SpatialModel& model_;
  const SpatialModeOptions& options_;
  SpatialModeTree& out_;
  std::vector<std::string> alphabets_;                   ///< per contact
  std::vector<std::vector<std::size_t>> known_;          ///< out.proofs by the last contact of their prefix
  std::vector<std::vector<std::vector<SignRow>>> rows_;  ///< per contact and letter
  std::vector<std::size_t> at_;                          ///< the current prefix's letters as indices
  std::vector<std::pair<std::size_t, bool>> landed_;     ///< reuse's scratch: where a proof's weights land
  const std::vector<bool> kept_;                         ///< per contact: its a_n >= 0 in prefix_system (kept_normals)
  std::vector<bool> in_lp_;                              ///< per later contact: its a_n >= 0 in the current LP
};

}  // namespace

SpatialModeTree spatial_modes(const SpatialModel& model, const SpatialModeOptions& options) {
  SpatialModeTree out;
  Walker(model, options, out).walk();
  return out;
}

Vec<Q> dead_motzkin(const SpatialModeTree& tree, const SpatialDeadPrefix& dead) {
  Vec<Q> y = Vec<Q>::Zero(row_count(tree.row_keys.size(), dead_keys(tree, dead)));
  move_proof(tree.proofs[dead.proof], dead_keys(tree, dead), [&](Index row, Q w) { y(row) = std::move(w); });
  return y;
}

Vec<Q> move_rows(const SpatialModel& model, const std::string& from, const Vec<Q>& y, const std::string& to) {
  const std::size_t k = model.contacts.size();
  std::vector<std::vector<RowKey>> from_keys, to_keys;
  for (std::size_t i = 0; i < k; ++i) {
    from_keys.push_back(i < from.size() ? letter_keys(model.contacts[i].d.size(), from[i]) : later_keys());
    to_keys.push_back(i < to.size() ? letter_keys(model.contacts[i].d.size(), to[i]) : later_keys());
  }
  auto from_at = [&](std::size_t c) -> const std::vector<RowKey>& { return from_keys[c]; };
  auto to_at = [&](std::size_t c) -> const std::vector<RowKey>& { return to_keys[c]; };
  const Index from_rows = row_count(k, from_at), tail = y.size() - from_rows;
  Vec<Q> out = Vec<Q>::Zero(row_count(k, to_at) + tail);
  out.tail(tail) = y.tail(tail);  // the trailing rows copied
  if (!move_proof(proof_of(k, from_at, y), to_at, [&](Index row, Q w) { out(row) = std::move(w); })) return Vec<Q>();
  return out;
}

}  // namespace contactcert::solvers::spatial
