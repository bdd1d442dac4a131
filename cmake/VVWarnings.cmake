# SPDX-License-Identifier: GPL-3.0-or-later
# vv_target_defaults(<target>): the project's warning set, applied to every
# target we own. Warnings become errors with -DVV_WERROR=ON (CI, presets).
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
  if(VV_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
