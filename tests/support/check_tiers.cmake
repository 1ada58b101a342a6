# tests.tiers: every Catch2 case carries exactly one tier tag, and every CTest test of the build a
# tier label (tests/CMakeLists.txt says how tiers are given).
# cmake -DTESTS_EXE=nanopush_tests -DCTEST=ctest -DBUILD_DIR=build -P check_tiers.cmake
set(_bad "")
# Catch2 test specs: [a][b] is "a and b", a comma is "or", ~ is "not".
foreach(_spec IN ITEMS "~[unit]~[numeric]~[regression]"
                       "[unit][numeric],[unit][regression],[numeric][regression]")
  execute_process(COMMAND ${TESTS_EXE} ${_spec} --list-test-names-only
                  OUTPUT_VARIABLE _out RESULT_VARIABLE _rc)
  string(STRIP "${_out}" _out)
  if(NOT _out STREQUAL "")
    string(APPEND _bad "C++ cases matching ${_spec} (no tier tag, or two):\n${_out}\n")
  endif()
endforeach()
# The same cases under each tier's spec add up to all of them: nothing lost between discoveries.
execute_process(COMMAND ${TESTS_EXE} --list-test-names-only OUTPUT_VARIABLE _all)
string(REGEX MATCHALL "[^\n]+" _all "${_all}")
list(LENGTH _all _n_all)
set(_n_sum 0)
foreach(_tier IN ITEMS unit numeric regression)
  execute_process(COMMAND ${TESTS_EXE} "[${_tier}]" --list-test-names-only OUTPUT_VARIABLE _some)
  string(REGEX MATCHALL "[^\n]+" _some "${_some}")
  list(LENGTH _some _n)
  math(EXPR _n_sum "${_n_sum} + ${_n}")
  message(STATUS "C++ cases tagged [${_tier}]: ${_n}")
endforeach()
if(NOT _n_sum EQUAL _n_all)
  string(APPEND _bad "C++ cases: ${_n_all}, but the three tiers hold ${_n_sum}\n")
endif()
# CTest tests without a tier label (ctest -N only lists; it runs nothing).
execute_process(COMMAND ${CTEST} -N -LE "^(unit|numeric|regression)$" WORKING_DIRECTORY ${BUILD_DIR}
                OUTPUT_VARIABLE _out RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0 OR NOT _out MATCHES "Total Tests: 0")
  string(APPEND _bad "CTest tests without a tier label (ctest -N -LE 'unit|numeric|regression'):\n${_out}\n")
endif()
if(_bad)
  message(FATAL_ERROR "${_bad}")
endif()
message("tiers: ok (${_n_all} C++ cases, each with one tier; every CTest test labelled)")
