# The controller library built alone, as a game's build would take it: configure and build
# src/control as its own project (nothing of fragsim's top CMakeLists.txt, so nothing of the
# tool's dependencies), install it, then build and run examples/minimal_c against that install.
# Then the C API's tests (tests/control/api) as their own project, which takes the library's
# folder with add_subdirectory as a game's tree would; and, when CLANG_CC is given, the same with
# clang, -Werror and ThreadSanitizer (the library and the thread test).
#
# Every configure runs under standalone_guard.cmake, which fails it if anything beyond Eigen (and
# Threads, for the thread test) is looked for. The built shared library must need nothing but
# the C and C++ runtimes, and its sources must see no include folder but its own and Eigen's
# (the library is built from a copy of its folder with nothing beside it).
# With DUMPS (dumps of `fragsim run --dump-control`, joined by "|"), the C replay program is
# built against each standalone install (gcc's and clang's) and must reproduce the tool's
# forces bit for bit: the standalone build keeps -ffp-contract=off.
#   cmake -DSOURCE_DIR=src/control -DEXAMPLE_DIR=examples/minimal_c -DAPI_TESTS_DIR=tests/control/api
#         -DWORK_DIR=<scratch> -DCXX=<c++ compiler> -DCC=<c compiler> [-DREPLAY_SOURCE=replay.c
#         -DDUMPS=a.bin|b.bin] [-DCLANG_CXX=clang++ -DCLANG_CC=clang] -P standalone_build.cmake
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

set(GUARD ${CMAKE_CURRENT_LIST_DIR}/standalone_guard.cmake)

# The shared library's NEEDED entries: the C and C++ runtimes only.
function(check_needed library)
  execute_process(COMMAND readelf -d ${library} RESULT_VARIABLE status OUTPUT_VARIABLE dynamic)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "readelf -d ${library} failed")
  endif()
  string(REGEX MATCHALL "Shared library: \\[[A-Za-z0-9_.+-]+\\]" needed "${dynamic}")
  foreach(entry ${needed})
    string(REGEX REPLACE "Shared library: \\[(.*)\\]" "\\1" name "${entry}")
    if(NOT name MATCHES "^(libstdc\\+\\+|libm|libgcc_s|libc|ld-linux.*)\\.so")
      message(FATAL_ERROR "${library} needs ${name}: the library alone may need only the C and "
                          "C++ runtimes")
    endif()
  endforeach()
  string(REPLACE "Shared library: " "" needed "${needed}")
  message(STATUS "${library} needs ${needed}")
endfunction()

# Every include folder the library's sources are compiled with: its copy's parent (which holds the
# copy alone), its include/, or Eigen's.
function(check_include_dirs build_dir)
  file(READ ${build_dir}/compile_commands.json commands)
  string(JSON count LENGTH "${commands}")
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON command GET "${commands}" ${i} command)
    string(REGEX MATCHALL "(-I|-isystem )[^ ]+" dirs "${command}")
    foreach(dir ${dirs})
      string(REGEX REPLACE "^(-I|-isystem )" "" dir "${dir}")
      string(FIND "${dir}" "${ALONE_DIR}" at)
      if(NOT at EQUAL 0 AND NOT dir MATCHES "eigen3$")
        message(FATAL_ERROR "the library is compiled with the include folder ${dir}")
      endif()
    endforeach()
  endforeach()
endfunction()

