# push.mode = tip (docs/tip.md) and `nanopush plan` (docs/planning.md) from the command line.
set(_np $<TARGET_FILE:nanopush>)
# The example scene runs: the tip's columns are in the CSV, the contact and release events in
# the summary, and the bar ends where the tip slipped off.
add_test(NAME cli.tip.run_example
         COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; mkdir -p \"$d\"; \"$0\" run tip_push_nanorod --out \"$d/t.csv\" 2> \"$d/err\"; \
head -1 \"$d/t.csv\" | grep -qx 't,x,y,theta,vx,vy,omega,fx,fy,mf,tip_x,tip_y,tip_fx,tip_fy,contact'; \
grep -q 'tip: contact at t = ' \"$d/err\"; grep -q 'tip: release at t = ' \"$d/err\"; \
test \"$(wc -l < \"$d/t.csv\")\" -eq 402; echo tip-run: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_tip_run)
set_tests_properties(cli.tip.run_example PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "tip-run: ok")
# Keys of the force push with push.mode = tip, the F77 engine and a tip inside the bar are bad
# input (exit 2), and nothing is written (the output is a path in a scratch directory).
add_test(NAME cli.tip.bad_input
         COMMAND bash -c "d=\"$1\"; rm -rf \"$d\"; mkdir -p \"$d\"; \
\"$0\" run tip_push_nanorod --set push.force=1e-6 --out \"$d/a.csv\"; a=$?; \
\"$0\" run tip_push_nanorod --engine f77 --out \"$d/b.csv\"; b=$?; \
\"$0\" run tip_push_nanorod --set tip.start_x=0 --out \"$d/c.csv\"; c=$?; \
n=$(ls -A \"$d\" | wc -l); echo \"codes $a $b $c files $n\"" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_tip_bad)
set_tests_properties(cli.tip.bad_input PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "codes 2 2 2 files 0")
# The dynamic tip model from the command line: it runs and says so (file name and summary);
# a negative stiffness, a zero speed, an unknown tip.model and a negative tip friction are bad
# input (exit 2) naming the key, and nothing is written; at the example's AFM speed the dynamic
# model cannot start a slide, and says so at once (exit 3) and points to the quasi-static model.
add_test(NAME cli.tip.dynamic
         COMMAND bash -c "d=\"$1\"; rm -rf \"$d\"; mkdir -p \"$d\"; cd \"$d\"; \
\"$0\" run tip_push_nanorod --set tip.model=dynamic --set tip.stiffness=10 --set tip.speed=1 --set solver.samples=51 --set solver.rtol=1e-8 --set solver.error_estimate=false 2> err; r=$?; \
test -s tip_push_nanorod.cxx-tip-dynamic.csv && grep -q 'cxx-tip-dynamic' err && w=yes || w=no; \
\"$0\" run tip_push_nanorod --set tip.model=dynamic --set tip.stiffness=-1 --out a.csv 2> e1; a=$?; grep -q 'tip.stiffness = -1' e1 || a=x; \
\"$0\" run tip_push_nanorod --set tip.model=dynamic --set tip.stiffness=1 --set tip.speed=0 --out b.csv 2> e2; b=$?; grep -q 'tip.speed' e2 || b=x; \
\"$0\" run tip_push_nanorod --set tip.model=fast --out c.csv 2> e3; c=$?; grep -q 'quasi_static, dynamic, auto' e3 || c=x; \
\"$0\" run tip_push_nanorod --set tip.model=dynamic --set tip.stiffness=1 --set tip.mu=-0.1 --out d.csv 2> e4; m=$?; grep -q 'tip.mu = -0.1' e4 || m=x; \
\"$0\" run tip_push_nanorod --set tip.model=dynamic --set tip.stiffness=10 --set tip.mu=0.3 --out f.csv 2> e5; f=$?; grep -q 'use tip.model = quasi_static or auto' e5 || f=x; \
n=$(ls -A | grep -c '^[abcdf].csv'); echo \"dynamic $r $w codes $a $b $c $m $f files $n\"" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_tip_dynamic)
set_tests_properties(cli.tip.dynamic PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "dynamic 0 yes codes 2 2 2 2 3 files 0")
# A plan for a seeded goal: found and verified, with its files; a goal out of reach in one push
# is not_found (exit 3) with the best plan written; a bad goal is exit 2 and writes nothing.
add_test(NAME cli.plan.found
         COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; \"$0\" plan tip_push_nanorod --goal 60e-9,40e-9,0.3 --tolerance 2e-9,0.02 \
--check 5 --noise x=0.2e-9,theta=0.001 --mu-range 0.05:0.2 --out \"$d\" 2> \"$d.err\"; grep -q 'found (verified)' \"$d.err\"; \
grep -q 'check: success ' \"$d.err\"; \
head -1 \"$d/check.csv\" | grep -qx 'point,trial,start_x,start_y,start_theta,mu,tip_mu,pushes_made,final_x,final_y,final_theta,final_distance,final_angle,success,status,message'; \
test -s \"$d/check.schema.json\"; grep -q '\"trials\": 5' \"$d/check.json\"; test ! -e \"$d/check.csv.journal\"; \
head -1 \"$d/plan.csv\" | grep -qx 'push,start_x,start_y,direction,speed,travel,x_end,y_end,theta_end'; \
test -s \"$d/plan.json\"; test -s \"$d/tip_path.csv\"; test -s \"$d/plan.png\"; test -s \"$d/plan.schema.json\"; \
echo plan: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_found)
set_tests_properties(cli.plan.found PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "plan: ok")
add_test(NAME cli.plan.not_found_and_bad_goal
         COMMAND bash -c "d=\"$1\"; rm -rf \"$d\" \"$d.bad\"; \"$0\" plan tip_push_nanorod --goal 2e-6,1e-6,1 --max-pushes 1 --out \"$d\" 2>/dev/null; a=$?; \
grep -q '\"status\": \"not_found\"' \"$d/plan.json\" && s=written || s=missing; \
\"$0\" plan tip_push_nanorod --goal 1e-9,nan --out \"$d.bad\" 2>/dev/null; b=$?; test -e \"$d.bad\" && w=yes || w=no; \
echo \"codes $a $b $s $w\"" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_nf)
set_tests_properties(cli.plan.not_found_and_bad_goal PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "codes 3 2 written no")
# A robust range with a negative end is bad input naming it (it read as "no range" and gave an
# unrelated message about --noise).
add_test(NAME cli.plan.robust_bad_range
         COMMAND ${_np} plan tip_push_nanorod --goal 2e-7,0,0 --robust --tip-mu-range=-0.1:0.1 --out ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_rb)
set_tests_properties(cli.plan.robust_bad_range PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "--tip-mu-range = -0.1:0.1: must be LO:HI with 0 <= LO <= HI")
# The closed loop: a truth with tip friction the model does not know, noisy images; reached.
add_test(NAME cli.plan.closed_loop
         COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; \"$0\" plan tip_push_nanorod --goal 60e-9,40e-9,0.3 --tolerance 3e-9,0.03 \
--closed-loop --truth tip.mu=0.3 --noise x=0.5e-9,theta=0.003 --seed 3 --out \"$d\" 2> \"$d.err\"; grep -q 'closed loop: reached' \"$d.err\"; \
head -1 \"$d/closed_loop.csv\" | grep -q '^step,seen_x,seen_y,seen_theta,true_x'; \
rc=0; \"$0\" plan tip_push_nanorod --goal 1e-8,0,0 --closed-loop --noise x=-1 --out \"$d.bad\" 2>/dev/null || rc=$?; \
test $rc -eq 2; echo closed-loop: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_cl)
set_tests_properties(cli.plan.closed_loop PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "closed-loop: ok")
# The planner from C and Fortran (bindings/nanopush.h nanopush_plan, the module's nanopush_plan):
# the C API's pushes equal the command line's plan.csv bit for bit.
set(_tip_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/examples/tip_push_nanorod.toml)
add_test(NAME cli.plan.for_capi
         COMMAND ${_np} plan ${_tip_scene} --goal 60e-9,40e-9,0.3 --tolerance 2e-9,0.02 --quiet
                 --out ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_capi)
set_tests_properties(cli.plan.for_capi PROPERTIES FIXTURES_SETUP plan_capi)
nanopush_capi_test(capi.plan_c capi_test_plan test_capi_plan.c "capi plan: all checks hold"
                   ${_tip_scene} ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_capi/plan.csv)
set_tests_properties(capi.plan_c PROPERTIES FIXTURES_REQUIRED plan_capi)
nanopush_capi_test(capi.plan_fortran capi_test_plan_fortran test_fortran_plan.f90 "[0-9]+ checks, 0 failures"
                   ${_tip_scene})
target_link_libraries(capi_test_plan_fortran PRIVATE nanopush_test_support_f)
# bench-plan on two tasks, open and closed loop and robust: its tables, report and figure are written.
add_test(NAME cli.bench.plan_quick
         COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; \"$0\" bench-plan --tasks 2 --closed-loop 2 --robust 2 --robust-trials 4 --max-pushes 10 \
--out \"$d\" > /dev/null 2> \"$d.err\"; grep -q '^| plan | ' \"$d/plan_benchmark.md\"; \
grep -q 'Closed loop.*after each push, reached [0-2]/2.*keeping the model.s tip friction, reached [0-2]/2' \"$d/plan_benchmark.md\"; test \"$(wc -l < \"$d/plan_closed_loop.csv\")\" -eq 3; \
head -1 \"$d/plan_closed_loop.csv\" | grep -qx 'task,bar,mu_truth,tip_mu_truth,tip_mu_fit,reached,pushes,reached_kept,pushes_kept,tip_travel,planning_time,final_distance,final_angle'; \
grep -q 'Robust plans.*the robust plan .*found [0-2]/2' \"$d/plan_benchmark.md\"; test \"$(wc -l < \"$d/plan_robust.csv\")\" -eq 3; \
test -s \"$d/plan_benchmark.csv\"; echo bench-plan: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_bench_plan)
set_tests_properties(cli.bench.plan_quick PROPERTIES PASS_REGULAR_EXPRESSION "bench-plan: ok")

# plan --check through the sweep engine: two threads, and two MPI ranks of nanopush-mpi, write
# the table of one thread byte for byte (each trial draws its world from its own stream).
if(NANOPUSH_MPI)
  add_test(NAME cli.plan.check_threads_mpi
           COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; mkdir -p \"$d\"; \
a=(plan tip_push_nanorod --goal 60e-9,40e-9,0.3 --tolerance 2e-9,0.02 --check 8 --noise x=1e-9,theta=0.01 --seed 5 --quiet); \
\"$0\" \"\${a[@]}\" --jobs 1 --out \"$d/one\"; \"$0\" \"\${a[@]}\" --jobs 2 --out \"$d/two\"; \
\"$2\" --oversubscribe -np 2 \"$(dirname \"$0\")/nanopush-mpi\" \"\${a[@]}\" --jobs 1 --out \"$d/mpi\"; \
cmp \"$d/one/check.csv\" \"$d/two/check.csv\"; cmp \"$d/one/check.csv\" \"$d/mpi/check.csv\"; \
cmp \"$d/one/check.json\" \"$d/mpi/check.json\"; cmp \"$d/one/plan.csv\" \"$d/mpi/plan.csv\"; \
grep -q '\"ranks\": 2' \"$d/mpi/check.schema.json\"; echo check: ok" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_plan_check ${MPIEXEC_EXECUTABLE})
  set_tests_properties(cli.plan.check_threads_mpi PROPERTIES PASS_REGULAR_EXPRESSION "check: ok"
    ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
endif()

# nanopush assemble: two nanorods into a two-slot pattern (each rod to the other's side):
# assembled (exit 0) with its tables; a pattern of another size, or an unknown column, is bad
# input (exit 2) and writes nothing.
add_test(NAME cli.assemble.two_rods
         COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; mkdir -p \"$d\"; cd \"$d\"; \
printf 'x,y,theta\\n0,0,0\\n100e-9,0,0\\n' > o.csv; printf 'x,y,theta\\n110e-9,20e-9,0.1\\n10e-9,20e-9,0.1\\n' > p.csv; \
printf 'x,y,theta\\n0,0,0\\n' > one.csv; printf 'x,y,phi\\n0,0,0\\n100e-9,0,0\\n' > bad.csv; \
\"$0\" assemble o.csv p.csv --tolerance 2e-9,0.02 --out a 2> err; grep -q 'assembled, 2 bars, 2 moved' err; \
head -1 a/assembly.csv | grep -qx 'bar,slot,push,start_x,start_y,direction,speed,travel,x_end,y_end,theta_end'; \
grep -q '\"status\": \"assembled\"' a/assembly.json; test -s a/assembly.png; test -s a/assembly.schema.json; \
rc1=0; \"$0\" assemble o.csv one.csv --out b 2> err1 || rc1=$?; \
rc2=0; \"$0\" assemble bad.csv p.csv --out c 2> err2 || rc2=$?; \
grep -q 'one slot per bar (2)' err1; grep -q 'phi: unknown column' err2; test ! -e b; test ! -e c; \
echo \"assemble: ok $rc1 $rc2\"" ${_np} ${CMAKE_CURRENT_BINARY_DIR}/cli_assemble)
set_tests_properties(cli.assemble.two_rods PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "assemble: ok 2 2")
# nanopush_assemble from C and Fortran: the module's wrapper over the C API gives the command's
# assembly.csv row for row.
add_test(NAME cli.assemble.for_capi
         COMMAND bash -c "set -e; d=\"$1\"; rm -rf \"$d\"; mkdir -p \"$d\"; \
printf 'x,y,theta\\n0,0,0\\n100e-9,0,0\\n' > \"$d/o.csv\"; printf 'x,y,theta\\n110e-9,20e-9,0.1\\n10e-9,20e-9,0.1\\n' > \"$d/p.csv\"; \
\"$0\" assemble \"$d/o.csv\" \"$d/p.csv\" --scene \"$2\" --tolerance 2e-9,0.02 --quiet --out \"$d/a\"" ${_np}
                 ${CMAKE_CURRENT_BINARY_DIR}/cli_assemble_capi ${_tip_scene})
set_tests_properties(cli.assemble.for_capi PROPERTIES FIXTURES_SETUP assemble_capi)
nanopush_capi_test(capi.assemble_fortran capi_test_assemble_fortran test_fortran_assemble.f90 "[0-9]+ checks, 0 failures"
                   ${_tip_scene} ${CMAKE_CURRENT_BINARY_DIR}/cli_assemble_capi/a/assembly.csv)
target_link_libraries(capi_test_assemble_fortran PRIVATE nanopush_test_support_f)
set_tests_properties(capi.assemble_fortran PROPERTIES FIXTURES_REQUIRED assemble_capi)
