# Rough-surface scenes: run, compare (thesis law, C++ vs F77), the legacy F77 program.
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")

add_test(NAME cli.rough.run_coulomb COMMAND ${_np} run fig3_27 --law coulomb --out ${CMAKE_CURRENT_BINARY_DIR}/fig3_27.csv)
set_tests_properties(cli.rough.run_coulomb PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "stuck \\(applied wrench inside the limit surface\\)")

add_test(NAME cli.rough.run_cvode COMMAND ${_np} run fig3_27 --law coulomb --method cvode --out -)
set_tests_properties(cli.rough.run_cvode PROPERTIES ENVIRONMENT "${_env}")

# The thesis law chatters past mu = 0.125: the run fails cleanly, partial samples kept apart.
add_test(NAME cli.rough.thesis_chatter COMMAND ${_np} run fig3_27 --law thesis --keep-partial
                                               --out ${CMAKE_CURRENT_BINARY_DIR}/fig3_27_thesis.csv)
set_tests_properties(cli.rough.thesis_chatter PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "no_static_friction: .*--law coulomb.*\\.partial\\.csv \\(incomplete\\)")
add_test(NAME cli.rough.thesis_chatter_fails COMMAND ${_np} run fig3_27 --law thesis --out -)
set_tests_properties(cli.rough.thesis_chatter_fails PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)

# nanopush compare works for rough scenes under the thesis law.
foreach(_f 12 17 22 24)
  add_test(NAME cli.compare.fig3_${_f} COMMAND ${_np} compare fig3_${_f})
  set_tests_properties(cli.compare.fig3_${_f} PROPERTIES ENVIRONMENT "${_env}"
    PASS_REGULAR_EXPRESSION "engines agree")
endforeach()

# The legacy FORTRAN 77 main program on a deck written by nanopush reproduces the F77 engine.
foreach(_s fig3_6c fig3_17 fig3_22)
  add_test(NAME cli.legacy.${_s} COMMAND ${_np} legacy ${_s} --program $<TARGET_FILE:nanobar>)
  set_tests_properties(cli.legacy.${_s} PROPERTIES ENVIRONMENT "${_env}"
    PASS_REGULAR_EXPRESSION "Coordinates of Application Force: Xn= 0.275000E-07\\[m\\] Yn= 0.450000E-07\\[m\\].*reproduces the F77 engine")
endforeach()
add_test(NAME cli.deck.fig3_12 COMMAND ${_np} deck fig3_12)
set_tests_properties(cli.deck.fig3_12 PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "\\* XN YN \\[m\\].*2.75000000000000014E-08 4.49999999999999993E-08")
# A truncated deck: the legacy program says so and exits non-zero.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/truncated.deck "* title\nbroken\n* XN YN\n")
add_test(NAME cli.legacy.bad_deck COMMAND sh -c "$<TARGET_FILE:nanobar> < ${CMAKE_CURRENT_BINARY_DIR}/truncated.deck")
set_tests_properties(cli.legacy.bad_deck PROPERTIES WILL_FAIL TRUE)

# Stick-slip under the coulomb law with the modern method over a range of tolerances. The
# event location's sub-integrations (one output, at their end) used to carry dense output:
# near the velocity's zero its error control held one of them at steps of 1e-6 of its span
# until the step budget ran out (stick_mu015 at rtol 1e-12: "more than 20000 steps"). They
# run without dense output now.
foreach(_r 1e-6 1e-9 1e-12 1e-13)
  add_test(NAME cli.run.stick_modern_${_r} COMMAND ${_np} run stick_mu015 --method modern --rtol ${_r}
           --out ${CMAKE_CURRENT_BINARY_DIR}/stick-modern-${_r}.csv)
  set_tests_properties(cli.run.stick_modern_${_r} PROPERTIES ENVIRONMENT "${_env}"
    PASS_REGULAR_EXPRESSION "came to rest at t = 3.81e-10 s: stuck")
endforeach()
