# Every rough preset (fig3_12..fig3_32) under every friction law either completes (exit 0) or
# fails with the documented exit code 3 and a message that says why and what to do
# (docs/errors.md, docs/rough.md). One test per law, so ctest can run them in parallel.
# This file is both the test definition (included by tests/CMakeLists.txt) and, with -P, the check.
include(${CMAKE_CURRENT_LIST_DIR}/scripts/every_rough_preset.cmake)
if(CMAKE_SCRIPT_MODE_FILE)
  foreach(_fig RANGE 12 32)
    execute_process(COMMAND ${NP} run fig3_${_fig} --law ${LAW} --out ${OUTDIR}/fig3_${_fig}.${LAW}.csv --quiet
                    RESULT_VARIABLE _rc ERROR_VARIABLE _err OUTPUT_QUIET)
    if(_rc EQUAL 0)
      if(NOT EXISTS ${OUTDIR}/fig3_${_fig}.${LAW}.csv)
        message(FATAL_ERROR "fig3_${_fig} --law ${LAW}: exit 0 but no trajectory written")
      endif()
      continue()
    endif()
    if(NOT _rc EQUAL 3)
      message(FATAL_ERROR "fig3_${_fig} --law ${LAW}: exit ${_rc} (expected 0, or 3 with a diagnosis):\n${_err}")
    endif()
    # Only the thesis law may fail, where it chatters at rest (mu N > F), and it must say where
    # the bar came to rest and that the coulomb law continues.
    thesis_law_rests_as_documented("${LAW}" "${_rc}" "${_err}" _documented)
    if(NOT _documented OR NOT _err MATCHES "^nanopush: no_static_friction: ")
      message(FATAL_ERROR "fig3_${_fig} --law ${LAW}: exit 3 without the documented diagnosis:\n${_err}")
    endif()
  endforeach()
  return()
endif()

add_test_per_law(cli.rough.every_preset -DOUTDIR=${CMAKE_CURRENT_BINARY_DIR})
