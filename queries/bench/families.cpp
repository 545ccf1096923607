#include "queries/bench/families.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "geometry/scene_json.h"
#include "runtime/scenes.h"
#include "solvers/ucp/generate.h"
#include "solvers/wrench_cone/contact_model.h"

namespace contactcert::bench {

namespace {

using geometry::Point2;
using Rng = std::mt19937_64;

/// A uniform rational in [lo, hi] with denominator den.
Q random_q(Rng& rng, long lo, long hi, long den) {
  std::uniform_int_distribution<long> d(lo * den, hi * den);
  Q q(d(rng), den);
  q.canonicalize();
  return q;
}

/// 10^k, exactly (k may be negative).
Q pow10(int k) {
  Q p(1);
  for (int i = 0; i < std::abs(k); ++i) p *= 10;
  return k >= 0 ? p : Q(1) / p;
}

/// The knob's integer level at `difficulty` in [0, 1], between lo (easiest) and hi (hardest).
int level(double difficulty, int lo, int hi) { return lo + static_cast<int>(std::lround(difficulty * (hi - lo))); }

/// A scene on the convex counter-clockwise polygon V with touching fixels at V[e] + s (V[e+1] - V[e]) for
/// each (e, s), inward normals perp(edge) (not unit: SPEC section 3), uniform density, mu_s = mu_k = mu.
geometry::PlanarScene polygon_scene(const std::vector<Point2>& V, const std::vector<std::pair<std::size_t, Q>>& at,
                                    const Q& mu) {
  geometry::PlanarScene scene;
  const Point2 com = geometry::polygon_centroid(V);
  scene.workpiece = {geometry::PolygonShape{V}, com, geometry::polygon_inertia_per_mass(V, com)};
  for (const auto& [e, s] : at) {
    const Point2 edge = V[(e + 1) % V.size()] - V[e];
    scene.fixels.push_back({{V[e] + s * edge, geometry::perp(edge), Q(0)}, mu, mu, std::nullopt});
  }
  return scene;
}

/// Contact forces (c_1n..c_kn, c_1t..c_kt) in the frames of solvers::jacobian, in the static friction cones
/// |c_t| <= mu c_n (a frame scales n and t alike, so the cone does not depend on it). The first `on_edge`
/// fixels get c_t = +-mu c_n: the force on an edge of its cone, so -J c lies on a face of the rolling mode's
/// wrench cone.
Vec<Q> friction_forces(const geometry::PlanarScene& scene, std::size_t on_edge, Rng& rng) {
  const auto k = static_cast<Eigen::Index>(scene.fixels.size());
  Vec<Q> c(2 * k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const Q& mu = scene.fixels[static_cast<std::size_t>(i)].mu_s;
    c(i) = random_q(rng, 1, 5, 4);
    const Q u = static_cast<std::size_t>(i) < on_edge ? Q(rng() % 2 ? 1 : -1) : random_q(rng, -1, 1, 8);
    c(k + i) = mu * c(i) * u;
  }
  return c;
}

/// The wrench g that contact forces c balance at rest: J c + g = 0 (eq. 6 with zero acceleration).
Vec<Q> wrench_at_rest(const geometry::PlanarScene& scene, const Vec<Q>& c) { return -(solvers::jacobian(scene) * c); }

/// A mode with one random letter of `letters` per fixel.
solvers::ModeString random_mode(std::size_t fixels, const std::string& letters, Rng& rng) {
  solvers::ModeString m;
  for (std::size_t i = 0; i < fixels; ++i)
    m.letters.push_back(static_cast<solvers::Interaction>(letters[rng() % letters.size()]));
  return m;
}

std::string sci(const Q& x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0e", x.get_d());
  return buf;
}

/// Scene families: one stability question (wrench -J c + offset) and one cone question (mode).
std::vector<Instance> scene_instances(Family f, double d, std::uint64_t seed, std::string knob,
                                      const geometry::PlanarScene& scene, const Vec<Q>& wrench,
                                      const solvers::ModeString& mode) {
  std::vector<Instance> out;
  out.push_back({f, d, knob, seed, StabilityQuestion{scene, wrench}});
  out.push_back({f, d, std::move(knob), seed, ConeQuestion{scene, mode}});
  return out;
}

std::vector<Instance> parallel(double d, std::uint64_t seed) {
  Rng rng(seed);
  const int k = level(d, 1, 12);
  const Q eps = pow10(-k);
  // Bottom edges with inward normals (0, 1) and (-eps, 1): the angle between them is atan(eps).
  const std::vector<Point2> V = {{-2, 0}, {0, 0}, {2, 2 * eps}, {2, 1}, {-2, 1}};
  // mu is drawn before the fixels, as gcc evaluated polygon_scene's arguments (right to left).
  const Q mu = random_q(rng, 1, 4, 5) / 5;
  const auto scene = polygon_scene(V, {{0, random_q(rng, 1, 3, 4) / 4}, {1, random_q(rng, 1, 3, 4) / 4}}, mu);
  const Vec<Q> g = wrench_at_rest(scene, friction_forces(scene, 1, rng));
  return scene_instances(Family::kParallel, d, seed, "angle " + sci(eps), scene, g, random_mode(2, "nlr", rng));
}

std::vector<Instance> boundary(double d, std::uint64_t seed) {
  Rng rng(seed);
  const int k = level(d, 3, 15);
  const Q a = random_q(rng, 2, 5, 2), b = random_q(rng, 1, 3, 2);
  const std::vector<Point2> V = {{0, 0}, {a, 0}, {a, b}, {0, b}};
  // mu = p/q with q in 3..9: not a binary fraction, so the float path sees a rounded friction cone.
  const long q = 3 + static_cast<long>(rng() % 7);
  const Q mu = random_q(rng, 1, q - 1, 1) / q;
  const auto scene =
      polygon_scene(V, {{0, random_q(rng, 1, 3, 8) / 8}, {0, random_q(rng, 5, 7, 8) / 8}, {3, Q(1, 2)}}, mu);
  Vec<Q> g = wrench_at_rest(scene, friction_forces(scene, 3, rng));
  // On the face (offset 0) or 10^-k off it, to either side.
  const long side = static_cast<long>(seed % 3) - 1;
  Vec<Q> e(3);
  for (Eigen::Index i = 0; i < 3; ++i) e(i) = random_q(rng, -2, 2, 1);
  const Q offset = Q(side) * pow10(-k);
  g += offset * e;
  const std::string knob = side == 0 ? "on face" : "offset " + sci(pow10(-k));
  return scene_instances(Family::kBoundary, d, seed, knob, scene, g, random_mode(3, "n", rng));
}

std::vector<Instance> lever(double d, std::uint64_t seed) {
  Rng rng(seed);
  const int k = level(d, 0, 6);
  const Q L = pow10(k), h = pow10(-k);
  // A 2L x h plate touched near both ends of its bottom edge and on its left side: arms from h to L.
  const std::vector<Point2> V = {{-L, 0}, {L, 0}, {L, h}, {-L, h}};
  // mu is drawn before the fixels, as gcc evaluated polygon_scene's arguments (right to left).
  const Q mu = random_q(rng, 1, 4, 5) / 5;
  const auto scene = polygon_scene(
      V, {{0, random_q(rng, 1, 4, 8) / 32}, {0, 1 - random_q(rng, 1, 4, 8) / 32}, {3, random_q(rng, 1, 3, 4) / 4}}, mu);
  const Vec<Q> g = wrench_at_rest(scene, friction_forces(scene, 0, rng));
  return scene_instances(Family::kLever, d, seed, "arms 1e-" + std::to_string(k) + "..1e" + std::to_string(k), scene, g,
                         random_mode(3, "nlr", rng));
}

solvers::ucp::UcpProblem random_ucp(int nc, Rng& rng) {
  solvers::ucp::RandomProblemOptions o;
  o.nc = nc;
  return solvers::ucp::generate_random_problem(o, rng);
}

std::vector<Instance> degenerate(double d, std::uint64_t seed) {
  Rng rng(seed);
  const int nc = 10, stopped = level(d, 0, nc);
  solvers::ucp::UcpProblem p = random_ucp(nc, rng);
  // Point finger i has joints 2i, 2i+1 (section 5): stopping it zeroes its part of J_alpha theta_dot_alpha, so
  // the right-hand side of X lies in a lower-dimensional cone and X's vertices become degenerate.
  auto& qs = *p.quasistatic;
  for (int i = 0; i < stopped; ++i) qs.theta_dot(2 * i) = 0, qs.theta_dot(2 * i + 1) = 0;
  p.set(solvers::ucp::build_ucp(qs));
  p.source = "degenerate: section 5 problem nc=10 with " + std::to_string(stopped) + " fingers stopped";
  return {{Family::kDegenerate, d, std::to_string(stopped) + "/10 stopped", seed, ucp_question(std::move(p))}};
}

std::vector<Instance> reduction(double d, std::uint64_t seed) {
  Rng rng(seed);
  const int n = level(d, 4, 14);
  const auto zo = solvers::ucp::random_zero_one(2, n, seed % 2 == 1, rng);
  UcpQuestion q = ucp_question(solvers::ucp::reduction_problem(zo), solvers::ucp::zero_one_feasible(zo));
  return {{Family::kReduction, d, "2 x " + std::to_string(n), seed, std::move(q)}};
}

std::vector<Instance> large(double d, std::uint64_t seed) {
  Rng rng(seed);
  const int nc = level(d, 5, 40), k = level(d, 2, 8);
  std::vector<Instance> out;
  out.push_back({Family::kLarge, d, "nc " + std::to_string(nc) + ", " + std::to_string(k) + " fixels", seed,
                 ucp_question(random_ucp(nc, rng))});
  // Fixels on k edges of an octagon; every fixel rolls but one, which slides.
  const std::vector<Point2> V = {{2, -1}, {2, 1}, {1, 2}, {-1, 2}, {-2, 1}, {-2, -1}, {-1, -2}, {1, -2}};
  std::vector<std::pair<std::size_t, Q>> at;
  for (int i = 0; i < k; ++i) at.emplace_back(static_cast<std::size_t>(i), random_q(rng, 1, 3, 8) / 4);
  const auto scene = polygon_scene(V, at, random_q(rng, 1, 4, 5) / 5);
  solvers::ModeString mode = random_mode(static_cast<std::size_t>(k), "n", rng);
  mode.letters[rng() % mode.letters.size()] =
      rng() % 2 ? solvers::Interaction::kSlideLeft : solvers::Interaction::kSlideRight;
  out.push_back({Family::kLarge, d, out.front().knob, seed, ConeQuestion{scene, mode}});
  return out;
}

/// Data Sets 1-4 (Pang, Trinkle, Lo), the section 7 disk under three wrenches and the cones of section 4 and
/// Figure 4 (Balkcom, Trinkle), as in README.md.
std::vector<Instance> paper(double d, std::uint64_t seed) {
  if (d != 0 || seed != 1) return {};
  const std::string dir = runtime::bundled_scenes_dir();
  std::vector<Instance> out;
  for (int k = 1; k <= 4; ++k) {
    const std::string file = "pang1994_dataset" + std::to_string(k) + ".json";
    out.push_back({Family::kPaper, d, file, seed, ucp_question(solvers::ucp::load_ucp_problem(dir + "/" + file))});
  }
  const auto disk = geometry::load_planar_scene(dir + "/bt2002_section7_disk.json");
  for (const auto& [text, g] : std::vector<std::pair<std::string, std::vector<int>>>{
           {"0,-1,0", {0, -1, 0}}, {"-1,-1,0", {-1, -1, 0}}, {"1,-2,0", {1, -2, 0}}}) {
    Vec<Q> w(3);
    for (Eigen::Index i = 0; i < 3; ++i) w(i) = g[static_cast<std::size_t>(i)];
    out.push_back({Family::kPaper, d, "section 7 disk, g = (" + text + ")", seed, StabilityQuestion{disk, w}});
  }
  for (const auto& [file, mode] :
       std::vector<std::pair<std::string, std::string>>{{"bt2002_section4_disk.json", "na"},
                                                        {"bt2002_fig4a_lla.json", "lla"},
                                                        {"bt2002_fig4b_nnn.json", "nnn"},
                                                        {"bt2002_fig4c_peg_lra.json", "lra"},
                                                        {"bt2002_fig4d_peg_nn.json", "nn"}}) {
    const auto scene = geometry::load_planar_scene(dir + "/" + file);
    std::vector<bool> touching;
    for (const auto& f : scene.fixels) touching.push_back(f.frame.touching());
    out.push_back({Family::kPaper, d, file + " '" + mode + "'", seed,
                   ConeQuestion{scene, solvers::parse_mode(mode, touching).mode}});
  }
  return out;
}

/// Every family with its name, description, number of knob values and generator, in report order.
struct FamilyInfo {
  Family family;
  const char* name;
  const char* description;
  int levels;
  std::vector<Instance> (*generate)(double, std::uint64_t);
};

const std::vector<FamilyInfo>& family_table() {
  static const std::vector<FamilyInfo> table = {
      {Family::kPaper, "paper",
       "the papers' data: Data Sets 1-4, the section 7 disk under three wrenches, the section 4 and Figure 4 cones "
       "(no knob)",
       1, paper},
      {Family::kParallel, "parallel",
       "two contacts with nearly parallel normals, angle 1e-1 (difficulty 0) to 1e-12 (difficulty 1)", 12, parallel},
      {Family::kBoundary, "boundary",
       "friction mu = p/q (q = 3..9), wrench on a face of the rolling mode cone or 1e-3..1e-15 off it", 13, boundary},
      {Family::kLever, "lever", "a 2L x 1/L plate, L = 1 .. 1e6: lever arms from 1e-6 to 1e6", 7, lever},
      {Family::kDegenerate, "degenerate", "section 5 UCPs, nc = 10, 0 .. 10 fingers stopped: degenerate vertices of X",
       11, degenerate},
      {Family::kReduction, "reduction",
       "Proposition 2 reductions of 0-1 feasibility, 2 rows, 4 .. 14 columns (answer known by brute force)", 11,
       reduction},
      {Family::kLarge, "large", "section 5 UCPs with nc = 5 .. 40; wrench cones with 2 .. 8 fixels", 36, large},
  };
  return table;
}

const FamilyInfo& info(Family f) {
  for (const FamilyInfo& i : family_table())
    if (i.family == f) return i;
  throw std::invalid_argument("unknown family");
}

}  // namespace

UcpQuestion ucp_question(solvers::ucp::UcpProblem problem, std::optional<bool> known_solvable) {
  std::string text = solvers::ucp::to_json_text(problem);
  return {std::move(problem), known_solvable, std::move(text)};
}

const char* question_kind(const Question& q) {
  return std::visit(
      [](const auto& x) -> const char* {
        using X = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<X, UcpQuestion>) return "ucp";
        if constexpr (std::is_same_v<X, StabilityQuestion>) return "stability";
        return "cone";
      },
      q);
}

const std::vector<Family>& all_families() {
  static const std::vector<Family> families = [] {
    std::vector<Family> f;
    for (const FamilyInfo& i : family_table()) f.push_back(i.family);
    return f;
  }();
  return families;
}

const char* family_name(Family f) { return info(f).name; }
const char* family_description(Family f) { return info(f).description; }
int family_levels(Family f) { return info(f).levels; }

std::optional<Family> parse_family(const std::string& name) {
  for (const FamilyInfo& i : family_table())
    if (name == i.name) return i.family;
  return std::nullopt;
}

std::vector<Instance> generate(Family family, double difficulty, std::uint64_t seed) {
  if (!(difficulty >= 0 && difficulty <= 1)) throw std::invalid_argument("difficulty must lie in [0, 1]");
  return info(family).generate(difficulty, seed);
}

}  // namespace contactcert::bench
