// cddlib (GMP rationals) span <-> face conversion, as an independent reference for tests and benches.
// cddlib has global state: not thread safe.
#pragma once

#include "geometry/face_cone.h"
#include "geometry/span_cone.h"

namespace contactcert::reference {

/// Face form of pos(rays) + span(lines) by cddlib's dd_DDMatrix2Poly (GMP), in our sign convention.
geometry::FaceCone<exact::Q> cdd_to_face(const geometry::SpanCone<exact::Q>& cone);

/// Span form (rays, lines) of { F g <= 0, E g = 0 } by cddlib (GMP); strict rows are not allowed.
geometry::SpanCone<exact::Q> cdd_to_span(const geometry::FaceCone<exact::Q>& cone);

/// cddlib's floating-point conversion (ddf_*), span -> face, for benchmarks.
geometry::FaceCone<double> cddf_to_face(const geometry::SpanCone<double>& cone);

}  // namespace contactcert::reference
