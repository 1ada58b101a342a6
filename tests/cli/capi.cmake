# Tests of the C API (bindings/nanopush.h) and the Fortran module `nanopush` (issue 8).
# Sources in tests/capi/; one CTest per interop concern. (Defined here because tests/cli/*.cmake
# is the hook the test directory includes; the targets need nanopush_capi / nanopush_fortran.)
set(_capi_dir ${CMAKE_CURRENT_SOURCE_DIR}/capi)
set(_capi_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6c.toml)

# A C API test program from tests/capi/SOURCE: Fortran (.f90: `use nanopush`, its own module
# directory) or C (the C API and libm); further arguments are more libraries to link.
function(nanopush_capi_program target source)
  add_executable(${target} ${_capi_dir}/${source})
  if(source MATCHES "\\.f90$")
    target_link_libraries(${target} PRIVATE nanopush_fortran nanopush_warnings ${ARGN})
    set_target_properties(${target} PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/${target})
  else()
    target_link_libraries(${target} PRIVATE nanopush_capi nanopush_warnings m ${ARGN})
  endif()
endfunction()

# A Fortran program that calls the module without stat= and must error-stop: CTest NAME_message
# passes on the library's MESSAGE (and fails if the program reaches its end), NAME_exit on the
# nonzero exit status.
function(nanopush_capi_error_stop name target source message)
  nanopush_capi_program(${target} ${source})
  add_test(NAME ${name}_message COMMAND ${target})
  set_tests_properties(${name}_message PROPERTIES PASS_REGULAR_EXPRESSION "${message}"
                                                 FAIL_REGULAR_EXPRESSION "not reached")
  add_test(NAME ${name}_exit COMMAND ${target})
  set_tests_properties(${name}_exit PROPERTIES WILL_FAIL TRUE)
endfunction()

# A C API test program run as CTest NAME with ARGN as its arguments; it passes when its output
# matches PASS (the program's closing line).
function(nanopush_capi_test name target source pass)
  nanopush_capi_program(${target} ${source})
  add_test(NAME ${name} COMMAND ${target} ${ARGN})
  set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION "${pass}")
endfunction()

# Shared Fortran test problems (a module over `use nanopush`).
add_library(capi_test_problems STATIC ${_capi_dir}/problems.f90)
target_link_libraries(capi_test_problems PUBLIC nanopush_fortran PRIVATE nanopush_warnings)
set_target_properties(capi_test_problems PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_problems)
target_include_directories(capi_test_problems PUBLIC ${NANOPUSH_MODDIR}/capi_test_problems)

# C: handles, NULLs, truncation, query-then-copy, engines agree, C callback with udata.
nanopush_capi_program(capi_test_c test_capi.c)
add_test(NAME capi.c_api COMMAND capi_test_c ${_capi_scene})

# Fortran RHS through the C++ Bulirsch-Stoer vs the same problem through the F77 BSINT: 1e-12.
nanopush_capi_program(capi_test_rhs_vs_f77 test_fortran_rhs_vs_f77.f90 capi_test_problems nanopush_f77)
add_test(NAME capi.fortran_rhs_vs_f77 COMMAND capi_test_rhs_vs_f77)

# C++ errors reach the Fortran caller as stat + errmsg; nothing crashes.
nanopush_capi_program(capi_test_errors test_fortran_errors.f90 capi_test_problems)
add_test(NAME capi.fortran_errors COMMAND capi_test_errors)

# Without stat: error stop with the C++ message (message test + non-zero exit test).
nanopush_capi_error_stop(capi.fortran_error_stop capi_error_stop error_stop_without_stat.f90
                         "nanopush: nanopush_parse_scene: object.mass = -1: must be > 0 \\(kg\\)")

# Two pthreads integrating different problems through the Fortran API = sequential runs.
find_package(Threads REQUIRED)
add_executable(capi_test_threads ${_capi_dir}/test_threads.c ${_capi_dir}/threads_problem.f90)
target_link_libraries(capi_test_threads PRIVATE capi_test_problems Threads::Threads nanopush_warnings)
set_target_properties(capi_test_threads PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_threads
                                                   LINKER_LANGUAGE Fortran)
add_test(NAME capi.fortran_two_threads COMMAND capi_test_threads)

# No C++ exception crosses the C API: exceptions thrown inside come back as status + message.
nanopush_capi_program(capi_test_exceptions test_capi_exceptions.cpp)
add_test(NAME capi.exceptions_caught COMMAND capi_test_exceptions)

