# Tests of the C API (bindings/nanopush.h) and the Fortran module `nanopush` (issue 8).
# Sources in tests/capi/; one CTest per interop concern. (Defined here because tests/cli/*.cmake
# is the hook the test directory includes; the targets need nanopush_capi / nanopush_fortran.)
set(_capi_dir ${CMAKE_CURRENT_SOURCE_DIR}/capi)
set(_capi_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6c.toml)

# Shared Fortran test problems (a module over `use nanopush`).
add_library(capi_test_problems STATIC ${_capi_dir}/problems.f90)
target_link_libraries(capi_test_problems PUBLIC nanopush_fortran PRIVATE nanopush_warnings)
set_target_properties(capi_test_problems PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_problems)
target_include_directories(capi_test_problems PUBLIC ${NANOPUSH_MODDIR}/capi_test_problems)

# C: handles, NULLs, truncation, query-then-copy, engines agree, C callback with udata.
add_executable(capi_test_c ${_capi_dir}/test_capi.c)
target_link_libraries(capi_test_c PRIVATE nanopush_capi nanopush_warnings m)
add_test(NAME capi.c_api COMMAND capi_test_c ${_capi_scene})

# Fortran RHS through the C++ Bulirsch-Stoer vs the same problem through the F77 BSINT: 1e-12.
add_executable(capi_test_rhs_vs_f77 ${_capi_dir}/test_fortran_rhs_vs_f77.f90)
target_link_libraries(capi_test_rhs_vs_f77 PRIVATE capi_test_problems nanopush_f77 nanopush_warnings)
set_target_properties(capi_test_rhs_vs_f77 PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_rhs_vs_f77)
add_test(NAME capi.fortran_rhs_vs_f77 COMMAND capi_test_rhs_vs_f77)

# C++ errors reach the Fortran caller as stat + errmsg; nothing crashes.
add_executable(capi_test_errors ${_capi_dir}/test_fortran_errors.f90)
target_link_libraries(capi_test_errors PRIVATE capi_test_problems nanopush_warnings)
set_target_properties(capi_test_errors PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_errors)
add_test(NAME capi.fortran_errors COMMAND capi_test_errors)

# Without stat: error stop with the C++ message (message test + non-zero exit test).
add_executable(capi_error_stop ${_capi_dir}/error_stop_without_stat.f90)
target_link_libraries(capi_error_stop PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_error_stop PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_error_stop)
add_test(NAME capi.fortran_error_stop_message COMMAND capi_error_stop)
set_tests_properties(capi.fortran_error_stop_message PROPERTIES
  PASS_REGULAR_EXPRESSION "nanopush: nanopush_parse_scene: object.mass = -1: must be > 0 \\(kg\\)"
  FAIL_REGULAR_EXPRESSION "not reached")
add_test(NAME capi.fortran_error_stop_exit COMMAND capi_error_stop)
set_tests_properties(capi.fortran_error_stop_exit PROPERTIES WILL_FAIL TRUE)

# Two pthreads integrating different problems through the Fortran API = sequential runs.
find_package(Threads REQUIRED)
add_executable(capi_test_threads ${_capi_dir}/test_threads.c ${_capi_dir}/threads_problem.f90)
target_link_libraries(capi_test_threads PRIVATE capi_test_problems Threads::Threads nanopush_warnings)
set_target_properties(capi_test_threads PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_threads
                                                   LINKER_LANGUAGE Fortran)
add_test(NAME capi.fortran_two_threads COMMAND capi_test_threads)

# No C++ exception crosses the C API: exceptions thrown inside come back as status + message.
add_executable(capi_test_exceptions ${_capi_dir}/test_capi_exceptions.cpp)
target_link_libraries(capi_test_exceptions PRIVATE nanopush_capi nanopush_warnings)
add_test(NAME capi.exceptions_caught COMMAND capi_test_exceptions)

