#include "queries/options.h"

#include "exact/input_error.h"
#include "exact/json_input.h"

namespace contactcert::queries {

exact::Arith parse_arith(const std::string& text, const std::string& field) {
  for (const exact::Arith a :
       {exact::Arith::kExact, exact::Arith::kFloat, exact::Arith::kVerified, exact::Arith::kAdaptive})
    if (text == exact::arith_name(a)) return a;
  throw exact::InputError("command line", field,
                          "exact, float, verified or adaptive, found " + exact::quoted_excerpt(text));
}

solvers::Route parse_route(const std::string& text, const std::string& field) {
  for (const solvers::Route r : {solvers::Route::kPaper, solvers::Route::kProject})
    if (text == route_name(r)) return r;
  throw exact::InputError("command line", field, "paper or project, found " + exact::quoted_excerpt(text));
}

const char* route_name(solvers::Route route) { return route == solvers::Route::kPaper ? "paper" : "project"; }

Table2 parse_table2(const std::string& text, const std::string& field) {
  for (const Table2 t : {Table2::kStrict, Table2::kPrinted})
    if (text == table2_name(t)) return t;
  throw exact::InputError("command line", field, "strict or printed, found " + exact::quoted_excerpt(text));
}

const char* table2_name(Table2 table2) { return table2 == Table2::kStrict ? "strict" : "printed"; }

void refuse_float(exact::Arith arith, const std::string& why) {
  if (arith == exact::Arith::kFloat) throw exact::InputError("command line", "--arith", why);
}

exact::Arith scene_arith(exact::Arith arith) {
  return arith == exact::Arith::kAdaptive ? exact::Arith::kVerified : arith;
}

}  // namespace contactcert::queries
