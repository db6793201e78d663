# check_layers.cmake - the layers depend downward only. The one statement of
# their order, lowest first (the README points here):
#
#   ir                 the IR, source manager, diagnostics
#   ir/assets          packages and the URIs models name (mdlc_assets)
#   ir/syntax          syntax the readers and the writers share (mdlc_syntax)
#   frontend/xml       hardened XML reading (mdlc_xml)
#   frontend/pyexpr    xacro's Python expressions (mdlc_pyexpr)
#   frontend/xacro     the xacro stage (mdlc_xacro)
#   frontend           the format readers (mdlc_frontend)
#   passes/mesh/io     what mdlc and the mesh reader say to each other (mdlc_mesh_io)
#   passes/mesh/import reading a mesh file with assimp (mdlc_mesh_import)
#   passes/mesh/reader the mesh reader's program and module
#   passes/mesh        the mesh library (mdlc_mesh)
#   passes             the passes (mdlc_passes)
#   backend            the plant (mdlc_backend): the IR alone
#   backend/writers    other formats out (mdlc_writers)
#   tools/driver/include  the public API, included as "mdlc/..."
#   tools/driver       the pipeline behind it (mdlc_driver)
#   tools/mdlc         the command line
#   tools/python       the Python module
#   examples           programs embedding mdlc
#
# A layer may include its own headers and those of the layers its row in
# `may_use` below names; every one of those must sit below it in `layers`
# (checked too, so the table cannot allow an include upward). Every source
# under the layers' folders belongs to one layer, its longest folder here;
# a source in none is an error, and so is a check that read too few files.
#   cmake -DSOURCE_DIR=... -P check_layers.cmake
cmake_minimum_required(VERSION 3.20)  # IN_LIST
if(NOT DEFINED SOURCE_DIR)
  message(FATAL_ERROR "check_layers.cmake needs -DSOURCE_DIR=...")
endif()

set(layers ir ir/assets ir/syntax frontend/xml frontend/pyexpr frontend/xacro frontend
    passes/mesh/io passes/mesh/import passes/mesh/reader passes/mesh passes
    backend backend/writers tools/driver/include tools/driver tools/mdlc tools/python examples)

# layer -> the layers it may include (besides its own)
set(may_use_ir "")
set(may_use_ir/assets "ir")
set(may_use_ir/syntax "ir")
set(may_use_frontend/xml "ir;ir/assets")
set(may_use_frontend/pyexpr "ir")
set(may_use_frontend/xacro "ir;ir/assets;frontend/xml;frontend/pyexpr")
set(may_use_frontend "ir;ir/assets;ir/syntax;frontend/xml;frontend/pyexpr;frontend/xacro")
set(may_use_passes/mesh/io "ir")
set(may_use_passes/mesh/import "ir;passes/mesh/io")
set(may_use_passes/mesh/reader "ir;passes/mesh/io;passes/mesh/import")
# the module's entry point (passes/mesh/reader/import_entry.h), which
# in_process_reader.cc looks up; never the assimp loading of mesh/import
set(may_use_passes/mesh "ir;passes/mesh/io;passes/mesh/reader")
set(may_use_passes "ir;ir/assets;passes/mesh")
set(may_use_backend "ir")
set(may_use_backend/writers "ir;ir/syntax;backend")
# the public API hands out the IR and the plant, nothing of the pipeline
set(may_use_tools/driver/include "ir;backend")
set(may_use_tools/driver
    "ir;ir/assets;ir/syntax;frontend/xml;frontend/pyexpr;frontend/xacro;frontend;passes/mesh;passes;backend;backend/writers;tools/driver/include")
# the command line: the public API, the IR and plant it hands out, and the
# driver's own headers (heap policy, MJCF file assets)
set(may_use_tools/mdlc "ir;backend;tools/driver/include;tools/driver")
set(may_use_tools/python "ir;backend;tools/driver/include")
set(may_use_examples "tools/driver/include")

# fewer sources than this means the walk went wrong (a moved folder, a bad
# SOURCE_DIR), not that the project shrank: today there are far more
set(minimum_sources 300)

# the table itself: each allowed layer is a layer, and below
set(violations "")
set(index 0)
foreach(layer IN LISTS layers)
  foreach(used IN LISTS may_use_${layer})
    list(FIND layers "${used}" used_index)
    if(used_index EQUAL -1)
      string(APPEND violations "  ${layer} may use '${used}', which is no layer\n")
    elseif(NOT used_index LESS index)
      string(APPEND violations "  ${layer} may use ${used}, which is not below it\n")
    endif()
  endforeach()
  math(EXPR index "${index} + 1")
endforeach()

# The layer a path inside the source tree belongs to: the longest layer
# folder holding it ("" for none). Headers of the public API are included
# as "mdlc/...", from tools/driver/include/mdlc/.
function(layer_of path out)
  if(path MATCHES "^mdlc/")
    set(${out} tools/driver/include PARENT_SCOPE)
    return()
  endif()
  set(best "")
  foreach(layer IN LISTS layers)
    string(LENGTH "${layer}" length)
    string(LENGTH "${best}" best_length)
    if(path MATCHES "^${layer}/" AND length GREATER best_length)
      set(best ${layer})
    endif()
  endforeach()
  set(${out} "${best}" PARENT_SCOPE)
endfunction()

set(checked 0)
set(per_layer "")
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/ir/* ${SOURCE_DIR}/frontend/* ${SOURCE_DIR}/passes/* ${SOURCE_DIR}/backend/*
     ${SOURCE_DIR}/tools/* ${SOURCE_DIR}/examples/*)
list(FILTER sources INCLUDE REGEX "\\.(h|hh|hpp|c|cc|cpp|cxx|inc|def)$")
# a JavaScript package manager's downloads are not mdlc's sources
list(FILTER sources EXCLUDE REGEX "/node_modules/")
foreach(rel IN LISTS sources)
  layer_of("${rel}" layer)
  if(layer STREQUAL "")
    string(APPEND violations "  ${rel} is in no layer\n")
    continue()
  endif()
  math(EXPR checked "${checked} + 1")
  list(APPEND per_layer ${layer})
  # quoted and angled includes alike, however indented: an include of a
  # project header in <...> must not slip past
  file(STRINGS ${SOURCE_DIR}/${rel} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" header "${line}")
    if(NOT header MATCHES "/")
      continue()  # a header beside the source, or a system header
    endif()
    if(NOT header MATCHES "^(ir|frontend|passes|backend|tools|examples|mdlc)/")
      continue()  # a library's header (fmt/, Eigen/, libxml/, ...)
    endif()
    layer_of("${header}" used)
    if(used STREQUAL "")
      string(APPEND violations "  ${rel} includes \"${header}\", in no layer\n")
    elseif(NOT used STREQUAL layer AND NOT used IN_LIST may_use_${layer})
      string(APPEND violations "  ${rel} (${layer}) includes \"${header}\" (${used})\n")
    endif()
  endforeach()
endforeach()

# every layer has sources: a layer folder that moved away is caught here
foreach(layer IN LISTS layers)
  if(NOT layer IN_LIST per_layer)
    string(APPEND violations "  no source was found in ${layer}/\n")
  endif()
endforeach()
if(checked LESS minimum_sources)
  string(APPEND violations "  only ${checked} sources were checked; expected at least ${minimum_sources}\n")
endif()

if(violations)
  message(FATAL_ERROR "the layers do not depend downward only:\n${violations}")
endif()
list(REMOVE_DUPLICATES per_layer)
list(LENGTH per_layer layer_count)
message(STATUS "${checked} sources in ${layer_count} layers: every include points down")
