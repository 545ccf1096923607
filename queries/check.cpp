#include "queries/check.h"

#include <optional>

#include "checker/assembly_modes_check.h"
#include "checker/cone_check.h"
#include "checker/frame_check.h"
#include "checker/goal_check.h"
#include "checker/modes_check.h"
#include "checker/spatial_cone_check.h"
#include "checker/spatial_modes_check.h"
#include "checker/spatial_stability_check.h"
#include "checker/stability_check.h"
#include "checker/ucp_check.h"
#include "checker/uniqueness_check.h"
#include "exact/sha256.h"
#include "queries/assembly_check_view.h"
#include "queries/check_views.h"
#include "solvers/ucp/problem.h"

namespace contactcert::queries {
namespace {

/// The problem a certificate embeds, parsed once, on first use: after its checker ran, so that the checker's
/// message about a malformed certificate comes first. A UCP problem is JSON inside the certificate; a scene is a
/// JSON text (its exact spelling is what the digest covers).
class EmbeddedProblem {
 public:
  EmbeddedProblem(const exact::JsonInput& cert, bool scene) : cert_(cert), scene_(scene) {}
  const exact::JsonInput& get() {
    if (!parsed_)
      parsed_ = scene_ ? exact::JsonInput::parse(cert_.at("scene").string(), cert_.file() + " (embedded scene)")
                       : cert_.at("problem");
    return *parsed_;
  }

