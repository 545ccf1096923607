#include "cli/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>

#include "cli/html_report.h"
#include "exact/arith.h"
#include "exact/input_error.h"

namespace contactcert::cli {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// max that skips NaN (NaN only if both are).
double nan_max(double a, double b) { return std::isnan(a) ? b : (std::isnan(b) ? a : std::max(a, b)); }

/// Instances that share a key (e.g. question kind and knob value), summarised per rung.
struct Group {
  std::string a, b;  ///< the key
  long n = 0;
  std::vector<std::vector<double>> seconds;  ///< per rung, per instance
  std::vector<long> wrong, undecided;
  std::vector<double> violation, xTy, generators;
};

/// Which two columns a table is keyed on.
enum class Key { kFamilyQuestion, kQuestionKnob };

/// The groups of the instances (of `family`, if given) by `key`, in order of first appearance.
std::vector<Group> groups(const BenchRun& run, Key key, std::optional<bench::Family> family = std::nullopt) {
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

std::string fmt(const char* f, double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

std::string err_text(double x) { return std::isnan(x) ? "-" : (x == 0 ? "0" : fmt("%.1e", x)); }
std::string ms_text(double seconds) { return std::isnan(seconds) ? "-" : fmt("%.3g", 1e3 * seconds); }

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// A row per group: times per rung, the cost of each rung over the first, and each inexact rung's errors.
Table table(const BenchRun& run, Key key, std::optional<bench::Family> family = std::nullopt) {
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

/// A wide table of table() as tables that fit a page: each repeats the 3 key columns; the first holds the times
/// and ratios (2R - 1 columns), the others the error columns of two inexact rungs each (4 per rung).
std::vector<Table> split(const Table& t, std::size_t rungs) {
  constexpr std::size_t kKey = 3, kPerRung = 4;
  std::vector<std::pair<std::size_t, std::size_t>> chunks = {{kKey, kKey + 2 * rungs - 1}};
  for (std::size_t c = chunks[0].second; c < t.header.size(); c += 2 * kPerRung)
    chunks.emplace_back(c, std::min(t.header.size(), c + 2 * kPerRung));
  std::vector<Table> out;
  for (const auto& [a, b] : chunks) {
    Table part;
    const auto take = [&](const std::vector<std::string>& r) {
      std::vector<std::string> x(r.begin(), r.begin() + kKey);
      x.insert(x.end(), r.begin() + static_cast<std::ptrdiff_t>(a), r.begin() + static_cast<std::ptrdiff_t>(b));
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

std::vector<bench::Family> families_in(const BenchRun& run) {
  std::vector<bench::Family> out;
  for (bench::Family f : bench::all_families())
    if (std::any_of(run.instances.begin(), run.instances.end(), [&](const InstanceRecord& r) { return r.family == f; }))
      out.push_back(f);
  return out;
}

struct Totals {
  double seconds = 0;
  long wrong = 0, undecided = 0;
};

Totals totals(const BenchRun& run, std::size_t k) {
  Totals t;
  for (const auto& r : run.instances) {
    t.seconds += r.rungs[k].median_seconds;
    t.wrong += r.rungs[k].errors.wrong_verdict;
    t.undecided += r.rungs[k].errors.undecided;
  }
  return t;
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

const char* kLegend =
    "columns: median time per rung (ms) over the instances of the row; cost of each rung over the first; for each "
    "inexact rung: wrong verdicts against exact (+u: undecided), largest constraint violation relative to max(1, "
    "|rhs|), largest |x^T y|, largest distance between unit cone generators (2: one side empty). '-': does not "
    "apply.";

json errors_json(const bench::Errors& e) {
  return {{"wrong_verdict", e.wrong_verdict},
          {"undecided", e.undecided},
          {"violation", e.violation},
          {"xTy", e.xTy},
          {"generator_distance", e.generator_distance}};
}

}  // namespace

namespace {

/// One point of a plot: time (s), error against exact, an optional label drawn beside it.
struct PlotPoint {
  double seconds = 0, error = 0;
  std::string label;
};
struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;
  bool connect = false;  ///< a line through the points, in order
};

/// Time (x) against error (y), log scales, one colour per series; an error of exactly 0 sits on the bottom line.
std::string svg_plot(const std::vector<PlotSeries>& series, const std::string& x_label) {
  constexpr double W = 640, H = 420, left = 70, right = 130, top = 20, bottom = 50;
  constexpr double y_floor = -18;  // log10 of the error drawn for an exact 0
  const char* colours[] = {"#d73027", "#4575b4", "#1a9850", "#984ea3", "#ff7f00", "#a65628", "#f781bf", "#666666"};
  double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
  for (const auto& ser : series)
    for (const auto& p : ser.points)
      if (p.seconds > 0) tmin = std::min(tmin, p.seconds), tmax = std::max(tmax, p.seconds);
  if (!(tmin < tmax)) tmin = 1e-6, tmax = 1;
  const double x0 = std::floor(std::log10(tmin)), x1 = std::ceil(std::log10(tmax));
  const auto X = [&](double t) { return left + (std::max(std::log10(t), x0) - x0) / (x1 - x0) * (W - left - right); };
  const auto Y = [&](double e) {
    const double l = e > 0 ? std::max(std::log10(e), y_floor + 1) : y_floor;
    return top + (0 - l) / (0 - y_floor) * (H - top - bottom);
  };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (double d = x0; d <= x1; ++d)
    s << "<line x1=\"" << X(std::pow(10, d)) << "\" y1=\"" << top << "\" x2=\"" << X(std::pow(10, d)) << "\" y2=\""
      << H - bottom << "\" stroke=\"#ddd\"/><text x=\"" << X(std::pow(10, d)) << "\" y=\"" << H - bottom + 15
      << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
  for (double d = 0; d >= y_floor; d -= 3) {
    const double y = d == y_floor ? Y(0) : Y(std::pow(10, d));
    s << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << W - right << "\" y2=\"" << y
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 5 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
      << (d == y_floor ? std::string("0")
          : d == 0     ? std::string("1 (wrong)")
                       : "1e" + std::to_string(int(d)))
      << "</text>\n";
  }
  s << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12 << "\" text-anchor=\"middle\">"
    << html_escape(x_label) << "</text>\n<text transform=\"translate(14," << (top + H - bottom) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">error against exact</text>\n";
  for (std::size_t k = 0; k < series.size(); ++k) {
    const char* c = colours[k % 8];
    const PlotSeries& ser = series[k];
    if (ser.connect && ser.points.size() > 1) {
      s << "<polyline fill=\"none\" stroke=\"" << c << "\" stroke-opacity=\"0.5\" points=\"";
      for (const auto& p : ser.points) s << X(p.seconds) << "," << Y(p.error) << " ";
      s << "\"/>\n";
    }
    for (const auto& p : ser.points) {
      s << "<circle cx=\"" << X(p.seconds) << "\" cy=\"" << Y(p.error) << "\" r=\"3\" fill=\"" << c
        << "\" fill-opacity=\"0.55\"/>\n";
      if (!p.label.empty())
        s << "<text x=\"" << X(p.seconds) + 4 << "\" y=\"" << Y(p.error) - 4 << "\" font-size=\"10\" fill=\"" << c
          << "\" paint-order=\"stroke\" stroke=\"white\" stroke-width=\"3\">" << html_escape(p.label) << "</text>\n";
    }
    s << "<circle cx=\"" << W - right + 15 << "\" cy=\"" << top + 10 + 18 * k << "\" r=\"4\" fill=\"" << c
      << "\"/><text x=\"" << W - right + 24 << "\" y=\"" << top + 14 + 18 * k << "\">" << html_escape(ser.name)
      << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

/// One family on one rung: median time, wrong verdicts, undecided, worst error of the decided
/// answers (largest violation, |x^T y| or generator distance; NaN if none applies).
struct LadderCell {
  long n = 0, wrong = 0, undecided = 0;
  double median_seconds = kNaN, worst = kNaN;
};

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

/// The family's precision ladder: a row per rung.
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

/// "Where does the family stop making wrong verdicts?": the rungs (unchecked ones included) with none.
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

const char* kLadderLegend =
    "precision ladder: per family and rung, the median time over the family's instances, wrong verdicts against "
    "exact, undecided answers (unknown, failed, or an uncertain interval sign), and the worst error of the decided "
    "answers.";

}  // namespace

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

long disagreements(const BenchRun& run, std::size_t rung) {
  const std::size_t x = run.rungs.size() - 1;
  return std::count_if(run.instances.begin(), run.instances.end(),
                       [&](const InstanceRecord& r) { return r.rungs[rung].verdict != r.rungs[x].verdict; });
}

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

std::string bench_svg(const BenchRun& run) {
  std::vector<PlotSeries> series;
  for (std::size_t k = 0; k < run.rungs.size(); ++k) {
    PlotSeries ser{run.rungs[k].name, {}, false};
    for (const auto& r : run.instances)
      ser.points.push_back({r.rungs[k].median_seconds, bench::worst_error(r.rungs[k].errors), {}});
    series.push_back(std::move(ser));
  }
  return svg_plot(series, "time per instance (s, median of repeats)");
}

std::string ladder_svg(const BenchRun& run) {
  std::vector<PlotSeries> series;
  for (bench::Family f : families_in(run)) {
    PlotSeries ser{bench::family_name(f), {}, true};
    for (std::size_t k = 0; k < run.rungs.size(); ++k) {
      const LadderCell c = ladder_cell(run, f, k);
      // A wrong or undecided answer anywhere in the family puts its rung on the "1 (wrong)" line.
      const double e = c.wrong + c.undecided > 0 ? 1.0 : (std::isnan(c.worst) ? 0.0 : c.worst);
      ser.points.push_back({c.median_seconds, e, run.rungs[k].name});
    }
    series.push_back(std::move(ser));
  }
  return svg_plot(series, "median time per instance of the family (s)");
}

std::string ladder_text(const BenchRun& run) {
  std::string s = "precision ladder\n";
  for (bench::Family f : families_in(run))
    s += std::string("\n") + bench::family_name(f) + " (" + ladder_summary(run, f) + ")\n" +
         aligned(ladder_table(run, f));
  return s + "\n" + kLadderLegend + "\n";
}

std::vector<std::string> write_bench_report(const BenchRun& run, const std::string& dir) {
  create_output_dir(dir);
  const auto path = [&](const char* name) { return (std::filesystem::path(dir) / name).string(); };
  std::vector<std::string> written = {path("report.txt"), path("report.md"), path("time_vs_error.svg"),
                                      path("bench.json"), path("precision_ladder.svg")};
  write_text_file(written[0], bench_text(run));
  write_text_file(written[1], bench_markdown(run));
  const std::string svg = bench_svg(run);
  write_text_file(written[2], svg);
  write_text_file(written[3], bench_json(run).dump(1) + "\n");
  const std::string ladder = ladder_svg(run);
  write_text_file(written[4], ladder);
  HtmlReport html("contactcert bench: speed against error");
  html.preformatted(header_text(run));
  html.figure(svg,
              "Each dot is one instance on one rung: its median time and its largest error against the exact "
              "answer (a wrong verdict counts as 1; an error of exactly 0 sits on the bottom line).");
  html.heading("summary by family");
  for (const Table& t : split(table(run, Key::kFamilyQuestion), run.rungs.size())) html.table(t.header, t.rows);
  for (bench::Family f : families_in(run)) {
    html.heading(bench::family_name(f));
    html.paragraph(bench::family_description(f));
    for (const Table& t : split(table(run, Key::kQuestionKnob, f), run.rungs.size())) html.table(t.header, t.rows);
  }
  html.paragraph(kLegend);
  html.heading("precision ladder");
  html.figure(ladder,
              "One point per family and rung: the median time over the family's instances and the worst error of "
              "its decided answers (any wrong or undecided answer: 1).");
  for (bench::Family f : families_in(run)) {
    const Table t = ladder_table(run, f);
    html.heading(std::string(bench::family_name(f)) + ": precision ladder");
    html.paragraph(ladder_summary(run, f));
    html.table(t.header, t.rows);
  }
  html.paragraph(kLadderLegend);
  written.push_back(html.write(dir));
  return written;
}

}  // namespace contactcert::cli
