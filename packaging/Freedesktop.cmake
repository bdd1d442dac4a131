# SPDX-License-Identifier: GPL-3.0-or-later
# Desktop integration on Linux and other freedesktop.org systems, for every
# package format and for a plain `cmake --install`:
#   share/applications/org.vesselview.VesselView.desktop
#   share/icons/hicolor/{16x16..512x512,scalable}/apps/org.vesselview.VesselView.{png,svg}
#   share/metainfo/org.vesselview.VesselView.metainfo.xml   (AppStream)
#   share/mime/packages/vesselview.xml                      (shared-mime-info)
#   share/man/man1/vesselview.1.gz, vesselview-cli.1.gz
#   share/doc/vesselview/copyright
# Sources: resources/desktop, resources/icons, resources/man, packaging/debian.

set(_vv_res "${PROJECT_SOURCE_DIR}/resources")
set(VV_INSTALL_DOCDIR "${CMAKE_INSTALL_DATAROOTDIR}/doc/${CPACK_PACKAGE_NAME}")

install(FILES "${_vv_res}/desktop/${VV_APP_ID}.desktop"
        DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/applications")

# Icons: the SVG, and the PNG sizes rendered from it (resources/icons/render-pngs).
install(FILES "${_vv_res}/icons/${VV_APP_ID}.svg"
        DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/icons/hicolor/scalable/apps")
install(DIRECTORY "${_vv_res}/icons/hicolor/"
        DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/icons/hicolor"
        FILES_MATCHING PATTERN "*.png")

# AppStream: version and release date from the project.
configure_file("${_vv_res}/desktop/${VV_APP_ID}.metainfo.xml.in"
               "${VV_PACKAGING_BINARY_DIR}/${VV_APP_ID}.metainfo.xml" @ONLY)
install(FILES "${VV_PACKAGING_BINARY_DIR}/${VV_APP_ID}.metainfo.xml"
        DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/metainfo")

install(FILES "${_vv_res}/desktop/vesselview-mime.xml"
        DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/mime/packages"
        RENAME "vesselview.xml")

# vv_gzip(<in> <out>): gzip -n -9 (no name, no time stamp: reproducible, as
# Debian wants), redone whenever <in> changes; plain copy without gzip.
find_program(VV_GZIP gzip)
function(vv_gzip in out)
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${in}")
  if(VV_GZIP)
    execute_process(COMMAND "${VV_GZIP}" -n -9 -c "${in}" OUTPUT_FILE "${out}"
                    RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "gzip ${in} failed: ${rc}")
    endif()
  else()
    file(COPY_FILE "${in}" "${out}")
  endif()
endfunction()

foreach(_vv_page vesselview-cli.1 vesselview.1)
  vv_gzip("${_vv_res}/man/${_vv_page}" "${VV_PACKAGING_BINARY_DIR}/${_vv_page}.gz")
  install(FILES "${VV_PACKAGING_BINARY_DIR}/${_vv_page}.gz"
          DESTINATION "${CMAKE_INSTALL_MANDIR}/man1")
endforeach()

install(FILES "${VV_PACKAGING_DIR}/debian/copyright" DESTINATION "${VV_INSTALL_DOCDIR}")
