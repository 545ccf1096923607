# Finds the interpreter and pybind11 (Debian: python3-pybind11, pybind11-dev) for the module in python/;
# without pybind11 the module is skipped with a message. Debian's python3-* packages serve /usr/bin/python3,
# so it is preferred over another python3 earlier on PATH (pass -DPython3_EXECUTABLE=... to choose).
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Interpreter of the Python module")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module)
if(Python3_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(pybind11_FOUND)
  set(CONTACTCERT_HAVE_PYTHON ON)
  # The static libraries are linked into the module's shared object; no interposition keeps their inlining.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  add_compile_options($<$<CXX_COMPILER_ID:GNU>:-fno-semantic-interposition>)
else()
  message(STATUS "contactcert: pybind11 not found (Debian: python3-pybind11 pybind11-dev), Python module skipped")
endif()
