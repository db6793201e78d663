# readme_walkthrough.cmake - the README's walk-through, run as written.
#
#   cmake -DREADME=README.md -DEXAMPLES=examples -DMDLC=mdlc -DORACLE=mujoco_oracle_test
#         -DWORK=DIR [-DFUSE=ON] -P readme_walkthrough.cmake
#
# WORK is laid out as the repository (examples/, build/tools/mdlc/mdlc, both
# links), and every `build/tools/mdlc/mdlc ...` line of the README's
# "Walk-through" section is run there by the shell, as a reader would. The
# MJCF the lines write is then loaded in MuJoCo 3.3.8 (the npm oracle,
# tests/oracle/mujoco_oracle_test's Extra cases), whose reading must agree
# with mdlc's compile of the source URDF (MDLC_ORACLE_MDLC_SOURCE).
#
# With FUSE=ON, the same lines get `--fuse-fixed` (a written file of its
# own): MuJoCo must then agree with mdlc's reading of the fused file, which
# the round-trip tests compare with the source (tests/convert).
foreach(var README EXAMPLES MDLC ORACLE WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "readme_walkthrough.cmake needs -D${var}=...")
  endif()
endforeach()

# the walk-through's command lines
file(STRINGS ${README} lines)
set(in_section FALSE)
set(commands "")
foreach(line IN LISTS lines)
  if(line MATCHES "^#+ ")
    if(line MATCHES "^#+ Walk-through")
      set(in_section TRUE)
    else()
      set(in_section FALSE)
    endif()
  elseif(in_section AND line MATCHES "^    (build/tools/mdlc/mdlc .*)$")
    list(APPEND commands "${CMAKE_MATCH_1}")
  endif()
endforeach()
list(LENGTH commands n)
if(n EQUAL 0)
  message(FATAL_ERROR "no `build/tools/mdlc/mdlc` line in the README's Walk-through section")
endif()

# a folder laid out as the repository
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/build/tools/mdlc)
file(CREATE_LINK ${EXAMPLES} ${WORK}/examples SYMBOLIC)
file(CREATE_LINK ${MDLC} ${WORK}/build/tools/mdlc/mdlc SYMBOLIC)

set(written "")
set(source "")
foreach(command IN LISTS commands)
  if(FUSE)
    # a file of its own, fused
    string(REGEX REPLACE "-o ([^ ]+)\\.xml" "-o \\1_fused.xml" command "${command}")
    string(APPEND command " --fuse-fixed")
  endif()
  message(STATUS "$ ${command}")
  execute_process(COMMAND bash -c "${command}" WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the README's command failed (status ${rc}): ${command}")
  endif()
  if(command MATCHES " convert ([^ ]+) .*-o ([^ ]+\\.xml)")
    set(source ${WORK}/${CMAKE_MATCH_1})
    set(written ${WORK}/${CMAKE_MATCH_2})
  endif()
endforeach()
if(NOT written OR NOT EXISTS ${written})
  message(FATAL_ERROR "the walk-through wrote no MJCF file (${written})")
endif()

# MuJoCo 3.3.8 loads it and agrees with mdlc's compile of the source (or,
# fused, of the written file)
set(env MDLC_ORACLE_EXTRA_MODELS=${written})
if(NOT FUSE)
  list(APPEND env MDLC_ORACLE_MDLC_SOURCE=${source})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${ORACLE} --gtest_filter=Extra/*
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "MuJoCo 3.3.8 does not load ${written} as mdlc reads its source")
endif()
