# The installed C++ surface (docs/cpp.md): checks that the header lists of cmake/public_headers.cmake are closed
# and installs them. In the source tree headers include each other from the repo root ("exact/number.h"); installed,
# public PATH becomes <contactcert/PATH> and detail PATH <contactcert/detail/PATH>, and each installed header's
# project includes are rewritten to those names, so the package exports the one include directory PREFIX/include.
#   cmake -DSOURCE=REPO -P header_surface.cmake         the closure check alone (ctest public_header_surface)
#   include() + contactcert_install_headers(...)       from `cmake --install` (cmake/install.cmake)
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST) under -P
include(${CMAKE_CURRENT_LIST_DIR}/public_headers.cmake)

# The installed name of project header PATH in OUT; FATAL_ERROR, naming INCLUDER, if PATH is in neither list.
function(contactcert_installed_name path includer out)
  if(path IN_LIST CONTACTCERT_PUBLIC_HEADERS)
    set(${out} contactcert/${path} PARENT_SCOPE)
  elseif(path IN_LIST CONTACTCERT_DETAIL_HEADERS)
    set(${out} contactcert/detail/${path} PARENT_SCOPE)
  else()
    message(FATAL_ERROR "${includer} includes \"${path}\", which is neither public nor detail: add it to "
                        "CONTACTCERT_PUBLIC_HEADERS or CONTACTCERT_DETAIL_HEADERS in cmake/public_headers.cmake, "
                        "or include it from a .cpp instead")
  endif()
endfunction()

# The project headers (quoted includes) that header PATH includes, in OUT.
function(contactcert_includes source path out)
  if(NOT EXISTS ${source}/${path})
    message(FATAL_ERROR "cmake/public_headers.cmake lists ${path}, which does not exist")
  endif()
  file(STRINGS ${source}/${path} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  set(found)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*$" "\\1" included "${line}")
    list(APPEND found ${included})
  endforeach()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# FATAL_ERROR unless: no header is both public and detail; every include of a listed header is listed; every detail
# header is reached from a public one; contactcert.h includes exactly the other public headers.
function(contactcert_check_headers source)
  foreach(path IN LISTS CONTACTCERT_PUBLIC_HEADERS)
    if(path IN_LIST CONTACTCERT_DETAIL_HEADERS)
      message(FATAL_ERROR "${path} is listed both public and detail in cmake/public_headers.cmake")
    endif()
  endforeach()
  set(reached ${CONTACTCERT_PUBLIC_HEADERS})  # breadth first from the public headers
  set(queue ${CONTACTCERT_PUBLIC_HEADERS})
  while(queue)
    list(POP_FRONT queue path)
    contactcert_includes(${source} ${path} included)
    foreach(inc IN LISTS included)
      contactcert_installed_name(${inc} ${path} name)
      if(NOT inc IN_LIST reached)
        list(APPEND reached ${inc})
        list(APPEND queue ${inc})
      endif()
    endforeach()
  endwhile()
  foreach(path IN LISTS CONTACTCERT_DETAIL_HEADERS)
    if(NOT path IN_LIST reached)
      message(FATAL_ERROR "detail header ${path} is included by no installed header: drop it from "
                          "CONTACTCERT_DETAIL_HEADERS in cmake/public_headers.cmake")
    endif()
  endforeach()
  contactcert_includes(${source} contactcert.h umbrella)
  set(public ${CONTACTCERT_PUBLIC_HEADERS})
  list(REMOVE_ITEM public contactcert.h)
  list(SORT public)
  list(SORT umbrella)
  if(NOT public STREQUAL umbrella)
    message(FATAL_ERROR "contactcert.h must include exactly the public headers of cmake/public_headers.cmake:\n"
                        "  public:   ${public}\n  included: ${umbrella}")
  endif()
endfunction()

# Writes every public and detail header under INCLUDEDIR (PREFIX/include) with its project includes rewritten to
# their installed names (<contactcert/...>); the written files in OUT, for the install manifest.
function(contactcert_install_headers source includedir out)
  contactcert_check_headers(${source})
  set(written)
  foreach(path IN LISTS CONTACTCERT_PUBLIC_HEADERS CONTACTCERT_DETAIL_HEADERS)
    file(READ ${source}/${path} text)
    contactcert_includes(${source} ${path} included)
    foreach(inc IN LISTS included)
      contactcert_installed_name(${inc} ${path} name)
      string(REPLACE "#include \"${inc}\"" "#include <${name}>" text "${text}")
    endforeach()
    contactcert_installed_name(${path} ${path} name)
    set(file ${includedir}/${name})
    set(old)
    if(EXISTS ${file})
      file(READ ${file} old)
    endif()
    if(old STREQUAL text)
      message(STATUS "Up-to-date: ${file}")
    else()
      message(STATUS "Installing: ${file}")
      file(WRITE ${file} "${text}")
    endif()
    list(APPEND written ${file})
  endforeach()
  set(${out} ${written} PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  list(APPEND CONTACTCERT_PUBLIC_HEADERS ${EXTRA_PUBLIC})  # -DEXTRA_PUBLIC=PATH: the check's own test
  contactcert_check_headers(${SOURCE})
  list(LENGTH CONTACTCERT_PUBLIC_HEADERS n_public)
  list(LENGTH CONTACTCERT_DETAIL_HEADERS n_detail)
  message("public header surface closed: ${n_public} public, ${n_detail} detail headers")
endif()
