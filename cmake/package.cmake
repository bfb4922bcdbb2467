# `cpack` in the build folder: a Debian package of everything `cmake --install` puts under /usr (the CLI, its
# man pages, the libraries and headers, the paper's tables, the Python module), its Depends computed from the
# binaries by dpkg-shlibdeps, so `apt install ./scalcal_VERSION_ARCH.deb` brings the libraries it links.
# The Python module moves to Debian's lib/python3/dist-packages (package_python_path.cmake, before the archive
# is made), where Debian's python3 finds it. GPL as a binary: the CLI and the module link GiNaC and CLN.
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "scalcal")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "the scalcal authors <scalcal@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "scalar calibration of vector meters: designs with proven limits, calibration")
set(CPACK_PACKAGE_DESCRIPTION
    "scalcal designs calibration programs for triads of accelerometers, magnetometers and gyroscopes against "
    "proven and certified limits, plans them on benches, and calibrates raw logs with honest errors (CLI "
    "`scalcal`, C++ libraries, Python module). The binaries link GiNaC and CLN (GPL-2.0-or-later); the sources "
    "are BSD-3-Clause.")
if(NOT SCALCAL_WITH_GINAC)  # docs/library.md: the licences of what the binaries then link
  set(CPACK_PACKAGE_DESCRIPTION
      "scalcal designs calibration programs for triads of accelerometers, magnetometers and gyroscopes against "
      "proven and certified limits and calibrates raw logs with honest errors (CLI `scalcal`, C++ libraries, "
      "Python module), built without GiNaC (no `family`, no `jig`, no closed forms derived). The sources are "
      "BSD-3-Clause; the binaries link Ipopt (CPL-1.0/EPL-1.0), MUMPS (CeCILL-C), MPFR, GMP and MPFI (LGPL), no GPL-only library.")
endif()
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")  # scalcal_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, gnuplot-nox | gnuplot")
set(CPACK_DEBIAN_COMPRESSION_TYPE "gzip")  # xz takes minutes over the static archives
set(CPACK_STRIP_FILES OFF)
set(CPACK_PRE_BUILD_SCRIPTS "${CMAKE_CURRENT_LIST_DIR}/package_python_path.cmake")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
include(CPack)