# Friction and iCOR: the C API equals the C++ library bit for bit, errors come back as status +
# message (capi.friction_icor_c); C and Fortran give the numbers of `nanopush icor formulas`,
# `nanopush icor roots` and `nanopush friction` (capi.friction_icor_cli).
nanopush_capi_program(capi_test_friction_icor test_capi_friction_icor.cpp nanopush_outputs)
add_test(NAME capi.friction_icor_c COMMAND capi_test_friction_icor)
nanopush_capi_program(capi_test_friction_icor_fortran test_fortran_friction_icor.f90)
add_test(NAME capi.friction_icor_cli
  COMMAND ${CMAKE_COMMAND} -DNANOPUSH=$<TARGET_FILE:nanopush> -DREF_EXE=$<TARGET_FILE:capi_test_friction_icor>
    -DFORTRAN_EXE=$<TARGET_FILE:capi_test_friction_icor_fortran> -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/capi_friction_icor
    -P ${_capi_dir}/run_friction_icor_cli.cmake)
set_tests_properties(capi.friction_icor_cli PROPERTIES PASS_REGULAR_EXPRESSION "friction/icor CLI comparison: all checks hold")

# Friction coefficient from measurements (nanopush_estimate_mu_from_force / _from_icor): the C API
# equals icor::estimate_mu_* bit for bit in capi.friction_icor_c above; the Fortran module gives
# the numbers of `nanopush icor estimate-mu --out` (capi.estimate_mu_cli) and, without stat,
# error-stops with the library's message (capi.fortran_estimate_mu_error_stop_*).
nanopush_capi_program(capi_test_estimate_mu_fortran test_fortran_estimate_mu.f90)
add_test(NAME capi.estimate_mu_cli
  COMMAND ${CMAKE_COMMAND} -DNANOPUSH=$<TARGET_FILE:nanopush> -DFORTRAN_EXE=$<TARGET_FILE:capi_test_estimate_mu_fortran>
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/capi_estimate_mu -P ${_capi_dir}/run_estimate_mu_cli.cmake)
set_tests_properties(capi.estimate_mu_cli PROPERTIES PASS_REGULAR_EXPRESSION "estimate-mu CLI comparison: all checks hold")
nanopush_capi_error_stop(capi.fortran_estimate_mu_error_stop capi_error_stop_estimate_mu error_stop_estimate_mu.f90
                         "nanopush: nanopush_estimate_mu_from_icor: R = 0: must be > 0 \\(m\\)")

# A rough-surface scene from Fortran, law chosen by the caller = `nanopush run --law` exactly.
nanopush_capi_program(capi_test_rough test_fortran_rough.f90)
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
nanopush_capi_test(capi.fortran_precision capi_test_precision test_fortran_precision.f90 "test_fortran_precision: all checks hold")

# Scene keys set through the C API and the Fortran module (issue: scenes from code).
set(_capi_rough_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_18.toml)
nanopush_capi_test(capi.c_scene_set capi_test_scene_set test_capi_scene_set.c "capi scene_set: all checks hold"
                   ${_capi_rough_scene})
nanopush_capi_test(capi.fortran_scene_set capi_test_fortran_scene_set test_fortran_scene_set.f90 "fortran scene_set: all checks hold"
                   ${_capi_rough_scene})

# Hardening of the C API (issue: hardening): CVODE's start checks, non-finite arguments, bounded
# counts, derived quantities, conflicts; the Fortran names of the new statuses.
nanopush_capi_test(capi.c_hardening capi_test_hardening test_capi_hardening.c "capi hardening: all checks hold"
                   ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6a.toml)

# The engine comparison (nanopush_compare = compare_engines) from C and from Fortran.
nanopush_capi_test(capi.compare_c capi_test_compare test_capi_compare.c "capi compare: ok" ${_capi_scene})
nanopush_capi_test(capi.compare_fortran capi_test_compare_fortran test_fortran_compare.f90 "fortran compare: ok"
                   ${_capi_scene})

# The error estimate, the accuracy asked for and the outcomes, from C and from Fortran.
set(_capi_rough ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_18.toml)
nanopush_capi_test(capi.accuracy_c capi_test_accuracy test_capi_accuracy.c "capi accuracy: ok" ${_capi_rough})
nanopush_capi_test(capi.accuracy_fortran capi_test_accuracy_fortran test_fortran_accuracy.f90 "fortran accuracy: ok"
                   ${_capi_rough})

# A preset scene by name (nanopush_scene_preset) from C and from Fortran: the file the command
# line's preset rule finds, from scenes_dir or $NANOPUSH_SCENES; what is missing is named.
nanopush_capi_test(capi.c_preset capi_test_preset test_capi_preset.c "capi preset: all checks hold"
                   ${PROJECT_SOURCE_DIR}/drivers/scenes)
nanopush_capi_test(capi.fortran_preset capi_test_fortran_preset test_fortran_preset.f90 "fortran preset: all checks hold"
                   ${PROJECT_SOURCE_DIR}/drivers/scenes)
target_link_libraries(capi_test_fortran_preset PRIVATE nanopush_test_support_f)  # module test_support (tests/CMakeLists.txt)