# Friction and iCOR: the C API equals the C++ library bit for bit, errors come back as status +
# message (capi.friction_icor_c); C and Fortran give the numbers of `nanopush icor formulas`,
# `nanopush icor roots` and `nanopush friction` (capi.friction_icor_cli).
add_executable(capi_test_friction_icor ${_capi_dir}/test_capi_friction_icor.cpp)
target_link_libraries(capi_test_friction_icor PRIVATE nanopush_capi nanopush_outputs nanopush_warnings)
add_test(NAME capi.friction_icor_c COMMAND capi_test_friction_icor)
add_executable(capi_test_friction_icor_fortran ${_capi_dir}/test_fortran_friction_icor.f90)
target_link_libraries(capi_test_friction_icor_fortran PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_friction_icor_fortran PROPERTIES
  Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_friction_icor_fortran)
add_test(NAME capi.friction_icor_cli
  COMMAND ${CMAKE_COMMAND} -DNANOPUSH=$<TARGET_FILE:nanopush> -DREF_EXE=$<TARGET_FILE:capi_test_friction_icor>
    -DFORTRAN_EXE=$<TARGET_FILE:capi_test_friction_icor_fortran> -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/capi_friction_icor
    -P ${_capi_dir}/run_friction_icor_cli.cmake)
set_tests_properties(capi.friction_icor_cli PROPERTIES PASS_REGULAR_EXPRESSION "friction/icor CLI comparison: all checks hold")

# Friction coefficient from measurements (nanopush_estimate_mu_from_force / _from_icor): the C API
# equals icor::estimate_mu_* bit for bit in capi.friction_icor_c above; the Fortran module gives
# the numbers of `nanopush icor estimate-mu --out` (capi.estimate_mu_cli) and, without stat,
# error-stops with the library's message (capi.fortran_estimate_mu_error_stop_*).
add_executable(capi_test_estimate_mu_fortran ${_capi_dir}/test_fortran_estimate_mu.f90)
target_link_libraries(capi_test_estimate_mu_fortran PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_estimate_mu_fortran PROPERTIES
  Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_estimate_mu_fortran)
add_test(NAME capi.estimate_mu_cli
  COMMAND ${CMAKE_COMMAND} -DNANOPUSH=$<TARGET_FILE:nanopush> -DFORTRAN_EXE=$<TARGET_FILE:capi_test_estimate_mu_fortran>
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/capi_estimate_mu -P ${_capi_dir}/run_estimate_mu_cli.cmake)
set_tests_properties(capi.estimate_mu_cli PROPERTIES PASS_REGULAR_EXPRESSION "estimate-mu CLI comparison: all checks hold")
add_executable(capi_error_stop_estimate_mu ${_capi_dir}/error_stop_estimate_mu.f90)
target_link_libraries(capi_error_stop_estimate_mu PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_error_stop_estimate_mu PROPERTIES
  Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_error_stop_estimate_mu)
add_test(NAME capi.fortran_estimate_mu_error_stop_message COMMAND capi_error_stop_estimate_mu)
set_tests_properties(capi.fortran_estimate_mu_error_stop_message PROPERTIES
  PASS_REGULAR_EXPRESSION "nanopush: nanopush_estimate_mu_from_icor: R = 0: must be > 0 \\(m\\)"
  FAIL_REGULAR_EXPRESSION "not reached")
add_test(NAME capi.fortran_estimate_mu_error_stop_exit COMMAND capi_error_stop_estimate_mu)
set_tests_properties(capi.fortran_estimate_mu_error_stop_exit PROPERTIES WILL_FAIL TRUE)

# A rough-surface scene from Fortran, law chosen by the caller = `nanopush run --law` exactly.
add_executable(capi_test_rough ${_capi_dir}/test_fortran_rough.f90)
target_link_libraries(capi_test_rough PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_rough PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_rough)
set(_rough_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_15.toml)
foreach(_law thesis coulomb)
  add_test(NAME capi.fortran_rough_${_law}_reference
    COMMAND nanopush run ${_rough_scene} --engine cxx --law ${_law} --quiet
      --out ${CMAKE_CURRENT_BINARY_DIR}/capi_rough_${_law}.csv)
  set_tests_properties(capi.fortran_rough_${_law}_reference PROPERTIES FIXTURES_SETUP capi_rough_${_law})
  add_test(NAME capi.fortran_rough_${_law}
    COMMAND capi_test_rough ${_rough_scene} ${_law} ${CMAKE_CURRENT_BINARY_DIR}/capi_rough_${_law}.csv)
  set_tests_properties(capi.fortran_rough_${_law} PROPERTIES FIXTURES_REQUIRED capi_rough_${_law}
    PASS_REGULAR_EXPRESSION "identical to nanopush run")
