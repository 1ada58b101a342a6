# nanopush fit (issue 21, docs/fitting.md): synthetic data, the fit and its JSON, the
# non-identifiable pair, bad data named by row and column, non-convergence, the reproduce step.
set(_fit_dir ${CMAKE_CURRENT_BINARY_DIR}/fit)
file(MAKE_DIRECTORY ${_fit_dir})
set(_fit_span --set solver.t_end=0.4e-9)

add_test(NAME cli.fit.synthesize
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_span} --set solver.samples=101 --synthesize ${_fit_dir}/data.csv
                 --sigma x=1e-9 --sigma y=1e-9 --sigma theta=0.01 --seed 3)
set_tests_properties(cli.fit.synthesize PROPERTIES FIXTURES_SETUP fit_data)

# A model the thesis law cannot start (mu N > F): the classified outcome at once, exit 3,
# stderr named by the outcome as for `run`, no data written.
add_test(NAME cli.fit.no_static_friction
         COMMAND bash -c "\"$0\" fit fig3_20 --law thesis --set push.force=1e-12 --synthesize \"$1/stuck.csv\" --sigma x=1e-9 2> \"$1/stuck.err\"; \
r=$?; grep -q '^nanopush: no_static_friction: fig3_20 (thesis law): the object starts at rest' \"$1/stuck.err\" && m=yes || m=no; \
test -e \"$1/stuck.csv\" && f=yes || f=no; echo \"exit $r message $m file $f\"" $<TARGET_FILE:nanopush> ${_fit_dir})
set_tests_properties(cli.fit.no_static_friction PROPERTIES PASS_REGULAR_EXPRESSION "exit 3 message yes file no")

add_test(NAME cli.fit.json
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/data.csv ${_fit_span} --set surface.mu=0.1 --free surface.mu
                 --json - --out ${_fit_dir}/out)
set_tests_properties(cli.fit.json PROPERTIES FIXTURES_REQUIRED fit_data PASS_REGULAR_EXPRESSION
  "\"parameters\": {\n    \"surface.mu\": {\n      \"value\": 0\\.0[78][0-9]*,\n      \"stderr\": [0-9][.0-9e-]*,.*\"chi2_dof\": [01]\\.[0-9]*,.*\"converged\": true")

add_test(NAME cli.fit.summary
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/data.csv ${_fit_span} --set surface.mu=0.1 --free surface.mu
                 --out ${_fit_dir}/out2 --no-plot)
set_tests_properties(cli.fit.summary PROPERTIES FIXTURES_REQUIRED fit_data PASS_REGULAR_EXPRESSION
  "surface.mu = 0\\.0[78][0-9]* \\+- [0-9][.0-9e-]* \\(start 0\\.1\\).*chi2/dof = .*converged")

add_test(NAME cli.fit.identifiability
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/data.csv ${_fit_span} --set surface.mu=0.1 --free surface.mu
                 --free surface.f_vdw --out ${_fit_dir}/out3 --no-plot)
set_tests_properties(cli.fit.identifiability PROPERTIES FIXTURES_REQUIRED fit_data PASS_REGULAR_EXPRESSION
  "surface.mu = [0-9.e-]* \\(not determined separately\\).*surface.mu and surface.f_vdw are not determined separately by these data; they determine only mu\\*N = ")

# Bad data: each case names its row and column (exit 2).
file(WRITE ${_fit_dir}/unsorted.csv "t,x,sigma_x\n0,0,1e-9\n2e-10,1e-9,1e-9\n1e-10,2e-9,1e-9\n")
file(WRITE ${_fit_dir}/nan.csv "t,x,sigma_x\n0,0,1e-9\n1e-10,nan,1e-9\n")
file(WRITE ${_fit_dir}/sigma.csv "t,x,sigma_x\n0,0,1e-9\n1e-10,0,0\n")
file(WRITE ${_fit_dir}/late.csv "t,x,sigma_x\n0,0,1e-9\n9e-10,0,1e-9\n")
file(WRITE ${_fit_dir}/nosigma.csv "t,x\n0,0\n1e-10,0\n")
foreach(_case unsorted nan sigma late nosigma)
  add_test(NAME cli.fit.bad_${_case}
           COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/${_case}.csv ${_fit_span} --free surface.mu --out ${_fit_dir}/bad)
endforeach()
set_tests_properties(cli.fit.bad_unsorted PROPERTIES PASS_REGULAR_EXPRESSION
  "error: unsorted.csv row 3 \\(line 4\\), column t = 1e-10: unsorted")
set_tests_properties(cli.fit.bad_nan PROPERTIES PASS_REGULAR_EXPRESSION
  "error: nan.csv row 2 \\(line 3\\), column x = nan: must be a finite number")
set_tests_properties(cli.fit.bad_sigma PROPERTIES PASS_REGULAR_EXPRESSION
  "error: sigma.csv row 2 \\(line 3\\), column sigma_x = 0: a standard deviation must be > 0")
set_tests_properties(cli.fit.bad_late PROPERTIES PASS_REGULAR_EXPRESSION
  "error: late.csv row 2, column t = 9e-10: outside the scene's time span")
set_tests_properties(cli.fit.bad_nosigma PROPERTIES PASS_REGULAR_EXPRESSION
  "error: nosigma.csv column x = \\(no sigma\\): needs its standard deviation")
add_test(NAME cli.fit.bad_data_exit
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/nan.csv ${_fit_span} --free surface.mu
                 --out ${_fit_dir}/bad)
set_tests_properties(cli.fit.bad_data_exit PROPERTIES WILL_FAIL TRUE)

# A fit stopped by its evaluation limit says so, writes its last state, exits 3.
add_test(NAME cli.fit.not_converged
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/data.csv ${_fit_span} --set surface.mu=0.1 --free surface.mu
                 --max-evaluations 1 --json - --out ${_fit_dir}/nc --no-plot)
set_tests_properties(cli.fit.not_converged PROPERTIES FIXTURES_REQUIRED fit_data PASS_REGULAR_EXPRESSION
  "\"converged\": false.*fit did not converge")

add_test(NAME cli.fit.reproduce
         COMMAND $<TARGET_FILE:nanopush> reproduce --quick --out ${_fit_dir}/reproduce --only fit_synthetic)

# --format: the figure in SVG (and the .gp beside it), a bad format refused before any output.
add_test(NAME cli.fit.format_svg
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/data.csv ${_fit_span}
                 --set surface.mu=0.1 --free surface.mu --out ${_fit_dir}/svg --format svg)
set_tests_properties(cli.fit.format_svg PROPERTIES FIXTURES_REQUIRED fit_data FIXTURES_SETUP fit_svg)
add_test(NAME cli.fit.format_svg_written COMMAND ${CMAKE_COMMAND} -E cat ${_fit_dir}/svg/fig3_20.fit.svg)
set_tests_properties(cli.fit.format_svg_written PROPERTIES FIXTURES_REQUIRED fit_svg PASS_REGULAR_EXPRESSION "<svg")
add_test(NAME cli.fit.format_bad
         COMMAND $<TARGET_FILE:nanopush> fit fig3_20 ${_fit_dir}/data.csv --free surface.mu --out ${_fit_dir}/gif --format gif)
set_tests_properties(cli.fit.format_bad PROPERTIES FIXTURES_REQUIRED fit_data PASS_REGULAR_EXPRESSION
  "--format = gif: must be")
