# fragsim_control: the controller library of include/fragsim/control.h.
#
# One object library compiled with hidden visibility (only FRAGSIM_API functions are exported
# from the shared library), linked into two targets built side by side:
#   fragsim_control_shared  libfragsim_control.so   (exported as fragsim::control_shared)
#   fragsim_control_static  libfragsim_control.a    (exported as fragsim::control_static)
# find_package(fragsim_control CONFIG) also gives fragsim::control: the shared library, or the
# static one when fragsim_control_USE_STATIC is set before the call. Eigen is a private,
# header-only dependency: nothing of it is needed to use the installed library.

# Re-read when the header changes: a version bump must reach the package files without a fresh
# configure.
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/include/fragsim/control.h)
file(STRINGS ${PROJECT_SOURCE_DIR}/include/fragsim/control.h FRAGSIM_CONTROL_VERSION_LINES
  REGEX "^#define FRAGSIM_CONTROL_VERSION_(MAJOR|MINOR|PATCH) ")
foreach(line ${FRAGSIM_CONTROL_VERSION_LINES})
  string(REGEX REPLACE "^#define FRAGSIM_CONTROL_VERSION_([A-Z]+) ([0-9]+).*" "\\1;\\2" kv ${line})
  list(GET kv 0 key)
  list(GET kv 1 value)
  set(FRAGSIM_CONTROL_VERSION_${key} ${value})
endforeach()
set(FRAGSIM_CONTROL_VERSION
  ${FRAGSIM_CONTROL_VERSION_MAJOR}.${FRAGSIM_CONTROL_VERSION_MINOR}.${FRAGSIM_CONTROL_VERSION_PATCH})
# Before 1.0 every minor version may change the structs' layout (0.3 appended a field to
# fragsim_step_stats), so the soname carries the minor: a program built against 0.2 is not loaded
# with 0.3 and writing past its smaller struct. From 1.0 on, the major alone.
if(FRAGSIM_CONTROL_VERSION_MAJOR EQUAL 0)
  set(FRAGSIM_CONTROL_SOVERSION 0.${FRAGSIM_CONTROL_VERSION_MINOR})
else()
  set(FRAGSIM_CONTROL_SOVERSION ${FRAGSIM_CONTROL_VERSION_MAJOR})
endif()

file(GLOB FRAGSIM_CONTROL_API_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/control/*.cpp)
add_library(fragsim_control_objects OBJECT
  ${FRAGSIM_CONTROL_STRATEGY_SOURCES} ${FRAGSIM_CONTROL_API_SOURCES})
target_include_directories(fragsim_control_objects
  PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/include)
target_compile_options(fragsim_control_objects PRIVATE ${FRAGSIM_WARNINGS})
target_compile_definitions(fragsim_control_objects PRIVATE FRAGSIM_CONTROL_BUILDING)
target_link_libraries(fragsim_control_objects PRIVATE Eigen3::Eigen)
set_target_properties(fragsim_control_objects PROPERTIES
  POSITION_INDEPENDENT_CODE ON CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)

add_library(fragsim_control_shared SHARED $<TARGET_OBJECTS:fragsim_control_objects>)
add_library(fragsim_control_static STATIC $<TARGET_OBJECTS:fragsim_control_objects>)
foreach(target fragsim_control_shared fragsim_control_static)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  set_target_properties(${target} PROPERTIES OUTPUT_NAME fragsim_control LINKER_LANGUAGE CXX)
endforeach()
target_compile_definitions(fragsim_control_static INTERFACE FRAGSIM_CONTROL_STATIC)
# A C program (or any non-C++ link) using the static archive needs the C++ runtime it was built
# with; a C++ link brings it already. (libstdc++: GCC's, and Clang's default on Linux.)
target_link_libraries(fragsim_control_static INTERFACE
  "$<$<NOT:$<LINK_LANGUAGE:CXX>>:stdc++>" "$<$<NOT:$<LINK_LANGUAGE:CXX>>:m>")
set_target_properties(fragsim_control_shared PROPERTIES EXPORT_NAME control_shared
  VERSION ${FRAGSIM_CONTROL_VERSION} SOVERSION ${FRAGSIM_CONTROL_SOVERSION})
set_target_properties(fragsim_control_static PROPERTIES EXPORT_NAME control_static)
add_library(fragsim::control ALIAS fragsim_control_shared)

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(FRAGSIM_CONTROL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fragsim_control)
install(TARGETS fragsim_control_shared fragsim_control_static EXPORT fragsim_control_targets
  COMPONENT control
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/fragsim/control.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/fragsim COMPONENT control)
install(EXPORT fragsim_control_targets NAMESPACE fragsim:: FILE fragsim_control-targets.cmake
  DESTINATION ${FRAGSIM_CONTROL_CMAKE_DIR} COMPONENT control)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/fragsim_control-config.cmake.in
  ${PROJECT_BINARY_DIR}/fragsim_control-config.cmake
  INSTALL_DESTINATION ${FRAGSIM_CONTROL_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/fragsim_control-config-version.cmake
  VERSION ${FRAGSIM_CONTROL_VERSION} COMPATIBILITY SameMinorVersion)
# pkg-config: the prefix is found from the .pc file's own place, so an install with
# `cmake --install ... --prefix P` (another prefix than the configured one) still works.
file(RELATIVE_PATH FRAGSIM_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(${PROJECT_SOURCE_DIR}/cmake/fragsim-control.pc.in
  ${PROJECT_BINARY_DIR}/fragsim-control.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/fragsim_control-config.cmake
  ${PROJECT_BINARY_DIR}/fragsim_control-config-version.cmake
  DESTINATION ${FRAGSIM_CONTROL_CMAKE_DIR} COMPONENT control)
install(FILES ${PROJECT_BINARY_DIR}/fragsim-control.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT control)
