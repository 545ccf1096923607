#include "solvers/spatial/spatial_stability_certificate.h"

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "exact/rational_text.h"
#include "solvers/stability/sparse_motzkin.h"
#include "solvers/stability/stability_certificate.h"

namespace contactcert::solvers::spatial {
namespace {

using Index = Eigen::Index;
using json = nlohmann::ordered_json;
using exact::Z;

// Every letter row of every contact by the first row (letters in alphabet order, rows in the table's order) of the
// same functional up to sign: a Motzkin vector moved between letters (move_rows) weighs the same first rows, so its
// text repeats exactly.
class RowNames {
 public:
  struct Name {
    std::size_t letter, row;  ///< the first row: letter index in the contact's alphabet, row in its table
    int sign;                 ///< this row's functional = sign * the first row's
  };

  explicit RowNames(const SpatialModel& model) {
    for (const SpatialModel::Contact& c : model.contacts) {
      const std::string alphabet = letters(c.d.size());
      std::vector<std::pair<Name, Vec<Q>>> firsts;
      std::vector<std::vector<Name>>& names = names_.emplace_back();
      for (std::size_t L = 0; L < alphabet.size(); ++L) {
        std::vector<Name>& rows = names.emplace_back();
        const std::vector<SignRow> table = letter_rows(c, alphabet[L]);
        for (std::size_t r = 0; r < table.size(); ++r) {
          const Vec<Q>& f = table[r].f;
          std::size_t k = 0;
          while (k < firsts.size() && firsts[k].second != f && firsts[k].second != -f) ++k;
          if (k == firsts.size()) firsts.push_back({{L, r, 1}, f});
          rows.push_back({firsts[k].first.letter, firsts[k].first.row, firsts[k].second == f ? 1 : -1});
        }
      }
      alphabets_.push_back(alphabet);
    }
  }

  // The vector's line: {"rows": [[contact, letter, row], ...], "motzkin": [[index, weight], ...]}, its weights on
  // the first rows (in contact, letter, row order; a row's weight times its sign), followed with `dynamics` by the
  // six Newton-Euler rows' (y's last six entries), as one sparse primitive Motzkin vector (sparse_motzkin_json).
  std::string line(const std::string& letters, const Vec<Q>& y, bool dynamics) const {
    std::vector<std::pair<std::array<std::size_t, 3>, Q>> weights;  // (contact, letter, row), weight
    Index at = 0;
    for (std::size_t i = 0; i < letters.size(); ++i) {
      const std::vector<Name>& rows = names_[i][alphabets_[i].find(letters[i])];
      const std::size_t first = weights.size();
      for (const Name& n : rows) {
        const Q& w = y(at++);
        if (sgn(w) == 0) continue;
        const std::array<std::size_t, 3> key{i, n.letter, n.row};
        auto it = std::find_if(weights.begin() + static_cast<std::ptrdiff_t>(first), weights.end(),
                               [&](const auto& e) { return e.first == key; });
        if (it == weights.end()) it = weights.insert(weights.end(), {key, Q(0)});
        it->second += n.sign > 0 ? w : Q(-w);
      }
    }
    std::sort(weights.begin(), weights.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::erase_if(weights, [](const auto& e) { return sgn(e.second) == 0; });
    // Written directly (a JSON tree per proof would cost more than the verdict's LPs at k = 16).
    std::vector<Q> v;
    std::string text = "{\"rows\":[";
    for (std::size_t e = 0; e < weights.size(); ++e) {
      const auto& [i, L, r] = weights[e].first;
      text += (e ? ",[" : "[") + std::to_string(i) + ",\"" + alphabets_[i][L] + "\"," + std::to_string(r) + "]";
      v.push_back(weights[e].second);
    }
    for (Index d = 0; d < 6 && dynamics; ++d) v.push_back(y(y.size() - 6 + d));
    const std::vector<Z> w = exact::primitive(v);
    text += "],\"motzkin\":[";
    bool first = true;
    for (std::size_t e = 0; e < w.size(); ++e)
      if (sgn(w[e]) != 0) {
        text += (first ? "[" : ",[") + std::to_string(e) + ",\"" + w[e].get_str() + "\"]";
        first = false;
      }
    return text + "]}";
  }

 private:
  std::vector<std::string> alphabets_;
  std::vector<std::vector<std::vector<Name>>> names_;  ///< per contact, letter (alphabet index) and row
};

// The distinct vectors' lines in order of first use, each by its index.
class VectorLines {
 public:
  std::size_t index(std::string line) {
    const auto [it, fresh] = index_.try_emplace(std::move(line), lines_.size());
    if (fresh) lines_.push_back(&it->first);
    return it->second;
  }
  std::vector<std::string> lines() const {
    std::vector<std::string> out;
    for (const std::string* l : lines_) out.push_back(*l);
    return out;
  }

