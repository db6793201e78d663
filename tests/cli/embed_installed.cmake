# embed_installed.cmake - installs mdlc into a fresh prefix and builds
# examples/embed_cmake against it, as a user of the installed library would,
# with CMake (find_package) and with pkg-config; then runs the program.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DLIBDIR=lib -P embed_installed.cmake
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR LIBDIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "embed_installed.cmake needs -D${var}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed include/mdlc/mdlc.h include/mdlc/version.h include/mdlc/kinematics.h
                  include/mdlc/convert.h include/mdlc/ir.h include/mdlc/ir/module.h
                  include/mdlc/backend/plant.h bin/mdlc libexec/mdlc/mdlc-mesh-reader
                  ${LIBDIR}/mdlc/mdlc-mesh-import.so)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "not installed: ${installed}")
  endif()
endforeach()
if(EXISTS ${prefix}/include/mdlc/frontend OR EXISTS ${prefix}/include/mdlc/passes
   OR EXISTS ${prefix}/include/mdlc/backend/writers)
  message(FATAL_ERROR "internal headers (frontend/, passes/, backend/writers/) were installed")
endif()
# Only the public headers and what they include are installed: every
# project include ("ir/module.h", "mdlc/mdlc.h") of an installed header names
# an installed file, found as the installed Cflags find it (-I<includedir>
# and -I<includedir>/mdlc), and no internal *_detail.h is among them.
file(GLOB_RECURSE installed_headers ${prefix}/include/mdlc/*.h ${prefix}/include/mdlc/*.def)
foreach(header IN LISTS installed_headers)
  if(header MATCHES "_detail\\.h$")
    message(FATAL_ERROR "an internal header was installed: ${header}")
  endif()
  file(STRINGS ${header} includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[^\"]+\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${prefix}/include/mdlc/${included} AND NOT EXISTS ${prefix}/include/${included})
      message(FATAL_ERROR "${header} includes \"${included}\", which is not installed")
    endif()
  endforeach()
endforeach()
list(LENGTH installed_headers installed_count)
message(STATUS "${installed_count} installed headers; every project include among them is installed")
# mdlc/mdlc.h and its siblings but ir.h reach neither the IR module (opt-in,
# through mdlc/ir.h) nor absl: a program that does not ask for the IR does
# not depend on its shape
foreach(front mdlc.h kinematics.h convert.h meshes.h)
  set(todo ${prefix}/include/mdlc/${front})
  set(seen)
  while(todo)
    list(POP_FRONT todo header)
    file(STRINGS ${header} includes REGEX "^[ \t]*#[ \t]*include[ \t]+[\"<][^\">]+[\">]")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[^\"<]*[\"<]([^\">]+)[\">].*" "\\1" included "${line}")
      if(included STREQUAL "ir/module.h" OR included MATCHES "^absl/")
        message(FATAL_ERROR "mdlc/${front} reaches ${included} (through ${header})")
      endif()
      list(FIND seen "${included}" at)
      if(at EQUAL -1 AND EXISTS ${prefix}/include/mdlc/${included})
        list(APPEND seen "${included}")
        list(APPEND todo ${prefix}/include/mdlc/${included})
      elseif(at EQUAL -1 AND EXISTS ${prefix}/include/${included})
        list(APPEND seen "${included}")
        list(APPEND todo ${prefix}/include/${included})
      endif()
    endforeach()
  endwhile()
endforeach()

# the installed command reports the generated version
run("mdlc --version" ${prefix}/bin/mdlc --version)
if(NOT run_output MATCHES "^mdlc [0-9]+\\.[0-9]+\\.[0-9]+")
  message(FATAL_ERROR "unexpected mdlc --version output: ${run_output}")
endif()

# The installed command reads meshes with the installed reader (issue 16),
# found next to it, not with the build tree's: the program in a child
# process, and the import module in its own. `used` is what --time-passes
# must print when compiling a model with meshes with the extra flags ARGN.
function(expect_mesh_reader used)
  execute_process(COMMAND ${prefix}/bin/mdlc compile --emit=none --time-passes --no-cache ${ARGN}
                          ${SOURCE_DIR}/tests/models/mjcf/oracle/mesh_geoms.xml
                  ERROR_VARIABLE timing RESULT_VARIABLE rc)
  string(FIND "${timing}" "${used}" at)
  if(NOT rc EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "the installed mdlc did not print '${used}' (${rc}):\n${timing}")
  endif()
  message(STATUS "installed mdlc ${ARGN}: ${used}")
endfunction()
file(REAL_PATH ${prefix}/libexec/mdlc/mdlc-mesh-reader installed_reader)
expect_mesh_reader("mesh reader: ${installed_reader}\n")
file(REAL_PATH ${prefix}/${LIBDIR}/mdlc/mdlc-mesh-import.so installed_module)
expect_mesh_reader("mesh reader: in this process (asked for), with ${installed_module}\n"
                   --mesh-reader=in-process)
# the installed Python package (when the build has one) finds the same
# module from where it is installed
if(PYTHON AND EXISTS ${prefix}/${PYTHON_DIR}/mdlc)
  string(CONCAT program "import mdlc\n"
         "mdlc.compile('${SOURCE_DIR}/tests/models/mjcf/oracle/mesh_geoms.xml',"
         " mesh_reader='in-process')\n"
         "print(*sorted({l.split()[-1] for l in open('/proc/self/maps')"
         " if 'mdlc-mesh-import' in l}))")
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c "${program}"
    OUTPUT_VARIABLE opened OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_VARIABLE err RESULT_VARIABLE rc)
  file(REAL_PATH "${opened}" opened_real)
  if(NOT rc EQUAL 0 OR NOT opened_real STREQUAL installed_module)
    message(FATAL_ERROR "the installed Python package opened '${opened}', not ${installed_module} "
                        "(${rc}):\n${err}")
  endif()
  message(STATUS "the installed Python package reads meshes in its process with ${opened}")
endif()

# CMake: find_package(mdlc) from the prefix only
run("configure examples/embed_cmake" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/embed_cmake
    -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run("build examples/embed_cmake" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run("embed" ${WORK_DIR}/build/embed ${SOURCE_DIR}/examples/urdf/double_pendulum.urdf)
foreach(expected "double_pendulum\\.urdf: bodies 3, positions 2" "generated\\.urdf: bodies 1, positions 1"
                 "mass matrix at the default configuration \\(2 x 2\\)")
  if(NOT run_output MATCHES "${expected}")
    message(FATAL_ERROR "embed output lacks '${expected}':\n${run_output}")
  endif()
endforeach()
message(STATUS "find_package(mdlc): built and ran examples/embed_cmake")

# pkg-config: the same program, compiled with the flags mdlc.pc gives
find_program(PKG_CONFIG pkg-config)
find_program(CXX NAMES c++ g++ clang++)
if(PKG_CONFIG AND CXX)
  file(GLOB pc_dirs ${prefix}/lib*/pkgconfig ${prefix}/lib/*/pkgconfig)
  set(ENV{PKG_CONFIG_PATH} "${pc_dirs}")
  run("pkg-config" ${PKG_CONFIG} --cflags --libs mdlc)
  string(STRIP "${run_output}" flags)
  separate_arguments(flags UNIX_COMMAND "${flags}")
    # no -std flag of our own: mdlc.pc's Cflags carry the C++20 the headers need
  run("compile with pkg-config flags" ${CXX} ${SOURCE_DIR}/examples/embed_cmake/embed.cc
      ${flags} -o ${WORK_DIR}/embed_pc)
  run("embed (pkg-config)" ${WORK_DIR}/embed_pc ${SOURCE_DIR}/examples/urdf/double_pendulum.urdf)
  if(NOT run_output MATCHES "double_pendulum\\.urdf: bodies 3")
    message(FATAL_ERROR "pkg-config build printed:\n${run_output}")
  endif()
  message(STATUS "pkg-config mdlc: built and ran examples/embed_cmake/embed.cc")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
