# SPDX-License-Identifier: GPL-3.0-or-later
# Packaging: included once from the top-level CMakeLists.txt, after every
# target exists. Shared CPACK_PACKAGE_* settings here, then one file per
# platform, then CPack itself. See packaging/README.md and docs/packaging.md.
#
#   Linux    Freedesktop.cmake (desktop entry, icons, AppStream, MIME, man
#            pages, copyright) + Debian.cmake (cpack -G DEB)
#   Windows  Windows.cmake (cpack -G NSIS or -G WIX)
#   macOS    MacOS.cmake (cpack -G DragNDrop)

include(GNUInstallDirs)

# The application's reverse-DNS id: the desktop file, the AppStream
# component, the icon name and the macOS bundle identifier all use it.
set(VV_APP_ID "org.vesselview.VesselView")
set(VV_PACKAGE_MAINTAINER "The VesselView developers <vesselview-maintainers@vesselview.org>"
    CACHE STRING "Maintainer of the packages (Debian: 'Name <address>')")
# Release date of PROJECT_VERSION, as seconds since 1970 (UTC): the AppStream
# release and the Debian changelog derive their dates from it. Move it with
# the version: `date -u -d 2026-11-22 +%s`.
set(VV_RELEASE_EPOCH 1795305600)

# (string(TIMESTAMP) formats SOURCE_DATE_EPOCH when it is set.)
if(DEFINED ENV{SOURCE_DATE_EPOCH})
  set(_vv_saved_epoch "$ENV{SOURCE_DATE_EPOCH}")
endif()
set(ENV{SOURCE_DATE_EPOCH} "${VV_RELEASE_EPOCH}")
string(TIMESTAMP VV_RELEASE_DATE "%Y-%m-%d" UTC)
string(TIMESTAMP VV_RELEASE_DATE_RFC2822 "%a, %d %b %Y %H:%M:%S +0000" UTC)
if(DEFINED _vv_saved_epoch)
  set(ENV{SOURCE_DATE_EPOCH} "${_vv_saved_epoch}")
else()
  unset(ENV{SOURCE_DATE_EPOCH})
endif()

set(VV_PACKAGING_DIR "${CMAKE_CURRENT_LIST_DIR}")
set(VV_PACKAGING_BINARY_DIR "${PROJECT_BINARY_DIR}/packaging")
file(MAKE_DIRECTORY "${VV_PACKAGING_BINARY_DIR}")

# --- shared by every generator ----------------------------------------------
# Values reach CPack exactly as written here (no second round of escaping).
set(CPACK_VERBATIM_VARIABLES ON)
set(CPACK_PACKAGE_NAME "vesselview")
set(CPACK_PACKAGE_VENDOR "The VesselView developers")
set(CPACK_PACKAGE_CONTACT "${VV_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VERSION_MAJOR "${PROJECT_VERSION_MAJOR}")
set(CPACK_PACKAGE_VERSION_MINOR "${PROJECT_VERSION_MINOR}")
set(CPACK_PACKAGE_VERSION_PATCH "${PROJECT_VERSION_PATCH}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "vessel tree workstation with Void Space Surfaces")
set(CPACK_PACKAGE_DESCRIPTION_FILE "${VV_PACKAGING_DIR}/Description.txt")
set(CPACK_PACKAGE_INSTALL_DIRECTORY "VesselView")
set(CPACK_PACKAGE_EXECUTABLES "vesselview" "VesselView")
set(CPACK_RESOURCE_FILE_LICENSE "${VV_PACKAGING_DIR}/LicenseNotice.txt")
set(CPACK_PACKAGE_CHECKSUM SHA256)
set(CPACK_STRIP_FILES ON)
set(CPACK_SOURCE_IGNORE_FILES "/\\.git/" "/build[^/]*/")
set(CPACK_PACKAGE_FILE_NAME
    "${CPACK_PACKAGE_NAME}-${PROJECT_VERSION}-${CMAKE_SYSTEM_NAME}-${CMAKE_SYSTEM_PROCESSOR}")
# Directories the install creates: 0755 whatever the umask (lintian checks).
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

# --- per platform ----------------------------------------------------------------
if(WIN32)
  include("${VV_PACKAGING_DIR}/Windows.cmake")
elseif(APPLE)
  include("${VV_PACKAGING_DIR}/MacOS.cmake")
elseif(UNIX)
  include("${VV_PACKAGING_DIR}/Freedesktop.cmake")
  include("${VV_PACKAGING_DIR}/Debian.cmake")
endif()

include(CPack)
