# Runs `mdlc compile INPUT --emit=ir` and compares the output with EXPECTED.
# With the environment variable MDLC_UPDATE_GOLDEN=1 it rewrites EXPECTED.
# PACKAGE_PATH, when given, is a folder of packages for package:// URIs.
get_filename_component(dir ${INPUT} DIRECTORY)
set(packages "")
if(PACKAGE_PATH)
  set(packages --package-path ${PACKAGE_PATH})
endif()
execute_process(COMMAND ${MDLC} compile ${INPUT} --emit=ir ${packages}
  WORKING_DIRECTORY ${dir}
  OUTPUT_VARIABLE actual ERROR_VARIABLE errors RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "mdlc failed (${status}) on ${INPUT}:\n${errors}")
endif()
if("$ENV{MDLC_UPDATE_GOLDEN}" STREQUAL "1")
  file(WRITE ${EXPECTED} "${actual}")
  message(STATUS "updated ${EXPECTED}")
  return()
endif()
if(NOT EXISTS ${EXPECTED})
  message(FATAL_ERROR "missing ${EXPECTED}; run with MDLC_UPDATE_GOLDEN=1 to create it")
endif()
file(READ ${EXPECTED} expected)
if(NOT actual STREQUAL expected)
  file(WRITE ${EXPECTED}.actual "${actual}")
  message(FATAL_ERROR "IR dump differs from ${EXPECTED}; see ${EXPECTED}.actual\n"
          "(diff ${EXPECTED} ${EXPECTED}.actual)")
endif()
