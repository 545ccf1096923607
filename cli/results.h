// The JSON results the subcommands print with --json, built apart from the printing so that the Python module
// (python/) returns the same objects from the same code.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "exact/json_input.h"
#include "geometry/planar_scene.h"
#include "queries/json_out.h"
#include "solvers/stability/finger_push.h"
#include "solvers/stability/margin.h"
#include "solvers/stability/stable_region.h"
#include "solvers/stability/strong_stability.h"
#include "solvers/ucp/problem.h"
#include "solvers/ucp/solve.h"

namespace contactcert::cli {

using namespace queries;  // the front end names the query layer's writers unqualified


// ucp.cpp: `ucp --generate random|reduction` and the report (`certificate`: the file it was written to, or empty).
solvers::ucp::UcpProblem generated_problem(const std::string& kind, std::uint64_t seed, int nc,
                                           const std::string& mu_max, int abar, int rows, int cols, bool planted);
json ucp_json(const solvers::ucp::UcpReport& r, const std::string& certificate);
/// Refuses (InputError) a budget that `method` would ignore: --max-nodes budgets only the complete search's tree,
/// --max-bases only Step 3 (every method but enumerate).
void refuse_ignored_budgets(const std::string& method, bool max_nodes_given, bool max_bases_given);

// check.cpp: `check` of a parsed certificate; with `problem` (a problem or scene file), INVALID unless the
// certificate is about that problem (`check --problem`).
json check_json(const exact::JsonInput& certificate, const exact::JsonInput* problem = nullptr);

}  // namespace contactcert::cli
