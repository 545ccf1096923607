# cmake -DBUILD=... -DEXAMPLES=... -DWORK=... -DGENERATOR=... [-DLAUNCHER=ccache] [-DPYTHON=... -DPYTHON_DIR=...]
#       -P consumer_test.cmake
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}")
  endif()
endfunction()
file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
set(launcher)
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${EXAMPLES} -B ${WORK}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
run(${CMAKE_COMMAND} --build ${WORK}/build)
run(${WORK}/build/consumer ${prefix}/share/contactcert/scenes)
# The installed CLI's demo reads the installed scenes by default.
execute_process(COMMAND ${prefix}/bin/contactcert demo --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
string(FIND "${help}" "${prefix}/share/contactcert/scenes" at)
if(NOT rc EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR "the installed demo's default scenes are not ${prefix}/share/contactcert/scenes:\n${help}")
endif()
# The installed Python module imports from the prefix alone.
if(PYTHON)
  set(scene ${prefix}/share/contactcert/scenes/bt2002_section7_disk.json)
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c
      "import sys, contactcert; sys.exit(contactcert.Scene.from_file('${scene}').stability('1,-2,0').verdict != 'strongly_stable')")
endif()
