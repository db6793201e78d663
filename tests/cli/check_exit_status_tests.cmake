# check_exit_status_tests.cmake - no test passes on its output alone. ctest's
# PASS_REGULAR_EXPRESSION makes a test pass whatever its exit status, so a
# command that printed the right words and then crashed would pass; a test
# that looks for words runs through expect_output.cmake instead, which
# checks both. This fails on any use of the property outside a comment.
#   cmake -DSOURCE_DIR=... -P check_exit_status_tests.cmake
cmake_minimum_required(VERSION 3.20)
if(NOT DEFINED SOURCE_DIR)
  message(FATAL_ERROR "check_exit_status_tests.cmake needs -DSOURCE_DIR=...")
endif()

file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/CMakeLists.txt ${SOURCE_DIR}/*.cmake)
# build trees (their generated files and downloads) are not the project's
list(FILTER files EXCLUDE REGEX "(^build[^/]*/|/node_modules/|^\\.git/)")
list(FILTER files EXCLUDE REGEX "/check_exit_status_tests\\.cmake$")  # names it to find it
set(found "")
set(checked 0)
foreach(file IN LISTS files)
  math(EXPR checked "${checked} + 1")
  file(STRINGS ${SOURCE_DIR}/${file} lines REGEX "PASS_REGULAR_EXPRESSION")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "#.*" "" code "${line}")  # comments may name it
    if(code MATCHES "PASS_REGULAR_EXPRESSION")
      string(APPEND found "  ${file}: ${line}\n")
    endif()
  endforeach()
endforeach()
# the walk found the test files, or this proves nothing
if(checked LESS 10)
  message(FATAL_ERROR "only ${checked} CMake files were read; expected the tests' among them")
endif()
if(found)
  message(FATAL_ERROR "tests that pass on their output whatever their exit status "
                      "(use expect_output.cmake):\n${found}")
endif()
message(STATUS "${checked} CMake files: every test that reads output checks the exit status")
