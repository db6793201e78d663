# install_layer_headers.cmake - run by `cmake --install` (install.cmake): the
# IR's and the backend's headers that the public headers include, directly or
# through one another, into <includedir>/mdlc/ under their own paths
# ("ir/module.h"). Computed from the #include lines at install time, so the
# list is never stale and no header edit re-runs the configuration.
#   MDLC_SOURCE_DIR        the source folder, which the include paths are relative to
#   MDLC_PUBLIC_HEADERS    the public headers (include/mdlc/*.h)
#   MDLC_INCLUDE_DESTINATION  <includedir>/mdlc, relative to the prefix
set(todo ${MDLC_PUBLIC_HEADERS})
set(found)
while(todo)
  list(POP_FRONT todo file)
  file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[^\"]+\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*" "\\1" included "${line}")
    # only files of the source folder: "mdlc/..." are the public headers,
    # installed already, and <...> are other libraries'
    # (list(FIND), not IN_LIST: an install script runs under the old policies)
    list(FIND found "${included}" seen)
    if(EXISTS ${MDLC_SOURCE_DIR}/${included} AND seen EQUAL -1)
      list(APPEND found ${included})
      list(APPEND todo ${MDLC_SOURCE_DIR}/${included})
    endif()
  endforeach()
endwhile()
list(SORT found)
foreach(header IN LISTS found)
  if(header MATCHES "_detail\\.h$" OR header MATCHES "^backend/writers/")
    message(FATAL_ERROR "a public header reaches ${header}, which is internal")
  endif()
  get_filename_component(folder ${header} DIRECTORY)
  file(INSTALL ${MDLC_SOURCE_DIR}/${header}
       DESTINATION ${CMAKE_INSTALL_PREFIX}/${MDLC_INCLUDE_DESTINATION}/${folder})
endforeach()
