# nanopush compare with a C++ method whose steps differ from the F77 engine's (modern, dop853):
# judged by convergence (docs/rough.md, "Comparing the engines"). Every preset the thesis law
# runs to its end agrees; the faithful method keeps the same-steps criterion.
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")

foreach(_m modern dop853)
  foreach(_f 6a 6d 12 13 14 15 16 17 18 19 20 21 22 23 24)
    add_test(NAME cli.compare.${_m}.fig3_${_f} COMMAND ${_np} compare fig3_${_f} --method ${_m})
    set_tests_properties(cli.compare.${_m}.fig3_${_f} PROPERTIES ENVIRONMENT "${_env}"
      PASS_REGULAR_EXPRESSION "engines agree: they converge to the same solution"
      FAIL_REGULAR_EXPRESSION "DISAGREE")
  endforeach()
endforeach()

# The table names each engine's own error and the tight runs' difference.
add_test(NAME cli.compare.convergence_table COMMAND ${_np} compare fig3_16 --method modern)
set_tests_properties(cli.compare.convergence_table PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "error cxx +error f77 +\\|cxx - f77\\| +\\|cxx - f77\\| tight")

# An impossible tolerance is a disagreement with exit status 1, not a pass (faithful would pass:
# its C++ and F77 runs are identical to the last bit).
add_test(NAME cli.compare.tolerance_too_tight COMMAND ${_np} compare fig3_17 --method modern --tolerance 1e-30)
set_tests_properties(cli.compare.tolerance_too_tight PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
