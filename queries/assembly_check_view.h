// `contactcert check` on an "assembly_stability" certificate (solvers/assembly/assembly_certificate.h): the
// checker's answer in the shape of the other kinds, for the check dispatch.
#pragma once

#include <string>

#include "exact/json_input.h"
#include "queries/json_out.h"

namespace contactcert::queries {

struct AssemblyCheckView {
  bool valid = false;
  std::string reason;
  json details;  ///< {"bodies", "contacts", "dead_prefixes"} of the embedded assembly and the evidence
};

/// Verifies the certificate (InputError naming the field if it is malformed).
AssemblyCheckView assembly_check_view(const exact::JsonInput& certificate);

}  // namespace contactcert::queries
