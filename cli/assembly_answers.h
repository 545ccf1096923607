// The printing of the answers on an assembly (queries/assembly_query.h), shared by `contactcert assembly` and by the
// commands that take an assembly file as well as a one-workpiece file (`stability`, `ucp`, `modes`), so each
// prints the same answer the same way.
#pragma once

#include <string>

#include "queries/assembly_modes_query.h"
#include "queries/assembly_query.h"

namespace contactcert::cli {

/// Prints the stability answer (its --json object or its text) and returns the exit code: 0, or 3 (with the
/// coverage on stderr) if a budget ran out before a verdict; `command` names the command in that message.
int print_assembly_answer(const queries::AssemblyStabilityAnswer& a, const std::string& file, bool json,
                          bool certificate_asked, const std::string& command);
/// Prints the quasistatic answer and returns 0, or 3 for an unknown status.
int print_assembly_answer(const queries::AssemblyUcpAnswer& a, const std::string& file, bool json);
/// Prints the modes answer and returns 0.
int print_assembly_answer(const queries::AssemblyModesAnswer& a, const std::string& file, bool json);

}  // namespace contactcert::cli
