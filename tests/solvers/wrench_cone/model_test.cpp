// The model of the wrench cone paper, exactly: the section 4 example's Jacobian and eq. (12), the
// matrices K and P of section 4 and their identity with E C N R S V and E B (eqs. 15, 17), modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "exact/linalg.h"
#include "exact/rational_text.h"
#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/wrench_cone/cone_form.h"

namespace contactcert::solvers {
namespace {

using exact::Z;
using geometry::PlanarScene;

PlanarScene section4_scene() {
  return geometry::load_planar_scene(contactcert::runtime::bundled_scenes_dir() + "/bt2002_section4_disk.json");
}

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
    "fixels":[{"position":[0,-1]},{"point":[1,0],"normal":[-1,0],"gap":"1/10"}],"mu_s":"0.2","mu_k":"0.2"})",
                                                             "unit.json"));
}

TEST(Section4, Equation12IsReproducedExactly) {
  const ContactModel<Q> m = contact_model<Q>(unit_normal_section4());
  EXPECT_EQ(to_field<Q>(m.J), mat({{"0", "-1", "-1", "0"}, {"1", "0", "0", "-1"}, {"0", "0", "-1", "-1"}}));
  EXPECT_EQ(m.C(), mat({{"1", "0", "0", "0", "-1", "0", "0", "1"},
                        {"0", "1", "0", "0", "0", "-1", "-1", "0"},
                        {"0", "0", "1", "0", "0", "-1", "-2", "-1"},
                        {"0", "0", "0", "1", "1", "0", "-1", "-2"}}));
  EXPECT_EQ(to_field<Q>(m.B), mat({{"0", "1", "0"}, {"-1", "0", "0"}, {"-1", "0", "-1"}, {"0", "-1", "-1"}}));
}

TEST(Section4, KAndPOfModeNaAreThePapers) {
  const PlanarScene s = unit_normal_section4();
  const ContactModel<Q> m = contact_model<Q>(s);
  const ConeForm<Q> f = cone_form(s, m, mode_of(s, "na"));
  // Paper: K = [0 -1 -1; -1 mu -mu; 0 2mu -2mu], P = [0 1 0; -1 0 0; -1 0 -1], mu = 0.2.
  EXPECT_EQ(f.K, mat({{"0", "-1", "-1"}, {"-1", "1/5", "-1/5"}, {"0", "2/5", "-2/5"}}));
  EXPECT_EQ(f.P, mat({{"0", "1", "0"}, {"-1", "0", "0"}, {"-1", "0", "-1"}}));
  EXPECT_EQ(f.strict, (std::vector<bool>{true, false, false}));  // -a1n > 0 (the paper's -a2n: fixels from 0)
  EXPECT_EQ(f.names[0], "-a1n");
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
    const PlanarScene s = geometry::load_planar_scene(contactcert::runtime::bundled_scenes_dir() + file);
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
      const Mat<Q> P = mm.E * to_field<Q>(m.B);                   // eq. (17)
      EXPECT_EQ(f.K, K) << file << " " << mode.text();
      EXPECT_EQ(f.P, P) << file << " " << mode.text();
      EXPECT_EQ(f.strict.size(), static_cast<std::size_t>(K.cols()));
      ++checked;
      more = false;
      for (std::size_t i = 0; i < n && !more; ++i) {
        if (++digit[i] < letters[i].size())
          more = true;
        else
          digit[i] = 0;
      }
    }
  }
  EXPECT_EQ(checked, 5 * 5 * 3 + 5 * 5 * 3 + 5 * 3 + 5 * 5 * 5);
}

