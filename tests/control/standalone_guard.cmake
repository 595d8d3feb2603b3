# Injected into every standalone configure of the library (CMAKE_PROJECT_TOP_LEVEL_INCLUDES), so
# "nothing of the tool is asked for" is checked, not assumed: the configure fails, naming the
# call, if anything is looked for beyond FRAGSIM_ALLOWED_PACKAGES (Eigen3 for the library;
# Threads for the thread test). Stricter than hiding the tool's packages one by one
# (CMAKE_DISABLE_FIND_PACKAGE_<name>), which only catches the names listed: this refuses every
# find_package, and every find_library / find_path / pkg-config lookup, whatever it names, even
# one that would fail quietly (QUIET) or one whose package this machine does not have.
cmake_minimum_required(VERSION 3.24)  # dependency providers

# Comma-separated on the command line (-DFRAGSIM_ALLOWED_PACKAGES=Eigen3,Threads).
if(NOT DEFINED FRAGSIM_ALLOWED_PACKAGES)
  set(FRAGSIM_ALLOWED_PACKAGES Eigen3)
endif()
string(REPLACE "," ";" FRAGSIM_ALLOWED_PACKAGES "${FRAGSIM_ALLOWED_PACKAGES}")

macro(fragsim_guard_find_package method name)
  if(NOT "${name}" IN_LIST FRAGSIM_ALLOWED_PACKAGES)
    message(FATAL_ERROR "standalone guard: find_package(${name}) was called; the library alone "
                        "may look for ${FRAGSIM_ALLOWED_PACKAGES} only")
  endif()
  # Not setting ${name}_FOUND hands the call back to CMake's own find_package.
endmacro()
cmake_language(SET_DEPENDENCY_PROVIDER fragsim_guard_find_package
               SUPPORTED_METHODS FIND_PACKAGE)

# Finding a library or header by hand is how a tool dependency would slip past find_package.
function(find_library)
  message(FATAL_ERROR "standalone guard: find_library(${ARGV}) was called")
endfunction()
function(find_path)
  message(FATAL_ERROR "standalone guard: find_path(${ARGV}) was called")
endfunction()
