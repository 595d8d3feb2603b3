# The library's boundary: fails when a file of the library includes something outside its folder.
#   cmake -DFRAGSIM_CONTROL_ROOT=<folder> -P check_includes.cmake     (or include() it with
#   FRAGSIM_CONTROL_ROOT set, as src/control/CMakeLists.txt does at configure)
#
# `#include "X"` must name a file inside the folder: next to the including file, under the
# folder's root or under its include/ (the only include roots the library is compiled with).
# `#include <X>` is for the standard library and Eigen: it must not name a file of the tool's
# folders beside this one, where it would compile inside fragsim and nowhere else. Each offence
# is reported as file:line, and all of them at once.

function(fragsim_control_check_includes root)
  cmake_path(SET root NORMALIZE "${root}")
  cmake_path(GET root PARENT_PATH outside)
  file(GLOB_RECURSE files "${root}/*.cpp" "${root}/*.hpp" "${root}/*.h" "${root}/*.c")
  set(offences "")
  foreach(file ${files})
    cmake_path(GET file PARENT_PATH dir)
    file(STRINGS "${file}" lines)
    set(number 0)
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      if(NOT line MATCHES "^[ \t]*#[ \t]*include[ \t]*([\"<])([^\">]+)[\">]")
        continue()
      endif()
      set(quote "${CMAKE_MATCH_1}")
      set(name "${CMAKE_MATCH_2}")
      set(found "")
      foreach(base "${dir}" "${root}" "${root}/include")
        cmake_path(APPEND base "${name}" OUTPUT_VARIABLE candidate)
        cmake_path(NORMAL_PATH candidate)
        if(EXISTS "${candidate}" AND NOT IS_DIRECTORY "${candidate}")
          set(found "${candidate}")
          break()
        endif()
      endforeach()
      set(inside FALSE)
      if(found)
        cmake_path(IS_PREFIX root "${found}" NORMALIZE inside)
      endif()
      file(RELATIVE_PATH where "${root}" "${file}")
      if(quote STREQUAL "\"" AND NOT inside)
        string(APPEND offences "\n  ${where}:${number}: #include \"${name}\" is not in the library's folder")
      elseif(quote STREQUAL "<" AND NOT inside AND EXISTS "${outside}/${name}")
        string(APPEND offences "\n  ${where}:${number}: #include <${name}> is the tool's, outside the library's folder")
      endif()
    endforeach()
  endforeach()
  if(offences)
    message(FATAL_ERROR "The controller library (${root}) includes outside its folder:${offences}\n"
      "Move what it needs into the folder, or keep it out of the library.")
  endif()
endfunction()

if(NOT FRAGSIM_CONTROL_ROOT)
  message(FATAL_ERROR "check_includes.cmake: set FRAGSIM_CONTROL_ROOT to the library's folder")
endif()
fragsim_control_check_includes("${FRAGSIM_CONTROL_ROOT}")
