# Command-line tests of run / compare / reproduce (the drivers are tests too).
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")

add_test(NAME cli.help COMMAND ${_np} --help)
set_tests_properties(cli.help PROPERTIES PASS_REGULAR_EXPRESSION "reproduce")
foreach(_sub run compare reproduce)
  add_test(NAME cli.${_sub}.help COMMAND ${_np} ${_sub} --help)
  set_tests_properties(cli.${_sub}.help PROPERTIES PASS_REGULAR_EXPRESSION "Usage")
endforeach()

add_test(NAME cli.run.stdout COMMAND ${_np} run fig3_6c --engine cxx --out - --quiet)
set_tests_properties(cli.run.stdout PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "^t,x,y,theta,vx,vy,omega,fx,fy,mf\n0,0,0,0.5,")

add_test(NAME cli.run.f77 COMMAND ${_np} run fig3_6c --engine f77 --out ${CMAKE_CURRENT_BINARY_DIR}/fig3_6c.f77.csv)
set_tests_properties(cli.run.f77 PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "RHS evaluations [0-9]+, accepted steps [0-9]+, rejected steps [0-9]+")

add_test(NAME cli.run.missing_scene COMMAND ${_np} run no_such_scene)
set_tests_properties(cli.run.missing_scene PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
add_test(NAME cli.run.missing_scene_message COMMAND ${_np} run no_such_scene)
set_tests_properties(cli.run.missing_scene_message PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "SCENE = no_such_scene: no such file")

add_test(NAME cli.run.bad_rtol COMMAND ${_np} run fig3_6a --rtol -1)
set_tests_properties(cli.run.bad_rtol PROPERTIES WILL_FAIL TRUE)

# --precision (issue 7): quad on a smooth scene runs and writes its CSV (exit status 0,
# checked by the run itself; the file checked after it, stale copies removed before it).
set(_quad_csv ${CMAKE_CURRENT_BINARY_DIR}/fig3_6a.quad.csv)
add_test(NAME cli.run.precision_quad_clean COMMAND ${CMAKE_COMMAND} -E rm -f ${_quad_csv})
set_tests_properties(cli.run.precision_quad_clean PROPERTIES FIXTURES_SETUP cli_quad_clean)
add_test(NAME cli.run.precision_quad
  COMMAND ${_np} run fig3_6a --precision quad --method modern --rtol 1e-20 --out ${_quad_csv})
set_tests_properties(cli.run.precision_quad PROPERTIES ENVIRONMENT "${_env}"
  FIXTURES_REQUIRED cli_quad_clean FIXTURES_SETUP cli_quad_csv)
add_test(NAME cli.run.precision_quad_csv COMMAND ${CMAKE_COMMAND} -E cat ${_quad_csv})
set_tests_properties(cli.run.precision_quad_csv PROPERTIES FIXTURES_REQUIRED cli_quad_csv
  PASS_REGULAR_EXPRESSION "^t,x,y,theta,vx,vy,omega,fx,fy,mf\n0,0,0,-0.5,0,0,0,.*\n1.6e-09,[^\n]*\n$")
# The summary shows the precision and the wall time (the cost).
add_test(NAME cli.run.precision_summary COMMAND ${_np} run fig3_6a --precision long --out -)
set_tests_properties(cli.run.precision_summary PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "fig3_6a \\[cxx-faithful-long\\] rtol = 1e-12, precision long[^\n]*\n.*wall time [0-9.]+ m?s")
# An unknown value: refused by the option check, naming the option.
add_test(NAME cli.run.precision_bogus COMMAND ${_np} run fig3_6a --precision bogus)
set_tests_properties(cli.run.precision_bogus PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
add_test(NAME cli.run.precision_bogus_message COMMAND ${_np} run fig3_6a --precision bogus)
set_tests_properties(cli.run.precision_bogus_message PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "--precision: bogus not in \\{double,long,quad\\}")
# Extended precision where the RHS is double only (F77 engine): an input error naming it.
add_test(NAME cli.run.precision_f77 COMMAND ${_np} run fig3_6a --precision quad --engine f77)
set_tests_properties(cli.run.precision_f77 PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
add_test(NAME cli.run.precision_f77_message COMMAND ${_np} run fig3_6a --precision quad --engine f77)
set_tests_properties(cli.run.precision_f77_message PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "precision = quad: long and quad need engine = cxx")

# A bad scene file: the message names the field, the value and the range; exit code 2.
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bad_mass.toml
  "[object]\nlength = 1e-7\nwidth = 5e-8\nmass = -1\n[push]\nforce = 1e-6\nxn = 0\nyn = 0\n[solver]\nt_end = 1e-9\n")
add_test(NAME cli.run.bad_scene COMMAND ${_np} run ${CMAKE_CURRENT_BINARY_DIR}/bad_mass.toml)
set_tests_properties(cli.run.bad_scene PROPERTIES PASS_REGULAR_EXPRESSION "object.mass = -1: must be > 0 \\(kg\\)")
add_test(NAME cli.run.bad_scene_fails COMMAND ${_np} run ${CMAKE_CURRENT_BINARY_DIR}/bad_mass.toml)
set_tests_properties(cli.run.bad_scene_fails PROPERTIES WILL_FAIL TRUE)

# compare exits 0 on every Fig 3.6 preset.
foreach(_c a b c d e f g h)
  add_test(NAME cli.compare.fig3_6${_c} COMMAND ${_np} compare fig3_6${_c})
  set_tests_properties(cli.compare.fig3_6${_c} PROPERTIES ENVIRONMENT "${_env}")
endforeach()

# The main job, quick mode, into the build tree: must exit 0 (every check holds).
add_test(NAME cli.reproduce.quick COMMAND ${_np} reproduce --quick --out ${CMAKE_CURRENT_BINARY_DIR}/reproduce-quick)
set_tests_properties(cli.reproduce.quick PROPERTIES ENVIRONMENT "${_env}" TIMEOUT 600)