TEST(ConeForm, SlidingFrictionOpposesTheSlidingDirection) {
  // Table 2: l has c_t = -mu_k c_n, r has c_t = +mu_k c_n (docs/papers.md errata).
  const PlanarScene s = unit_normal_section4();
  const ContactModel<Q> m = contact_model<Q>(s);
  const ConeForm<Q> l = cone_form(s, m, mode_of(s, "ls"));
  const ConeForm<Q> r = cone_form(s, m, mode_of(s, "rs"));
  // The force column of fixel 0 (the paper's fixel 1) is C_c0n + c_t/c_n * C_c0t with C = [I -A]; rows kept: a0n,
  // a0t, a1n.
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
  EXPECT_EQ(l.names[2], "c0[n-mu t]");
  EXPECT_EQ(r.names[2], "c0[n+mu t]");
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
  const PlanarScene s =
      geometry::load_planar_scene(contactcert::runtime::bundled_scenes_dir() + "/bt2002_fig4a_lla.json");
  const ContactModel<Q> e = contact_model<Q>(s);
  const ContactModel<double> d = contact_model<double>(s);
  EXPECT_EQ(s.workpiece.inertia_per_mass, Q(5, 3));
  EXPECT_LT((exact::to_double(to_field<Q>(e.J)) - d.J).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((exact::to_double(to_field<Q>(e.A)) / 5 - d.A).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((exact::to_double(to_field<Q>(e.B)) / 5 - d.B).cwiseAbs().maxCoeff(), 1e-12);
}

PlanarScene parse(const std::string& text) {
  return geometry::read_planar_scene(exact::JsonInput::parse(text, "test.json"));
}

// a = c b for some c > 0.
bool positive_multiple(const std::vector<Q>& a, const std::vector<Q>& b) {
  if (a.size() != b.size()) return false;
  Q c = 0;
  for (std::size_t i = 0; i < b.size() && sgn(c) == 0; ++i)
    if (sgn(b[i]) != 0) c = a[i] / b[i];
  if (sgn(c) <= 0) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != c * b[i]) return false;
  return true;
}

std::vector<Q> column(const Mat<Q>& M, Eigen::Index j) {
  return std::vector<Q>(M.col(j).data(), M.col(j).data() + M.rows());
}

// The integer model in machine integers, and in Z when its numbers outgrow them (radius 10^12 and a
// com at (1/7, 2/9): torques ~10^13, A ~10^27): each frame of J is a positive multiple of
// (n_i, (p_i - com) x n_i) and (t_i, (p_i - com) x t_i), and B = J^T diag(1, 1, 2), A = B J (eq. 6,
// M^-1 = diag(1, 1, m/I) scaled by num(I/m) = 1).
TEST(Model, IntegerModelIsEquation6AndRestartsInZ) {
  for (const bool huge : {false, true}) {
    const std::string r = huge ? "1000000000000" : "5", x = huge ? "-600000000000" : "-3",
                      y = huge ? "800000000000" : "4";
    const PlanarScene s =
        parse(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":)" + r +
              R"(},"com":["1/7","2/9"],"mass":2,"inertia":1},"fixels":[{"position":[0,-)" + r + R"(]},{"position":[)" +
              r + R"(,0]},{"position":[)" + x + "," + y + R"(]}],"mu_s":"1/5"})");
    const ContactModel<Q> m = contact_model<Q>(s);
    EXPECT_EQ(m.A.is_wide(), huge);
    const Mat<Q> J = to_field<Q>(m.J), A = to_field<Q>(m.A), B = to_field<Q>(m.B);
    EXPECT_EQ(J, jacobian(s));
    Mat<Q> Minv = Mat<Q>::Identity(3, 3);
    Minv(2, 2) = 2;
    EXPECT_EQ(B, Mat<Q>(J.transpose() * Minv));
    EXPECT_EQ(A, Mat<Q>(B * J));
    const Eigen::Index n = 3;
    for (Eigen::Index i = 0; i < n; ++i) {
      const geometry::ContactFrame& f = s.fixels[static_cast<std::size_t>(i)].frame;
      const geometry::Point2 p = f.point - s.workpiece.com, t = f.tangent();
      const std::vector<Q> wn = {f.normal.x, f.normal.y, geometry::cross(p, f.normal)};
      const std::vector<Q> wt = {t.x, t.y, geometry::cross(p, t)};
      EXPECT_TRUE(positive_multiple(column(J, i), wn)) << i;
      EXPECT_TRUE(positive_multiple(column(J, n + i), wt)) << i;
      EXPECT_EQ(J(0, i) * f.normal.y, J(1, i) * f.normal.x);
      for (Eigen::Index k = 0; k < 3; ++k) EXPECT_EQ(J(k, i).get_den(), 1);
    }
  }
}

// ring_form: the rows [P | K] of cone_form up to a positive factor per row, with the force columns
// of K scaled by the denominator q of mu; q = 2^62 against A_ii = 25 overflows std::int64_t, and the
// rows then come in Z.
TEST(ConeForm, RingFormIsConeFormUpToPositiveScalingAndRestartsInZ) {
  for (const std::string mu : {"1/5", "3/4611686018427387904"}) {
    const PlanarScene s = parse(R"({"kind":"planar","workpiece":{"shape":{"type":"disk","center":[0,0],"radius":5}},
      "fixels":[{"position":[3,-4]},{"position":[-4,-3]},{"position":[5,0]}],"mu_s":")" +
                                mu + R"(","mu_k":")" + mu + R"("})");
    const ContactModel<Q> m = contact_model<Q>(s);
    const Q q = exact::parse_rational(mu).get_den();
    const bool huge = q > 5;
    for (const char* text : {"nnn", "lrs", "mns", "sss"}) {
      const ModeString mode = mode_of(s, text);
      const ConeForm<Q> f = cone_form(s, m, mode);
      const bool has_mu = std::any_of(f.names.begin(), f.names.end(),
                                      [](const std::string& name) { return name.find("mu") != std::string::npos; });
      if (huge && has_mu) {
        EXPECT_THROW(ring_form<std::int64_t>(s, m, mode), exact::RingOverflow) << text;
      }
      if (!huge) {
        EXPECT_EQ(ring_form<std::int64_t>(s, m, mode).rows.rows(), f.K.rows());
      }
      const RingForm<Z> g = ring_form<Z>(s, m, mode);
      EXPECT_EQ(g.strict, f.strict) << text;
      ASSERT_EQ(g.rows.rows(), f.K.rows()) << text;
      for (Eigen::Index r = 0; r < f.K.rows(); ++r) {
        std::vector<Q> want, got;
        for (Eigen::Index j = 0; j < 3; ++j) want.push_back(f.P(r, j));
        for (Eigen::Index j = 0; j < f.K.cols(); ++j)
          want.push_back(f.K(r, j) * (f.names[static_cast<std::size_t>(j)].find("mu") != std::string::npos ? q : Z(1)));
        for (Eigen::Index j = 0; j < g.rows.cols(); ++j) got.push_back(Q(g.rows(r, j)));
        EXPECT_TRUE(positive_multiple(got, want)) << text << " row " << r;
      }
    }
  }
}

}  // namespace
}  // namespace contactcert::solvers
