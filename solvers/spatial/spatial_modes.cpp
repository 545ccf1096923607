#include "solvers/spatial/spatial_modes.h"

#include <nlohmann/json.hpp>

#include "exact/input_error.h"
#include "exact/rational_text.h"
#include "exact/strict_feasibility.h"
#include "solvers/stability/sparse_motzkin.h"

namespace contactcert::solvers::spatial {

using Index = Eigen::Index;
using geometry::Vec3;

std::string letters(std::size_t m) {
  std::string s = "sf";
  for (std::size_t j = 0; j < 2 * m; ++j) s += static_cast<char>('A' + j);
  return s;
}

SpatialModel spatial_model(const geometry::SpatialScene& scene) {
  SpatialModel model;
  for (const geometry::SpatialContact& c : scene.contacts) {
    Vec3 r;
    for (std::size_t i = 0; i < 3; ++i) r[i] = c.point[i] - scene.body.com[i];
    auto w = [&](const Vec3& u) {  // w_u = (u, r x u): u . (a + alpha x r) = w_u . (a, alpha)
      const Vec3 m = geometry::cross(r, u);
      Vec<Q> f(6);
      f << u[0], u[1], u[2], m[0], m[1], m[2];
      return f;
    };
    SpatialModel::Contact k{w(c.normal), w(c.t1), w(c.t2), {}};
    for (std::size_t j = 0; j < c.edges.size(); ++j) k.d.push_back(w(c.edge(j)));
    model.contacts.push_back(std::move(k));
  }
  return model;
}

std::vector<SignRow> letter_rows(const SpatialModel::Contact& c, char L) {
  const std::size_t m = c.d.size();
  if (L == 's') return {{c.n, true}};
  if (L == 'f') return {{c.n, false}, {c.t1, false}, {c.t2, false}};
  if (L < 'A' || static_cast<std::size_t>(L - 'A') >= 2 * m) return {};
  const std::size_t j = static_cast<std::size_t>(L - 'A') / 2;
  const auto& d = c.d;
  const std::size_t prev = (j + m - 1) % m, next = (j + 1) % m, after = (j + 2) % m;
  if ((L - 'A') % 2 == 0) return {{c.n, false}, {d[prev] - d[j], true}, {d[next] - d[j], true}};
  return {{c.n, false}, {d[next] - d[j], false}, {d[prev] - d[j], true}, {d[after] - d[next], true}};
}

bool realises(const SpatialModel& model, const std::string& prefix, const Vec<Q>& vdot) {
  if (vdot.size() != 6 || prefix.size() > model.contacts.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    const std::vector<SignRow> rows = letter_rows(model.contacts[i], prefix[i]);
    if (rows.empty()) return false;
    for (const SignRow& r : rows) {
      const int s = sgn(Q(r.f.dot(vdot)));
      if (r.strict ? s <= 0 : s != 0) return false;
    }
  }
  return true;
}

namespace {

// The strict-feasibility system of a prefix (SpatialDeadPrefix's layout), by its non-zero entries: a row has at most
// six on vdot and one on its slack, so a deep prefix's system stays linear in its rows.
exact::SparseStrictSystem<Q> prefix_system(const SpatialModel& model, const std::string& prefix) {
  exact::SparseStrictSystem<Q> sys;
  sys.cols = 6;
  sys.is_free.assign(6, true);
  sys.strict.assign(6, false);
  for (std::size_t i = 0; i < prefix.size(); ++i)
    for (const SignRow& row : letter_rows(model.contacts[i], prefix[i])) {
      for (Index c = 0; c < 6; ++c)
        if (sgn(row.f(c)) != 0) sys.entries.push_back({sys.rows, c, row.f(c)});
      if (row.strict) {  // f . vdot - sigma = 0, sigma > 0
        sys.entries.push_back({sys.rows, sys.cols++, Q(-1)});
        sys.is_free.push_back(false);
        sys.strict.push_back(true);
      }
      ++sys.rows;
    }
  return sys;
}

class Walker {
 public:
  Walker(const SpatialModel& model, const SpatialModeOptions& options, SpatialModeTree& out)
      : model_(model), options_(options), out_(out) {}

  // Depth first with an explicit stack: per live prefix its realising vdot and the next letter to try below it.
  void walk() {
    struct Frame {
      Vec<Q> vdot;
      std::size_t next = 0;
    };
    const std::size_t k = model_.contacts.size();
    std::string prefix;
    std::vector<Frame> path{{Vec<Q>::Zero(6), 0}};
    count_node();
    while (!path.empty()) {
      const std::size_t i = path.size() - 1;
      if (i == k) {
        if (static_cast<long>(out_.modes.size()) >= options_.max_modes)
          throw exact::BudgetExceeded(
              "spatial modes: output budget of " + std::to_string(options_.max_modes) + " modes exhausted", covered());
        out_.modes.push_back(prefix);
        out_.accelerations.push_back(path.back().vdot);
      }
      const std::string alphabet = i < k ? letters(model_.contacts[i].d.size()) : std::string();
      if (i == k || path.back().next == alphabet.size()) {
        path.pop_back();
        if (!prefix.empty()) prefix.pop_back();
        continue;
      }
      prefix.push_back(alphabet[path.back().next++]);
      count_node();
      if (realises(model_, prefix, path.back().vdot)) {
        Vec<Q> vdot = path.back().vdot;
        path.push_back({std::move(vdot), 0});
        continue;
      }
      auto kin = exact::strict_feasibility(prefix_system(model_, prefix), options_.arith);
      out_.lps += kin.lps;
      if (kin.status == exact::StrictStatus::kFeasible) {
        path.push_back({Vec<Q>(kin.x.head(6)), 0});
        continue;
      }
      out_.dead.push_back({prefix, std::move(kin.motzkin)});
      prefix.pop_back();
    }
  }

 private:
  void count_node() {
    ++out_.nodes;
    if (out_.nodes > options_.max_nodes || options_.deadline.expired())
      throw exact::BudgetExceeded(
          out_.nodes > options_.max_nodes
              ? "spatial modes: node budget of " + std::to_string(options_.max_nodes) + " prefixes exhausted"
              : "spatial modes: " + options_.deadline.reached_text(),
          covered());
  }

  std::string covered() const {
    return std::to_string(out_.nodes - 1) + " prefixes visited, " + std::to_string(out_.modes.size()) +
           " feasible modes found";
  }

  const SpatialModel& model_;
  const SpatialModeOptions& options_;
  SpatialModeTree& out_;
};

}  // namespace

SpatialModeTree spatial_modes(const SpatialModel& model, const SpatialModeOptions& options) {
  SpatialModeTree out;
  Walker(model, options, out).walk();
  return out;
}

std::string spatial_modes_certificate(const std::string& scene_text, const SpatialModeTree& tree) {
  nlohmann::ordered_json j;
  j["kind"] = "spatial_modes";
  j["scene"] = scene_text;
  j["problem_sha256"] = exact::JsonInput::parse(scene_text, "scene").canonical_sha256();
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < tree.modes.size(); ++i) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (Index d = 0; d < 6; ++d) a.push_back(exact::to_string(tree.accelerations[i](d)));
    modes.push_back({{"mode", tree.modes[i]}, {"acceleration", a}});
  }
  j["modes"] = modes;
  nlohmann::ordered_json dead = nlohmann::ordered_json::array();
  for (const SpatialDeadPrefix& d : tree.dead)
    dead.push_back({{"prefix", d.prefix}, {"motzkin", sparse_motzkin_json(d.motzkin)}});
  j["dead"] = dead;
  return j.dump(1) + "\n";
}

}  // namespace contactcert::solvers::spatial
