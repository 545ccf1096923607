// PPL, Normaliz and lrs conversions beside cddlib for bench/cone_bench: PPL and Normaliz present only when
// the library was found (CONTACTCERT_HAVE_PPL / CONTACTCERT_HAVE_NORMALIZ), lrs when its program is.
#pragma once

#include <optional>
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

/// The output of one run of the lrs program (lrslib 7, hybrid arithmetic: 64 bits, then 128, then GMP):
/// inequality rows or rays as primitive integer rows, the linearity rows (equalities or lines), and
/// the CPU time of the lrs process (user + system), which reads and writes files.
struct LrsOutput {
  IntRows rows, linearity;
  double cpu_seconds = 0;
};

/// Facets of pos(rays) (f . x <= 0) / extreme rays of { F x <= 0 } by `lrs` (Debian's lrslib ships no
/// headers, so the program is run on files); nullopt when the program is missing or fails.
std::optional<LrsOutput> lrs_facets(const IntRows& rays, long dim);
std::optional<LrsOutput> lrs_rays(const IntRows& inequalities, long dim);

}  // namespace contactcert::bench
