# Build-time settings that keep the test command (scripts/test.sh) inside CI's budget on 2 cores,
# applied to every target from one place so that adding a stage, a suite or a file needs nothing
# here (docs/testing.md, "Where the time goes", has the measurements behind each choice):
#   - a faster linker (lld, when installed): linking the ~40 test executables with ld.bfd costs
#     minutes;
#   - precompiled headers (Eigen, OpenCV, nlohmann/json, GoogleTest, CLI11 and the standard
#     library) for the core stages, the test executables and the command line, each group
#     sharing one PCH (REUSE_FROM) because building a PCH costs as much as compiling 1-2 files;
#   - line-table debug info (-g1) for the test executables of a RelWithDebInfo build: backtraces
#     keep function names and lines, and the shipped binaries (and so the dbgsym package) keep
#     full debug info.
# Include this before the targets are defined (the linker is set for the targets that follow);
# call clm3d_speed_up_build() once they all are.

# A compiler launcher (ccache) already makes rebuilds cheap, and ccache caches PCH builds only with
# sloppiness=pch_defines,time_macros and -fpch-preprocess: keep ccache builds PCH-free (their
# objects then hit the cache of any other PCH-free tree). The fuzz build is clang, small, and
# instruments some libraries differently from others, so it is left alone too.
# Optimised builds are left alone as well: with the PCH, gcc 12 at -O1/-O2 reports false
# -Warray-bounds inside libstdc++'s string concatenation in some test files (manifest_test.cpp in
# the release build of a clean clone), which -Werror turns into a failed build. The asan build
# (Debug, -O0) passed with it.
if(CMAKE_CXX_COMPILER_LAUNCHER OR CLM3D_FUZZ OR NOT CMAKE_BUILD_TYPE STREQUAL "Debug")
  set(clm3d_pch_default OFF)
else()
  set(clm3d_pch_default ON)
endif()
option(CLM3D_PCH "Precompile heavy third-party headers (default: on for Debug builds without a compiler launcher such as ccache)"
       ${clm3d_pch_default})

# Unity builds (CMake's UNITY_BUILD): the files of a target compiled a batch at a time, so the heavy
# headers are parsed and their inline functions compiled once per batch instead of once per file.
# On by default where there is no compiler launcher: a clean build (CI's) is then far faster, and a
# ccache build, whose rebuilds are cheap anyway, keeps one object per file. Every file must then
# compile beside the others of its target: helpers in anonymous namespaces need distinct names.
if(CMAKE_CXX_COMPILER_LAUNCHER OR CLM3D_FUZZ)
  set(clm3d_unity_default OFF)
else()
  set(clm3d_unity_default ON)
endif()
option(CLM3D_UNITY "Compile each target's files in batches (default: on without a compiler launcher such as ccache)"
       ${clm3d_unity_default})
set(CLM3D_UNITY_BATCH 16 CACHE STRING "Files per unity batch")

find_program(CLM3D_LLD ld.lld)
if(CLM3D_LLD)
  set(clm3d_linker_default lld)
else()
  set(clm3d_linker_default "")
endif()
set(CLM3D_LINKER "${clm3d_linker_default}" CACHE STRING
    "Linker passed to the compiler as -fuse-ld=<value> (lld when installed; empty: the default ld)")
if(CLM3D_LINKER)
  add_link_options(-fuse-ld=${CLM3D_LINKER})
  if(CLM3D_LINKER STREQUAL "lld")
    # lld's own build id is 8 bytes; keep ld.bfd's 20-byte sha1, the usual name of the files in
    # the dbgsym package (/usr/lib/debug/.build-id/).
    add_link_options(LINKER:--build-id=sha1)
  endif()
endif()

