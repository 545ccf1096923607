#include "queries/bench_aggregate.h"

#include <algorithm>
#include <cmath>

namespace contactcert::queries {

double median(std::vector<double> v) {
  if (v.empty()) return bench_report::kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

long disagreements(const BenchRun& run, std::size_t rung) {
  const std::size_t x = run.rungs.size() - 1;
  return std::count_if(run.instances.begin(), run.instances.end(),
                       [&](const InstanceRecord& r) { return r.rungs[rung].verdict != r.rungs[x].verdict; });
}

namespace bench_report {

double nan_max(double a, double b) { return std::isnan(a) ? b : (std::isnan(b) ? a : std::max(a, b)); }

std::vector<Group> groups(const BenchRun& run, Key key, std::optional<bench::Family> family) {
  const std::size_t R = run.rungs.size();
  std::vector<Group> out;
  for (const InstanceRecord& r : run.instances) {
    if (family && r.family != *family) continue;
    const std::string a = key == Key::kFamilyQuestion ? bench::family_name(r.family) : r.kind;
    const std::string& b = key == Key::kFamilyQuestion ? r.kind : r.knob;
    auto g = std::find_if(out.begin(), out.end(), [&](const Group& x) { return x.a == a && x.b == b; });
    if (g == out.end()) {
      out.push_back({a, b, 0, std::vector<std::vector<double>>(R), std::vector<long>(R), std::vector<long>(R),
                     std::vector<double>(R, kNaN), std::vector<double>(R, kNaN), std::vector<double>(R, kNaN)});
      g = out.end() - 1;
    }
    ++g->n;
    for (std::size_t k = 0; k < R; ++k) {
      const RungRecord& rr = r.rungs[k];
      g->seconds[k].push_back(rr.median_seconds);
      g->wrong[k] += rr.errors.wrong_verdict;
      g->undecided[k] += rr.errors.undecided;
      g->violation[k] = nan_max(g->violation[k], rr.errors.violation);
      g->xTy[k] = nan_max(g->xTy[k], rr.errors.xTy);
      g->generators[k] = nan_max(g->generators[k], rr.errors.generator_distance);
    }
  }
  return out;
}

std::vector<bench::Family> families_in(const BenchRun& run) {
  std::vector<bench::Family> out;
  for (bench::Family f : bench::all_families())
    if (std::any_of(run.instances.begin(), run.instances.end(), [&](const InstanceRecord& r) { return r.family == f; }))
      out.push_back(f);
  return out;
}

Totals totals(const BenchRun& run, std::size_t k) {
  Totals t;
  for (const auto& r : run.instances) {
    t.seconds += r.rungs[k].median_seconds;
    t.wrong += r.rungs[k].errors.wrong_verdict;
    t.undecided += r.rungs[k].errors.undecided;
  }
  return t;
}

LadderCell ladder_cell(const BenchRun& run, bench::Family f, std::size_t k) {
  LadderCell c;
  std::vector<double> seconds;
  for (const InstanceRecord& r : run.instances) {
    if (r.family != f) continue;
    const bench::Errors& e = r.rungs[k].errors;
    ++c.n;
    seconds.push_back(r.rungs[k].median_seconds);
    c.wrong += e.wrong_verdict;
    c.undecided += e.undecided;
    c.worst = nan_max(c.worst, nan_max(e.violation, nan_max(e.xTy, e.generator_distance)));
    if (k + 1 == run.rungs.size()) c.worst = 0;
  }
  c.median_seconds = median(seconds);
  return c;
}

}  // namespace bench_report
}  // namespace contactcert::queries
