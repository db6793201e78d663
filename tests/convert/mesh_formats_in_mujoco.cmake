# mesh_formats_in_mujoco.cmake - a model with COLLADA, glTF, PLY and ASCII STL
# meshes, converted to MJCF with --copy-assets (issue 58), loads in MuJoCo
# 3.3.8 as mdlc reads the converted file (the oracle's Converted cases).
#
#   cmake -DMDLC=mdlc -DORACLE=mujoco_oracle_test -DMODEL=x.urdf -DWORK=DIR
#         -P mesh_formats_in_mujoco.cmake
foreach(var MDLC ORACLE MODEL WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "mesh_formats_in_mujoco.cmake needs -D${var}=...")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
set(folder ${WORK}/xml/mesh_formats)
file(MAKE_DIRECTORY ${folder})
execute_process(COMMAND ${MDLC} convert ${MODEL} -o ${folder}/mesh_formats.xml
                        --copy-assets ${folder}/assets
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mdlc convert failed (status ${rc}):\n${err}")
endif()
file(GLOB copies ${folder}/assets/*)
foreach(copy IN LISTS copies)
  if(NOT copy MATCHES "\\.obj$")
    message(FATAL_ERROR "a mesh copy MuJoCo cannot read: ${copy}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env MDLC_ORACLE_CONVERTED_MODELS=${WORK}
                        ${ORACLE} --gtest_filter=Converted/*
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "PASSED  \\] 1 test")
  message(FATAL_ERROR "MuJoCo 3.3.8 does not load the converted model as mdlc reads it")
endif()
