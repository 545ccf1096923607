// The "spatial_modes" certificate (issue 34; docs/formats.md section 5b) of solvers/spatial/spatial_modes.h's tree, in
// the lines of the spatial_stability certificate (section 5c; checker/certificate_lines.h): the head (scene, digest)
// one member a line, then each distinct Motzkin vector of the dead prefixes once (spatial_certificate_lines.h), the
// dead prefixes by their parent, each naming its vector, and each mode with its acceleration. A box on a plane with
// 32 contacts: ~720 000 dead prefixes name a few thousand vectors, so the file stays within what check reads.
#pragma once

#include <string>

#include "solvers/spatial/spatial_modes.h"

namespace contactcert::solvers::spatial {

/// The certificate text of `tree`, walked on the scene read from scene_text (embedded verbatim); checked by
/// checker/spatial_modes_check.h.
std::string spatial_modes_certificate(const std::string& scene_text, const SpatialModeTree& tree);

}  // namespace contactcert::solvers::spatial
