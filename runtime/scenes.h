// Where the bundled scenes (the papers' data, scenes/*.json) are: one answer for the CLI's demo, the `bench`
// families, the benchmarks and the tests.
#pragma once

#include <string>

namespace contactcert::runtime {

/// The bundled scenes folder: an installed data folder beside the executable (<prefix>/bin/contactcert ->
/// <prefix>/share/contactcert/scenes, or a scenes/ folder next to it), else the source tree's scenes/ the
/// program was built from.
std::string bundled_scenes_dir();

}  // namespace contactcert::runtime
