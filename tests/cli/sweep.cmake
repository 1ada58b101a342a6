# nanopush sweep and --set (issue: many scenes at once). Each check compares whole tables
# byte for byte (tests/cli/scripts/sweep_checks.sh).
set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")
set(_sweep_sh ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/sweep_checks.sh)
set(_sweep_dir ${CMAKE_CURRENT_BINARY_DIR}/sweep)
foreach(_mode jobs shards resume twice failing tasks inputs)
  add_test(NAME cli.sweep.${_mode} COMMAND bash ${_sweep_sh} ${_mode} ${_np} ${_sweep_dir}/${_mode})
  set_tests_properties(cli.sweep.${_mode} PROPERTIES ENVIRONMENT "${_env}"
                       PASS_REGULAR_EXPRESSION "sweep check ${_mode}: ok")
endforeach()
add_test(NAME cli.set.edited_file COMMAND bash ${_sweep_sh} set ${_np} ${_sweep_dir}/set ""
                                          ${NANOPUSH_SCENES}/thesis/fig3_18.toml)
set_tests_properties(cli.set.edited_file PROPERTIES ENVIRONMENT "${_env}" PASS_REGULAR_EXPRESSION "sweep check set: ok")
if(NANOPUSH_MPI)
  # CI runs as root: Open MPI refuses that unless told it is intended.
  add_test(NAME cli.sweep.mpi COMMAND bash ${_sweep_sh} mpi ${_np} ${_sweep_dir}/mpi ${MPIEXEC_EXECUTABLE})
  set_tests_properties(cli.sweep.mpi PROPERTIES PASS_REGULAR_EXPRESSION "sweep check mpi: ok"
    ENVIRONMENT "${_env};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
  # A rank waiting for the others does not spin: its CPU over a wall interval is well below a core.
  add_test(NAME cli.sweep.mpi_idle COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/mpi_idle_check.sh ${_np}
           ${_sweep_dir}/mpi_idle ${MPIEXEC_EXECUTABLE})
  set_tests_properties(cli.sweep.mpi_idle PROPERTIES PASS_REGULAR_EXPRESSION "mpi idle check: ok"
    ENVIRONMENT "${_env};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1")
endif()

# --set: bad keys and values are refused with key, value and range (exit 2), nothing written.
add_test(NAME cli.set.unknown_key COMMAND ${_np} run fig3_6a --set surface.muu=0.1 --out -)
set_tests_properties(cli.set.unknown_key PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "surface.muu = 0.1: unknown scene key")
add_test(NAME cli.set.unused_key COMMAND ${_np} run fig3_6a --set surface.mu=0.1 --out -)
set_tests_properties(cli.set.unused_key PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "surface.mu = \\(present\\): only meaningful with surface.kind = \"rough\"")
add_test(NAME cli.set.out_of_range COMMAND ${_np} compare fig3_18 --set surface.mu=-0.1)
set_tests_properties(cli.set.out_of_range PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "surface.mu = -0.1: must be in \\[0, 10\\]")
add_test(NAME cli.set.not_a_number COMMAND ${_np} run fig3_18 --set surface.mu=abc --out -)
set_tests_properties(cli.set.not_a_number PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "surface.mu = abc: must be a number")
add_test(NAME cli.set.exit_status COMMAND ${_np} run fig3_18 --set surface.mu=abc --out -)
set_tests_properties(cli.set.exit_status PROPERTIES ENVIRONMENT "${_env}" WILL_FAIL TRUE)
add_test(NAME cli.sweep.bad_axis COMMAND ${_np} sweep fig3_18 --vary surface.mu=0.1:0.2)
set_tests_properties(cli.sweep.bad_axis PROPERTIES ENVIRONMENT "${_env}"
  PASS_REGULAR_EXPRESSION "a range is FROM:TO:N")
add_test(NAME cli.scene_keys COMMAND ${_np} scene-keys)
set_tests_properties(cli.scene_keys PROPERTIES PASS_REGULAR_EXPRESSION "surface.mu +number")

# A text value of --vary (a choice) that the scene refuses is bad input before any point runs
# (exit 2, the key and the value named, no table), not a sweep whose every row fails (issue 34).
add_test(NAME cli.sweep.bad_choice_value
         COMMAND ${_np} sweep fig3_18 --vary surface.law=thesis,coulmb --out ${CMAKE_CURRENT_BINARY_DIR}/bad_choice.csv)
set_tests_properties(cli.sweep.bad_choice_value PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
  PASS_REGULAR_EXPRESSION "nanopush: error: surface.law = \"coulmb\": must be one of: thesis, printed, coulomb")
add_test(NAME cli.sweep.bad_choice_value_exit
         COMMAND ${_np} sweep fig3_18 --vary surface.law=thesis,coulmb --out ${CMAKE_CURRENT_BINARY_DIR}/bad_choice.csv)
set_tests_properties(cli.sweep.bad_choice_value_exit PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}" WILL_FAIL TRUE)

# Sweeps in bounded memory and plans that cannot lie (tests/cli/scripts/sweep_stream_checks.sh):
# --points read by index, numeric --vary values checked first, shards and journals of another
# plan refused naming the difference, the peak RSS of a streamed 1e6-point sweep (a generous
# bound; the benchmark `nanopush bench-sweep-memory` measures memory against points).
set(_stream_sh ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/sweep_stream_checks.sh)
foreach(_mode points vary_range foreign rss)
  add_test(NAME cli.sweep.stream_${_mode} COMMAND bash ${_stream_sh} ${_mode} ${_np} ${_sweep_dir}/stream_${_mode}
                                                    "${Python3_EXECUTABLE}")
  set_tests_properties(cli.sweep.stream_${_mode} PROPERTIES ENVIRONMENT "${_env}"
                       PASS_REGULAR_EXPRESSION "sweep check ${_mode}: ok")
endforeach()
set_tests_properties(cli.sweep.stream_rss PROPERTIES TIMEOUT 600)
if(NANOPUSH_SANITIZE)
  # AddressSanitizer keeps up to 256 MB of freed blocks in quarantine (to catch use after free),
  # which a peak-RSS bound would count as the program's: measured with the quarantine off
  # (98 MB under ASan; 11 MB in the release build), every other check of ASan still on.
  set_tests_properties(cli.sweep.stream_rss PROPERTIES
                       ENVIRONMENT "${_env};ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:quarantine_size_mb=0")
endif()
# Grid values exactly as NumPy computes them (NumPy is the oracle; the script finds a Python
# with NumPy when the Python package's interpreter is not configured yet).
add_test(NAME cli.sweep.linspace_numpy COMMAND bash ${_stream_sh} linspace ${_np} ${_sweep_dir}/linspace
                                               "${Python3_EXECUTABLE}")
set_tests_properties(cli.sweep.linspace_numpy PROPERTIES ENVIRONMENT "${_env}" LABELS numeric
                     PASS_REGULAR_EXPRESSION "sweep check linspace: ok")
