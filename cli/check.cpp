// `contactcert check FILE`: independent verification of a certificate. The certificate's top-level "kind"
// selects its checker; each checker re-derives everything from the embedded problem and trusts nothing else.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "cli/results.h"
#include "exact/json_input.h"
#include "solvers/stability/contact_modes.h"
#include "solvers/stability/stability_certificate.h"
#include "solvers/ucp/certificate.h"

namespace contactcert::cli {
namespace {

struct CheckOptions {
  CommonOptions common;
  std::string file;
};

/// A checker's answer in the common shape of all certificate kinds.
struct CheckOutcome {
  bool valid = false;
  std::string kind, reason;
  nlohmann::ordered_json details = nlohmann::ordered_json::object();
};

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
  if (kind == "modes") {
    const auto c = solvers::check_modes_certificate(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    out.details = {{"modes", c.modes}, {"dead_prefixes", c.dead}};
    return out;
  }
  if (kind == "stability") {
    const auto c = solvers::check_stability_certificate(cert);
    out.valid = c.valid;
    out.reason = c.reason;
    return out;
  }
  cert.at("kind").fail("expected a certificate kind: ucp_jammed, ucp_solvable, stability or modes, found \"" + kind + "\"");
}

}  // namespace

json check_json(const exact::JsonInput& certificate) {
  const CheckOutcome c = check_any(certificate);
  json j;
  j["valid"] = c.valid;
  j["kind"] = c.kind;
  j["reason"] = c.reason;
  for (auto it = c.details.begin(); it != c.details.end(); ++it) j[it.key()] = it.value();
  return j;
}

namespace {

int run_check(const CheckOptions& o) {
  const json j = check_json(exact::JsonInput::load(o.file));
  if (o.common.json) {
    std::cout << j.dump() << "\n";
  } else {
    std::cout << "check " << o.file << ": " << j["kind"].get<std::string>() << " certificate is "
              << (j["valid"].get<bool>() ? "VALID" : "INVALID") << "\n  " << j["reason"].get<std::string>() << "\n";
  }
  return 0;
}

}  // namespace

void register_check(CLI::App& app, Action& action) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* sub = app.add_subcommand("check", "Verify a certificate written by ucp (or stability) independently");
  add_common_options(*sub, o->common);
  sub->add_option("file", o->file, "Certificate file")->required();
  sub->callback([o, &action] { action = [o] { return run_check(*o); }; });
}

}  // namespace contactcert::cli
