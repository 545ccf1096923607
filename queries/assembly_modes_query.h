// `contactcert modes ASSEMBLY`: every kinematically feasible contact mode of an assembly from rest (Table 2's
// s l r n at every contact, N bodies), each with an acceleration of the 3N that realises it, found by the
// single-body prefix tree over the assembly's relative accelerations (solvers/assembly/assembly_modes.h), and the
// tree as a completeness proof (the "assembly_modes" certificate) for `contactcert check`.
#pragma once

#include <string>

#include "queries/assembly_query.h"
#include "solvers/assembly/assembly_modes.h"

namespace contactcert::queries {

struct AssemblyModesOptions {
  CommonOptions common;                                   ///< exact or verified (float is refused)
  long max_nodes = solvers::ModeTreeOptions{}.max_nodes;  ///< prefixes visited at most
  long max_modes = solvers::ModeTreeOptions{}.max_modes;  ///< modes listed at most
  std::string certificate;                                ///< the certificate's file ("" = none)
};

struct AssemblyModesAnswer {
  solvers::assembly::AssemblyModes modes;
  std::size_t bodies = 0, contacts = 0;
  std::string certificate;       ///< the file written ("" = none)
  std::string certificate_text;  ///< its text
};

/// The feasible modes (InputError for --arith float; a Limit past a budget or the time limit, or for a certificate
/// larger than `check` reads), the certificate written where asked.
Limited<AssemblyModesAnswer> run_assembly_modes(const AssemblyInput& in, const AssemblyModesOptions& options);

/// {"bodies", "contacts", "table2": "strict", "list": "kinematic", "modes": [{"mode", "group", "acceleration"}],
/// "counts", "tree": {"nodes", "dead_prefixes", "lps"}, "certificate"}.
json to_json(const AssemblyModesAnswer& answer);
std::string to_text(const AssemblyModesAnswer& answer, const std::string& name);

}  // namespace contactcert::queries
