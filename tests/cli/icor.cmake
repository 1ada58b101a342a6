# nanopush icor: the command line is a test too (issue 5).
add_test(NAME cli.icor.roots_both_branches
         COMMAND $<TARGET_FILE:nanopush> icor roots --yn 1e-9)
set_tests_properties(cli.icor.roots_both_branches PROPERTIES
  PASS_REGULAR_EXPRESSION "lapack,f77,3,0,0,-9\\.82225349651171[0-9]*e-08,9\\.84447594571973[0-9]*e-08")

add_test(NAME cli.icor.roots_bifurcation
         COMMAND $<TARGET_FILE:nanopush> icor roots --yn 0)
set_tests_properties(cli.icor.roots_bifurcation PROPERTIES
  PASS_REGULAR_EXPRESSION "brent,f77,2,0,1,-9\\.83333333333333[0-9]*e-08,9\\.83333333333333[0-9]*e-08")

add_test(NAME cli.icor.roots_sweep
         COMMAND $<TARGET_FILE:nanopush> icor roots --n 5 --log --yn-min 1e-15)
set_tests_properties(cli.icor.roots_sweep PROPERTIES PASS_REGULAR_EXPRESSION "^yn,solver,language")

add_test(NAME cli.icor.bad_yn_fails
         COMMAND $<TARGET_FILE:nanopush> icor roots --yn -1e-9)
set_tests_properties(cli.icor.bad_yn_fails PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.icor.bad_yn_message
         COMMAND $<TARGET_FILE:nanopush> icor roots --yn -1e-9)
set_tests_properties(cli.icor.bad_yn_message PROPERTIES
  PASS_REGULAR_EXPRESSION "--yn = -1[.0-9e-]*: must be in \\[0, 2.95e-07\\] \\(m; push point on the rod, at most b = L/2\\)")

add_test(NAME cli.icor.bad_length_fails
         COMMAND $<TARGET_FILE:nanopush> icor roots --yn 1e-9 --length 0)
set_tests_properties(cli.icor.bad_length_fails PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.icor.bad_length_message
         COMMAND $<TARGET_FILE:nanopush> icor roots --yn 1e-9 --length -1e-9)
set_tests_properties(cli.icor.bad_length_message PROPERTIES
  PASS_REGULAR_EXPRESSION "rod.length = -1[.0-9e-]*: must be > 0 \\(m\\)")

add_test(NAME cli.icor.formulas
         COMMAND $<TARGET_FILE:nanopush> icor formulas --n 5)
set_tests_properties(cli.icor.formulas PROPERTIES PASS_REGULAR_EXPRESSION "^yn,R_experimental_fit,R_falvo,R_li,R_unknown_pressure,R_known_pressure,F_min,F_from_icor,R_constrained_negative,R_constrained_positive,F_constrained_negative,R_impulsive\n")

add_test(NAME cli.icor.estimate_mu_from_force
         COMMAND $<TARGET_FILE:nanopush> icor estimate-mu --force 1e-6 --force-sigma 3e-8 --yn 200e-9
                 --yn-sigma 5e-9 --hamaker-sigma 2e-20)
set_tests_properties(cli.icor.estimate_mu_from_force PROPERTIES
  PASS_REGULAR_EXPRESSION "mu = 0\\.374656 \\+- 0\\.0202022")

add_test(NAME cli.icor.estimate_mu_from_icor
         COMMAND $<TARGET_FILE:nanopush> icor estimate-mu --force 1e-6 --icor 150e-9 --icor-sigma 5e-9)
set_tests_properties(cli.icor.estimate_mu_from_icor PROPERTIES PASS_REGULAR_EXPRESSION "eq 4\\.10.*mu = ")

add_test(NAME cli.icor.estimate_mu_needs_one_map
         COMMAND $<TARGET_FILE:nanopush> icor estimate-mu --force 1e-6 --yn 1e-7 --icor 1e-7)
set_tests_properties(cli.icor.estimate_mu_needs_one_map PROPERTIES WILL_FAIL TRUE)

add_test(NAME cli.icor.reproduce
         COMMAND $<TARGET_FILE:nanopush> reproduce --quick --out ${CMAKE_CURRENT_BINARY_DIR}/icor_reproduce
                 --only table5_1 --only icor_error_analysis --only fig4_2 --only fig4_3 --only fig4_4
                 --only fig4_5 --only fig5_2)

# nanopush icor dynamic: a push below the minimum force leaves the rod stuck; above it the
# iCOR is read off the velocities (issue 5 item 3).
add_test(NAME cli.icor.dynamic_stuck
         COMMAND $<TARGET_FILE:nanopush> icor dynamic --yn 1e-7 --force-ratio 0.5)
set_tests_properties(cli.icor.dynamic_stuck PROPERTIES PASS_REGULAR_EXPRESSION ",1e-10,stuck,,,,0,")
add_test(NAME cli.icor.dynamic_moves
         COMMAND $<TARGET_FILE:nanopush> icor dynamic --yn 1e-7 --force-ratio 2)
set_tests_properties(cli.icor.dynamic_moves PROPERTIES
  PASS_REGULAR_EXPRESSION ",1e-10,rotation,2\\.3634[0-9e.-]*,2\\.3632[0-9e.-]*,")
add_test(NAME cli.icor.dynamic_bad_yn_fails
         COMMAND $<TARGET_FILE:nanopush> icor dynamic --yn 1e-6)
set_tests_properties(cli.icor.dynamic_bad_yn_fails PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.icor.dynamic_bad_yn_message
         COMMAND $<TARGET_FILE:nanopush> icor dynamic --yn 1e-6)
set_tests_properties(cli.icor.dynamic_bad_yn_message PROPERTIES
  PASS_REGULAR_EXPRESSION "--yn = 1e-06: must be in \\[0, 2\\.95e-07\\]")
add_test(NAME cli.icor.dynamic_bad_integrator_fails
         COMMAND $<TARGET_FILE:nanopush> icor dynamic --yn 1e-7 --integrator euler)
set_tests_properties(cli.icor.dynamic_bad_integrator_fails PROPERTIES WILL_FAIL TRUE)

# nanopush icor rectangle: a thin strip is eq 4.13 (issue 5 item 4).
add_test(NAME cli.icor.rectangle_thin
         COMMAND $<TARGET_FILE:nanopush> icor rectangle --n 3 --aspect 1e-4)
set_tests_properties(cli.icor.rectangle_thin PROPERTIES
  PASS_REGULAR_EXPRESSION "1e-04,[0-9e.-]+,[0-9e.-]+,1\\.47[0-9e.-]+,1\\.8232003[0-9e.-]*,1\\.5707963")
add_test(NAME cli.icor.rectangle_bad_aspect_fails
         COMMAND $<TARGET_FILE:nanopush> icor rectangle --aspect 2)
set_tests_properties(cli.icor.rectangle_bad_aspect_fails PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.icor.rectangle_bad_aspect_message
         COMMAND $<TARGET_FILE:nanopush> icor rectangle --aspect 2)
set_tests_properties(cli.icor.rectangle_bad_aspect_message PROPERTIES
  PASS_REGULAR_EXPRESSION "--aspect = 2: must be in \\[1e-06, 1\\]")
