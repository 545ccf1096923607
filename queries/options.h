// The options every query shares, typed (SPEC section 6): the arithmetic, the cone route, the Table 2 reading and
// the wall-clock limit, each parsed from its text once (by the front ends, with the option's name in the error)
// and defaulted once, here. A query's own options struct (queries/*_query.h) holds these and its own fields.
#pragma once

#include <string>

#include "exact/arith.h"
#include "exact/deadline.h"
#include "solvers/wrench_cone/wrench_cone.h"

namespace contactcert::queries {

/// Largest time limit accepted, in seconds (about 116 days): keeps the deadline's clock arithmetic exact.
inline constexpr double kMaxTimeLimit = 1e7;

/// How `modes` and `cone --mode` read Table 2's separating rows: strictly (a_n > 0) or as printed (a_n >= 0).
enum class Table2 { kStrict, kPrinted };

/// What every query takes: its arithmetic (default verified) and its wall-clock limit in seconds (0 = none).
struct CommonOptions {
  exact::Arith arith = exact::Arith::kVerified;
  double time_limit = 0;
  /// The deadline of `time_limit`, from now.
  exact::Deadline deadline() const { return exact::Deadline::after(time_limit); }
};

/// "exact" | "float" | "verified" | "adaptive"; InputError naming `field` (e.g. "--arith") otherwise.
exact::Arith parse_arith(const std::string& text, const std::string& field);
/// "paper" | "project"; InputError naming `field` otherwise.
solvers::Route parse_route(const std::string& text, const std::string& field);
const char* route_name(solvers::Route route);
/// "strict" | "printed"; InputError naming `field` otherwise.
Table2 parse_table2(const std::string& text, const std::string& field);
const char* table2_name(Table2 table2);

/// For a question answered only exactly: InputError naming --arith if `arith` is float, with `why` as its message
/// (e.g. "modes are enumerated exactly (use exact or verified)").
void refuse_float(exact::Arith arith, const std::string& why);

/// The arithmetic a planar-scene query runs: its verified path already settles each LP from a float answer checked
/// exactly, so the UCP's precision ladder (adaptive) runs, and is reported, as verified.
exact::Arith scene_arith(exact::Arith arith);

}  // namespace contactcert::queries
