// The independent checker of the UCP certificates "ucp_jammed" and "ucp_solvable" (their format:
// solvers/ucp/certificate.h). It re-derives X and Y from the embedded problem with its own code (not build_X /
// build_Y: Y's rows are written out from eq. (5)-(10), X of a quasistatic problem is tested through the column
// space of P), recomputes every node's fixings from the tree and checks every leaf's Farkas vector exactly.
#pragma once

#include <string>

#include "exact/json_input.h"

namespace contactcert::checker {

enum class CertificateVerdict { kValid, kInvalid };

/// The checker's answer, with why.
struct CertificateCheck {
  CertificateVerdict verdict = CertificateVerdict::kInvalid;
  std::string kind;
  std::string reason;
  long nodes = 0, leaves = 0;
};

/// Checks a UCP certificate without trusting the solver: re-derives X and Y from the embedded problem,
/// recomputes every node's fixings from the tree, and checks every leaf's Farkas vector exactly.
CertificateCheck check_ucp_certificate(const exact::JsonInput& certificate);

}  // namespace contactcert::checker
