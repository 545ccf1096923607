#include "queries/assembly_check_view.h"

#include "checker/assembly_check.h"

namespace contactcert::queries {

AssemblyCheckView assembly_check_view(const exact::JsonInput& certificate) {
  const auto c = checker::check_assembly_certificate(certificate);
  return {c.valid, c.reason, {{"bodies", c.bodies}, {"contacts", c.contacts}, {"dead_prefixes", c.dead}}};
}

}  // namespace contactcert::queries
