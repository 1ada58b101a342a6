# nanopush forces: the term report, "model only what a scene requires", bad input.
set(_fs ${CMAKE_CURRENT_LIST_DIR}/scenes)

add_test(NAME cli.forces.default COMMAND $<TARGET_FILE:nanopush> forces)
set_tests_properties(cli.forces.default PROPERTIES
  PASS_REGULAR_EXPRESSION "contact_adhesion +JKR line[^\n]*evaluated")

add_test(NAME cli.forces.gravity_dropped COMMAND $<TARGET_FILE:nanopush> forces)
set_tests_properties(cli.forces.gravity_dropped PROPERTIES
  PASS_REGULAR_EXPRESSION "gravity +m g[^\n]*dropped")

add_test(NAME cli.forces.no_adhesion COMMAND $<TARGET_FILE:nanopush> forces --no-adhesion)
set_tests_properties(cli.forces.no_adhesion PROPERTIES
  PASS_REGULAR_EXPRESSION "models evaluated: Hertz \\(2.56-2.59\\) x1\n")

add_test(NAME cli.forces.scene COMMAND $<TARGET_FILE:nanopush> forces ${_fs}/forces_mwcnt_humid.toml
         --push 3e-6 --push-height 0 --mu 0.1)
set_tests_properties(cli.forces.scene PROPERTIES
  PASS_REGULAR_EXPRESSION "capillary +cylinder meniscus[^\n]*evaluated.*push F = 3e-06 N at h = 0 m, mu = 0.1: sliding")

add_test(NAME cli.forces.bad_humidity_message COMMAND $<TARGET_FILE:nanopush> forces ${_fs}/forces_bad_humidity.toml)
set_tests_properties(cli.forces.bad_humidity_message PROPERTIES
  PASS_REGULAR_EXPRESSION "environment.humidity = 1.5: must be in \\[0, 1\\]")
add_test(NAME cli.forces.bad_humidity_exit COMMAND $<TARGET_FILE:nanopush> forces ${_fs}/forces_bad_humidity.toml)
set_tests_properties(cli.forces.bad_humidity_exit PROPERTIES WILL_FAIL TRUE)

add_test(NAME cli.forces.bad_option_message COMMAND $<TARGET_FILE:nanopush> forces --shape sphere --radius -1e-9)
set_tests_properties(cli.forces.bad_option_message PROPERTIES
  PASS_REGULAR_EXPRESSION "--radius = -1e-09: must be > 0 \\(m\\)")
add_test(NAME cli.forces.bad_option_exit COMMAND $<TARGET_FILE:nanopush> forces --shape sphere --radius -1e-9)
set_tests_properties(cli.forces.bad_option_exit PROPERTIES WILL_FAIL TRUE)

add_test(NAME cli.forces.reproduce
         COMMAND $<TARGET_FILE:nanopush> reproduce --quick --only table3_1 --only fig3_3 --only fig3_4
                 --out ${CMAKE_CURRENT_BINARY_DIR}/cli_forces_reproduce)

add_test(NAME cli.forces.bar COMMAND $<TARGET_FILE:nanopush> forces --shape bar --length 100e-9 --width 55e-9
         --height 50e-9)
set_tests_properties(cli.forces.bar PROPERTIES
  PASS_REGULAR_EXPRESSION "van_der_waals +flat-flat[^\n]*evaluated.*contact half-width = 2.75e-08 m")

add_test(NAME cli.forces.liquid COMMAND $<TARGET_FILE:nanopush> forces --medium liquid --liquid water --no-drop)
set_tests_properties(cli.forces.liquid PROPERTIES
  PASS_REGULAR_EXPRESSION "buoyancy +-rho_liquid V g[^\n]*evaluated.*capillary[^\n]*not needed")

# docs/errata.md C3: the Fig 3.4 report states the width the thesis' "about 3 nm" needs.
set_tests_properties(cli.forces.reproduce PROPERTIES FIXTURES_SETUP cli_forces_reproduce)
add_test(NAME cli.forces.jkr_width_report
         COMMAND ${CMAKE_COMMAND} -E cat ${CMAKE_CURRENT_BINARY_DIR}/cli_forces_reproduce/report.md)
set_tests_properties(cli.forces.jkr_width_report PROPERTIES FIXTURES_REQUIRED cli_forces_reproduce
  PASS_REGULAR_EXPRESSION "half-width b = 4.77293e-09 m.*axial modulus E = 1 TPa,[^\n]*\n[^\n]*width of 2.69049e-09 m")
