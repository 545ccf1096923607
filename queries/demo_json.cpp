// `demo`'s answer written out: the readable report's lines and the --json object (queries/demo_query.h).
#include "exact/rational_text.h"
#include "queries/demo_query.h"

namespace contactcert::queries {
std::string generators_text(const exact::Mat<exact::Q>& M) {
  std::string s;
  for (Eigen::Index r = 0; r < M.rows(); ++r)
    s += (r ? ", " : "") + tuple_text(exact::Vec<exact::Q>(M.row(r).transpose()));
  return s.empty() ? "none" : s;
}

namespace {

json row_json(const DemoCone& c) {
  json x = {{"scene", c.scene}, {"mode", c.mode}, {"status", c.empty ? "empty" : "non_empty"}};
  if (!c.empty) {
    x["dimension"] = c.dimension;
    x["generators"] = exact_json(c.generators);
    x["open_faces"] = c.open_faces;
  }
  return x;
}

json row_json(const DemoStability& s) {
  json x = {{"wrench", exact_json(s.wrench)},
            {"verdict", solvers::verdict_name(s.verdict)},
            {"evidence", s.evidence},
            {"certificate_valid", s.certificate_valid},
            {"lps", s.lps}};
  if (!s.certificate_valid) x["certificate_reason"] = s.certificate_reason;
  return x;
}

json row_json(const DemoInsertion& i) {
  return {{"scene", i.scene},   {"mu", exact_json(exact::parse_rational(i.mu))},
          {"cones", i.cones},   {"non_redundant", i.non_redundant},
          {"pushes", i.pushes}, {"boundary_fraction", i.boundary_fraction}};
}

json row_json(const DemoDataSet& d) {
  json x = {{"data_set", d.data_set}, {"status", solvers::ucp::status_name(d.status)}};
  if (d.xTy) x["xTy"] = exact_json(*d.xTy);
  x["pairs"] = d.pairs;
  x["lps"] = d.lps;
  x["evidence"] = d.evidence;
  x["seconds"] = d.seconds;
  return x;
}

json row_json(const DemoRandomProblem& p) {
  json x = {{"nc", p.nc}, {"mu_max", exact_json(p.mu_max)}, {"abar", p.abar}};
  for (const DemoRandomProblem::Run& r : p.runs)
    x[solvers::ucp::method_name(r.method)] = {
        {"status", solvers::ucp::status_name(r.status)}, {"pairs", r.pairs}, {"lps", r.lps}, {"seconds", r.seconds}};
  return x;
}

json row_json(const DemoScene& s) {
  return {{"file", s.file}, {"kind", s.kind}, {"verdict", s.verdict}, {"evidence", s.evidence}};
}

/// j[key]: a row_json per row, if the section ran (has rows).
template <class Row>
void add_rows(json& j, const char* key, const std::vector<Row>& rows) {
  if (rows.empty()) return;
  json out = json::array();
  for (const Row& r : rows) out.push_back(row_json(r));
  j[key] = out;
}

}  // namespace

std::string demo_header_line(const std::string& scenes) { return "contactcert demo on " + scenes + "\n"; }

std::string demo_line(const DemoCone& c) {
  return "  cone  " + c.scene + " '" + c.mode +
         "': " + (c.empty ? "empty" : "generators " + generators_text(c.generators)) + "\n";
}

std::string demo_line(const DemoStability& s) {
  return "  stability g = " + tuple_text(s.wrench) + ": " + solvers::verdict_name(s.verdict) + " (certificate " +
         (s.certificate_valid ? "valid" : "INVALID") + ")\n";
}

std::string demo_line(const DemoRegion& r) {
  return "  region: " + std::to_string(r.cells) + " exact cells, " + std::to_string(r.strongly_stable_regions) +
         " open strongly stable regions\n";
}

std::string demo_insertion_line(const std::vector<DemoInsertion>& rows) {
  return "  insertion: " + std::to_string(rows.size()) + " friction cases\n";
}

std::string demo_line(const DemoDataSet& d) {
  return "  Data Set " + std::to_string(d.data_set) + ": " + solvers::ucp::status_name(d.status) + " (" + d.evidence +
         ")\n";
}

std::string demo_table1_line(const std::vector<DemoRandomProblem>& rows) {
  return "  Table 1: " + std::to_string(rows.size()) + " random problems\n";
}

std::string demo_line(const DemoScene& s) { return "  your scene " + s.file + ": " + s.verdict + "\n"; }

std::string demo_report_line(const DemoAnswer& a) {
  return "report: " + a.report + " (" + std::to_string(a.seconds).substr(0, 5) + " s)\n";
}

std::string demo_text(const DemoAnswer& a) {
  std::string s = demo_header_line(a.scenes);
  for (const DemoCone& c : a.cones) s += demo_line(c);
  for (const DemoStability& x : a.stability) s += demo_line(x);
  if (a.region) s += demo_line(*a.region);
  if (!a.insertion.empty()) s += demo_insertion_line(a.insertion);
  for (const DemoDataSet& d : a.data_sets) s += demo_line(d);
  if (!a.table1.empty()) s += demo_table1_line(a.table1);
  for (const DemoScene& x : a.scenes_of_folder) s += demo_line(x);
  return s + demo_report_line(a);
}

json to_json(const DemoAnswer& a) {
  json j;
  j["command"] = "demo";
  j["scenes"] = a.scenes;
  add_rows(j, "wrench_cones", a.cones);
  add_rows(j, "stability", a.stability);
  if (a.region) {
    json pushes = json::array();
    for (const DemoRegion::Push& p : a.region->pushes)
      pushes.push_back({{"piece", p.piece}, {"verdict", solvers::verdict_name(p.verdict)}});
    j["region"] = {{"cells", a.region->cells},
                   {"strongly_stable_regions", a.region->strongly_stable_regions},
                   {"finger_pushes", pushes}};
  }
  add_rows(j, "insertion", a.insertion);
  add_rows(j, "data_sets", a.data_sets);
  add_rows(j, "table1", a.table1);
  add_rows(j, "scenes_of_folder", a.scenes_of_folder);
  j["report"] = a.report;
  j["seconds"] = a.seconds;
  return j;
}

}  // namespace contactcert::queries
