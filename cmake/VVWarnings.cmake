# SPDX-License-Identifier: GPL-3.0-or-later
# vv_target_defaults(<target>): the project's warning set, applied to every
# target we own. Warnings become errors with -DVV_WERROR=ON (CI, presets).
get_filename_component(VV_SANITIZER_DIR "${CMAKE_CURRENT_LIST_DIR}/../tests/sanitizers" ABSOLUTE)

function(vv_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast
    -Wcast-align -Woverloaded-virtual -Wimplicit-fallthrough)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    # GCC 12 reports false -Wrestrict positives inside libstdc++'s std::string
    # concatenation at -O2/-O3 (GCC bug 105329).
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_FLAGS MATCHES "-fsanitize")
    # GCC's flow analysis reports false -Wmaybe-uninitialized positives on
    # sanitizer-instrumented code (the asan preset), e.g. in SIMD lanes.
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize")
    # Sanitizer builds: every executable carries the project's default
    # ASan / UBSan / LSan options and the LSan suppressions of third-party
    # libraries (tests/sanitizers/SanitizerDefaults.cpp, lsan.supp).
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE")
      target_sources(${target} PRIVATE ${VV_SANITIZER_DIR}/SanitizerDefaults.cpp)
      set_property(SOURCE ${VV_SANITIZER_DIR}/SanitizerDefaults.cpp
        TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_DEFINITIONS
        "VV_LSAN_SUPPRESSIONS=\"${VV_SANITIZER_DIR}/lsan.supp\"")
    endif()
  endif()
  if(VV_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# vv_unity_build(<target>): compile the target's sources in batches of
# VV_UNITY_BATCH, one translation unit per batch (CMake's unity build). For
# targets whose files spend most of their compile time in the same large
# headers (Qt Widgets, OpenGL, GoogleTest): the app's libraries, vv_render and
# the test programs parse them once per batch instead of once per file. The
# sources of one target must then not repeat a name at namespace scope,
# anonymous namespaces included.
# -DVV_UNITY=OFF compiles every file alone (to find such a clash, or to edit).
option(VV_UNITY "Unity builds of the app's libraries, vv_render and the test programs" ON)
set(VV_UNITY_BATCH 8 CACHE STRING "Sources per unity translation unit")

function(vv_unity_build target)
  if(NOT VV_UNITY)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${VV_UNITY_BATCH})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # A batch includes its .cpp files, which GCC then treats as headers: a
    # test fixture in an anonymous namespace would warn as if a header held it.
    target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
  endif()
endfunction()
