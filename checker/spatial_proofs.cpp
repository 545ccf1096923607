#include "checker/spatial_proofs.h"

#include "checker/sparse_motzkin_reader.h"

namespace contactcert::checker::spatial_check {

using exact::Q;
using exact::Vec;
using table2_check::Rows;

struct SpatialProofs::Vector {
  struct Weight {
    std::size_t contact, cls;
    Q w;  ///< on the class's direction
  };
  std::vector<Weight> weights;
  bool dynamics = false;  ///< z != 0
  bool balanced = false;
  int zg = 0;
  std::vector<std::vector<int>> beta_signs;  ///< per contact and edge
};

namespace {

/// The weight columns' rows (u, r x u), u = n + d_j, per contact and edge: built once per scene.
using EdgeRows = std::vector<std::vector<std::vector<Rows::Entry>>>;

/// A line of "vectors", read and verified once.
using Vector = SpatialProofs::Vector;

Vector read_vector(const exact::JsonInput& e, const geometry::SpatialBody& body, const RowBlocks& blocks,
                   const EdgeRows& edges, const Vec<Q>* g) {
  e.expect_keys({"rows", "motzkin"});
  const exact::JsonInput rows = e.at("rows");
  const std::size_t n = rows.size();
  const std::size_t z_rows = g != nullptr ? 6 : 0;
  const Vec<Q> y = read_sparse_motzkin(e.at("motzkin"), n + z_rows);  // the rows', then z's
  Vector v;
  Vec<Q> balance = Vec<Q>::Zero(6);
  for (std::size_t r = 0; r < n; ++r) {
    const exact::JsonInput row = rows.at(r);
    if (!row.is_array() || row.size() != 3) row.fail("a row [contact, letter, row of the letter]");
    const auto i = static_cast<std::size_t>(row.at(0).integer(0, static_cast<long>(edges.size()) - 1));
    const std::string L = row.at(1).string();
    const auto* letter = L.size() == 1 ? blocks.rows(i, L[0]) : nullptr;
    if (letter == nullptr) row.at(1).fail("a letter of contact " + std::to_string(i) + ": s, f or A..");
    const RowBlocks::Row& at =
        (*letter)[static_cast<std::size_t>(row.at(2).integer(0, static_cast<long>(letter->size()) - 1))];
    const Q& w = y(static_cast<Eigen::Index>(r));
    if (sgn(w) == 0) row.fail("a row the vector weighs (its motzkin lists every row)");
    for (const Vector::Weight& x : v.weights)
      if (x.contact == i && x.cls == at.cls) row.fail("each functional weighed once: this row's is weighed twice");
    v.weights.push_back({i, at.cls, at.sign > 0 ? w : Q(-w)});
    for (const Rows::Entry& f : blocks.functional(i, at.cls))
      balance(static_cast<Eigen::Index>(f.col)) += v.weights.back().w * f.value;
  }
  const Vec<Q> z = g != nullptr ? Vec<Q>(y.tail(6)) : Vec<Q>(Vec<Q>::Zero(6));
  v.dynamics = !z.isZero();
  for (std::size_t d = 0; d < 6 && v.dynamics; ++d)
    for (const Rows::Entry& f : mass_row(body, d))
      balance(static_cast<Eigen::Index>(f.col)) += z(static_cast<Eigen::Index>(d)) * f.value;
  v.balanced = balance.isZero();
  v.zg = g != nullptr ? sgn(z.dot(*g)) : 0;
  for (const std::vector<std::vector<Rows::Entry>>& contact : edges) {
    std::vector<int>& signs = v.beta_signs.emplace_back(contact.size(), 0);
    for (std::size_t j = 0; j < signs.size() && v.dynamics; ++j) {
      Q dot(0);
      for (const Rows::Entry& f : contact[j]) dot -= z(static_cast<Eigen::Index>(f.col)) * f.value;
      signs[j] = sgn(dot);
    }
  }
  return v;
}

}  // namespace

SpatialProofs::SpatialProofs(const CertificateLines& c, const geometry::SpatialBody& body, const std::vector<Seen>& cs,
                             const Vec<Q>* g)
    : cs_(cs), blocks_(cs) {
  EdgeRows edges;
  for (const Seen& s : cs) {
    edges.emplace_back();
    for (std::size_t j = 0; j < s.d.size(); ++j) edges.back().push_back(along(s, edge_force(s, j)));
  }
  for (std::size_t i = 0; i < c.size("vectors"); ++i)
    vectors_.push_back(read_vector(c.element("vectors", i), body, blocks_, edges, g));
}

SpatialProofs::~SpatialProofs() = default;

bool SpatialProofs::proves(const exact::JsonInput& id, const std::string& letters, bool mode) const {
  if (vectors_.empty()) id.fail("an index of \"vectors\", which lists none");
  const Vector& v = vectors_[static_cast<std::size_t>(id.integer(0, static_cast<long>(vectors_.size()) - 1))];
  if (!v.balanced || (v.dynamics && !mode)) return false;
  bool strict_negative = false;
  for (const Vector::Weight& x : v.weights) {
    if (x.contact >= letters.size()) {  // past a prefix's letters: its row n . A vdot >= 0 (a non-strict inequality)
      const RowBlocks::Row& normal = blocks_.rows(x.contact, 's')->front();
      if (mode || x.cls != normal.cls || normal.sign * sgn(x.w) > 0) return false;
      continue;
    }
    const RowBlocks::Row* on = nullptr;
    for (const RowBlocks::Row& row : *blocks_.rows(x.contact, letters[x.contact]))
      if (row.cls == x.cls && (on == nullptr || (on->strict && !row.strict))) on = &row;
    if (on == nullptr) return false;
    const int y = on->sign * sgn(x.w);
    if (on->strict && y > 0) return false;
    strict_negative = strict_negative || (on->strict && y < 0);
  }
  if (!mode) return strict_negative;
  for (std::size_t i = 0; i < letters.size(); ++i)
    for (const std::size_t j : allowed(cs_[i].d.size(), letters[i]))
      if (v.beta_signs[i][j] < 0) return false;
  return v.zg < 0 || (v.zg == 0 && strict_negative);
}

std::string SpatialProofs::dead_fault(const CertificateLines& c, std::vector<std::string>& dead) const {
  for (std::size_t at = 0; at < c.size("dead"); ++at) {
    const exact::JsonInput e = c.element("dead", at);
    e.expect_keys({"parent", "letters", "vectors"});
    const std::string parent = read_letters(e.at("parent"), cs_, false, true);
    const std::string letters = e.at("letters").string();
    const exact::JsonInput ids = e.at("vectors");
    const std::string alphabet_here = alphabet(cs_[parent.size()].d.size());
    if (letters.empty() || letters.find_first_not_of(alphabet_here) != std::string::npos)
      e.at("letters").fail("letters of contact " + std::to_string(parent.size()) + ": s, f or A.., at least one");
    if (ids.size() != letters.size()) ids.fail("one vector index per letter (" + std::to_string(letters.size()) + ")");
    for (std::size_t l = 0; l < letters.size(); ++l) {
      std::string prefix = parent + letters[l];
      if (!proves(ids.at(l), prefix, false)) return "the kinematic proof for prefix " + prefix + " does not verify";
      dead.push_back(std::move(prefix));
    }
  }
  return {};
}

}  // namespace contactcert::checker::spatial_check
