# SPDX-License-Identifier: GPL-3.0-or-later
# Image baseline tests: one line declares one test.
#
#   vv_add_image_test(NAME name DATA mesh-file [SIZE WxH] ARGS render-options...
#                     THRESHOLD t [DISABLED "why"])
#   vv_add_image_test(NAME name SESSION file.vvs [SIZE WxH] [ARGS options...] ...)
#
# The test (ctest name "baseline.<name>", label "baseline") runs
# `vesselview-cli render <DATA> --size <SIZE> <ARGS> -o ...` (with SESSION:
# `render --session <file.vvs> ...`, the ARGS overriding it) offscreen (it
# needs an X display: scripts/test runs ctest under xvfb-run with
# QT_QPA_PLATFORM=xcb), compares the image with tests/baselines/<name>.png by
# the SSIM-like difference of tests/support/ImageCompare.h (0 = identical) and
# fails when it exceeds THRESHOLD or there is no baseline; the candidate is
# then written to <build>/test-tmp/baselines/<name>.png (and the differences
# to <name>.diff.png) and both paths are printed.
#
# Update mode: VV_UPDATE_BASELINES=1 ctest -L baseline (or
# scripts/update-baselines) writes every candidate into tests/baselines/ for a
# person to look at and commit.
#
# SIZE defaults to 320x240 to keep the tests fast. DISABLED "why" declares the
# test but marks it disabled (e.g. for a render option not accepted yet).

set(VV_BASELINE_DIR "${PROJECT_SOURCE_DIR}/tests/baselines" CACHE INTERNAL
  "Where the image baselines live (source tree)")
set(VV_BASELINE_OUT_DIR "${PROJECT_BINARY_DIR}/test-tmp/baselines" CACHE INTERNAL
  "Where failing image tests write their candidates")

function(vv_add_image_test)
  cmake_parse_arguments(ARG "" "NAME;DATA;SESSION;SIZE;THRESHOLD;DISABLED" "ARGS" ${ARGN})
  if(NOT ARG_NAME OR NOT DEFINED ARG_THRESHOLD OR (NOT ARG_DATA AND NOT ARG_SESSION)
     OR (ARG_DATA AND ARG_SESSION))
    message(FATAL_ERROR "vv_add_image_test: NAME, THRESHOLD and one of DATA or SESSION are required")
  endif()
  if(ARG_SESSION)
    set(input --session ${ARG_SESSION})
  else()
    set(input ${ARG_DATA})
  endif()
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "vv_add_image_test(${ARG_NAME}): unexpected ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_SIZE)
    set(ARG_SIZE 320x240)
  endif()
  set(test baseline.${ARG_NAME})
  add_test(NAME ${test}
    COMMAND vv_image_test
      --name ${ARG_NAME}
      --cli $<TARGET_FILE:vesselview-cli>
      --baseline ${VV_BASELINE_DIR}/${ARG_NAME}.png
      --out-dir ${VV_BASELINE_OUT_DIR}
      --threshold ${ARG_THRESHOLD}
      -- ${input} --size ${ARG_SIZE} ${ARG_ARGS})
  set_tests_properties(${test} PROPERTIES
    LABELS "gl;baseline"
    TIMEOUT 300)
  if(ARG_DISABLED)
    set_tests_properties(${test} PROPERTIES DISABLED TRUE)
  endif()
endfunction()
