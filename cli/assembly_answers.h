// The printing of the answers on an assembly (queries/assembly_query.h), shared by `contactcert assembly` and by the
// commands that take an assembly file as well as a one-workpiece file (`stability`, `ucp`, `modes`), so each
// prints the same answer the same way.
#pragma once

#include <string>

#include "queries/assembly_modes_query.h"
#include "queries/assembly_query.h"

namespace contactcert::cli {

// Each prints its query's Limit as every command does (report_limit, exit 3); `command` names the command there.

/// Prints the stability answer (its --json object or its text) and returns 0, or if a budget ran out before a
/// verdict only that limit (queries::limit_of) and 3.
int print_assembly_answer(const queries::Limited<queries::AssemblyStabilityAnswer>& r, const std::string& file,
                          bool json, const std::string& command);
/// Prints the quasistatic answer and returns 0, or 3 for an unknown status: a run stopped by a budget or the time
/// limit prints only that limit.
int print_assembly_answer(const queries::Limited<queries::AssemblyUcpAnswer>& r, const std::string& file, bool json,
                          const std::string& command);
/// Prints the modes answer and returns 0.
int print_assembly_answer(const queries::Limited<queries::AssemblyModesAnswer>& r, const std::string& file, bool json,
                          const std::string& command);

}  // namespace contactcert::cli
