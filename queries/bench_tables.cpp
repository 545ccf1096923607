#include "queries/bench_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace contactcert::queries {
namespace bench_report {

std::string fmt(const char* f, double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

namespace {

std::string err_text(double x) { return std::isnan(x) ? "-" : (x == 0 ? "0" : fmt("%.1e", x)); }
std::string ms_text(double seconds) { return std::isnan(seconds) ? "-" : fmt("%.3g", 1e3 * seconds); }

}  // namespace

Table table(const BenchRun& run, Key key, std::optional<bench::Family> family) {
  const std::size_t R = run.rungs.size(), exact_rung = R - 1;
  Table t;
  t.header = key == Key::kFamilyQuestion ? std::vector<std::string>{"family", "question", "n"}
                                         : std::vector<std::string>{"question", "knob", "n"};
  for (const auto& rung : run.rungs) t.header.push_back(rung.name + " ms");
  for (std::size_t k = 1; k < R; ++k) t.header.push_back(run.rungs[k].name + "/" + run.rungs[0].name);
  for (std::size_t k = 0; k < exact_rung; ++k)
    for (const char* m : {" wrong", " viol", " xTy", " gen"}) t.header.push_back(run.rungs[k].name + m);
  for (const Group& g : groups(run, key, family)) {
    std::vector<std::string> row = {g.a, g.b, std::to_string(g.n)};
    for (std::size_t k = 0; k < R; ++k) row.push_back(ms_text(median(g.seconds[k])));
    for (std::size_t k = 1; k < R; ++k) {
      const double ratio = median(g.seconds[k]) / median(g.seconds[0]);
      row.push_back(std::isnan(ratio) ? "-" : fmt("%.2gx", ratio));
    }
    for (std::size_t k = 0; k < exact_rung; ++k) {
      std::string wrong = std::to_string(g.wrong[k]);
      if (g.undecided[k]) wrong.append("+").append(std::to_string(g.undecided[k])).append("u");
      row.push_back(wrong);
      for (double e : {g.violation[k], g.xTy[k], g.generators[k]}) row.push_back(err_text(e));
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::vector<Table> split(const Table& t, std::size_t rungs) {
  constexpr std::size_t kKey = 3, kPerRung = 4;
  std::vector<std::pair<std::size_t, std::size_t>> chunks = {{kKey, kKey + 2 * rungs - 1}};
  for (std::size_t c = chunks[0].second; c < t.header.size(); c += 2 * kPerRung)
    chunks.emplace_back(c, std::min(t.header.size(), c + 2 * kPerRung));
  std::vector<Table> out;
  for (const auto& chunk : chunks) {
    Table part;
    const auto take = [&](const std::vector<std::string>& r) {
      std::vector<std::string> x(r.begin(), r.begin() + kKey);
      x.insert(x.end(), r.begin() + static_cast<std::ptrdiff_t>(chunk.first),
               r.begin() + static_cast<std::ptrdiff_t>(chunk.second));
      return x;
    };
    part.header = take(t.header);
    for (const auto& r : t.rows) part.rows.push_back(take(r));
    out.push_back(std::move(part));
  }
  return out;
}

std::string aligned(const Table& t) {
  std::vector<std::size_t> w(t.header.size());
  for (std::size_t c = 0; c < w.size(); ++c) {
    w[c] = t.header[c].size();
    for (const auto& r : t.rows) w[c] = std::max(w[c], r[c].size());
  }
  std::ostringstream s;
  const auto line = [&](const std::vector<std::string>& r) {
    // Text columns (question, knob) left-aligned, numbers right-aligned.
    for (std::size_t c = 0; c < r.size(); ++c) {
      const std::string pad(w[c] - r[c].size(), ' ');
      s << "  " << (c < 2 ? r[c] + pad : pad + r[c]);
    }
    s << "\n";
  };
  line(t.header);
  for (const auto& r : t.rows) line(r);
  return s.str();
}

std::string markdown(const Table& t) {
  std::ostringstream s;
  const auto line = [&](const std::vector<std::string>& r) {
    s << "|";
    for (const auto& c : r) s << " " << c << " |";
    s << "\n";
  };
  line(t.header);
  s << "|";
  for (std::size_t c = 0; c < t.header.size(); ++c) s << (c < 2 ? "---|" : "---:|");
  s << "\n";
  for (const auto& r : t.rows) line(r);
  return s.str();
}

std::string header_text(const BenchRun& run) {
  std::ostringstream s;
  s << "contactcert bench: suite " << run.suite << (run.quick ? " (quick)" : "") << ", " << run.instances.size()
    << " instances, median of up to " << run.max_repeats << " repeats per rung, " << fmt("%.1f", run.seconds)
    << " s in all\n";
  for (std::size_t k = 0; k < run.rungs.size(); ++k) {
    const Totals t = totals(run, k);
    s << "  " << run.rungs[k].name << ": " << fmt("%.3f", t.seconds) << " s summed over instances";
    if (k + 1 < run.rungs.size())
      s << ", " << t.wrong << " wrong verdicts, " << t.undecided << " undecided (against exact)";
    s << "\n";
  }
  return s.str();
}

const char* const kLegend =
    "columns: median time per rung (ms) over the instances of the row; cost of each rung over the first; for each "
    "inexact rung: wrong verdicts against exact (+u: undecided), largest constraint violation relative to max(1, "
    "|rhs|), largest |x^T y|, largest distance between unit cone generators (2: one side empty). '-': does not "
    "apply.";

Table ladder_table(const BenchRun& run, bench::Family f) {
  Table t;
  t.header = {"rung", "bits", "n", "median ms", "wrong", "undecided", "worst error"};
  for (std::size_t k = 0; k < run.rungs.size(); ++k) {
    const bench::Rung& rung = run.rungs[k];
    const std::string bits = rung.number.kind == exact::Rung::Kind::kInterval ? "53 (interval)"
                             : rung.precision_bits > 0                        ? std::to_string(rung.precision_bits)
                                                                              : "exact";
    const LadderCell c = ladder_cell(run, f, k);
    t.rows.push_back({rung.name, bits, std::to_string(c.n), ms_text(c.median_seconds), std::to_string(c.wrong),
                      std::to_string(c.undecided), err_text(c.worst)});
  }
  return t;
}

std::string ladder_summary(const BenchRun& run, bench::Family f) {
  std::string right, wrong;
  for (std::size_t k = 0; k + 1 < run.rungs.size(); ++k) {
    const LadderCell c = ladder_cell(run, f, k);
    std::string& list = c.wrong == 0 ? right : wrong;
    list += (list.empty() ? "" : ", ") + run.rungs[k].name;
  }
  return std::string("no wrong verdicts: ") + (right.empty() ? "-" : right) +
         "; wrong verdicts: " + (wrong.empty() ? "-" : wrong);
}

const char* const kLadderLegend =
    "precision ladder: per family and rung, the median time over the family's instances, wrong verdicts against "
    "exact, undecided answers (unknown, failed, or an uncertain interval sign), and the worst error of the decided "
    "answers.";

}  // namespace bench_report

using namespace bench_report;

std::string bench_text(const BenchRun& run) {
  std::string s = header_text(run) + "\nsummary by family\n" + aligned(table(run, Key::kFamilyQuestion));
  for (bench::Family f : families_in(run))
    s += std::string("\n") + bench::family_name(f) + ": " + bench::family_description(f) + "\n" +
         aligned(table(run, Key::kQuestionKnob, f));
  return s + "\n" + kLegend + "\n\n" + ladder_text(run);
}

std::string bench_markdown(const BenchRun& run) {
  const auto tables = [&](const Table& t) {
    std::string out;
    for (const Table& part : split(t, run.rungs.size())) {
      if (!out.empty()) out += "\n";
      out += markdown(part);
    }
    return out;
  };
  std::string s =
      "```\n" + header_text(run) + "```\n\n### summary by family\n\n" + tables(table(run, Key::kFamilyQuestion));
  for (bench::Family f : families_in(run))
    s += std::string("\n### ") + bench::family_name(f) + "\n" + bench::family_description(f) + "\n\n" +
         tables(table(run, Key::kQuestionKnob, f));
  s += std::string("\n") + kLegend + "\n\n## precision ladder\n";
  for (bench::Family f : families_in(run))
    s += std::string("\n### ") + bench::family_name(f) + "\n" + ladder_summary(run, f) + "\n\n" +
         markdown(ladder_table(run, f));
  return s + "\n" + kLadderLegend + "\n";
}

std::string ladder_text(const BenchRun& run) {
  std::string s = "precision ladder\n";
  for (bench::Family f : families_in(run))
    s += std::string("\n") + bench::family_name(f) + " (" + ladder_summary(run, f) + ")\n" +
         aligned(ladder_table(run, f));
  return s + "\n" + kLadderLegend + "\n";
}

}  // namespace contactcert::queries
