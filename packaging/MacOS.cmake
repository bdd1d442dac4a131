# SPDX-License-Identifier: GPL-3.0-or-later
# macOS disk image: `cpack -G DragNDrop` on a Mac after macdeployqt has put
# Qt's frameworks and plugins into VesselView.app (docs/packaging.md).
# The bundle itself (MACOSX_BUNDLE, Info.plist with the document types,
# vesselview-cli and the data inside it) is set up in app/CMakeLists.txt.
# Dragging VesselView.app to the Applications link installs it; dragging it
# to the bin uninstalls it.

set(CPACK_GENERATOR "DragNDrop")
set(CPACK_PACKAGE_FILE_NAME "VesselView-${PROJECT_VERSION}-macos")
set(CPACK_DMG_VOLUME_NAME "VesselView ${PROJECT_VERSION}")
set(CPACK_DMG_FORMAT "UDZO")
set(CPACK_DMG_FILESYSTEM "HFS+")
set(CPACK_PACKAGE_ICON "${PROJECT_SOURCE_DIR}/resources/icons/${VV_APP_ID}.icns")
# The licence as the disk image's agreement page.
set(CPACK_DMG_SLA_USE_RESOURCE_FILE_LICENSE ON)
