#include "checker/assembly_modes_check.h"

#include "checker/assembly_check.h"
#include "checker/modes_check.h"
#include "checker/sparse_motzkin_reader.h"
#include "exact/input_error.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using exact::Vec;

using table2_check::Rows;
using Sign = Rows::Sign;
using Accelerations = std::vector<std::array<std::vector<Rows::Entry>, 2>>;

/// The kinematic rows of a prefix in the layout of assembly_modes.h.
Rows prefix_rows(const Accelerations& acc, std::size_t dims, const std::string& letters) {
  Rows R;
  R.columns.assign(dims, Sign::kFree);
  for (std::size_t i = 0; i < letters.size(); ++i) {
    const char L = letters[i];
    std::size_t sigma = 0;
    if (L != 'n') {
      sigma = R.columns.size();
      R.columns.push_back(Sign::kPositive);
    }
    R.rows.push_back(acc[i][0]);  // a_n
    if (L == 's') {
      R.rows.back().push_back({sigma, Q(-1)});
      continue;
    }
    R.rows.push_back(acc[i][1]);  // a_t
    if (L != 'n') R.rows.back().push_back({sigma, Q(L == 'l' ? -1 : 1)});
  }
  return R;
}

/// Whether vdot meets Table 2's signs of the mode at every contact, read directly.
bool realises(const Accelerations& acc, const std::string& mode, const Vec<Q>& vdot) {
  for (std::size_t i = 0; i < mode.size(); ++i) {
    int sign[2];
    for (std::size_t r = 0; r < 2; ++r) {
      Q a(0);
      for (const Rows::Entry& e : acc[i][r]) a += e.value * vdot(static_cast<Eigen::Index>(e.col));
      sign[r] = sgn(a);
    }
    const char L = mode[i];
    const bool ok = L == 's' ? sign[0] > 0 : sign[0] == 0 && sign[1] == (L == 'l' ? 1 : L == 'r' ? -1 : 0);
    if (!ok) return false;
  }
  return true;
}

}  // namespace

ModesCertificateCheck check_assembly_modes_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "scene", "problem_sha256", "modes", "dead"});
  const exact::JsonInput embedded = exact::JsonInput::parse(c.at("scene").string(), c.file() + " (embedded scene)");
  const geometry::Assembly a = geometry::read_assembly(embedded);
  if (c.at("problem_sha256").string() != embedded.canonical_sha256())
    return {false, "problem_sha256 is not the digest of the embedded scene", 0, 0};
  const CheckedAccelerations acc = checked_accelerations(a);
  if (!acc.violation.empty()) return {false, acc.violation, 0, 0};
  const std::size_t k = a.contacts.size(), dims = 3 * a.bodies.size();
  std::vector<std::string> leaves, dead;
  for (const exact::JsonInput& e : c.at("modes").elements()) {
    e.expect_keys({"mode", "acceleration"});
    std::string m = read_mode_letters(e.at("mode"), ModeAlphabet{}, k, false);
    if (!realises(acc.rows, m, e.at("acceleration").rational_vector(dims)))
      return {false, "the acceleration listed for mode " + m + " does not realise it (Table 2)", 0, 0};
    leaves.push_back(std::move(m));
  }
  for (const exact::JsonInput& e : c.at("dead").elements()) {
    e.expect_keys({"prefix", "motzkin"});
    std::string p = read_mode_letters(e.at("prefix"), ModeAlphabet{}, k, true);
    const Rows rows = prefix_rows(acc.rows, dims, p);
    if (!table2_check::motzkin_holds(rows, read_sparse_motzkin(e.at("motzkin"), rows.rows.size())))
      return {false, "the certificate of dead prefix " + p + " does not verify", 0, 0};
    dead.push_back(std::move(p));
  }
  return modes_coverage_check(k, ModeAlphabet{}, dead, leaves);
}

}  // namespace contactcert::checker
