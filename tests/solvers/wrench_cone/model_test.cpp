// The model of the wrench cone paper, exactly: the section 4 example's Jacobian and eq. (12), the
// matrices K and P of section 4 and their identity with E C N R S V and E B (eqs. 15, 17), modes.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "exact/linalg.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "solvers/wrench_cone/cone_form.h"

namespace contactcert::solvers {
namespace {

using geometry::PlanarScene;

PlanarScene section4_scene() { return geometry::load_planar_scene(CONTACTCERT_SCENES_DIR "/bt2002_section4_disk.json"); }

Mat<Q> mat(std::initializer_list<std::initializer_list<const char*>> rows) {
  Mat<Q> M(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.begin()->size()));
  Eigen::Index i = 0;
  for (const auto& r : rows) {
    Eigen::Index j = 0;
    for (const char* x : r) M(i, j++) = exact::parse_rational(x);
    ++i;
  }
  return M;
}

ModeString mode_of(const PlanarScene& s, const std::string& text) {
  std::vector<bool> touching;
  for (const auto& f : s.fixels) touching.push_back(f.frame.touching());
  const ModeParse p = parse_mode(text, touching);
  EXPECT_EQ(p.status, ModeStatus::kValid) << p.message;
  return p.mode;
}

TEST(Section4, JacobianMatchesThePaper) {
  const PlanarScene s = section4_scene();
  const Mat<Q> J = jacobian(s);
  // The scene gives fixel 2 by its position (11/10, 0), so n_2 = (-11/10, 0); the Jacobian scales
  // each frame to a primitive integer normal, which gives the paper's unit normal (-1, 0).
  EXPECT_TRUE(s.fixels[1].frame.normal == (geometry::Point2{Q(-11, 10), Q(0)}));
  EXPECT_EQ(J, mat({{"0", "-1", "-1", "0"}, {"1", "0", "0", "-1"}, {"0", "0", "-1", "-1"}}));
}

PlanarScene unit_normal_section4() {
  // The same scene with fixel 2 given as an explicit contact with a unit normal, so that the matrices
  // are literally the paper's.
  return geometry::read_planar_scene(exact::JsonInput::parse(R"({"kind":"planar",
    "workpiece":{"shape":{"type":"disk","center":[0,0],"radius":1},"mass":1,"inertia":1},
    "fixels":[{"position":[0,-1]},{"point":[1,0],"normal":[-1,0],"gap":"1/10"}],"mu_s":"0.2","mu_k":"0.2"})", "unit.json"));
}

TEST(Section4, Equation12IsReproducedExactly) {
  const ContactModel<Q> m = contact_model<Q>(unit_normal_section4());
  EXPECT_EQ(m.J, mat({{"0", "-1", "-1", "0"}, {"1", "0", "0", "-1"}, {"0", "0", "-1", "-1"}}));
  EXPECT_EQ(m.C(), mat({{"1", "0", "0", "0", "-1", "0", "0", "1"},
                      {"0", "1", "0", "0", "0", "-1", "-1", "0"},
                      {"0", "0", "1", "0", "0", "-1", "-2", "-1"},
                      {"0", "0", "0", "1", "1", "0", "-1", "-2"}}));
  EXPECT_EQ(m.B, mat({{"0", "1", "0"}, {"-1", "0", "0"}, {"-1", "0", "-1"}, {"0", "-1", "-1"}}));
}

TEST(Section4, KAndPOfModeNaAreThePapers) {
  const PlanarScene s = unit_normal_section4();
  const ContactModel<Q> m = contact_model<Q>(s);
  const ConeForm<Q> f = cone_form(s, m, mode_of(s, "na"));
  // Paper: K = [0 -1 -1; -1 mu -mu; 0 2mu -2mu], P = [0 1 0; -1 0 0; -1 0 -1], mu = 0.2.
  EXPECT_EQ(f.K, mat({{"0", "-1", "-1"}, {"-1", "1/5", "-1/5"}, {"0", "2/5", "-2/5"}}));
  EXPECT_EQ(f.P, mat({{"0", "1", "0"}, {"-1", "0", "0"}, {"-1", "0", "-1"}}));
  EXPECT_EQ(f.strict, (std::vector<bool>{true, false, false}));  // -a2n > 0
  EXPECT_EQ(f.names[0], "-a2n");
  // G = P^-1 K: the paper's printed span form [1 -0.2 0.2; 0 -1 -1; -1 -0.2 0.2].
  const Mat<Q> G = *exact::inverse<Q>(f.P) * f.K;
  EXPECT_EQ(G, mat({{"1", "-1/5", "1/5"}, {"0", "-1", "-1"}, {"-1", "-1/5", "1/5"}}));
  // The paper's matrices of section 5: R has r75 = -0.2, r57 = 1, r77 = 0.2 (1-based); E drops row 4.
  const ModeMatrices<Q> mm = mode_matrices<Q>(s, mode_of(s, "na"));
  EXPECT_EQ(mm.R(6, 4), Q(-1, 5));
  EXPECT_EQ(mm.R(4, 6), 1);
  EXPECT_EQ(mm.R(6, 6), Q(1, 5));
  EXPECT_EQ(mm.E, mat({{"1", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "1", "0"}}));
  EXPECT_EQ(mm.N(1, 1), -1);
  EXPECT_EQ(mm.V.cols(), 3);
}

TEST(ConeForm, DirectKEqualsTheLiteralProductECNRSVOnEveryModeOfSeveralScenes) {
  const char* files[] = {"/bt2002_fig4a_lla.json", "/bt2002_fig4c_peg_lra.json", "/bt2002_section4_disk.json",
                         "/bt2002_fig4b_nnn.json"};
  int checked = 0;
  for (const char* file : files) {
    const PlanarScene s = geometry::load_planar_scene(std::string(CONTACTCERT_SCENES_DIR) + file);
    const ContactModel<Q> m = contact_model<Q>(s);
    const std::size_t n = s.fixels.size();
    // Every mode: odometer over the letters that fit each fixel.
    std::vector<std::vector<Interaction>> letters;
    for (const auto& f : s.fixels) letters.push_back(letters_for(f.frame.touching()));
    std::vector<std::size_t> digit(n, 0);
    for (bool more = true; more;) {
      ModeString mode;
      for (std::size_t i = 0; i < n; ++i) mode.letters.push_back(letters[i][digit[i]]);
      const ModeMatrices<Q> mm = mode_matrices<Q>(s, mode);
      const ConeForm<Q> f = cone_form(s, m, mode);
      const Mat<Q> K = mm.E * m.C() * mm.N * mm.R * mm.S * mm.V;  // eq. (15)
      const Mat<Q> P = mm.E * m.B;                                // eq. (17)
      EXPECT_EQ(f.K, K) << file << " " << mode.text();
      EXPECT_EQ(f.P, P) << file << " " << mode.text();
      EXPECT_EQ(f.strict.size(), static_cast<std::size_t>(K.cols()));
      ++checked;
      more = false;
      for (std::size_t i = 0; i < n && !more; ++i) {
        if (++digit[i] < letters[i].size()) more = true;
        else digit[i] = 0;
      }
    }
  }
  EXPECT_EQ(checked, 5 * 5 * 3 + 5 * 5 * 3 + 5 * 3 + 5 * 5 * 5);
}

TEST(ConeForm, SlidingFrictionOpposesTheSlidingDirection) {
  // Table 2: l has c_t = -mu_k c_n, r has c_t = +mu_k c_n (seeds/README.md errata).
  const PlanarScene s = unit_normal_section4();
  const ContactModel<Q> m = contact_model<Q>(s);
  const ConeForm<Q> l = cone_form(s, m, mode_of(s, "ls"));
  const ConeForm<Q> r = cone_form(s, m, mode_of(s, "rs"));
  // The force column of fixel 1 is C_c1n + c_t/c_n * C_c1t with C = [I -A]; rows kept: a1n, a1t, a2n.
  const Q mu(1, 5);
  const Mat<Q> C = m.C();
  Vec<Q> cn(4), ct(4);
  for (int i = 0; i < 4; ++i) {
    cn(i) = C(i, 4);
    ct(i) = C(i, 6);
  }
  const Vec<Q> left = cn - mu * ct, right = cn + mu * ct;
  ASSERT_EQ(l.K.rows(), 3);
  EXPECT_EQ(l.K(0, 2), left(0));
  EXPECT_EQ(l.K(1, 2), left(1));
  EXPECT_EQ(r.K(1, 2), right(1));
  EXPECT_EQ(l.names[2], "c1[n-mu t]");
  EXPECT_EQ(r.names[2], "c1[n+mu t]");
}

TEST(Modes, ParseValidatesLettersAgainstTheTouchingState) {
  const std::vector<bool> touching = {true, false};
  EXPECT_EQ(parse_mode("na", touching).status, ModeStatus::kValid);
  EXPECT_EQ(parse_mode("ss", touching).status, ModeStatus::kValid);
  EXPECT_EQ(parse_mode("ms", touching).status, ModeStatus::kValid);
  EXPECT_EQ(parse_mode("an", touching).status, ModeStatus::kNeedsGap);
  EXPECT_EQ(parse_mode("nl", touching).status, ModeStatus::kNeedsContact);
  EXPECT_EQ(parse_mode("nx", touching).status, ModeStatus::kUnknownLetter);
  EXPECT_EQ(parse_mode("n", touching).status, ModeStatus::kWrongLength);
  EXPECT_EQ(parse_mode("nau", touching).status, ModeStatus::kWrongLength);
  EXPECT_EQ(parse_mode("nl", touching).fixel, 1u);
  EXPECT_EQ(letters_for(true).size(), 5u);
  EXPECT_EQ(letters_for(false).size(), 3u);
  // Table 2 with the strict separation of a touching fixel.
  EXPECT_EQ(table2(Interaction::kSeparate, true).a_n, SignConstraint::kPositive);
  EXPECT_EQ(table2(Interaction::kSeparate, false).a_n, SignConstraint::kNonNegative);
  EXPECT_EQ(table2(Interaction::kSlideLeft, true).a_t, SignConstraint::kPositive);
  EXPECT_EQ(table2(Interaction::kSlideLeft, true).c_t, FrictionConstraint::kLeftEdge);
}

TEST(Model, FloatModelIsTheExactModelUpToThePositiveScaleOfM) {
  // fig4a: unit normals, integer torques, I/m = 5/3: the exact model uses M^-1 ~ diag(5, 5, 3), the
  // float model diag(1, 1, 3/5), a factor 5 apart.
  const PlanarScene s = geometry::load_planar_scene(CONTACTCERT_SCENES_DIR "/bt2002_fig4a_lla.json");
  const ContactModel<Q> e = contact_model<Q>(s);
  const ContactModel<double> d = contact_model<double>(s);
  EXPECT_EQ(s.workpiece.inertia_per_mass, Q(5, 3));
  EXPECT_LT((exact::to_double(e.J) - d.J).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((exact::to_double(e.A) / 5 - d.A).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((exact::to_double(e.B) / 5 - d.B).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace contactcert::solvers
