# nanopush bench-sweep (the sweep benchmark): the driver runs on a small grid and writes its
# CSV (with the documented columns and rows), sidecar and report. Structure only: no timing
# is ever asserted (a benchmark, not a timed test; docs/sweeps.md "Benchmark").
#
# This file is also the structure check itself, run as cmake -DDIR=<out> -P bench_sweep.cmake.
if(CMAKE_SCRIPT_MODE_FILE)
  if(NOT DIR)
    message(FATAL_ERROR "bench-sweep files: -DDIR=<output directory> is required")
  endif()
  foreach(_f sweep_bench.csv sweep_bench.schema.json report.md)
    if(NOT EXISTS "${DIR}/${_f}")
      message(FATAL_ERROR "bench-sweep files: ${DIR}/${_f} is missing")
    endif()
  endforeach()
  file(STRINGS "${DIR}/sweep_bench.csv" _lines)
  list(GET _lines 0 _header)
  set(_expected "mode,threads,ranks,workers,points,repeats,wall_s,wall_min_s,wall_max_s,points_per_s,efficiency,overhead,overhead_cpu,cpu_s,cpu_efficiency,launch_s,mpirun_wall_s,load_1min")
  if(NOT _header STREQUAL _expected)
    message(FATAL_ERROR "bench-sweep files: CSV header\n  ${_header}\nexpected\n  ${_expected}")
  endif()
  # --no-mpi, 2 points per axis: rows threads 1, threads 2 and direct, 8 points each.
  list(LENGTH _lines _n)
  if(NOT _n EQUAL 4)
    message(FATAL_ERROR "bench-sweep files: ${_n} lines in the CSV, expected a header and 3 rows")
  endif()
  foreach(_re "^threads,1,1,1,8,1,[^,]+,[^,]+,[^,]+,[^,]+,1,,,[^,]+,[^,]+,,,[^,]+$" "^threads,2,1,2,8,1,[^,]+,[^,]+,[^,]+,[^,]+,[^,]+,,,[^,]+,[^,]+,,,[^,]+$"
              "^direct,1,1,1,8,1,[^,]+,[^,]+,[^,]+,[^,]+,,[^,]+,[^,]+,[^,]+,1,,,[^,]+$")
    set(_found FALSE)
    foreach(_l IN LISTS _lines)
      if(_l MATCHES "${_re}")
        set(_found TRUE)
      endif()
    endforeach()
    if(NOT _found)
      message(FATAL_ERROR "bench-sweep files: no CSV row matches ${_re}")
    endif()
  endforeach()
  file(READ "${DIR}/report.md" _md)
  foreach(_re "sweep overhead \\(1 thread\\) <= 2 % \\| [0-9.-]+ % \\(CPU time: [0-9.-]+ %\\) \\| (met|\\*\\*NOT met\\*\\*) \\|"
              "parallel efficiency, 2 threads >= 0.90 \\| [0-9.]+ \\(CPU time: [0-9.]+\\) \\| (met|\\*\\*NOT met\\*\\*) \\|"
              "CPU efficiency \\(points' CPU / the run's CPU\\): 1 thread, 2 threads \\| [0-9.]+, [0-9.]+ \\|"
              "parallel efficiency, 2 MPI ranks >= 0.90 \\| n/a \\| MPI configurations skipped"
              "load average \\(1, 5, 15 min\\) [0-9.]+ [0-9.]+ [0-9.]+ at the start")
    if(NOT _md MATCHES "${_re}")
      message(FATAL_ERROR "bench-sweep files: report.md lacks ${_re}")
    endif()
  endforeach()
  message("bench-sweep files: ok")
  return()
endif()

set(_np $<TARGET_FILE:nanopush>)
set(_env "NANOPUSH_SCENES=${NANOPUSH_SCENES}")
set(_bs_dir ${CMAKE_CURRENT_BINARY_DIR}/bench-sweep)

add_test(NAME cli.bench_sweep.help COMMAND ${_np} bench-sweep --help)
set_tests_properties(cli.bench_sweep.help PROPERTIES
  PASS_REGULAR_EXPRESSION "--points-per-axis.*values per axis.*--no-mpi")

# 8 points, one repeat, no MPI: the run itself (it fails loudly when a configuration's table
# differs from the 1-thread table).
add_test(NAME cli.bench_sweep.quick COMMAND ${_np} bench-sweep --points-per-axis 2 --repeats 1 --no-mpi --quiet
         --out ${_bs_dir}/quick)
set_tests_properties(cli.bench_sweep.quick PROPERTIES ENVIRONMENT "${_env}" FIXTURES_SETUP bench_sweep_quick
  PASS_REGULAR_EXPRESSION "equals the 1-thread table byte for byte")

# The files and their structure: the CSV's header and rows, the sidecar, the report's targets.
add_test(NAME cli.bench_sweep.files COMMAND ${CMAKE_COMMAND} -DDIR=${_bs_dir}/quick
         -P ${CMAKE_CURRENT_LIST_FILE})
set_tests_properties(cli.bench_sweep.files PROPERTIES FIXTURES_REQUIRED bench_sweep_quick
  PASS_REGULAR_EXPRESSION "bench-sweep files: ok")
add_test(NAME cli.bench_sweep.sidecar COMMAND ${CMAKE_COMMAND} -DDIR=${_bs_dir}/quick -DSCENE=fig3_18
         -P ${CMAKE_CURRENT_LIST_DIR}/scripts/check_sidecars.cmake)
set_tests_properties(cli.bench_sweep.sidecar PROPERTIES FIXTURES_REQUIRED bench_sweep_quick)

add_test(NAME cli.bench_sweep.bad_repeats COMMAND ${_np} bench-sweep --repeats 0 --no-mpi --out ${_bs_dir}/bad)
set_tests_properties(cli.bench_sweep.bad_repeats PROPERTIES WILL_FAIL TRUE)
add_test(NAME cli.bench_sweep.bad_points COMMAND ${_np} bench-sweep --points-per-axis 1 --no-mpi --out ${_bs_dir}/bad)
set_tests_properties(cli.bench_sweep.bad_points PROPERTIES WILL_FAIL TRUE)