# src/control alone with one compiler: configure under the guard, build, check, install to
# ${WORK_DIR}/${name}-prefix, and replay the tool's dumps against the install.
function(build_library_alone name cxx cc)
  run("configure src/control alone (${name})" ${CMAKE_COMMAND} -S ${ALONE_DIR}/control
    -B ${WORK_DIR}/${name} -DCMAKE_CXX_COMPILER=${cxx} -DCMAKE_BUILD_TYPE=Release
    -DFRAGSIM_WERROR=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "-DCMAKE_CXX_FLAGS=${ARGN}"
    -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=${GUARD})
  run("build (${name})" ${CMAKE_COMMAND} --build ${WORK_DIR}/${name} --parallel 2)
  check_include_dirs(${WORK_DIR}/${name})
  run("install (${name})" ${CMAKE_COMMAND} --install ${WORK_DIR}/${name}
    --prefix ${WORK_DIR}/${name}-prefix)
  file(GLOB shared ${WORK_DIR}/${name}-prefix/lib/libfragsim_control.so.*.*.*)
  check_needed(${shared})
  if(DEFINED DUMPS AND DEFINED REPLAY_SOURCE)
    set(replay ${WORK_DIR}/${name}-replay)
    run("build the replay against the install (${name})" ${cc} -std=c99 -O2 -Wall -Wextra
      -Werror -o ${replay} ${REPLAY_SOURCE} -I${WORK_DIR}/${name}-prefix/include
      -L${WORK_DIR}/${name}-prefix/lib -lfragsim_control -lm
      -Wl,-rpath,${WORK_DIR}/${name}-prefix/lib)
    string(REPLACE "|" ";" dumps "${DUMPS}")
    foreach(dump ${dumps})
      get_filename_component(dump_name ${dump} NAME_WE)
      run("replay ${dump_name} bit for bit (${name})" ${replay} ${dump})
      run("replay ${dump_name} bit for bit, arrays (${name})" ${replay} ${dump} --arrays)
    endforeach()
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
# A copy of the folder with nothing beside it: the library's include root is its folder's parent,
# so in the tree it could see the tool's folders; here there is nothing else to see.
set(ALONE_DIR ${WORK_DIR}/alone)
file(COPY ${SOURCE_DIR} DESTINATION ${ALONE_DIR})
if(NOT EXISTS ${ALONE_DIR}/control/CMakeLists.txt)
  message(FATAL_ERROR "standalone_build.cmake: SOURCE_DIR must be the library's folder, control")
endif()
# gcc's with debug information (which changes no instruction): Control.Library.AbiStable reads
# the ABI from this install, kept when the rest of the work folder is removed.
build_library_alone(gcc ${CXX} ${CC} -g)
# clang's build without Eigen's vectorisation: a sum over a 3-vector must not depend on the
# vector width the library is compiled for (geometry/vec3_sums.hpp), so its replays must match
# the tool's as the SSE2 build's do.
if(CLANG_CC AND CLANG_CXX)
  build_library_alone(clang ${CLANG_CXX} ${CLANG_CC} -DEIGEN_DONT_VECTORIZE)
endif()
run("configure examples/minimal_c on the install" ${CMAKE_COMMAND} -S ${EXAMPLE_DIR}
  -B ${WORK_DIR}/example -DCMAKE_C_COMPILER=${CC} -DCMAKE_PREFIX_PATH=${WORK_DIR}/gcc-prefix
  -DCMAKE_BUILD_TYPE=Release)
run("build examples/minimal_c" ${CMAKE_COMMAND} --build ${WORK_DIR}/example)
run("run examples/minimal_c" ${WORK_DIR}/example/minimal_c)

run("configure tests/control/api alone (src/control by add_subdirectory)" ${CMAKE_COMMAND}
  -S ${API_TESTS_DIR} -B ${WORK_DIR}/api -DCMAKE_C_COMPILER=${CC} -DCMAKE_CXX_COMPILER=${CXX}
  -DCMAKE_BUILD_TYPE=Release -DFRAGSIM_WERROR=ON -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=${GUARD}
  -DFRAGSIM_ALLOWED_PACKAGES=Eigen3,Threads)
run("build tests/control/api" ${CMAKE_COMMAND} --build ${WORK_DIR}/api --parallel 2)
run("run tests/control/api" ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/api --output-on-failure)
if(CLANG_CC AND CLANG_CXX)
  run("configure tests/control/api with clang and ThreadSanitizer" ${CMAKE_COMMAND}
    -S ${API_TESTS_DIR} -B ${WORK_DIR}/tsan -DCMAKE_C_COMPILER=${CLANG_CC}
    -DCMAKE_CXX_COMPILER=${CLANG_CXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRAGSIM_WERROR=ON
    -DFRAGSIM_API_TESTS_TSAN=ON -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=${GUARD}
    -DFRAGSIM_ALLOWED_PACKAGES=Eigen3,Threads)
  run("build tests/control/api with clang and ThreadSanitizer" ${CMAKE_COMMAND}
    --build ${WORK_DIR}/tsan --parallel 2)
  run("run the thread test under ThreadSanitizer" ${CMAKE_COMMAND} -E env
    TSAN_OPTIONS=halt_on_error=1:abort_on_error=0 ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/tsan
    --output-on-failure)
endif()
# Everything but gcc's install (for Control.Library.AbiStable).
file(GLOB work_entries ${WORK_DIR}/*)
list(REMOVE_ITEM work_entries ${WORK_DIR}/gcc-prefix)
file(REMOVE_RECURSE ${work_entries})