 private:
  const exact::JsonInput& cert_;
  bool scene_;
  std::optional<exact::JsonInput> parsed_;
};

void check_ucp(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  const checker::CertificateCheck u = checker::check_ucp_certificate(cert);
  c.verdict = u.verdict == checker::CertificateVerdict::kValid ? CheckVerdict::kValid : CheckVerdict::kInvalid;
  c.reason = u.reason;
  if (c.kind == "ucp_jammed") c.details = {{"nodes", u.nodes}, {"leaves", u.leaves}};
}

/// The verdict of a checker whose answer is {valid, reason}.
template <class Answer>
void take(const Answer& a, CheckResult& c) {
  c.verdict = a.valid ? CheckVerdict::kValid : CheckVerdict::kInvalid;
  c.reason = a.reason;
}

void check_stability(const exact::JsonInput& cert, EmbeddedProblem& scene, CheckResult& c) {
  take(checker::check_stability_certificate(cert), c);
  if (c.valid()) stability_view(cert, scene.get(), c);
}

void check_modes(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  const checker::ModesCertificateCheck m = checker::check_modes_certificate(cert);
  take(m, c);
  c.details = {{"modes", m.modes}, {"dead_prefixes", m.dead}};
}

void check_cone(const exact::JsonInput& cert, EmbeddedProblem& scene, CheckResult& c) {
  const checker::ConeCertificateCheck k = checker::check_cone_certificate(cert);
  take(k, c);
  if (c.valid() && c.kind == "cone_nonempty") cone_view(cert, scene.get(), k.touching, k.forces, c);
}

void check_goal(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  take(checker::check_goal_certificate(cert), c);
}

void check_assembly(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  const AssemblyCheckView a = assembly_check_view(cert);
  take(a, c);
  c.details = a.details;
}

void check_assembly_modes(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  const checker::ModesCertificateCheck m = checker::check_assembly_modes_certificate(cert);
  take(m, c);
  c.details = {{"modes", m.modes}, {"dead_prefixes", m.dead}};
}

/// The certificates in lines (docs/formats.md section 5c) as another layout: refused, naming the command that writes
/// them (check_text reads them line by line).
void check_in_lines(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult&) {
  const std::string kind = cert.at("kind").string();
  cert.fail("a " + kind + " certificate in lines, as " + (kind == "spatial_modes" ? "modes" : "stability") +
            " writes it (docs/formats.md section 5c): check reads it line by line, and this text is another layout");
}

void check_spatial_cone(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  const checker::SpatialConeCheck k = checker::check_spatial_cone_certificate(cert);
  take(k, c);
  if (c.valid())
    c.details = {{"dimension", k.dimension},
                 {"rays", k.rays},
                 {"lines", k.lines},
                 {"inequalities", k.inequalities},
                 {"strict", k.strict}};
}

void check_uniqueness(const exact::JsonInput& cert, EmbeddedProblem&, CheckResult& c) {
  const checker::UniquenessCertificateCheck u = checker::check_uniqueness_certificate(cert);
  take(u, c);
  c.details = {{"verdict", u.verdict}, {"solution_modes", u.solution_modes}, {"dead_prefixes", u.dead}};
}

/// One certificate kind: whether it embeds a planar scene (else a UCP problem) and its checker, which sets the
/// verdict, the reason and the details and, for a valid certificate, the view a person reads of its evidence (which
/// makes it INVALID if the certificate's own readable numbers are not those of the checked evidence).
struct CertificateKind {
  const char* name;
  bool embeds_scene;
  void (*check)(const exact::JsonInput& cert, EmbeddedProblem& problem, CheckResult& c);
};

constexpr CertificateKind kKinds[] = {
    {"ucp_jammed", false, check_ucp},
    {"ucp_solvable", false, check_ucp},
    {"stability", true, check_stability},
    {"modes", true, check_modes},
    {"cone_empty", true, check_cone},
    {"cone_nonempty", true, check_cone},
    {"goal_nonempty", true, check_goal},
    {"assembly_stability", true, check_assembly},
    {"assembly_modes", true, check_assembly_modes},
    {"spatial_modes", true, check_in_lines},
    {"spatial_stability", true, check_in_lines},
    {"spatial_cone", true, check_spatial_cone},
    {"motion_uniqueness", false, check_uniqueness},
};

const CertificateKind& certificate_kind(const exact::JsonInput& cert) {
  const std::string kind = cert.at("kind").string();
  std::string names;
  for (const CertificateKind& k : kKinds) {
    if (kind == k.name) return k;
    names += std::string(names.empty() ? "" : &k == std::end(kKinds) - 1 ? " or " : ", ") + k.name;
  }
  cert.at("kind").fail("expected a certificate kind: " + names + ", found " + exact::quoted_excerpt(kind));
}

/// The canonical text of a problem file as the certificate kind reads it: a UCP problem through its reader (a
/// quasistatic_scene with the checker's frames) and writer (so equal problems compare equal whatever their spelling),
/// a scene or an assembly as its canonical JSON.
std::string problem_file_text(const exact::JsonInput& in, const CertificateKind& kind) {
  if (kind.embeds_scene || in.find("bodies")) return in.canonical_text();
  const std::string text =
      solvers::ucp::to_json_text(solvers::ucp::read_ucp_problem(in, nullptr, checker::frame_check::checked_frame));
  return exact::JsonInput::parse(text, in.file()).canonical_text();
}

/// The canonical text of the assembly an `assembly --ucp` certificate embeds ("" if it embeds none).
std::string embedded_assembly_text(const exact::JsonInput& cert) {
  const auto assembly = cert.find("assembly");
  return assembly ? exact::JsonInput::parse(assembly->string(), cert.file() + " (embedded assembly)").canonical_text()
                  : "";
}

/// Kind's checker (`run`) on a certificate whose members (all, or its head in lines) are `certificate`, then the
/// digest of its embedded problem and, with a problem file, whether it is about that problem.
template <class Run>
CheckResult checked(const exact::JsonInput& certificate, const CertificateKind& kind, const exact::JsonInput* problem,
                    const Run& run) {
  CheckResult c;
  c.kind = kind.name;
  EmbeddedProblem embedded(certificate, kind.embeds_scene);
  run(embedded, c);
  c.digest = embedded.get().canonical_sha256();
  if (problem != nullptr) {
    c.problem = problem->file();
    const std::string file_text = problem_file_text(*problem, kind);
    // An assembly file against a UCP certificate: the assembly an `assembly --ucp` certificate embeds.
    const bool by_assembly = !kind.embeds_scene && problem->find("bodies");
    const std::string about = by_assembly ? embedded_assembly_text(certificate) : embedded.get().canonical_text();
    if (c.valid() && file_text != about) {
      c.verdict = CheckVerdict::kInvalid;
      c.reason = "the certificate is about another problem than " + problem->file() + " (" +
                 (!by_assembly    ? "its problem_sha256 is " + c.digest
                  : about.empty() ? std::string("it embeds no assembly")
                                  : "its embedded assembly's sha256 is " + exact::sha256_hex(about)) +
                 ", the file's " + exact::sha256_hex(file_text) + ")";
    }
  }
  return c;
}

}  // namespace

CheckResult check(const exact::JsonInput& certificate, const exact::JsonInput* problem) {
  const CertificateKind& kind = certificate_kind(certificate);
  return checked(certificate, kind, problem,
                 [&](EmbeddedProblem& embedded, CheckResult& c) { kind.check(certificate, embedded, c); });
}

CheckResult check_text(const std::string& text, const std::string& file, const exact::JsonInput* problem) {
  const bool modes = checker::CertificateLines::starts_as(text, "spatial_modes");
  if (!modes && !checker::CertificateLines::starts_as(text, "spatial_stability"))
    return check(exact::JsonInput::parse(text, file), problem);
  const checker::CertificateLines lines(text, file);
  return checked(lines.head(), certificate_kind(lines.head()), problem, [&](EmbeddedProblem&, CheckResult& c) {
    if (!modes) return take(checker::check_spatial_stability_certificate(lines), c);
    const checker::ModesCertificateCheck m = checker::check_spatial_modes_certificate(lines);
    take(m, c);
    c.details = {{"modes", m.modes}, {"dead_prefixes", m.dead}};
  });
}

json to_json(const CheckResult& c) {
  json j;
  j["valid"] = c.valid();
  j["kind"] = c.kind;
  j["reason"] = c.reason;
  j["problem_sha256"] = c.digest;
  if (!c.problem.empty()) j["problem"] = c.problem;
  for (auto it = c.details.begin(); it != c.details.end(); ++it) j[it.key()] = it.value();
  return j;
}

}  // namespace contactcert::queries
