# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian package: `cpack -G DEB` (scripts/package wraps it and runs lintian).
# Installs to /usr; runtime dependencies come from dpkg-shlibdeps.

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # vesselview_<version>-1_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${VV_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Only what the linker cannot see, because Qt loads it at run time: the
# platform plugins (xcb), without which no window and no offscreen GL context
# can be made. libqt6gui6 only recommends them. Likewise Qt SQL's SQLite
# driver, which the local study store's index needs (docs/dicom-networking.md).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6sql6-sqlite")
# `render` without a display needs a virtual X server: suggested, not required.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "xvfb, xauth")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_DEBIAN_COMPRESSION_TYPE "xz")

# The Debian changelog (non-native version <upstream>-<release>, so
# changelog.Debian.gz), from packaging/debian/changelog.in.
set(VV_DEB_VERSION "${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE}")
configure_file("${VV_PACKAGING_DIR}/debian/changelog.in"
               "${VV_PACKAGING_BINARY_DIR}/changelog.Debian" @ONLY)
vv_gzip("${VV_PACKAGING_BINARY_DIR}/changelog.Debian"
        "${VV_PACKAGING_BINARY_DIR}/changelog.Debian.gz")
install(FILES "${VV_PACKAGING_BINARY_DIR}/changelog.Debian.gz" DESTINATION "${VV_INSTALL_DOCDIR}")

# Strip as Debian's dh_strip does: CPack's stripping (CPACK_STRIP_FILES)
# leaves the .comment and .note sections, which lintian reports.
if(CMAKE_STRIP)
  install(CODE "
    if(CMAKE_INSTALL_DO_STRIP)
      foreach(_vv_exe vesselview vesselview-cli)
        set(_vv_path \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/\${_vv_exe}\")
        if(EXISTS \"\${_vv_path}\")
          execute_process(COMMAND \"${CMAKE_STRIP}\" --remove-section=.comment
                                  --remove-section=.note \"\${_vv_path}\")
        endif()
      endforeach()
    endif()
  ")
endif()
