# cpack.cmake - `cpack -G DEB` in the build tree: mdlc_<version>_amd64.deb,
# everything `cmake --install` installs (the command, the mesh reader, the
# static libraries, the headers, mdlcConfig.cmake, mdlc.pc, the Python
# package), under /usr.
#
# CPack installs the build tree into a staging folder and moves it under
# CPACK_PACKAGING_INSTALL_PREFIX, so the paths relative to the prefix are the
# ones the build was configured with (lib/, libexec/mdlc/, and the Python
# package's MDLC_PYTHON_INSTALL_DIR, lib/python3/dist-packages by default,
# which Debian's python3 searches under /usr). The installed code finds the
# mesh reader relative to its own prefix, so no rebuild for /usr is needed.
# With Ninja, cpack builds nothing: build first, then package.
set(CPACK_PACKAGE_NAME mdlc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "mdlc")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "model compiler for robotics: URDF, SDFormat, MJCF and Drake Model Directives")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Stripped (CMAKE_INSTALL_DO_STRIP, as `cmake --install --strip`): built with
# -g1 the command and the Python module are 36 and 31 MB, the static
# libraries 77 MB, mostly line tables; the package is 35 MB unstripped, 18 MB
# with the programs stripped, about 6 MB with the archives' debug sections
# dropped too (what Debian's dh_strip does to static libraries). An installed
# mdlc's stack traces then show addresses, not lines: profile a build from
# source.
set(CPACK_STRIP_FILES ON)
# install(TARGETS) strips programs and modules, never archives: under
# --strip (and so in the package) their debug sections go here, after the
# libraries' own install rules (install rules run in the order they are
# declared)
if(CMAKE_STRIP)
  install(CODE "
if(CMAKE_INSTALL_DO_STRIP)
  file(GLOB archives \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/libmdlc_*.a\")
  foreach(archive IN LISTS archives)
    execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug \"\${archive}\" COMMAND_ERROR_IS_FATAL ANY)
  endforeach()
endif()")
endif()

set(MDLC_PACKAGE_MAINTAINER "mdlc maintainers <maintainers@users.noreply.h-seed-ab51bb72.example>"
    CACHE STRING "The Maintainer field of the Debian package")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # mdlc_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${MDLC_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# (CPack puts CPACK_PACKAGE_DESCRIPTION_SUMMARY before it as the synopsis)
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "mdlc reads robot models (URDF, SDFormat, MJCF, Drake Model Directives, xacro)
and builds the multibody plant and scene graph Drake's parser builds, without
Drake. This package holds the mdlc command, its mesh reader, the C++ static
libraries and headers with mdlcConfig.cmake and mdlc.pc, and the Python
module (import mdlc).")
# Depends: from the shared libraries the command, the mesh reader and the
# Python module link (dpkg-shlibdeps, from dpkg-dev)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# what find_package(mdlc) and mdlc.pc require of an embedding project (the
# headers of the libraries mdlc's static libraries link), and the Python
# module's NumPy: recommended, not needed to run the command
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "libeigen3-dev, libfmt-dev, libxml2-dev, libyaml-cpp-dev, libqhull-dev, libabsl-dev, libxxhash-dev, pkg-config, python3-numpy")

# Python writes the package's bytecode (__pycache__) beside it at the first
# import as root; dpkg did not install those files, so it would leave them,
# and the package's folder, behind. prerm removes them first, as py3clean
# does for Debian's own Python packages.
if(TARGET mdlc_python)
  set(python_package ${CPACK_PACKAGING_INSTALL_PREFIX}/${MDLC_PYTHON_INSTALL_DIR}/mdlc)
  file(WRITE ${PROJECT_BINARY_DIR}/packaging/prerm
       "#!/bin/sh\nset -e\nrm -rf '${python_package}/__pycache__'\n")
  set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/packaging/prerm)
  set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)  # scripts 0755
endif()

include(CPack)
