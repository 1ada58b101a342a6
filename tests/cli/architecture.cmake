# The layers link only downward (docs/architecture.md): checked over every file under cxx/.
add_test(NAME architecture.layers COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/check_layers.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(architecture.layers PROPERTIES PASS_REGULAR_EXPRESSION "layers: ok")
