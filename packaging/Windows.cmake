# SPDX-License-Identifier: GPL-3.0-or-later
# Windows installers: `cpack -G NSIS` (default) or `cpack -G WIX` on a Windows
# build after windeployqt has put Qt's DLLs and plugins beside the binaries
# (docs/packaging.md). Start-menu entry, uninstaller, file associations.
# Nothing here may assume a Unix shell or Unix paths.

set(CPACK_GENERATOR "NSIS")
set(CPACK_PACKAGE_FILE_NAME "VesselView-${PROJECT_VERSION}-win64")
set(VV_WINDOWS_ICON "${PROJECT_SOURCE_DIR}/resources/icons/${VV_APP_ID}.ico")

# Mesh and DICOM files: VesselView is offered under "Open with" (it does not
# take over the default program); .vvs sessions are VesselView's own type.
set(VV_WINDOWS_OPEN_WITH_EXTENSIONS .vtp .vtu .vtk .stl .obj .ply .dcm)
set(VV_WINDOWS_SESSION_EXTENSION .vvs)

# --- NSIS ------------------------------------------------------------------------
# CPACK_VERBATIM_VARIABLES is on: a "\\" here is one backslash in the script.
set(CPACK_NSIS_PACKAGE_NAME "VesselView ${PROJECT_VERSION}")
set(CPACK_NSIS_DISPLAY_NAME "VesselView")
set(CPACK_NSIS_MUI_ICON "${VV_WINDOWS_ICON}")
set(CPACK_NSIS_MUI_UNIICON "${VV_WINDOWS_ICON}")
set(CPACK_NSIS_INSTALLED_ICON_NAME "bin\\vesselview.exe")
set(CPACK_NSIS_ENABLE_UNINSTALL_BEFORE_INSTALL ON)
set(CPACK_NSIS_MODIFY_PATH ON)  # optionally puts bin\ (vesselview-cli) on PATH
set(CPACK_NSIS_EXECUTABLES_DIRECTORY "bin")
set(CPACK_NSIS_MUI_FINISHPAGE_RUN "vesselview.exe")  # in CPACK_NSIS_EXECUTABLES_DIRECTORY
set(_vv_exe "$INSTDIR\\bin\\vesselview.exe")
set(_vv_install
    "WriteRegStr HKCR 'VesselView.Mesh' '' 'Vessel mesh'"
    "WriteRegStr HKCR 'VesselView.Mesh\\DefaultIcon' '' '${_vv_exe},0'"
    "WriteRegStr HKCR 'VesselView.Mesh\\shell\\open\\command' '' '\"${_vv_exe}\" \"%1\"'"
    "WriteRegStr HKCR 'VesselView.Session' '' 'VesselView session'"
    "WriteRegStr HKCR 'VesselView.Session\\DefaultIcon' '' '${_vv_exe},0'"
    "WriteRegStr HKCR 'VesselView.Session\\shell\\open\\command' '' '\"${_vv_exe}\" \"%1\"'"
    "WriteRegStr HKCR '${VV_WINDOWS_SESSION_EXTENSION}' '' 'VesselView.Session'")
set(_vv_uninstall
    "DeleteRegKey HKCR 'VesselView.Mesh'"
    "DeleteRegKey HKCR 'VesselView.Session'"
    "DeleteRegKey HKCR '${VV_WINDOWS_SESSION_EXTENSION}'")
foreach(_vv_ext IN LISTS VV_WINDOWS_OPEN_WITH_EXTENSIONS)
  list(APPEND _vv_install "WriteRegStr HKCR '${_vv_ext}\\OpenWithProgids' 'VesselView.Mesh' ''")
  list(APPEND _vv_uninstall "DeleteRegValue HKCR '${_vv_ext}\\OpenWithProgids' 'VesselView.Mesh'")
endforeach()
# Tell Explorer that associations changed (SHCNE_ASSOCCHANGED).
set(_vv_notify "System::Call 'shell32::SHChangeNotify(i 0x08000000, i 0, p 0, p 0)'")
list(APPEND _vv_install "${_vv_notify}")
list(APPEND _vv_uninstall "${_vv_notify}")
list(JOIN _vv_install "\n" CPACK_NSIS_EXTRA_INSTALL_COMMANDS)
list(JOIN _vv_uninstall "\n" CPACK_NSIS_EXTRA_UNINSTALL_COMMANDS)

# --- WiX (MSI) ---------------------------------------------------------------------
# The upgrade code stays the same for every version: a new MSI replaces the old.
set(CPACK_WIX_UPGRADE_GUID "5E0B6A7C-2F4D-4C1E-9B8A-3D6F1A2C7E40")
set(CPACK_WIX_PRODUCT_ICON "${VV_WINDOWS_ICON}")
set(CPACK_WIX_PROGRAM_MENU_FOLDER "VesselView")
set(CPACK_WIX_ARCHITECTURE "x64")
set(CPACK_WIX_PROPERTY_ARPURLINFOABOUT "https://www.gnu.org/licenses/gpl-3.0.html")
# File associations and the start-menu entry's icon, patched into the
# component that holds bin/vesselview.exe.
set(CPACK_WIX_PATCH_FILE "${VV_PACKAGING_DIR}/windows/wix-patch.xml")
