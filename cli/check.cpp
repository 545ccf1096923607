// `contactcert check FILE [--problem PROBLEM]`: independent verification of a certificate. The certificate's
// top-level "kind" selects its checker; each checker re-derives everything from the embedded problem and
// trusts nothing else. The embedded problem's digest (problem_sha256) is printed; with --problem it must also
// be the problem of the file given, compared as canonical text after exact parsing. Exit 0: VALID; exit 2:
// INVALID (or a malformed certificate).
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/command.h"
#include "cli/results.h"
#include "exact/json_input.h"
#include "exact/sha256.h"
#include "queries/assembly_check_view.h"
#include "queries/contact_forces.h"
#include "solvers/design/goal_certificate.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/frame_check.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/ucp/certificate.h"
#include "solvers/ucp/problem.h"
#include "solvers/wrench_cone/cone_certificate.h"

namespace contactcert::cli {
namespace {

struct CheckOptions {
  CommonOptions common;
  std::string file;
  std::string problem;
};

/// A checker's answer in the common shape of all certificate kinds.
struct CheckOutcome {
  bool valid = false;
  std::string kind, reason, digest;
  nlohmann::ordered_json details = nlohmann::ordered_json::object();
  std::string text;  ///< readable lines of the evidence (the contact forces of a stability witness)
};

/// Whether a certificate of this kind embeds a planar scene (else a UCP problem).
bool embeds_scene(const std::string& kind) {
  return kind == "stability" || kind == "modes" || kind == "goal_nonempty" || kind == "assembly_stability" ||
         solvers::is_cone_certificate_kind(kind);
}

/// The problem a certificate embeds: a UCP problem as JSON, a scene as JSON text.
exact::JsonInput embedded_problem(const exact::JsonInput& cert, const std::string& kind) {
  if (embeds_scene(kind)) return exact::JsonInput::parse(cert.at("scene").string(), cert.file() + " (embedded scene)");
  return cert.at("problem");
}

/// The canonical text of a problem file as the certificate kind reads it: a UCP problem through its reader (a
/// quasistatic_scene with the checker's frames) and writer (so equal problems compare equal whatever their spelling),
/// a scene as its canonical JSON.
std::string problem_file_text(const exact::JsonInput& in, const std::string& kind) {
  if (embeds_scene(kind)) return in.canonical_text();
  const std::string text =
      solvers::ucp::to_json_text(solvers::ucp::read_ucp_problem(in, nullptr, solvers::frame_check::checked_frame));
  return exact::JsonInput::parse(text, in.file()).canonical_text();
}

/// The world forces of a valid "cone_nonempty" certificate's witness, from the contact forces the checker derived
/// from its z. The certificate's own readable "contacts" and "acceleration", if any, must be exactly these, else
/// it is INVALID.
void cone_view(const exact::JsonInput& cert, const solvers::ConeCertificateCheck& checked, CheckOutcome& c) {
  const geometry::PlanarScene scene = solvers::frame_check::read_checked_scene(embedded_problem(cert, c.kind)).scene;
  const exact::Vec<exact::Q> g = cert.at("wrench").rational_vector(3);
  const json view = witness_json(scene, checked.touching, checked.forces, g);
  c.details["witness"] = view;
  c.text = witness_text(scene, checked.touching, checked.forces, g, "  ");
  for (const char* key : {"contacts", "acceleration"})
    if (const auto given = cert.find(key);
        given && given->canonical_text() != exact::JsonInput::parse(view.at(key).dump(), key).canonical_text()) {
      c.valid = false;
      c.reason = std::string(key) + " is not the view of the checked witness";
    }
}

CheckOutcome check_any(const exact::JsonInput& cert) {
  const std::string kind = cert.at("kind").string();
  CheckOutcome out;
  out.kind = kind;
  if (solvers::ucp::is_ucp_certificate_kind(kind)) {
    const auto c = solvers::ucp::check_ucp_certificate(cert);
    out.valid = c.verdict == solvers::ucp::CertificateVerdict::kValid;
    out.reason = c.reason;
    if (kind == "ucp_jammed") out.details = {{"nodes", c.nodes}, {"leaves", c.leaves}};
    return out;
  }
  if (kind == "stability") {
    const auto c = solvers::check_stability_certificate(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    return out;
  }
  if (solvers::is_cone_certificate_kind(kind)) {
    const auto c = solvers::check_cone_certificate(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    if (c.valid && kind == "cone_nonempty") cone_view(cert, c, out);
    return out;
  }
  if (kind == "goal_nonempty") {
    const auto c = solvers::check_goal_certificate(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    return out;
  }
  if (kind == "modes") {
    const auto c = solvers::check_modes_certificate(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    out.details = {{"modes", c.modes}, {"dead_prefixes", c.dead}};
    return out;
  }
  if (kind == "assembly_stability") {
    const AssemblyCheckView c = assembly_check_view(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    out.details = c.details;
    return out;
  }
  cert.at("kind").fail(
      "expected a certificate kind: ucp_jammed, ucp_solvable, stability, modes, cone_empty, cone_nonempty, "
      "goal_nonempty or assembly_stability, found " +
      exact::quoted_excerpt(kind));
}

/// The contact forces of a checked stability witness as a person reads them (queries/contact_forces.h), recomputed
/// from the verified raw vector `forces` under `key`. The certificate's own readable "contacts", if any, must be
/// exactly these, else the certificate is INVALID: it would show a person numbers that were not checked.
void add_contacts(const exact::JsonInput& evidence, const std::string& key, const geometry::PlanarScene& scene,
                  const std::vector<Eigen::Index>& touching, CheckOutcome& c, json& view, std::string& text) {
  const exact::Vec<exact::Q> forces = evidence.at("forces").rational_vector(2 * touching.size());
  view = contacts_json(scene, touching, forces);
  text = contacts_text(scene, touching, forces, "    ");
  if (const auto given = evidence.find("contacts");
      given && given->canonical_text() != exact::JsonInput::parse(view.dump(), "contacts").canonical_text()) {
    c.valid = false;
    c.reason = key + ".contacts are not the world forces of the checked " + key + ".forces";
  }
}

/// The world forces of a valid stability certificate's resting and moving witnesses, in details and text.
void stability_view(const exact::JsonInput& cert, CheckOutcome& c) {
  const exact::JsonInput embedded = embedded_problem(cert, c.kind);
  const geometry::PlanarScene scene = solvers::frame_check::read_checked_scene(embedded).scene;
  std::vector<Eigen::Index> touching;
  solvers::touching_scene(scene, &touching);
  const exact::Vec<exact::Q> g = cert.at("wrench").rational_vector(3);
  c.details["wrench"] = exact_json(g);
  c.text = "  wrench g = " + tuple_text(g) + "\n";
  if (cert.at("resting").find("forces")) {
    json view;
    std::string lines;
    add_contacts(cert.at("resting"), "resting", scene, touching, c, view, lines);
    c.details["resting_contacts"] = view;
    c.text += "  at rest with contact forces (world coordinates; they balance g):\n" + lines;
  } else {
    c.text += "  at rest: no contact forces in the friction cones balance g (Motzkin vector checked)\n";
  }
  if (auto moving = cert.find("moving")) {
    json view;
    std::string lines;
    add_contacts(*moving, "moving", scene, touching, c, view, lines);
    const auto a = moving->at("acceleration").rational_vector(3);
    c.details["moving"] = {{"mode", moving->at("mode").string()}, {"acceleration", exact_json(a)}, {"contacts", view}};
    c.text += "  moves in mode '" + moving->at("mode").string() + "' with acceleration " + tuple_text(a) +
              ", contact forces (world coordinates):\n" + lines;
  }
}

/// The answer for one certificate, checked against the problem file `given` too unless it is null.
CheckOutcome check_certificate(const exact::JsonInput& cert, const exact::JsonInput* given) {
  CheckOutcome c = check_any(cert);
  if (c.valid && c.kind == "stability") stability_view(cert, c);
  const exact::JsonInput problem = embedded_problem(cert, c.kind);
  c.digest = problem.canonical_sha256();
  if (given != nullptr) {
    const std::string file_text = problem_file_text(*given, c.kind);
    if (c.valid && file_text != problem.canonical_text()) {
      c.valid = false;
      c.reason = "the certificate is about another problem than " + given->file() + " (its problem_sha256 is " +
                 c.digest + ", the file's " + exact::sha256_hex(file_text) + ")";
    }
  }
  return c;
}

json outcome_json(const CheckOutcome& c, const exact::JsonInput* given) {
  json j;
  j["valid"] = c.valid;
  j["kind"] = c.kind;
  j["reason"] = c.reason;
  j["problem_sha256"] = c.digest;
  if (given != nullptr) j["problem"] = given->file();
  for (auto it = c.details.begin(); it != c.details.end(); ++it) j[it.key()] = it.value();
  return j;
}

}  // namespace

json check_json(const exact::JsonInput& certificate, const exact::JsonInput* problem) {
  return outcome_json(check_certificate(certificate, problem), problem);
}

namespace {

int run_check(const CheckOptions& o) {
  const exact::JsonInput cert = exact::JsonInput::load(o.file);
  std::optional<exact::JsonInput> problem;
  if (!o.problem.empty()) problem = exact::JsonInput::load(o.problem);
  const CheckOutcome c = check_certificate(cert, problem ? &*problem : nullptr);
  if (o.common.json) {
    std::cout << outcome_json(c, problem ? &*problem : nullptr).dump() << "\n";
  } else {
    std::cout << "check " << o.file << ": " << c.kind << " certificate is " << (c.valid ? "VALID" : "INVALID")
              << (o.problem.empty() || !c.valid ? "" : " for " + o.problem) << "\n  " << c.reason << "\n"
              << (c.valid ? c.text : "") << "  problem sha256 " << c.digest << "\n";
  }
  return c.valid ? 0 : 2;
}

}  // namespace

void register_check(CLI::App& app, Action& action) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* sub = app.add_subcommand(
      "check", "Verify a certificate written by ucp, stability, modes, cone or design, independently");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Certificate file")->required();
  sub->add_option("--problem", o->problem,
                  "Problem (or scene) file the certificate must be about: INVALID if its embedded problem differs");
  sub->callback([o, &action] {
    // The checkers re-derive everything in rationals: a float check would be ignored, so it is refused.
    if (o->common.arith == "float")
      throw exact::InputError("command line", "--arith", "check verifies exactly (use exact or verified)");
    action = [o] { return run_check(*o); };
  });
}

}  // namespace contactcert::cli
