# nanopush compare cannot be fooled: where a reference run does not complete (the printed law
# under dop853 at rtol 1e-14 fails at t = 0 on fig3_29..32) the verdict is "cannot judge" with
# exit 3, never "agree" (docs/rough.md, "Comparing the engines").
# This file is both the test definition (included by tests/CMakeLists.txt) and, with -P, the check.
if(CMAKE_SCRIPT_MODE_FILE)
  execute_process(COMMAND ${NP} compare ${FIG} --law printed --method dop853
                  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 3 OR NOT _err MATCHES "cannot judge: the cxx-dop853-printed run \\(the reference at rtol 1e-14\\) did not complete"
     OR _out MATCHES "agree")
    message(FATAL_ERROR "${FIG} --law printed --method dop853: exit ${_rc}, expected 3 and \"cannot judge\":\n${_out}\n${_err}")
  endif()
  return()
endif()

foreach(_fig IN ITEMS fig3_29 fig3_32)
  add_test(NAME cli.compare.cannot_judge_${_fig}
           COMMAND ${CMAKE_COMMAND} -DNP=$<TARGET_FILE:nanopush> -DFIG=${_fig} -P ${CMAKE_CURRENT_LIST_FILE})
  set_tests_properties(cli.compare.cannot_judge_${_fig} PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                       LABELS "regression")
endforeach()
