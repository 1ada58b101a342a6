# Command-line tests of --method dop853 (docs/dop853.md): the smooth preset and a rough one
# under the thesis law run and write their CSV; what dop853 does not do is refused with an
# input error (exit status 2) naming the field, the value and what is allowed.
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")

add_test(NAME cli.run.dop853_smooth
  COMMAND ${_np} run fig3_6a --method dop853 --out ${CMAKE_CURRENT_BINARY_DIR}/fig3_6a.dop853.csv)
set_tests_properties(cli.run.dop853_smooth PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "fig3_6a \\[cxx-dop853\\] rtol = 1e-12, precision double\n[^\n]*\n  RHS evaluations [0-9]+, accepted steps [0-9]+, rejected steps [0-9]+")
add_test(NAME cli.run.dop853_smooth_stdout COMMAND ${_np} run fig3_6a --method dop853 --out - --quiet)
set_tests_properties(cli.run.dop853_smooth_stdout PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "^t,x,y,theta,vx,vy,omega,fx,fy,mf\n0,0,0,-0.5,0,0,0,.*\n1.6e-09,[^\n]*\n$")

add_test(NAME cli.run.dop853_rough
  COMMAND ${_np} run fig3_17 --method dop853 --out ${CMAKE_CURRENT_BINARY_DIR}/fig3_17.dop853.csv)
set_tests_properties(cli.run.dop853_rough PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "fig3_17 \\[cxx-dop853-thesis\\] rtol = 1e-10, precision double\n[^\n]*\n  RHS evaluations [0-9]+")

# Refused: the coulomb law (no event location), extended precision, the F77 engine.
add_test(NAME cli.run.dop853_coulomb COMMAND ${_np} run stick_mu015 --method dop853)
set_tests_properties(cli.run.dop853_coulomb PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "method = dop853: the coulomb law needs its rest events located[^\n]*use faithful, modern or cvode")
add_test(NAME cli.run.dop853_coulomb_fails COMMAND ${_np} run stick_mu015 --method dop853)
set_tests_properties(cli.run.dop853_coulomb_fails PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
add_test(NAME cli.run.dop853_quad COMMAND ${_np} run fig3_6a --method dop853 --precision quad)
set_tests_properties(cli.run.dop853_quad PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "precision = quad: long and quad need engine = cxx, method faithful or modern[^\n]*dop853 is double only")
add_test(NAME cli.run.dop853_f77 COMMAND ${_np} run fig3_6a --method dop853 --engine f77)
set_tests_properties(cli.run.dop853_f77 PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "method = dop853: the f77 engine has one method")
add_test(NAME cli.run.dop853_tight_rtol COMMAND ${_np} run fig3_6a --method dop853 --rtol 1e-16)
set_tests_properties(cli.run.dop853_tight_rtol PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "rtol = 1e-16: must be >= 2.22e-15 \\(10 eps of double\\) with the dop853 method")
# The help lists it.
add_test(NAME cli.run.dop853_help COMMAND ${_np} run --help)
set_tests_properties(cli.run.dop853_help PROPERTIES PASS_REGULAR_EXPRESSION "dop853 \\(Dormand-Prince 8\\(5,3\\)")

# --method auto: dop853 down to rtol 1e-11 where it runs, modern below it, in extended
# precision and under the coulomb law (the run's label names the method taken).
foreach(_case "fig3_6a;1e-10;cxx-dop853" "fig3_6a;1e-12;cxx-modern" "fig3_17;1e-8;cxx-dop853-thesis"
              "stick_mu015;1e-8;cxx-modern-coulomb")
  list(GET _case 0 _scene)
  list(GET _case 1 _rtol)
  list(GET _case 2 _label)
  add_test(NAME cli.run.auto_${_scene}_${_rtol}
    COMMAND ${_np} run ${_scene} --method auto --rtol ${_rtol} --out ${CMAKE_CURRENT_BINARY_DIR}/auto_${_scene}_${_rtol}.csv)
  set_tests_properties(cli.run.auto_${_scene}_${_rtol} PROPERTIES ENVIRONMENT "${_env}"
    PASS_REGULAR_EXPRESSION "${_scene} \\[${_label}\\] rtol = ")
endforeach()
add_test(NAME cli.run.auto_quad COMMAND ${_np} run fig3_6a --method auto --precision quad --rtol 1e-20
  --out ${CMAKE_CURRENT_BINARY_DIR}/auto_quad.csv)
set_tests_properties(cli.run.auto_quad PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "fig3_6a \\[cxx-modern-quad\\] rtol = 1e-20")
