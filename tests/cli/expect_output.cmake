# expect_output.cmake - runs a command and passes only when it exits with the
# expected status AND its output (stdout and stderr together) matches a
# pattern. ctest's PASS_REGULAR_EXPRESSION alone ignores the exit status, so
# a command that printed the right words and then failed would pass.
#   cmake -DPASS_REGEX=... [-DEXIT_CODE=0] -P expect_output.cmake -- COMMAND ARGS...
# (the command is a CMake list: no argument may hold a semicolon)
cmake_minimum_required(VERSION 3.20)
if(NOT DEFINED PASS_REGEX)
  message(FATAL_ERROR "expect_output.cmake needs -DPASS_REGEX=...")
endif()
if(NOT DEFINED EXIT_CODE)
  set(EXIT_CODE 0)
endif()

# the command is everything after "--"
set(command "")
set(after_separator FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(after_separator)
    list(APPEND command "${CMAKE_ARGV${i}}")
  elseif(CMAKE_ARGV${i} STREQUAL "--")
    set(after_separator TRUE)
  endif()
endforeach()
if(NOT command)
  message(FATAL_ERROR "expect_output.cmake: no command after --")
endif()

execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE output
                ERROR_VARIABLE output)
message("${output}")
if(NOT "${status}" STREQUAL "${EXIT_CODE}")
  message(FATAL_ERROR "the command exited with '${status}', not ${EXIT_CODE}")
endif()
if(NOT output MATCHES "${PASS_REGEX}")
  message(FATAL_ERROR "the output does not match '${PASS_REGEX}'")
endif()
