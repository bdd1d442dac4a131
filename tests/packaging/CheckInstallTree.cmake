# SPDX-License-Identifier: GPL-3.0-or-later
# ctest packaging.install_tree: `cmake --install` into PREFIX (outside the
# build tree), assert the expected files, then run the installed
# vesselview-cli from a working directory outside the build tree.
# -DBUILD_DIR= -DPREFIX= -DVERSION= -DAPP_ID= -DWITH_GUI=
cmake_minimum_required(VERSION 3.25)

set(failures "")
macro(fail message)
  list(APPEND failures "${message}")
  message(SEND_ERROR "install_tree: ${message}")
endmacro()

file(REMOVE_RECURSE "${PREFIX}" "${PREFIX}-work")
execute_process(
  COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}\n${err}")
endif()

# --- the files ---------------------------------------------------------------------
set(expected
  bin/vesselview-cli
  share/vesselview/demo/vessel-tree.vtp
  share/applications/${APP_ID}.desktop
  share/icons/hicolor/scalable/apps/${APP_ID}.svg
  share/metainfo/${APP_ID}.metainfo.xml
  share/mime/packages/vesselview.xml
  share/man/man1/vesselview-cli.1.gz
  share/man/man1/vesselview.1.gz
  share/doc/vesselview/copyright
  share/doc/vesselview/changelog.Debian.gz)
set(icon_sizes 16 24 32 48 64 128 256 512)
foreach(size IN LISTS icon_sizes)
  list(APPEND expected share/icons/hicolor/${size}x${size}/apps/${APP_ID}.png)
endforeach()
if(WITH_GUI)
  list(APPEND expected bin/vesselview)
endif()
foreach(f IN LISTS expected)
  if(NOT EXISTS "${PREFIX}/${f}" OR IS_DIRECTORY "${PREFIX}/${f}")
    fail("missing ${f}")
  endif()
endforeach()

# Each PNG is as large as the folder it is in says (PNG IHDR: width, height).
foreach(size IN LISTS icon_sizes)
  set(png "${PREFIX}/share/icons/hicolor/${size}x${size}/apps/${APP_ID}.png")
  if(EXISTS "${png}")
    file(READ "${png}" header OFFSET 16 LIMIT 8 HEX)
    string(SUBSTRING "${header}" 0 8 w)
    string(SUBSTRING "${header}" 8 8 h)
    math(EXPR w "0x${w}")
    math(EXPR h "0x${h}")
    if(NOT w EQUAL size OR NOT h EQUAL size)
      fail("${png} is ${w}x${h}, not ${size}x${size}")
    endif()
  endif()
endforeach()

# The AppStream release is this version; the desktop entry starts the binary.
set(metainfo "${PREFIX}/share/metainfo/${APP_ID}.metainfo.xml")
if(EXISTS "${metainfo}")
  file(READ "${metainfo}" text)
  if(NOT text MATCHES "<release version=\"${VERSION}\" date=\"[0-9]+-[0-9]+-[0-9]+\"")
    fail("${metainfo} has no release ${VERSION}")
  endif()
endif()
set(desktop "${PREFIX}/share/applications/${APP_ID}.desktop")
if(EXISTS "${desktop}")
  file(STRINGS "${desktop}" exec_line REGEX "^Exec=")
  if(NOT exec_line STREQUAL "Exec=vesselview %F")
    fail("${desktop}: unexpected '${exec_line}'")
  endif()
endif()

# No installed binary points into the build tree (RPATH / RUNPATH).
foreach(exe vesselview-cli vesselview)
  set(path "${PREFIX}/bin/${exe}")
  if(EXISTS "${path}")
    file(READ_ELF "${path}" RPATH rpath RUNPATH runpath CAPTURE_ERROR elf_error)
    if(elf_error)
      fail("${exe}: ${elf_error}")
    endif()
    if("${rpath}${runpath}" MATCHES "${BUILD_DIR}")
      fail("${exe} has a run path into the build tree: '${rpath}${runpath}'")
    endif()
  endif()
endforeach()

# --- the installed CLI, run outside the build tree ------------------------------
set(work "${PREFIX}-work")
file(MAKE_DIRECTORY "${work}")
set(cli "${PREFIX}/bin/vesselview-cli")
if(EXISTS "${cli}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=VV_DEMO_FILE "${cli}" --version
    WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out STREQUAL "vesselview-cli ${VERSION}\n")
    fail("`vesselview-cli --version` gave ${rc}: '${out}' ${err}")
  endif()

  set(demo "${PREFIX}/share/vesselview/demo/vessel-tree.vtp")
  execute_process(COMMAND "${cli}" info "${demo}" --json
    WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("`vesselview-cli info ${demo}` gave ${rc}: ${err}")
  else()
    foreach(array wss pressure)
      if(NOT out MATCHES "\"${array}\"")
        fail("`info` of the installed demo lists no '${array}' array:\n${out}")
      endif()
    endforeach()
  endif()
endif()

list(LENGTH expected n_expected)
list(LENGTH failures n_failures)
if(n_failures GREATER 0)
  message(FATAL_ERROR "install_tree: ${n_failures} problem(s)")
endif()
message(STATUS "install_tree: ${n_expected} files present, the installed CLI runs from ${work}")
