# nanopush presets: the preset scenes, sorted, with the names `nanopush run` accepts and their
# one-line descriptions (the first comment line of each TOML file).
set(_np $<TARGET_FILE:nanopush>)
add_test(NAME cli.presets.help COMMAND ${_np} presets --help)
set_tests_properties(cli.presets.help PROPERTIES
  PASS_REGULAR_EXPRESSION "List the preset scenes, sorted.*first comment line")
# Listed from NANOPUSH_SCENES: header, then thesis/fig3_6a with its short name and description,
# in sorted order (fig3_6a before fig3_6b; bench/ before examples/ before thesis/).
add_test(NAME cli.presets.list COMMAND ${_np} presets)
set_tests_properties(cli.presets.list PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
  PASS_REGULAR_EXPRESSION "preset scenes in [^\n]*\nname +short +description\nbench/stick_mu015 +stick_mu015 +Work-precision scene[^\n]*\nexamples/nanobar_humid_air +nanobar_humid_air +The thesis nanobar[^\n]*\n.*thesis/fig3_6a +fig3_6a +Thesis Fig 3.6 \\(a\\): nanobar on a smooth surface[^\n]*\nthesis/fig3_6b +fig3_6b ")
# Without NANOPUSH_SCENES, the build tree finds its source tree's presets (no path compiled in).
add_test(NAME cli.presets.build_tree COMMAND ${CMAKE_COMMAND} -E env --unset=NANOPUSH_SCENES ${_np} presets)
set_tests_properties(cli.presets.build_tree PROPERTIES
  PASS_REGULAR_EXPRESSION "[0-9]+ preset scenes in ${PROJECT_SOURCE_DIR}/drivers/scenes\n")
# A missing preset directory: an input error naming it.
add_test(NAME cli.presets.missing_dir COMMAND ${CMAKE_COMMAND} -E env NANOPUSH_SCENES=${CMAKE_CURRENT_BINARY_DIR}/no_such_dir ${_np} presets)
set_tests_properties(cli.presets.missing_dir PROPERTIES
  PASS_REGULAR_EXPRESSION "no_such_dir: no such directory")
