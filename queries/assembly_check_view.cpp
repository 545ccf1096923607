#include "queries/assembly_check_view.h"

#include "solvers/assembly/assembly_certificate.h"

namespace contactcert::queries {

AssemblyCheckView assembly_check_view(const exact::JsonInput& certificate) {
  const auto c = solvers::assembly::check_assembly_certificate(certificate);
  return {c.valid, c.reason, {{"bodies", c.bodies}, {"contacts", c.contacts}, {"dead_prefixes", c.dead}}};
}

}  // namespace contactcert::queries
