# Precompiled headers (CONTACTCERT_PCH, off by default; scripts/test turns it on for the clang sanitizer build).
# The tests and the CLI spend a third of a clang -O0 compile parsing the same third-party headers (GoogleTest,
# CLI11, nlohmann/json, Eigen, gmpxx): with them precompiled, a sanitized test source compiles in ~8.0 s of CPU
# instead of ~11.4 s, a CLI source in ~10.1 s instead of ~13.3 s. gcc gains little (its precompiled header is
# ~190 MB to read back), and the libraries' sources include too little of these headers to gain.
# With ccache, a precompiled header is cached only with `sloppiness = pch_defines,time_macros,include_file_mtime,
# include_file_ctime` in ccache.conf (docs/building.md).
option(CONTACTCERT_PCH "Precompile the third-party headers shared by the tests and the CLI" OFF)

set(CONTACTCERT_PCH_HEADERS
    <algorithm> <functional> <map> <optional> <random> <sstream> <string> <vector> <Eigen/Core> <gmpxx.h>
    <boost/container/small_vector.hpp> <nlohmann/json.hpp>)

# contactcert_precompile_headers(TARGET [HEADER...]): TARGET's sources see CONTACTCERT_PCH_HEADERS and HEADER...
# precompiled, when CONTACTCERT_PCH is on.
function(contactcert_precompile_headers target)
  if(CONTACTCERT_PCH)
    target_precompile_headers(${target} PRIVATE ${CONTACTCERT_PCH_HEADERS} ${ARGN})
  endif()
endfunction()

# contactcert_reuse_precompiled_headers(TARGET FROM): TARGET's sources use FROM's precompiled header, which needs
# the same compiler options and no definition that FROM has and TARGET lacks.
function(contactcert_reuse_precompiled_headers target from)
  if(CONTACTCERT_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
