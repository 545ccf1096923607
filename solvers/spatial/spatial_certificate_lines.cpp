#include "solvers/spatial/spatial_certificate_lines.h"

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "exact/rational_text.h"

namespace contactcert::solvers::spatial {

using Index = Eigen::Index;
using exact::Z;

RowNames::RowNames(const SpatialModel& model) {
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

std::string RowNames::line(const std::string& letters, const Vec<Q>& y, bool dynamics) const {
  std::vector<std::pair<std::array<std::size_t, 3>, Q>> weights;  // (contact, letter, row), weight
  Index at = 0;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    // Past the letters, the row a_n >= 0: named by s's one row, the functional n.
    const std::vector<Name>& rows = names_[i][alphabets_[i].find(i < letters.size() ? letters[i] : 's')];
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

std::size_t VectorLines::index(std::string line) {
  const auto [it, fresh] = index_.try_emplace(std::move(line), lines_.size());
  if (fresh) lines_.push_back(&it->first);
  return it->second;
}

std::vector<std::string> VectorLines::lines() const {
  std::vector<std::string> out;
  for (const std::string* l : lines_) out.push_back(*l);
  return out;
}

std::vector<std::string> dead_lines(const SpatialModeTree& tree, const RowNames& names, VectorLines& vectors) {
  struct Children {
    std::string letters;
    std::vector<std::size_t> vectors;
  };
  std::vector<std::pair<std::string, Children>> parents;
  std::unordered_map<std::string, std::size_t> parent_at;
  // One dense vector at a time: each proof's line made from the first prefix it proves.
  std::vector<std::size_t> vector_of(tree.proofs.size(), tree.proofs.size());
  for (const SpatialDeadPrefix& d : tree.dead) {
    std::size_t& v = vector_of[d.proof];
    if (v == tree.proofs.size()) v = vectors.index(names.line(d.prefix, dead_motzkin(tree, d), false));
    const std::string parent = d.prefix.substr(0, d.prefix.size() - 1);
    const auto [it, fresh] = parent_at.try_emplace(parent, parents.size());
    if (fresh) parents.push_back({parent, {}});
    parents[it->second].second.letters += d.prefix.back();
    parents[it->second].second.vectors.push_back(v);
  }
  std::vector<std::string> dead;
  for (const auto& [parent, children] : parents)
    dead.push_back(
        nlohmann::ordered_json{{"parent", parent}, {"letters", children.letters}, {"vectors", children.vectors}}
            .dump());
  return dead;
}

void put_lines(std::string& out, const char* name, const std::vector<std::string>& lines) {
  out += std::string(",\n \"") + name + "\": [";
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? ",\n  " : "\n  ") + lines[i];
  out += "\n ]";
}

}  // namespace contactcert::solvers::spatial
