#include "queries/ucp_uniqueness.h"

#include "exact/input_error.h"
#include "solvers/motion/uniqueness_certificate.h"

namespace contactcert::queries {

namespace motion = solvers::motion;
namespace ucp = solvers::ucp;

void check_uniqueness_options(const UniquenessOptions& o, exact::Arith arith) {
  if (!o.all && o.max_modes)
    throw exact::InputError("command line", "--max-modes", "the budget of --all's uniqueness question; add --all");
  if (!o.all && !o.certificate.empty())
    throw exact::InputError("command line", "--uniqueness-certificate",
                            "the certificate of --all's uniqueness verdict; add --all");
  if (o.all && arith == exact::Arith::kFloat)
    throw exact::InputError("command line", "--all",
                            "the uniqueness question is decided exactly: --arith exact or verified");
}

Limited<std::optional<UniquenessAnswer>> decide_uniqueness(const ucp::UcpProblem& problem, const ucp::UcpReport& report,
                                                           const UniquenessOptions& o, exact::Arith arith,
                                                           const std::string& command,
                                                           const std::string& assembly_text) {
  if (!o.all || report.status == ucp::UcpStatus::kUnknown) return std::optional<UniquenessAnswer>();
  UniquenessAnswer a;
  if (report.status == ucp::UcpStatus::kJammed) {  // no solution, no motion: the jamming certificate proves it
    a.verdict.status = motion::UniquenessStatus::kNoMotion;
    return std::optional<UniquenessAnswer>(std::move(a));
  }
  const long budget = o.max_modes.value_or(motion::SimulateOptions{}.max_uniqueness_modes);
  a.verdict = motion::motion_uniqueness(problem, arith, budget, !o.certificate.empty());
  if (a.verdict.status == motion::UniquenessStatus::kUnknown)
    return Limit{
        command + ": the uniqueness prefix tree's LP budget (--max-modes " + std::to_string(budget) + ") ran out",
        std::to_string(a.verdict.lps) + " lps"};
  if (!o.certificate.empty()) {
    a.certificate_text = motion::uniqueness_certificate(problem, a.verdict, assembly_text);
    write_certificate_file(command, o.certificate, a.certificate_text,
                           std::string("the motion is ") + motion::uniqueness_name(a.verdict.status));
    a.certificate = o.certificate;
  }
  a.verdict.evidence.reset();  // written down
  return std::optional<UniquenessAnswer>(std::move(a));
}

json uniqueness_json(const motion::MotionUniqueness& u) {
  json motions = json::array();
  for (const exact::Vec<exact::Q>& m : u.motions) motions.push_back(exact_json(m));
  return {{"status", motion::uniqueness_name(u.status)}, {"motions", motions},       {"modes", u.modes},
          {"solution_modes", u.solution_modes},          {"unbounded", u.unbounded}, {"lps", u.lps}};
}

json to_json(const UniquenessAnswer& a) {
  json j = uniqueness_json(a.verdict);
  if (!a.certificate.empty()) j["certificate"] = a.certificate;
  return j;
}

std::string to_text(const UniquenessAnswer& a, long body_size) {
  const motion::MotionUniqueness& u = a.verdict;
  if (u.status == motion::UniquenessStatus::kNoMotion)
    return "  uniqueness: no motion (jammed, no solution: the jamming certificate is the proof; no motion_uniqueness "
           "certificate)\n";
  const bool unique = u.status == motion::UniquenessStatus::kUnique;
  std::string s = std::string("  uniqueness: ") + (unique ? "unique" : "not unique") + " (" +
                  std::to_string(u.solution_modes.size()) + " solution modes, " + std::to_string(u.lps) + " LPs" +
                  (u.unbounded ? ", a q_dot component unbounded" : "") + ")\n";
  for (std::size_t k = 0; k < u.motions.size(); ++k) {
    const exact::Vec<exact::Q>& m = u.motions[k];
    s += std::string("    ") + (unique ? "the motion" : "motion " + std::to_string(k + 1)) + " (mode " + u.modes[k] +
         "):";
    const Eigen::Index n = body_size > 0 ? body_size : m.size();
    for (Eigen::Index b = 0; b * n < m.size(); ++b)
      s += (m.size() > n ? (b > 0 ? ", body " : " body ") + std::to_string(b) + " " : std::string(" q_dot ")) +
           tuple_text(exact::Vec<exact::Q>(m.segment(b * n, std::min(n, m.size() - b * n))));
    s += "\n";
  }
  if (!a.certificate.empty()) s += std::string("  uniqueness certificate written to ") + a.certificate + "\n";
  return s;
}

}  // namespace contactcert::queries
