// The stability walk's reuse of dead prefixes' certificates (assembly_certificate_memory.h): a remembered Motzkin
// vector, carried by row labels onto another prefix's system, is given back only where it proves that system
// infeasible; and the walk that uses it keeps its verdicts and valid evidence while solving fewer LPs.
#include "solvers/assembly/assembly_certificate_memory.h"

#include <gtest/gtest.h>

#include <set>

#include "checker/assembly_check.h"
#include "tests/solvers/assembly/assembly_fixtures.h"

namespace contactcert::solvers::assembly {
namespace {

/// A row of n boxes on the ground, each pushed along +x by a quarter of its weight (strongly stable for n = 2, 4: the
/// root's system, every contact relaxed, is feasible and the walk proves many prefixes dead).
geometry::Assembly windy_row(std::size_t n) {
  testing::SceneText s = testing::box_row(n);
  for (std::string& b : s.bodies) b.insert(b.size() - 1, R"(, "load": ["1/2", -2, 0])");
  return s.read();
}

/// The system of a prefix in the walk's contact order `order` (AssemblyStabilityResult::contact_order).
AssemblySystem prefix_system(const AssemblyModel& m, const std::vector<std::size_t>& order, const std::string& prefix) {
  return assembly_system(m, file_letters(order, prefix));
}

TEST(AssemblyCertificateMemory, RowLabelsNameEveryRowOnce) {
  const AssemblyModel m = assembly_model(windy_row(2));
  for (const std::string& letters : {std::string("******"), std::string("slrn*s"), std::string("nnnnnn")}) {
    const AssemblySystem s = assembly_system(m, letters);
    ASSERT_EQ(static_cast<Eigen::Index>(s.row_label.size()), s.system.rows);
    EXPECT_EQ(std::set<Eigen::Index>(s.row_label.begin(), s.row_label.end()).size(), s.row_label.size()) << letters;
  }
}

TEST(AssemblyCertificateMemory, RecallsOnlyCertificatesThatHold) {
  const geometry::Assembly a = windy_row(2);
  const AssemblyModel m = assembly_model(a);
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.verdict, AssemblyVerdict::kStronglyStable);
  ASSERT_GE(r.dead.size(), 2u);
  const AssemblyDeadPrefix& d = r.dead.front();
  const AssemblySystem dead = prefix_system(m, r.contact_order, d.prefix);
  ASSERT_TRUE(motzkin_holds(dead, d.motzkin));
  // A wrong vector fails: its negation, and (the system being infeasible only through it) zero.
  EXPECT_FALSE(motzkin_holds(dead, Vec<Q>(-d.motzkin)));
  EXPECT_FALSE(motzkin_holds(dead, Vec<Q>(Vec<Q>::Zero(d.motzkin.size()))));
  EXPECT_FALSE(motzkin_holds(dead, Vec<Q>(d.motzkin.head(d.motzkin.size() - 1))));
  // Any positive multiple holds, also where its doubles overflow or underflow (the float pre-test only rejects a
  // vector far from the conditions; the exact test decides).
  Q huge(1), tiny(1);
  mpz_ui_pow_ui(huge.get_num_mpz_t(), 10, 400);
  mpz_ui_pow_ui(tiny.get_den_mpz_t(), 10, 400);
  EXPECT_TRUE(motzkin_holds(dead, Vec<Q>(d.motzkin * huge)));
  EXPECT_TRUE(motzkin_holds(dead, Vec<Q>(d.motzkin * tiny)));
  EXPECT_FALSE(motzkin_holds(dead, Vec<Q>(-d.motzkin * huge)));

  CertificateMemory memory;
  EXPECT_FALSE(memory.recall(dead, d.prefix.size()));  // nothing remembered yet
  memory.remember(dead, d.prefix.size(), d.motzkin);
  const std::optional<Vec<Q>> again = memory.recall(dead, d.prefix.size());
  ASSERT_TRUE(again);
  EXPECT_TRUE(motzkin_holds(dead, *again));
  // The root's system (every contact relaxed) is feasible: no certificate can hold there, whatever is remembered.
  for (const AssemblyDeadPrefix& e : r.dead) memory.remember(prefix_system(m, r.contact_order, e.prefix), 0, e.motzkin);
  EXPECT_FALSE(memory.recall(prefix_system(m, r.contact_order, ""), 0));
  // Every recall on a dead prefix's system gives a certificate of that system.
  for (const AssemblyDeadPrefix& e : r.dead) {
    const AssemblySystem s = prefix_system(m, r.contact_order, e.prefix);
    if (const std::optional<Vec<Q>> y = memory.recall(s, 0)) {
      EXPECT_TRUE(motzkin_holds(s, *y)) << e.prefix;
    }
  }
}

// The walk with the memory: the row of four boxes under wind is strongly stable, its certificate checks, and more
// prefixes are proved dead than LPs are solved for them (the rest recalled).
TEST(AssemblyCertificateMemory, WalkReusesCertificates) {
  const geometry::Assembly a = windy_row(4);
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.status, AssemblyStatus::kDecided);
  EXPECT_EQ(r.verdict, AssemblyVerdict::kStronglyStable);
  EXPECT_EQ(checker::check_assembly_stability(a, r), "");
  EXPECT_LT(r.lps, r.nodes - static_cast<long>(r.dead.size()) + static_cast<long>(r.dead.size()) / 2);
}

// The walk's LPs take a dead prefix's certificate from the float LP's basis (exact::FloatInfeasible::kBasisCertificate)
// where the rounded one fails the check: on the row of four boxes under wind, some dead prefixes' float certificates
// do not round, and for each of them the basis gives a certificate of that system, where the default gives nothing
// (the verified LP would solve it again).
TEST(AssemblyCertificateMemory, DeadPrefixCertificatesFromTheFloatBasis) {
  const geometry::Assembly a = windy_row(4);
  const AssemblyModel m = assembly_model(a);
  const AssemblyStabilityResult r = assembly_stability(a);
  ASSERT_EQ(r.verdict, AssemblyVerdict::kStronglyStable);
  int from_basis = 0;
  for (const AssemblyDeadPrefix& d : r.dead) {
    const AssemblySystem s = prefix_system(m, r.contact_order, d.prefix);
    const exact::StrictSolver<Q> solver(s.system);
    bool feasible = true;
    if (solver.solve_rounded(s.b, &feasible) || feasible) continue;
    const std::optional<exact::StrictFeasibility<Q>> f =
        solver.solve_rounded(s.b, &feasible, nullptr, exact::FloatInfeasible::kBasisCertificate);
    ASSERT_TRUE(f) << d.prefix;
    ASSERT_EQ(f->status, exact::StrictStatus::kInfeasible);
    EXPECT_TRUE(exact::verify_motzkin(s.system.dense(s.b), f->motzkin)) << d.prefix;
    ++from_basis;
  }
  EXPECT_GT(from_basis, 0);
}

}  // namespace
}  // namespace contactcert::solvers::assembly
