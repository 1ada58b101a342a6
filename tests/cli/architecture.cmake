# The layers link only downward (docs/architecture.md): checked over every folder with code
# (cxx/, fortran/, fortran/bridge/, bindings/, python/src/, drivers/), and the check itself
# against a small tree holding one violation of each kind.
add_test(NAME architecture.layers COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/check_layers.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(architecture.layers PROPERTIES PASS_REGULAR_EXPRESSION "layers: ok")
add_test(NAME architecture.layers_selftest
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/check_layers_selftest.sh ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(architecture.layers_selftest PROPERTIES PASS_REGULAR_EXPRESSION "layers selftest: ok")
# Choices are types: no engine/method/law/kind compared as text outside scenes/choices.hpp.
add_test(NAME architecture.choices COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/check_choices.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(architecture.choices PROPERTIES PASS_REGULAR_EXPRESSION "choices: ok")
