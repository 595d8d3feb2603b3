# The controller library built alone, as a game's build would take it: configure and build
# src/control as its own project (nothing of fragsim's top CMakeLists.txt, so nothing of the
# tool's dependencies), install it, then build and run examples/minimal_c against that install.
# Then the C API's tests (tests/control/api) as their own project, which takes the library's
# folder with add_subdirectory as a game's tree would; and, when CLANG_CC is given, the same with
# clang, -Werror and ThreadSanitizer (the library and the thread test).
#   cmake -DSOURCE_DIR=src/control -DEXAMPLE_DIR=examples/minimal_c -DAPI_TESTS_DIR=tests/control/api
#         -DWORK_DIR=<scratch> -DCXX=<c++ compiler> -DCC=<c compiler>
#         [-DCLANG_CXX=clang++ -DCLANG_CC=clang] -P standalone_build.cmake
foreach(var SOURCE_DIR EXAMPLE_DIR API_TESTS_DIR WORK_DIR CXX CC)
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

run("configure tests/control/api alone (src/control by add_subdirectory)" ${CMAKE_COMMAND}
  -S ${API_TESTS_DIR} -B ${WORK_DIR}/api -DCMAKE_C_COMPILER=${CC} -DCMAKE_CXX_COMPILER=${CXX}
  -DCMAKE_BUILD_TYPE=Release -DFRAGSIM_WERROR=ON)
run("build tests/control/api" ${CMAKE_COMMAND} --build ${WORK_DIR}/api --parallel 2)
run("run tests/control/api" ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/api --output-on-failure)
if(CLANG_CC AND CLANG_CXX)
  run("configure tests/control/api with clang and ThreadSanitizer" ${CMAKE_COMMAND}
    -S ${API_TESTS_DIR} -B ${WORK_DIR}/tsan -DCMAKE_C_COMPILER=${CLANG_CC}
    -DCMAKE_CXX_COMPILER=${CLANG_CXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRAGSIM_WERROR=ON
    -DFRAGSIM_API_TESTS_TSAN=ON)
  run("build tests/control/api with clang and ThreadSanitizer" ${CMAKE_COMMAND}
    --build ${WORK_DIR}/tsan --parallel 2)
  run("run the thread test under ThreadSanitizer" ${CMAKE_COMMAND} -E env
    TSAN_OPTIONS=halt_on_error=1:abort_on_error=0 ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/tsan
    --output-on-failure)
endif()
file(REMOVE_RECURSE ${WORK_DIR})