 private:
  std::unordered_map<std::string, std::size_t> index_;
  std::vector<const std::string*> lines_;
};

// Appends `,\n "name": [`, the lines one a line, and `\n ]` (checker/certificate_lines.h's layout).
void put_lines(std::string& out, const char* name, const std::vector<std::string>& lines) {
  out += std::string(",\n \"") + name + "\": [";
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? ",\n  " : "\n  ") + lines[i];
  out += "\n ]";
}

}  // namespace

std::string spatial_stability_certificate(const geometry::SpatialScene& scene, const std::string& scene_text,
                                          const Vec<Q>& g, const SpatialStability& r) {
  json head = stability_certificate_head("spatial_stability", r.verdict, scene_text, g);
  head["resting"] = r.has_resting ? json{{"weights", exact_strings(r.resting_weights)}}
                                  : json{{"motzkin", sparse_motzkin_json(r.resting_motzkin)}};
  if (r.has_moving)
    head["moving"] = {{"mode", r.moving.mode},
                      {"weights", exact_strings(r.moving.weights)},
                      {"acceleration", exact_strings(r.moving.acceleration)}};
  std::string out = "{";
  for (auto it = head.begin(); it != head.end(); ++it)
    out += std::string(it == head.begin() ? "\n " : ",\n ") + json(it.key()).dump() + ": " + it.value().dump();
  // The proofs, one line each: dead prefixes grouped by their parent (a node of the tree, its dead children's
  // letters and vectors), then the moving modes.
  const RowNames names(spatial_model(scene));
  VectorLines vectors;
  struct Children {
    std::string letters;
    std::vector<std::size_t> vectors;
  };
  std::vector<std::pair<std::string, Children>> parents;
  std::unordered_map<std::string, std::size_t> parent_at;
  // A tree proof moved onto any prefix it proves weighs the same functionals by the same amounts (move_rows), so
  // its line is the same on each: built once, from the first prefix it proves, one dense vector at a time.
  std::vector<std::size_t> vector_of(r.tree.proofs.size(), r.tree.proofs.size());
  for (const SpatialDeadPrefix& d : r.tree.dead) {
    std::size_t& v = vector_of[d.proof];
    if (v == r.tree.proofs.size()) v = vectors.index(names.line(d.prefix, dead_motzkin(r.tree, d), false));
    const std::string parent = d.prefix.substr(0, d.prefix.size() - 1);
    const auto [it, fresh] = parent_at.try_emplace(parent, parents.size());
    if (fresh) parents.push_back({parent, {}});
    parents[it->second].second.letters += d.prefix.back();
    parents[it->second].second.vectors.push_back(v);
  }
  std::vector<std::string> modes;
  for (const SpatialModeProof& p : r.proofs)
    modes.push_back(json{{"mode", p.mode}, {"vector", vectors.index(names.line(p.mode, p.motzkin, true))}}.dump());
  std::vector<std::string> dead;
  for (const auto& [parent, children] : parents)
    dead.push_back(json{{"parent", parent}, {"letters", children.letters}, {"vectors", children.vectors}}.dump());
  put_lines(out, "vectors", vectors.lines());
  put_lines(out, "dead", dead);
  put_lines(out, "modes", modes);
  return out + "\n}\n";
}

}  // namespace contactcert::solvers::spatial
