# `cmake --install`: the libraries, the public headers under include/mdlc/,
# the mdlc command, the mesh reader program (libexec/mdlc/) and module
# (<libdir>/mdlc/), and what finds
# them: mdlcConfig.cmake (CMake) and mdlc.pc (pkg-config). Internal headers
# (frontends, passes, the writers, the IR and backend headers no public header
# includes) are not installed.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MDLC_LIBRARIES mdlc_driver mdlc_writers mdlc_backend mdlc_passes mdlc_mesh mdlc_mesh_io mdlc_frontend mdlc_xacro mdlc_pyexpr mdlc_assets mdlc_syntax mdlc_xml mdlc_ir)
set_target_properties(mdlc_driver PROPERTIES EXPORT_NAME mdlc)
foreach(lib IN LISTS MDLC_LIBRARIES)
  if(NOT lib STREQUAL mdlc_driver)
    string(REPLACE "mdlc_" "" short ${lib})
    set_target_properties(${lib} PROPERTIES EXPORT_NAME ${short})
  endif()
endforeach()

install(TARGETS ${MDLC_LIBRARIES} EXPORT mdlcTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${CMAKE_INSTALL_INCLUDEDIR}/mdlc)
# the mesh reader program, where the installed library looks for it
# (passes/mesh/reader_location.h)
install(TARGETS mdlc_mesh_reader RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/mdlc
        COMPONENT runtime)
install(TARGETS mdlc_mesh_import_module LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/mdlc
        COMPONENT runtime)
# The public headers (include/mdlc/*.h and the generated version.h) go to
# include/mdlc/; of the layers' headers only those they include, directly or
# through one another, are installed (install_layer_headers.cmake). The
# install test (tests/cli/embed_installed.cmake) checks that every project
# include of an installed header is installed and that no *_detail.h is.
file(GLOB public_headers CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/include/mdlc/*.h)
install(FILES ${public_headers} ${PROJECT_BINARY_DIR}/include/mdlc/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mdlc)
install(CODE "set(MDLC_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
set(MDLC_PUBLIC_HEADERS \"${public_headers}\")
set(MDLC_INCLUDE_DESTINATION \"${CMAKE_INSTALL_INCLUDEDIR}/mdlc\")")
install(SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/install_layer_headers.cmake)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/mdlc)
install(EXPORT mdlcTargets NAMESPACE mdlc:: DESTINATION ${config_dir})
configure_package_config_file(mdlcConfig.cmake.in ${PROJECT_BINARY_DIR}/mdlcConfig.cmake
                              INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mdlcConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mdlcConfig.cmake ${PROJECT_BINARY_DIR}/mdlcConfigVersion.cmake
        DESTINATION ${config_dir})

# relocatable: the prefix is found from where the .pc file was installed
file(RELATIVE_PATH pc_to_prefix "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
set(MDLC_PC_PREFIX "\${pcfiledir}/${pc_to_prefix}")
configure_file(mdlc.pc.in ${PROJECT_BINARY_DIR}/mdlc.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/mdlc.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
