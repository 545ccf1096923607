// The checkers' own Table 2 rows (checker/table2_rows.h) against the solver's (motion_system.h, cone_form.h) on
// seeded random scenes: written independently, they must agree entry by entry. And forged evidence whose proofs
// hold for wrong rows (a tangent turned the wrong way, a friction coefficient changed) must be refused: a checker
// that shared the solver's model would accept such proofs together with the model's error (issue 17, item 5).
#include "checker/table2_rows.h"

#include <gtest/gtest.h>

#include <random>

#include "checker/modes_check.h"
#include "checker/stability_check.h"
#include "exact/json_input.h"
#include "exact/strict_feasibility.h"
#include "geometry/scene_json.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/wrench_cone/cone_form.h"
#include "tests/solvers/stability/random_scene.h"

namespace contactcert::solvers {
namespace {

using exact::Mat;
using exact::Q;
using exact::StrictSystem;
using exact::Vec;
namespace t2 = checker::table2_check;

geometry::PlanarScene parse(const std::string& text) {
  return geometry::read_planar_scene(exact::JsonInput::parse(text, "scene.json"));
}

bool flag(const std::vector<bool>& v, std::size_t j) { return !v.empty() && v[j]; }

// The checker's rows as a dense system, to compare with the solver's.
StrictSystem<Q> dense(const t2::Rows& r) {
  StrictSystem<Q> s;
  s.A = Mat<Q>::Zero(static_cast<Eigen::Index>(r.rows.size()), static_cast<Eigen::Index>(r.columns.size()));
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    for (const auto& e : r.rows[i]) s.A(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(e.col)) += e.value;
  s.b = r.b.size() ? r.b : Vec<Q>(Vec<Q>::Zero(s.A.rows()));
  for (t2::Rows::Sign c : r.columns) {
    s.is_free.push_back(c == t2::Rows::Sign::kFree);
    s.strict.push_back(c == t2::Rows::Sign::kPositive);
  }
  return s;
}

void expect_same(const StrictSystem<Q>& checker, const StrictSystem<Q>& solver, const std::string& what) {
  ASSERT_EQ(checker.A.rows(), solver.A.rows()) << what;
  ASSERT_EQ(checker.A.cols(), solver.A.cols()) << what;
  EXPECT_TRUE(checker.A == solver.A) << what;
  EXPECT_TRUE(checker.b == (solver.b.size() ? solver.b : Vec<Q>(Vec<Q>::Zero(solver.A.rows())))) << what;
  for (std::size_t j = 0; j < static_cast<std::size_t>(solver.A.cols()); ++j) {
    EXPECT_EQ(flag(checker.is_free, j), flag(solver.is_free, j)) << what << " column " << j;
    EXPECT_EQ(flag(checker.strict, j), flag(solver.strict, j)) << what << " column " << j;
  }
}

ModeString random_mode(std::mt19937_64& rng, const std::vector<Interaction>& letters, std::size_t length) {
  ModeString m;
  for (std::size_t i = 0; i < length; ++i) m.letters.push_back(letters[rng() % letters.size()]);
  return m;
}

Vec<Q> random_wrench(std::mt19937_64& rng) {
  Vec<Q> g(3);
  for (Eigen::Index d = 0; d < 3; ++d) {
    // The denominator is drawn first, as gcc evaluated the two constructor arguments (right to left).
    const auto den = static_cast<long>(1 + rng() % 3);
    g(d) = Q(static_cast<long>(rng() % 7) - 3, den);
  }
  return g;
}

TEST(Table2RowsCheck, EqualTheSolversRowsOnRandomScenes) {
  std::mt19937_64 rng(1702);
  int motion = 0, kinematic = 0, cones = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const geometry::PlanarScene full = parse(test::random_scene(rng, 1 + static_cast<std::size_t>(rng() % 4)));
    const std::size_t n = full.fixels.size();
    // The Jacobian: the checker's primitive frames are the solver's integer columns.
    const t2::CheckedScene all = t2::checked_scene(full, false);
    const Mat<Q> J = jacobian(full);
    for (std::size_t i = 0; i < n; ++i)
      for (Eigen::Index d = 0; d < 3; ++d) {
        EXPECT_EQ(all.fixels[i].w_n[static_cast<std::size_t>(d)], J(d, static_cast<Eigen::Index>(i)));
        EXPECT_EQ(all.fixels[i].w_t[static_cast<std::size_t>(d)], J(d, static_cast<Eigen::Index>(n + i)));
      }
    // Kinematic rows of prefixes over every letter of the modes alphabet, s strict or as printed.
    const bool printed = rng() % 2;
    std::vector<bool> touching;
    for (const auto& f : full.fixels) touching.push_back(f.frame.touching());
    const ModeAlphabet alphabet{{touching, printed}, true};
    const MotionModel<Q> all_model = motion_model<Q>(full);
    for (int p = 0; p < 4; ++p) {
      ModeString prefix;
      for (std::size_t i = 0, len = 1 + rng() % n; i < len; ++i) {
        const auto letters = alphabet.letters(i);
        prefix.letters.push_back(letters[rng() % letters.size()]);
      }
      t2::Rows rows;
      ASSERT_TRUE(t2::kinematic_rows(all, prefix.text(), printed, rows)) << prefix.text();
      expect_same(dense(rows), kinematic_system(all_model, prefix, alphabet.rules).dense(), "prefix " + prefix.text());
      ++kinematic;
    }
    // Moving modes and the resting system of the touching fixels.
    const geometry::PlanarScene touching_only = touching_scene(full);
    const std::size_t k = touching_only.fixels.size();
    const t2::CheckedScene checked = t2::checked_scene(full, true);
    ASSERT_EQ(checked.fixels.size(), k);
    const MotionModel<Q> model = motion_model<Q>(touching_only);
    const Vec<Q> g = random_wrench(rng);
    expect_same(dense(t2::resting_rows(checked, g)),
                motion_system(model, ModeString{std::vector<Interaction>(k, Interaction::kRoll)}, true).with_wrench(g),
                "resting");
    if (k > 0)
      for (int m = 0; m < 4; ++m) {
        const ModeString mode = random_mode(
            rng, {Interaction::kSeparate, Interaction::kSlideLeft, Interaction::kSlideRight, Interaction::kRoll}, k);
        t2::Rows rows;
        ASSERT_TRUE(t2::motion_rows(checked, mode.text(), g, rows)) << mode.text();
        expect_same(dense(rows), motion_system(model, mode).with_wrench(g), "mode " + mode.text());
        ++motion;
      }
    // The wrench cone's K and P (eqs. 15, 17) of modes of all fixels, rebuilt from the checker's columns with
    // M^-1 = diag(p, p, q) for I/m = p/q.
    const ContactModel<Q> cm = contact_model<Q>(full);
    const Q& inertia = full.workpiece.inertia_per_mass;
    for (int m = 0; m < 3; ++m) {
      ModeString mode;
      for (std::size_t i = 0; i < n; ++i) {
        const auto letters = letters_for(touching[i]);
        mode.letters.push_back(letters[rng() % letters.size()]);
      }
      const ConeForm<Q> f = cone_form<Q>(full, cm, mode);
      t2::ConeColumns cols;
      ASSERT_TRUE(t2::cone_columns(all, mode.text(), cols)) << mode.text();
      const auto rows = static_cast<Eigen::Index>(cols.row_wrenches.size());
      Mat<Q> K = Mat<Q>::Zero(rows, static_cast<Eigen::Index>(cols.z.size())), P(rows, 3);
      auto m_inv = [&](const std::array<Q, 3>& w) {
        return std::array<Q, 3>{w[0] * inertia.get_num(), w[1] * inertia.get_num(), w[2] * inertia.get_den()};
      };
      for (Eigen::Index r = 0; r < rows; ++r) {
        const auto wr = m_inv(cols.row_wrenches[static_cast<std::size_t>(r)]);
        for (Eigen::Index d = 0; d < 3; ++d) P(r, d) = wr[static_cast<std::size_t>(d)];
        for (std::size_t j = 0; j < cols.z.size(); ++j) {
          const auto& z = cols.z[j];
          const auto c = static_cast<Eigen::Index>(j);
          if (z.acceleration) {
            if (static_cast<Eigen::Index>(z.row) == r) K(r, c) = z.sign;
            continue;
          }
          const t2::CheckedFixel& fx = all.fixels[z.fixel];
          for (std::size_t d = 0; d < 3; ++d) K(r, c) -= wr[d] * (fx.w_n[d] + z.t_per_n * fx.w_t[d]);
        }
      }
      EXPECT_TRUE(K == f.K) << mode.text();
      EXPECT_TRUE(P == f.P) << mode.text();
      std::vector<std::string> names;
      std::vector<bool> strict;
      for (const auto& z : cols.z) names.push_back(z.name), strict.push_back(z.strict);
      EXPECT_EQ(names, f.names) << mode.text();
      EXPECT_EQ(strict, f.strict) << mode.text();
      // The contact forces a z applies (the witness view of cone_nonempty certificates): the solver's columns
      // (fixel, t_per_n) and the checker's give the same c, on a z with distinct entries.
      Vec<Q> z(static_cast<Eigen::Index>(cols.z.size()));
      for (Eigen::Index j = 0; j < z.size(); ++j) z(j) = Q(static_cast<long>(j) + 1) / Q(7);
      std::vector<Eigen::Index> on;
      std::vector<std::size_t> on_checker;
      for (std::size_t i = 0; i < n; ++i)
        if (touching[i]) on.push_back(static_cast<Eigen::Index>(i)), on_checker.push_back(i);
      EXPECT_TRUE(contact_forces(f, on, z) == t2::cone_contact_forces(cols, on_checker, z)) << mode.text();
      ++cones;
    }
  }
  EXPECT_GT(motion, 100);
  EXPECT_GT(kinematic, 200);
  EXPECT_GT(cones, 150);
}

// A strongly stable claim built from a wrong model by the solver's own machinery: resting forces, the dead prefixes
// of its mode tree and a Motzkin vector for each of its kinematically feasible moving modes, each valid for the
// wrong model's rows. Empty if that model does not find g strongly stable.
std::optional<StabilityResult<Q>> claim_from_model(const MotionModel<Q>& model, const Vec<Q>& g) {
  const std::size_t k = model.mu_s.size();
  const ModeString rolling{std::vector<Interaction>(k, Interaction::kRoll)};
  StabilityResult<Q> r;
  const MotionSystem<Q> rest = motion_system(model, rolling, true);
  auto resting = exact::strict_feasibility(rest.with_wrench(g));
  if (resting.status != exact::StrictStatus::kFeasible) return std::nullopt;
  r.has_resting = true;
  r.resting_forces = rest.forces(resting.x);
  const ModeTree<Q> tree = walk_modes(model, moving_alphabet(k), {});
  for (const auto& d : tree.dead) r.proofs.push_back({d.prefix, true, d.motzkin});
  for (const ModeString& m : tree.modes) {
    if (m.text() == rolling.text()) continue;
    const auto sys = motion_system(model, m).with_wrench(g);
    auto f = exact::strict_feasibility(sys);
    if (f.status == exact::StrictStatus::kFeasible) return std::nullopt;
    EXPECT_TRUE(exact::verify_motzkin(sys, f.motzkin));  // valid for the wrong model's rows
    r.proofs.push_back({m, false, f.motzkin});
  }
  r.verdict = StabilityVerdict::kStronglyStable;
  return r;
}

// Whether every vector of the claim also holds for the true model's rows.
bool holds_for(const MotionModel<Q>& model, const Vec<Q>& g, const StabilityResult<Q>& claim) {
  const std::size_t k = model.mu_s.size();
  const MotionSystem<Q> rest = motion_system(model, ModeString{std::vector<Interaction>(k, Interaction::kRoll)}, true);
  if (!exact::verify_strict_point(rest.with_wrench(g), rest.point(Vec<Q>(), claim.resting_forces))) return false;
  for (const ModeProof<Q>& p : claim.proofs)
    if (!exact::verify_motzkin(
            p.kinematic ? kinematic_system(model, p.mode).dense() : motion_system(model, p.mode).with_wrench(g),
            p.motzkin))
      return false;
  return true;
}

// Claims whose vectors hold for the rows of a wrong model - every contact frame turned round (n_i from the
// workpiece to the fixel: the sign of every row of J flipped), or friction coefficients changed - are refused
// unless every vector also holds for the true rows, and false verdicts are refused.
TEST(Table2RowsCheck, RefusesProofsOfWrongRows) {
  std::mt19937_64 rng(17);
  int refused_flipped = 0, refused_friction = 0, false_verdicts = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const geometry::PlanarScene full = parse(test::random_scene(rng, 2 + static_cast<std::size_t>(rng() % 2)));
    const geometry::PlanarScene scene = touching_scene(full);
    const std::size_t k = scene.fixels.size();
    if (k == 0) continue;
    const Vec<Q> g = random_wrench(rng);
    const bool strongly = strong_stability<Q>(full, g).verdict == StabilityVerdict::kStronglyStable;
    const MotionModel<Q> truth = motion_model<Q>(scene);
    MotionModel<Q> flipped = truth, friction = truth;
    flipped.J *= Q(-1);  // every n_i (and so t_i) from the workpiece to the fixel
    for (std::size_t i = 0; i < k; ++i) friction.mu_s[i] += 2, friction.mu_k[i] += 2;
    for (const MotionModel<Q>* wrong : {&flipped, &friction}) {
      const auto claim = claim_from_model(*wrong, g);
      if (!claim) continue;
      const std::string why = checker::check_stability(full, g, *claim);
      if (!strongly) {
        EXPECT_NE(why, "") << "a false strongly stable claim was accepted";
        ++false_verdicts;
      }
      if (holds_for(truth, g, *claim)) continue;
      EXPECT_NE(why, "") << "a proof of wrong rows was accepted";
      ++(wrong == &flipped ? refused_flipped : refused_friction);
    }
  }
  EXPECT_GE(refused_flipped, 5);
  EXPECT_GE(refused_friction, 20);
  EXPECT_GE(false_verdicts, 20);
}

