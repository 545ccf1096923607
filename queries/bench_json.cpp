// The JSON of `contactcert bench`: the rungs, totals, a summary per family and rung, the precision ladder and
// every instance.
#include "exact/arith.h"
#include "queries/bench_aggregate.h"

namespace contactcert::queries {

namespace {

using namespace bench_report;

json errors_json(const bench::Errors& e) {
  return {{"wrong_verdict", e.wrong_verdict},
          {"undecided", e.undecided},
          {"violation", e.violation},
          {"xTy", e.xTy},
          {"generator_distance", e.generator_distance}};
}

}  // namespace

json bench_json(const BenchRun& run) {
  json j;
  j["command"] = "bench";
  j["suite"] = run.suite;
  j["quick"] = run.quick;
  j["max_repeats"] = run.max_repeats;
  j["seconds"] = run.seconds;
  j["rungs"] = json::array();
  for (const auto& r : run.rungs)
    j["rungs"].push_back(
        {{"name", r.name}, {"arith", exact::arith_name(r.arith)}, {"precision_bits", r.precision_bits}});
  j["totals"] = json::object();
  for (std::size_t k = 0; k < run.rungs.size(); ++k) {
    const Totals t = totals(run, k);
    j["totals"][run.rungs[k].name] = {{"seconds", t.seconds},
                                      {"wrong_verdicts", t.wrong},
                                      {"undecided", t.undecided},
                                      {"disagreements_with_exact", disagreements(run, k)}};
  }
  // One row per group: the key, the count, and per rung the median time and the worst errors.
  const auto rows = [&](Key key, std::optional<bench::Family> family) {
    json out = json::array();
    for (const Group& g : groups(run, key, family)) {
      json row = key == Key::kFamilyQuestion ? json{{"family", g.a}, {"question", g.b}, {"n", g.n}}
                                             : json{{"question", g.a}, {"knob", g.b}, {"n", g.n}};
      for (std::size_t k = 0; k < run.rungs.size(); ++k)
        row["rungs"][run.rungs[k].name] = {{"median_seconds", median(g.seconds[k])},
                                           {"wrong_verdicts", g.wrong[k]},
                                           {"undecided", g.undecided[k]},
                                           {"max_violation", g.violation[k]},
                                           {"max_xTy", g.xTy[k]},
                                           {"max_generator_distance", g.generators[k]}};
      out.push_back(row);
    }
    return out;
  };
  j["summary"] = rows(Key::kFamilyQuestion, std::nullopt);
  j["families"] = json::array();
  for (bench::Family f : families_in(run)) {
    j["families"].push_back({{"name", bench::family_name(f)},
                             {"description", bench::family_description(f)},
                             {"rows", rows(Key::kQuestionKnob, f)}});
  }
  j["precision_ladder"] = json::object();
  for (bench::Family f : families_in(run))
    for (std::size_t k = 0; k < run.rungs.size(); ++k) {
      const LadderCell c = ladder_cell(run, f, k);
      j["precision_ladder"][bench::family_name(f)][run.rungs[k].name] = json{{"n", c.n},
                                                                             {"median_seconds", c.median_seconds},
                                                                             {"wrong_verdicts", c.wrong},
                                                                             {"undecided", c.undecided},
                                                                             {"worst_error", c.worst}};
    }
  j["instances"] = json::array();
  for (const auto& r : run.instances) {
    json inst = {{"family", bench::family_name(r.family)},
                 {"question", r.kind},
                 {"knob", r.knob},
                 {"difficulty", r.difficulty},
                 {"seed", r.seed}};
    for (std::size_t k = 0; k < run.rungs.size(); ++k) {
      const RungRecord& rr = r.rungs[k];
      json x = {{"verdict", rr.verdict}, {"median_seconds", rr.median_seconds}, {"repeats", rr.repeats}};
      if (k + 1 < run.rungs.size()) x["errors"] = errors_json(rr.errors);
      if (!rr.failure.empty()) x["failure"] = rr.failure;
      inst["rungs"][run.rungs[k].name] = x;
    }
    j["instances"].push_back(inst);
  }
  return j;
}

}  // namespace contactcert::queries
