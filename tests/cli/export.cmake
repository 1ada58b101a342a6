# The installed package works for other projects (issue 8): `cmake --install` into a fresh
# prefix, then configure/build/run the consumer project tests/export against it; its C++ and
# Fortran programs must print the same numbers as `nanopush run` for the same scene.
add_test(NAME export.consumer
  COMMAND ${CMAKE_COMMAND}
    -DBUILD_DIR=${PROJECT_BINARY_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/export
    -DCONSUMER_SOURCE=${PROJECT_SOURCE_DIR}/tests/export
    -DSCENE=${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6c.toml
    -DGENERATOR=${CMAKE_GENERATOR}
    -DMAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}
    -DC_COMPILER=${CMAKE_C_COMPILER}
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DFortran_COMPILER=${CMAKE_Fortran_COMPILER}
    -P ${PROJECT_SOURCE_DIR}/tests/export/run_export_test.cmake)
set_tests_properties(export.consumer PROPERTIES TIMEOUT 600
  PASS_REGULAR_EXPRESSION "export test: all checks hold")
