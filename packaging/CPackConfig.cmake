# Debian package of the clm3d command line, clm3d-studio (with its desktop entry), the render
# module and resources (cpack -G DEB); dependencies come from the binaries (SHLIBDEPS). The
# binaries are stripped; their debug symbols go into a separate clm3d-dbgsym package
# (/usr/lib/debug/.build-id/..., found by gdb by build id), so the main package stays small.
# scripts/package-test.sh checks both and runs the packaged clm3d.
set(CPACK_PACKAGE_NAME "clm3d")
set(CPACK_PACKAGE_VENDOR "clm3d developers")
set(CPACK_PACKAGE_CONTACT "clm3d developers <clm3d@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_GENERATOR "DEB")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_DEBUGINFO_PACKAGE ON)
include(CPack)
