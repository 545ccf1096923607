#include "queries/wrenches_query.h"

#include <sstream>

#include "exact/input_error.h"
#include "exact/json_input.h"

namespace contactcert::queries {

using exact::Q;
using exact::Vec;

StabilityVerdicts::StabilityVerdicts(const geometry::PlanarScene& scene, const CommonOptions& common)
    : scene_(scene), arith_(scene_arith(common.arith)) {
  std::vector<Eigen::Index> every(scene.fixels.size());
  for (std::size_t i = 0; i < every.size(); ++i) every[i] = static_cast<Eigen::Index>(i);
  frames_ = std::make_shared<const solvers::ForceFrames>(scene, every);
  const solvers::StabilityOptions options = stability_options(arith_, common.deadline());
  if (arith_ == exact::Arith::kFloat)
    float_.emplace(scene, options);
  else
    exact_.emplace(scene, options);
}

StabilityOutcome StabilityVerdicts::verdict(const Vec<Q>& g) const {
  if (float_) return float_->verdict(exact::to_double(g));
  return exact_->verdict(g);
}

StabilityAnswer StabilityVerdicts::answer(const Vec<Q>& g) const { return answer(g, verdict(g)); }

StabilityAnswer StabilityVerdicts::answer(const Vec<Q>& g, StabilityOutcome verdict) const {
  return {scene_, g, arith_, std::move(verdict), std::nullopt, "", "", frames_};
}

std::vector<StabilityOutcome> StabilityVerdicts::verdicts(const std::vector<Vec<Q>>& wrenches) const {
  std::vector<StabilityOutcome> out;
  out.reserve(wrenches.size());
  auto each = [&](const auto& oracle, auto convert) {
    using T = typename std::decay_t<decltype(convert(wrenches.front()))>::Scalar;
    solvers::ReusedCertificates<T> reuse;
    for (const Vec<Q>& g : wrenches) out.emplace_back(oracle.verdict(convert(g), reuse));
  };
  if (float_)
    each(*float_, [](const Vec<Q>& g) { return exact::to_double(g); });
  else
    each(*exact_, [](const Vec<Q>& g) -> const Vec<Q>& { return g; });
  return out;
}

long StabilityVerdicts::preparation_lps() const {
  return float_ ? float_->preparation_lps() : exact_->preparation_lps();
}

std::vector<Vec<Q>> read_wrenches(const std::string& path) {
  const std::string text = exact::JsonInput::read_text(path);
  std::vector<Vec<Q>> out;
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '[') {
    const auto in = exact::JsonInput::parse(text, path);
    for (const auto& e : in.elements()) out.push_back(e.rational_vector(3));
  } else {
    std::istringstream lines(text);
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n) {
      const auto a = line.find_first_not_of(" \t\r");
      if (a == std::string::npos || line[a] == '#') continue;
      const auto b = line.find_last_not_of(" \t\r");
      try {
        std::string w = line.substr(a, b - a + 1);
        const bool commas = w.find(',') != std::string::npos;
        std::string t;
        for (char ch : w)
          if (ch == ' ' || ch == '\t') {
            if (!commas && !t.empty() && t.back() != ',') t += ',';
          } else {
            t += ch;
          }
        out.push_back(parse_number_list(t, "wrench", 3));
      } catch (const exact::InputError&) {
        throw exact::InputError(path, "line " + std::to_string(n), "a wrench fx,fy,tz of exact numbers");
      }
    }
  }
  if (out.empty()) throw exact::InputError(path, "", "at least one wrench");
  return out;
}

namespace {

WrenchesAnswer wrenches_answer(const SceneInput& input, const WrenchesOptions& options) {
  WrenchesAnswer a;
  a.arith = scene_arith(options.common.arith);
  a.wrenches = read_wrenches(options.wrenches);
  const StabilityVerdicts oracle(input.scene, options.common);
  a.lps = oracle.preparation_lps();
  for (const StabilityOutcome& r : oracle.verdicts(a.wrenches)) {
    const solvers::StabilityVerdict v = std::visit([](const auto& x) { return x.verdict; }, r);
    a.verdicts.push_back(v);
    ++a.counts[static_cast<int>(v)];
    a.lps += std::visit([](const auto& x) { return x.lps; }, r);
  }
  return a;
}

}  // namespace

Limited<WrenchesAnswer> run_wrenches(const SceneInput& input, const WrenchesOptions& options) {
  return with_limits(options.common.arith, [&] { return wrenches_answer(input, options); });
}

json to_json(const WrenchesAnswer& answer) {
  json rows = json::array();
  for (std::size_t i = 0; i < answer.wrenches.size(); ++i)
    rows.push_back(
        {{"wrench", exact_json(answer.wrenches[i])}, {"verdict", solvers::verdict_name(answer.verdicts[i])}});
  const auto& c = answer.counts;
  return {{"wrenches", rows},
          {"counts", {{"strongly_stable", c[0]}, {"weakly_stable", c[1]}, {"unstable", c[2]}}},
          {"arith", exact::arith_name(answer.arith)},
          {"lps", answer.lps}};
}

}  // namespace contactcert::queries
