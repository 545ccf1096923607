// The checker of "goal_nonempty" certificates (solvers/design/goal_certificate.h). It trusts nothing from the solver:
// the sets of eq. (21) and Table 5 are stated here as the paper prints them, each set's scene is rebuilt from the
// embedded goal scene and its K and P by the checkers' own Table 2 (table2_rows.h, not cone_form.h), and the push
// wrench from the push point.
#include "checker/goal_check.h"

#include <sstream>

#include "checker/frame_check.h"
#include "checker/sparse_motzkin_reader.h"
#include "checker/table2_rows.h"

namespace contactcert::checker {
namespace {

using exact::Q;
using exact::Vec;
namespace t2 = table2_check;

/// The sets (contact state, mode) whose wrench cones G_goal avoids, row by row as printed: eq. (21) for two
/// fixels; Table 5 for three, whose state-111 row prints "mss" twice, the second being "ssm" (the row lists
/// every s/m string but mmm, and "ssm" is the one missing).
std::vector<std::pair<std::string, std::string>> goal_sets_as_printed(std::size_t fixels) {
  static const char* const kEq21[] = {"10: su, ms", "01: us, sm"};
  static const char* const kTable5[] = {"000: sss",
                                        "100: suu, mss",
                                        "010: usu, sms",
                                        "001: uus, ssm",
                                        "110: ssu, msu, smu, mms",
                                        "101: sus, mus, sum, msm",
                                        "011: uss, ums, usm, smm",
                                        "111: sss, mss, sms, ssm, mms, smm, msm"};
  std::vector<std::pair<std::string, std::string>> out;
  auto read_rows = [&](const auto& rows) {
    for (const char* row : rows) {
      std::istringstream in(row);
      std::string state, mode;
      in >> state;
      state.pop_back();  // the ':'
      while (in >> mode) {
        if (mode.back() == ',') mode.pop_back();
        out.emplace_back(state, mode);
      }
    }
  };
  if (fixels == 2) read_rows(kEq21);
  if (fixels == 3) read_rows(kTable5);
  return out;
}

/// Is g a positive multiple of the frictionless push (n, (p - com) x n) at boundary point p? Empty if so. The normal
/// is the checker's own (frame_check.h): that of a fixel touching at p.
std::string push_mismatch(const geometry::Workpiece& w, const geometry::Point2& p, const Vec<Q>& g) {
  const geometry::FrameResult at = frame_check::checked_frame(w.shape, {p, {}, {}, {}});
  if (at.status == geometry::FrameStatus::kNormalNotUnique)
    return "the push point is not a boundary point that is not a polygon vertex (" + at.message + ")";
  if (at.status != geometry::FrameStatus::kOk || !at.frame.touching())
    return std::string("the push point is not a point on the ") +
           (std::holds_alternative<geometry::DiskShape>(w.shape) ? "disk" : "polygon") + " boundary";
  const geometry::Point2& n = at.frame.normal;
  Vec<Q> push(3);
  push << n.x, n.y, geometry::cross(p - w.com, n);
  const Q scale = g.dot(push) / push.dot(push);
  if (sgn(scale) <= 0 || g != Vec<Q>(scale * push))
    return "the wrench is not a positive multiple of the push at the push point";
  return {};
}

}  // namespace

GoalCertificateCheck check_goal_certificate(const exact::JsonInput& c) {
  c.expect_keys({"kind", "problem_sha256", "wrench", "push", "outside", "scene"});
  // The frames are the checker's own (frame_check.h), never the solvers'; the digest is checked first.
  const frame_check::CheckedSceneRead read = frame_check::read_embedded_scene(c);
  if (!read.violation.empty()) return {false, read.violation};
  const geometry::PlanarScene& scene = read.scene;
  const std::size_t k = scene.fixels.size();
  if (k != 2 && k != 3)
    return {false, "G_goal is defined for 2 or 3 fixels (eq. 21, Table 5), found " + std::to_string(k)};
  for (std::size_t i = 0; i < k; ++i)
    if (!scene.fixels[i].frame.touching())
      return {false, "fixel " + std::to_string(i) + " does not touch: the scene is not a goal configuration"};
  const Vec<Q> g = c.at("wrench").rational_vector(3);
  if (g.isZero()) return {false, "the wrench is zero"};
  if (const auto push = c.find("push")) {
    const Vec<Q> p = push->rational_vector(2);
    const std::string why = push_mismatch(scene.workpiece, {p(0), p(1)}, g);
    if (!why.empty()) return {false, why};
  }
  const auto sets = goal_sets_as_printed(k);
  const std::vector<exact::JsonInput> outside = c.at("outside").elements();
  if (outside.size() != sets.size())
    return {false, "\"outside\" has " + std::to_string(outside.size()) + " sets, eq. (21) / Table 5 has " +
                       std::to_string(sets.size())};
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const exact::JsonInput& o = outside[i];
    o.expect_keys({"state", "mode", "motzkin"});
    const auto& [state, mode_text] = sets[i];
    if (o.at("state").string() != state || o.at("mode").string() != mode_text)
      return {false, "set " + std::to_string(i) + " is not " + mode_text + " in state " + state};
    // The scene in this contact state: the fixels not yet reached get a gap.
    geometry::PlanarScene in_state = scene;
    for (std::size_t f = 0; f < k; ++f)
      if (state[f] != '1') in_state.fixels[f].frame.gap_squared = 1;
    const t2::CheckedScene checked = t2::checked_scene(in_state, /*touching_only=*/false);
    t2::ConeColumns cols;
    if (!t2::cone_columns(checked, mode_text, cols))
      return {false, mode_text + " is not a mode of Table 2 in state " + state};
    const Vec<Q> y = read_sparse_motzkin(o.at("motzkin"), cols.row_wrenches.size());
    if (const std::string why = t2::wrench_outside_violation(checked, cols, y, g); !why.empty())
      return {false, "the Motzkin vector of " + mode_text + " in state " + state +
                         " does not prove the wrench outside its cone: " + why};
  }
  return {true, "the wrench is outside the wrench cone of every set of " +
                    std::string(k == 2 ? "eq. (21)" : "Table 5") + " (a Motzkin vector each): G_goal is non-empty" +
                    (c.find("push") ? " and holds the frictionless push at the push point" : "")};
}

}  // namespace contactcert::checker
