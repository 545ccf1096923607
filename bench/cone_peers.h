// PPL and Normaliz conversions beside cddlib for bench/cone_bench, each present only when the library
// was found (CONTACTCERT_HAVE_PPL / CONTACTCERT_HAVE_NORMALIZ): the number of output rows.
#pragma once

#include <vector>

#include "exact/number.h"

namespace contactcert::bench {

/// Integer rows (primitive) of a cone: generators (rays) or inequalities f . x <= 0.
using IntRows = std::vector<std::vector<exact::Z>>;

/// Facets of pos(rays) / extreme rays of { F x <= 0 }, by PPL (C_Polyhedron, minimized) or Normaliz
/// (SupportHyperplanes / ExtremeRays, one thread).
long ppl_facets(const IntRows& rays, long dim);
long ppl_rays(const IntRows& inequalities, long dim);
long normaliz_facets(const IntRows& rays, long dim);
long normaliz_rays(const IntRows& inequalities, long dim);

}  // namespace contactcert::bench
