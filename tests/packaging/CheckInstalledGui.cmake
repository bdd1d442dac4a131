# SPDX-License-Identifier: GPL-3.0-or-later
# ctest packaging.installed_gui_opens_demo: the installed vesselview, started
# without files from a folder outside the build tree, opens the installed demo
# (found relative to its binary: it says which file with VV_LOG=vv.app=debug)
# and saves its first frame. -DPREFIX=
cmake_minimum_required(VERSION 3.25)

set(work "${PREFIX}-work")
set(shot "${work}/installed-gui.png")
file(MAKE_DIRECTORY "${work}")
file(REMOVE "${shot}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env --unset=VV_DEMO_FILE VV_LOG=vv.app=debug QT_LOGGING_RULES=vv.debug=true
          "${PREFIX}/bin/vesselview" --screenshot "${shot}"
  WORKING_DIRECTORY "${work}" TIMEOUT 240
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "installed vesselview --screenshot gave '${rc}':\n${out}\n${err}")
endif()
if(NOT EXISTS "${shot}")
  message(FATAL_ERROR "installed vesselview wrote no ${shot}:\n${out}\n${err}")
endif()
set(demo "${PREFIX}/share/vesselview/demo/vessel-tree.vtp")
string(FIND "${err}" "demo file: ${demo}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "installed vesselview did not open ${demo}:\n${err}")
endif()
file(SIZE "${shot}" size)
if(size LESS 10000)
  message(FATAL_ERROR "${shot} is only ${size} bytes: no demo on screen?\n${err}")
endif()
message(STATUS "installed GUI opened the demo: ${shot} (${size} bytes)")
