# nanopush compare on every rough preset (fig3_12..fig3_32) under every friction law: the thesis
# and printed laws either agree (exit 0) or, where the thesis law comes to rest (no static friction), fail with exit
# 3 and the diagnosis; the coulomb law has no F77 peer and is refused (exit 2) with the command
# that checks it instead (docs/rough.md, "Comparing the engines").
# This file is both the test definition (included by tests/CMakeLists.txt) and, with -P, the check.
include(${CMAKE_CURRENT_LIST_DIR}/scripts/every_rough_preset.cmake)
if(CMAKE_SCRIPT_MODE_FILE)
  foreach(_fig RANGE 12 32)
    execute_process(COMMAND ${NP} compare fig3_${_fig} --law ${LAW}
                    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
    if(LAW STREQUAL "coulomb")
      if(NOT _rc EQUAL 2 OR NOT _err MATCHES "--law coulomb --method cvode")
        message(FATAL_ERROR "fig3_${_fig} --law coulomb: exit ${_rc}, expected 2 naming the CVODE check:\n${_err}")
      endif()
      continue()
    endif()
    if(_rc EQUAL 0)
      if(NOT _out MATCHES "engines agree")
        message(FATAL_ERROR "fig3_${_fig} --law ${LAW}: exit 0 without a verdict:\n${_out}")
      endif()
      continue()
    endif()
    thesis_law_rests_as_documented("${LAW}" "${_rc}" "${_err}" _documented)
    if(NOT _documented)
      message(FATAL_ERROR "fig3_${_fig} --law ${LAW}: exit ${_rc} (expected 0, or 3 with the diagnosis):\n${_out}\n${_err}")
    endif()
  endforeach()
  return()
endif()

add_test_per_law(cli.compare.every_preset)
