# `cmake --install`: the libraries, the public headers under include/mdlc/,
# the mdlc command, the mesh reader program (libexec/mdlc/) and module
# (<libdir>/mdlc/), and what finds
# them: mdlcConfig.cmake (CMake) and mdlc.pc (pkg-config). Internal headers
# (frontends, passes) are not installed; the public header reaches only the
# IR's and the backend's.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(MDLC_LIBRARIES mdlc_driver mdlc_writers mdlc_backend mdlc_passes mdlc_mesh_io mdlc_frontend mdlc_xacro mdlc_pyexpr mdlc_assets mdlc_xml mdlc_ir)
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
install(TARGETS mdlc_mesh_reader RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/mdlc)
install(TARGETS mdlc_mesh_import_module LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/mdlc)
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/mdlc ${PROJECT_BINARY_DIR}/include/mdlc
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# the layers' headers keep their paths ("ir/module.h") under include/mdlc/
install(DIRECTORY ${PROJECT_SOURCE_DIR}/ir ${PROJECT_SOURCE_DIR}/backend
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mdlc
        FILES_MATCHING PATTERN "*.h" PATTERN "*.def")

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
