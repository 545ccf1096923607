#include "checker/mode_coverage.h"

namespace contactcert::checker {

namespace {

/// The listed strings as a trie (first child, next sibling): one node per distinct prefix, so its size is at most
/// the lists' total length plus one, and a prefix is walked without being copied.
class PrefixTrie {
 public:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Node {
    std::size_t parent = kNone, first_child = kNone, next_sibling = kNone;
    std::size_t depth = 0;
    char letter = 0;
    bool listed = false;
  };

  PrefixTrie() : nodes_(1) {}

  /// Adds s; false if s was listed already.
  bool insert(const std::string& s) {
    std::size_t at = 0;
    for (const char c : s) {
      std::size_t next = child(at, c);
      if (next == kNone) {
        next = nodes_.size();
        Node n;
        n.parent = at;
        n.next_sibling = nodes_[at].first_child;
        n.depth = nodes_[at].depth + 1;
        n.letter = c;
        nodes_.push_back(n);
        nodes_[at].first_child = next;
      }
      at = next;
    }
    const bool fresh = !nodes_[at].listed;
    nodes_[at].listed = true;
    return fresh;
  }

  std::size_t size() const { return nodes_.size(); }

  std::size_t child(std::size_t at, char c) const {
    std::size_t n = nodes_[at].first_child;
    while (n != kNone && nodes_[n].letter != c) n = nodes_[n].next_sibling;
    return n;
  }

  const Node& operator[](std::size_t at) const { return nodes_[at]; }

  /// The prefix that node `at` stands for.
  std::string text(std::size_t at) const {
    std::string out(nodes_[at].depth, ' ');
    for (; at != 0; at = nodes_[at].parent) out[nodes_[at].depth - 1] = nodes_[at].letter;
    return out;
  }

 private:
  std::vector<Node> nodes_;
};

}  // namespace

std::optional<CoverageGap> mode_coverage(std::size_t k, const ModeAlphabet& alphabet,
                                         const std::vector<std::string>& dead, const std::vector<std::string>& leaves) {
  return mode_coverage(k, [&](std::size_t i) { return alphabet.letters(i); }, dead, leaves);
}

std::optional<CoverageGap> mode_coverage(std::size_t k, const std::function<std::string(std::size_t)>& letters,
                                         const std::vector<std::string>& dead, const std::vector<std::string>& leaves) {
  using Kind = CoverageGap::Kind;
  // A prefix is accounted for if it is listed (dead, or a full-length leaf); the walk descends only into
  // proper prefixes of listed strings, so it never expands more than the lists spell out. Memory and time are
  // linear in the lists' total length (each trie node is visited once, each with at most the fixel's letters).
  PrefixTrie trie;
  for (const auto* list : {&dead, &leaves})
    for (const auto& s : *list)
      if (s.size() <= k && (list == &dead || s.size() == k) && !trie.insert(s))
        return CoverageGap{Kind::kRepeated, s, {}};
  // The listed strings are disjoint sets of modes exactly when none is a proper prefix of another: a listed node
  // has no children. (Every trie leaf is listed, so a child leads down to the listed string inside.)
  for (std::size_t at = 0; at < trie.size(); ++at) {
    if (!trie[at].listed || trie[at].first_child == PrefixTrie::kNone) continue;
    std::size_t inside = trie[at].first_child;
    while (!trie[inside].listed) inside = trie[inside].first_child;
    return CoverageGap{Kind::kInside, trie.text(inside), trie.text(at)};
  }
  if (trie[0].listed) return std::nullopt;  // the empty prefix itself is listed: every mode is covered
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const std::size_t at = stack.back();
    stack.pop_back();
    if (trie[at].depth == k) return CoverageGap{Kind::kMissing, trie.text(at), {}};  // a full mode nothing lists
    for (const char L : letters(trie[at].depth)) {
      const std::size_t next = trie.child(at, L);
      if (next == PrefixTrie::kNone) return CoverageGap{Kind::kMissing, trie.text(at) + L, {}};
      if (!trie[next].listed) stack.push_back(next);
    }
  }
  return std::nullopt;
}

std::string coverage_gap_text(const CoverageGap& gap) {
  switch (gap.kind) {
    case CoverageGap::Kind::kMissing:
      return "the modes starting with '" + gap.prefix + "' are neither listed nor proven infeasible";
    case CoverageGap::Kind::kRepeated:
      return "'" + gap.prefix + "' is listed twice (each mode and each dead prefix belongs in the list once)";
    case CoverageGap::Kind::kInside:
      return "'" + gap.prefix + "' extends the listed prefix '" + gap.within +
             "', which accounts for its modes already (an extra entry)";
  }
  return {};
}

}  // namespace contactcert::checker
