# The error estimate and --accuracy on the command line, and every outcome a run can end in
# (docs/accuracy.md, docs/errors.md "Outcomes of a run").
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/accuracy)
file(MAKE_DIRECTORY ${_dir})

# Every run's summary carries its estimate; --no-error-estimate skips it.
add_test(NAME cli.accuracy.estimate COMMAND ${_np} run fig3_17 --out ${_dir}/fig3_17.csv)
set_tests_properties(cli.accuracy.estimate PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "error estimate of the final pose [0-9.e+-]+ \\(\\|dx\\| [0-9.e+-]+ m.*companion run \\[cxx-dop853-thesis\\] at rtol 1e-12")
add_test(NAME cli.accuracy.no_estimate COMMAND ${_np} run fig3_17 --no-error-estimate --out ${_dir}/fig3_17b.csv)
set_tests_properties(cli.accuracy.no_estimate PROPERTIES ENVIRONMENT "${_env}" FAIL_REGULAR_EXPRESSION "error estimate")
# The sidecar's run record holds it.
add_test(NAME cli.accuracy.sidecar COMMAND ${CMAKE_COMMAND} -E cat ${_dir}/fig3_17.schema.json)
set_tests_properties(cli.accuracy.sidecar PROPERTIES DEPENDS cli.accuracy.estimate
  PASS_REGULAR_EXPRESSION "\"outcome\": \"ok\".*\"error_estimate\": [0-9]")

