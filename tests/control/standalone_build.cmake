# The controller library built alone, as a game's build would take it: configure and build
# src/control as its own project (nothing of fragsim's top CMakeLists.txt, so nothing of the
# tool's dependencies), install it, then build and run examples/minimal_c against that install.
#   cmake -DSOURCE_DIR=src/control -DEXAMPLE_DIR=examples/minimal_c -DWORK_DIR=<scratch>
#         -DCXX=<c++ compiler> -DCC=<c compiler> -P standalone_build.cmake
foreach(var SOURCE_DIR EXAMPLE_DIR WORK_DIR CXX CC)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "standalone_build.cmake: ${var} not set")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
run("configure src/control alone" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
  -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release -DFRAGSIM_WERROR=ON)
run("build" ${CMAKE_COMMAND} --build ${WORK_DIR}/build --parallel 2)
run("install" ${CMAKE_COMMAND} --install ${WORK_DIR}/build --prefix ${WORK_DIR}/prefix)
run("configure examples/minimal_c on the install" ${CMAKE_COMMAND} -S ${EXAMPLE_DIR}
  -B ${WORK_DIR}/example -DCMAKE_C_COMPILER=${CC} -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
  -DCMAKE_BUILD_TYPE=Release)
run("build examples/minimal_c" ${CMAKE_COMMAND} --build ${WORK_DIR}/example)
run("run examples/minimal_c" ${WORK_DIR}/example/minimal_c)
file(REMOVE_RECURSE ${WORK_DIR})