# Every buildsystem target defined in DIR and below.
function(_clm3d_targets_below dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _clm3d_targets_below(${sub} below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# A target that only compiles a PCH for others to reuse: TYPE is STATIC (position-independent
# code, like the core stages) or EXECUTABLE (PIE, like the tests): gcc refuses a PCH whose -fPIC
# or -fPIE differs from the file's.
function(_clm3d_pch_host name type)
  cmake_parse_arguments(ARG "" "" "LIBS;HEADERS;OPTIONS" ${ARGN})
  set(source ${CMAKE_BINARY_DIR}/clm3d_pch/${name}.cpp)
  if(NOT EXISTS ${source})
    file(WRITE ${source} "// Compiles the precompiled header of ${name} (cmake/Clm3dBuildSpeed.cmake).\n"
                         "int main() { return 0; }\n")
  endif()
  if(type STREQUAL "EXECUTABLE")
    add_executable(${name} ${source})
  else()
    add_library(${name} STATIC ${source})
  endif()
  target_link_libraries(${name} PRIVATE ${ARG_LIBS})
  target_compile_options(${name} PRIVATE ${ARG_OPTIONS})
  # The same warnings as its users: -Wpedantic alone changes predefined macros gcc checks.
  clm3d_set_warnings(${name})
  target_precompile_headers(${name} PRIVATE ${ARG_HEADERS})
endfunction()

function(clm3d_speed_up_build)
  _clm3d_targets_below(${PROJECT_SOURCE_DIR} targets)
  set(debug_info_build FALSE)
  if(CMAKE_BUILD_TYPE STREQUAL "RelWithDebInfo" AND CMAKE_CXX_FLAGS_RELWITHDEBINFO MATCHES "-g( |$)")
    set(debug_info_build TRUE)
  endif()
  set(test_options "")
  if(debug_info_build)
    set(test_options -g1)
  endif()

  set(std_headers <algorithm> <array> <cmath> <cstdint> <filesystem> <functional> <map> <memory>
                  <optional> <span> <sstream> <stdexcept> <string> <string_view> <utility> <vector>)
  set(core_headers ${std_headers} <Eigen/Core> <Eigen/Geometry> <nlohmann/json.hpp>)
  set(core_libs Eigen3::Eigen nlohmann_json::nlohmann_json)
  if(TARGET opencv_core)
    list(APPEND core_headers <opencv2/core.hpp> <opencv2/imgproc.hpp>)
    list(APPEND core_libs opencv_core opencv_imgproc)
  endif()

  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(STATIC_LIBRARY|EXECUTABLE)$")
      continue()
    endif()
    get_target_property(automoc ${target} AUTOMOC)
    set(group "")
    if(target MATCHES "^clm3d_(test_|measure_|bench$|gui_)")
      target_compile_options(${target} PRIVATE ${test_options})
      if(type STREQUAL "EXECUTABLE" AND NOT automoc)
        set(group test)
      endif()
    elseif(target STREQUAL "clm3d")
      set(group app)
    elseif(type STREQUAL "STATIC_LIBRARY" AND NOT automoc AND target MATCHES "^clm3d_")
      set(group core)
    endif()
    # The GUI tests are one file each (with its moc output included): nothing to batch.
    if(CLM3D_UNITY AND target MATCHES "^clm3d" AND NOT target MATCHES "^clm3d_gui_")
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                                                 UNITY_BUILD_BATCH_SIZE ${CLM3D_UNITY_BATCH})
      # gcc takes a batch's included .cpp files for headers and warns of every class there that
      # holds a type from an anonymous namespace; in a .cpp file that is intended.
      if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
      endif()
    endif()
    if(NOT CLM3D_PCH OR NOT group)
      continue()
    endif()

    if(NOT TARGET clm3d_pch_${group})
      if(group STREQUAL "core")
        _clm3d_pch_host(clm3d_pch_core STATIC LIBS ${core_libs} HEADERS ${core_headers})
      elseif(group STREQUAL "test")
        _clm3d_pch_host(clm3d_pch_test EXECUTABLE LIBS ${core_libs} GTest::gtest
                        HEADERS ${core_headers} <gtest/gtest.h> OPTIONS ${test_options})
      else()
        _clm3d_pch_host(clm3d_pch_app EXECUTABLE LIBS ${core_libs} CLI11::CLI11
                        HEADERS ${core_headers} <CLI/CLI.hpp>)
      endif()
    endif()
    target_precompile_headers(${target} REUSE_FROM clm3d_pch_${group})
    # A file compiled with options of its own (e.g. core/detect's dlib file at -O2 in Debug) cannot
    # use a PCH built without them.
    get_target_property(sources ${target} SOURCES)
    get_target_property(source_dir ${target} SOURCE_DIR)
    foreach(source IN LISTS sources)
      get_source_file_property(options ${source} DIRECTORY ${source_dir} COMPILE_OPTIONS)
      if(options)
        set_source_files_properties(${source} DIRECTORY ${source_dir} PROPERTIES
                                    SKIP_PRECOMPILE_HEADERS ON)
      endif()
    endforeach()
  endforeach()
endfunction()