# --accuracy reaches its target and says with which rtol; out of range is bad input (exit 2).
add_test(NAME cli.accuracy.reached COMMAND ${_np} run fig3_18 --law coulomb --accuracy 1e-9 --out ${_dir}/fig3_18.csv)
set_tests_properties(cli.accuracy.reached PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "accuracy asked 1e-09: reached with rtol 1e-1[0-9]")
add_test(NAME cli.accuracy.reached_in_long COMMAND ${_np} run fig3_18 --law coulomb --accuracy 1e-14 --out ${_dir}/long.csv)
set_tests_properties(cli.accuracy.reached_in_long PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "cxx-modern-coulomb-long.*accuracy asked 1e-14: reached with rtol 1e-1[6-9]")
add_test(NAME cli.accuracy.out_of_range COMMAND ${_np} run fig3_18 --accuracy 1)
set_tests_properties(cli.accuracy.out_of_range PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
add_test(NAME cli.accuracy.scene_key_range COMMAND ${_np} run fig3_18 --set solver.accuracy=1e-20)
set_tests_properties(cli.accuracy.scene_key_range PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "solver.accuracy = 1e-20: must be in \\[1e-14, 0.1\\]")

# Outcomes: at_rest (coulomb law, a push inside the limit surface: an answer, exit 0) ...
add_test(NAME cli.accuracy.at_rest COMMAND ${_np} run fig3_18 --law coulomb --set push.force=1e-7 --out ${_dir}/rest.csv)
set_tests_properties(cli.accuracy.at_rest PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "at_rest: the push \\(F = 1e-07 N\\) lies inside the limit surface")
# ... no_static_friction (the same under the thesis law: exit 3 at once, both engines) ...
foreach(_engine cxx f77)
  add_test(NAME cli.accuracy.no_static_friction_${_engine}
           COMMAND ${_np} run fig3_18 --law thesis --engine ${_engine} --set push.force=1e-7 --out ${_dir}/nsf.csv)
  set_tests_properties(cli.accuracy.no_static_friction_${_engine} PROPERTIES ENVIRONMENT "${_env}"
    PASS_REGULAR_EXPRESSION "nanopush: no_static_friction: fig3_18 .*starts at rest .*--law coulomb")
endforeach()
# ... accuracy_not_reached (exit 3, the best estimate said): the printed law runs in double only,
# and 1e-14 is beyond its floor (the coulomb law goes on in long double: cli.accuracy.reached_in_long).
add_test(NAME cli.accuracy.not_reached COMMAND ${_np} run fig3_17 --law printed --accuracy 1e-14 --out ${_dir}/nr.csv)
set_tests_properties(cli.accuracy.not_reached PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "nanopush: accuracy_not_reached: .*the estimated error [0-9.e+-]+ of the final pose is above")

# The outcomes round-trip through a sweep table: at_rest is an answer, no_static_friction a failed row.
add_test(NAME cli.accuracy.sweep_outcomes
         COMMAND ${CMAKE_COMMAND} -DNP=${_np} -DOUT=${_dir}/outcomes.csv -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/accuracy_sweep.cmake)
set_tests_properties(cli.accuracy.sweep_outcomes PROPERTIES ENVIRONMENT "${_env}")

# The benchmark runs on a few scenes and writes its files (structure only, never timings); its
# cost bounds never exceed the cost of --accuracy's own answer, whose pairs lie on their grid.
add_test(NAME cli.accuracy.bench COMMAND ${_np} bench-accuracy --scenes 4 --out ${_dir}/bench)
set_tests_properties(cli.accuracy.bench PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "accuracy.md, accuracy_honesty.csv, accuracy_cost.csv"
  FAIL_REGULAR_EXPRESSION "costs more than --accuracy's answer|a cost bound above")

# The stability atlas runs on a 2 x 2 grid per map and writes its files (structure only).
add_test(NAME cli.accuracy.atlas COMMAND ${_np} bench-atlas --points 2 --out ${_dir}/atlas)
set_tests_properties(cli.accuracy.atlas PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "atlas.md, atlas.csv, atlas_\\*.png")

# compare --accuracy: both engines run at the rtol where the C++ configuration reaches it.
add_test(NAME cli.accuracy.compare COMMAND ${_np} compare fig3_17 --accuracy 1e-7)
set_tests_properties(cli.accuracy.compare PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "accuracy asked 1e-07: cxx-faithful-thesis reaches it at rtol 1e-[0-9]+ \\([0-9]+ runs\\); both engines run there.*engines agree")
add_test(NAME cli.accuracy.compare_with_rtol COMMAND ${_np} compare fig3_17 --accuracy 1e-7 --rtol 1e-9)
set_tests_properties(cli.accuracy.compare_with_rtol PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "--rtol = 1e-09: --accuracy chooses the rtol")

# fit --accuracy: the forward solves' rtol chosen, checked at the estimate (text and JSON).
add_test(NAME cli.accuracy.fit
         COMMAND ${_np} fit fig3_20 ${CMAKE_CURRENT_BINARY_DIR}/fit/data.csv --set solver.t_end=0.4e-9 --set surface.mu=0.1
                 --free surface.mu --accuracy 1e-8 --out ${_dir}/fit --no-plot)
set_tests_properties(cli.accuracy.fit PROPERTIES ENVIRONMENT "${_env}" FIXTURES_REQUIRED fit_data
  PASS_REGULAR_EXPRESSION "accuracy asked 1e-08 of the model's poses: reached with rtol 1e-[0-9]+ \\(estimate [0-9.e-]+ at the estimate\\)")
add_test(NAME cli.accuracy.fit_json
         COMMAND ${_np} fit fig3_20 ${CMAKE_CURRENT_BINARY_DIR}/fit/data.csv --set solver.t_end=0.4e-9 --set surface.mu=0.1
                 --free surface.mu --accuracy 1e-8 --json - --out ${_dir}/fit2 --no-plot)
set_tests_properties(cli.accuracy.fit_json PROPERTIES ENVIRONMENT "${_env}" FIXTURES_REQUIRED fit_data
  PASS_REGULAR_EXPRESSION "\"accuracy\": {[ \n]*\"requested\": 1e-08,[ \n]*\"rtol_used\": [0-9.e-]+,[ \n]*\"estimate\": [0-9.e-]+,[ \n]*\"reached\": true[ \n]*}")