endforeach()

# Extended precision from Fortran: nanopush_run(..., precision=, state_ext=) in kind nanopush_qp.
add_executable(capi_test_precision ${_capi_dir}/test_fortran_precision.f90)
target_link_libraries(capi_test_precision PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_precision PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_precision)
add_test(NAME capi.fortran_precision COMMAND capi_test_precision)
set_tests_properties(capi.fortran_precision PROPERTIES PASS_REGULAR_EXPRESSION "test_fortran_precision: all checks hold")

# Scene keys set through the C API and the Fortran module (issue: scenes from code).
set(_capi_rough_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_18.toml)
add_executable(capi_test_scene_set ${_capi_dir}/test_capi_scene_set.c)
target_link_libraries(capi_test_scene_set PRIVATE nanopush_capi nanopush_warnings)
add_test(NAME capi.c_scene_set COMMAND capi_test_scene_set ${_capi_rough_scene})
set_tests_properties(capi.c_scene_set PROPERTIES PASS_REGULAR_EXPRESSION "capi scene_set: all checks hold")
add_executable(capi_test_fortran_scene_set ${_capi_dir}/test_fortran_scene_set.f90)
target_link_libraries(capi_test_fortran_scene_set PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_fortran_scene_set PROPERTIES
  Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_fortran_scene_set)
add_test(NAME capi.fortran_scene_set COMMAND capi_test_fortran_scene_set ${_capi_rough_scene})
set_tests_properties(capi.fortran_scene_set PROPERTIES PASS_REGULAR_EXPRESSION "fortran scene_set: all checks hold")

# Hardening of the C API (issue: hardening): CVODE's start checks, non-finite arguments, bounded
# counts, derived quantities, conflicts; the Fortran names of the new statuses.
add_executable(capi_test_hardening ${_capi_dir}/test_capi_hardening.c)
target_link_libraries(capi_test_hardening PRIVATE nanopush_capi nanopush_warnings m)
add_test(NAME capi.c_hardening COMMAND capi_test_hardening ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6a.toml)
set_tests_properties(capi.c_hardening PROPERTIES PASS_REGULAR_EXPRESSION "capi hardening: all checks hold")

# The engine comparison (nanopush_compare = compare_engines) from C and from Fortran.
add_executable(capi_test_compare ${_capi_dir}/test_capi_compare.c)
target_link_libraries(capi_test_compare PRIVATE nanopush_capi nanopush_warnings m)
add_test(NAME capi.compare_c COMMAND capi_test_compare ${_capi_scene})
set_tests_properties(capi.compare_c PROPERTIES PASS_REGULAR_EXPRESSION "capi compare: ok")
add_executable(capi_test_compare_fortran ${_capi_dir}/test_fortran_compare.f90)
target_link_libraries(capi_test_compare_fortran PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_compare_fortran PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_compare_fortran)
add_test(NAME capi.compare_fortran COMMAND capi_test_compare_fortran ${_capi_scene})
set_tests_properties(capi.compare_fortran PROPERTIES PASS_REGULAR_EXPRESSION "fortran compare: ok")

# The error estimate, the accuracy asked for and the outcomes, from C and from Fortran.
set(_capi_rough ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_18.toml)
add_executable(capi_test_accuracy ${_capi_dir}/test_capi_accuracy.c)
target_link_libraries(capi_test_accuracy PRIVATE nanopush_capi nanopush_warnings m)
add_test(NAME capi.accuracy_c COMMAND capi_test_accuracy ${_capi_rough})
set_tests_properties(capi.accuracy_c PROPERTIES PASS_REGULAR_EXPRESSION "capi accuracy: ok")
add_executable(capi_test_accuracy_fortran ${_capi_dir}/test_fortran_accuracy.f90)
target_link_libraries(capi_test_accuracy_fortran PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_accuracy_fortran PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_accuracy_fortran)
add_test(NAME capi.accuracy_fortran COMMAND capi_test_accuracy_fortran ${_capi_rough})
set_tests_properties(capi.accuracy_fortran PROPERTIES PASS_REGULAR_EXPRESSION "fortran accuracy: ok")