// A "modes" certificate written from a model with one tangent turned the wrong way (a sign flipped in its rows) is
// refused unless the two lists happen to coincide.
TEST(Table2RowsCheck, RefusesModeListsOfWrongRows) {
  std::mt19937_64 rng(71);
  int refused = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const std::string text = test::random_scene(rng, 2 + static_cast<std::size_t>(rng() % 2));
    const geometry::PlanarScene scene = parse(text);
    ContactModes truth = contact_modes(scene);
    ContactModes forged = truth;
    const auto k = static_cast<Eigen::Index>(scene.fixels.size());
    forged.model.J.col(k) *= Q(-1);  // fixel 1's tangent turned the wrong way: its l and r swap
    forged.tree = walk_modes(forged.model, forged.alphabet, {});
    const auto check =
        checker::check_modes_certificate(exact::JsonInput::parse(modes_certificate(text, forged), "m.json"));
    std::vector<std::string> listed, actual;
    for (const auto& m : forged.tree.modes) listed.push_back(m.text());
    for (const auto& m : truth.tree.modes) actual.push_back(m.text());
    std::sort(listed.begin(), listed.end());
    std::sort(actual.begin(), actual.end());
    if (listed == actual) continue;
    EXPECT_FALSE(check.valid) << text;
    ++refused;
  }
  EXPECT_GT(refused, 5);
}

}  // namespace
}  // namespace contactcert::solvers
