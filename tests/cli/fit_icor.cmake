# nanopush fit-icor: quasi-static friction estimates in batch (issue 21 item 3). The data files
# are written here at configure time: four pushes of the thesis nanorod on the line-contact
# model with mu = 0.2 (F the minimum force, R of eq 4.13), so every equation gives 0.2.
set(_np $<TARGET_FILE:nanopush>)
set(_d ${CMAKE_CURRENT_BINARY_DIR}/fit_icor_data)
set(_rows
  "8.505610578323183e-07,1.7011221156646366e-08,5e-08,2e-9,2.492072860075436e-07,3e-9\n"
  "6.774012849226201e-07,1.3548025698452403e-08,1.2e-07,2e-9,1.9847291878588357e-07,3e-9\n"
  "5.33822956537572e-07,1.067645913075144e-08,2e-07,2e-9,1.5640566774393473e-07,3e-9\n"
  "4.325199148954151e-07,8.650398297908303e-09,2.8e-07,2e-9,1.2672472263190488e-07,3e-9\n")
string(REPLACE ";" "" _rows "${_rows}")
file(WRITE ${_d}/good.csv "# four pushes, SI\nF,sigma_F,yn,sigma_yn,R,sigma_R\n${_rows}")
file(WRITE ${_d}/yn_only.csv "F,yn\n8.505610578323183e-07,5e-08\n5.33822956537572e-07,2e-07\n")
file(WRITE ${_d}/R_only.csv "F,R\n8.505610578323183e-07,2.492072860075436e-07\n5.33822956537572e-07,1.5640566774393473e-07\n")
file(WRITE ${_d}/nan.csv "F,sigma_F,yn,sigma_yn\n1e-6,1e-8,1e-7,1e-9\n1e-6,1e-8,nan,1e-9\n")
file(WRITE ${_d}/sigma_zero.csv "F,sigma_F,yn,sigma_yn\n1e-6,1e-8,1e-7,1e-9\n1e-6,1e-8,1e-7,1e-9\n1e-6,0,1e-7,1e-9\n")
file(WRITE ${_d}/no_force.csv "yn,sigma_yn\n1e-7,1e-9\n2e-7,1e-9\n")
file(WRITE ${_d}/one_row.csv "F,sigma_F,yn,sigma_yn\n1e-6,1e-8,1e-7,1e-9\n")
file(WRITE ${_d}/typo.csv "F,sigma_F,yN,sigma_yn\n1e-6,1e-8,1e-7,1e-9\n1e-6,1e-8,1e-7,1e-9\n")
file(WRITE ${_d}/beyond.csv "F,sigma_F,yn,sigma_yn\n1e-6,1e-8,1e-7,1e-9\n1e-6,1e-8,4e-7,1e-9\n")
file(WRITE ${_d}/inconsistent.csv "F,R\n1e-6,1.5e-7\n1.3e-6,1.5e-7\n")

add_test(NAME cli.fit_icor.both COMMAND ${_np} fit-icor ${_d}/good.csv)
set_tests_properties(cli.fit_icor.both PROPERTIES PASS_REGULAR_EXPRESSION
  "known pressure \\(eq 4\\.10 x4\\): mu = 0\\.2 \\+- 0\\.00[0-9]+.*consistent.*unknown pressure \\(eq 4\\.11 x4\\): mu = 0\\.2 \\+- ")

add_test(NAME cli.fit_icor.yn_only_with_sigma_options
         COMMAND ${_np} fit-icor ${_d}/yn_only.csv --sigma F=1e-8 --sigma yn=2e-9 --pressure unknown)
set_tests_properties(cli.fit_icor.yn_only_with_sigma_options PROPERTIES PASS_REGULAR_EXPRESSION
  "unknown pressure \\(eq 4\\.8 x2\\): mu = 0\\.2 \\+- ")

# Outputs: table with sidecar, JSON summary (inside --out and at --json), plot when gnuplot exists.
set(_o ${CMAKE_CURRENT_BINARY_DIR}/fit_icor_out)
add_test(NAME cli.fit_icor.outputs_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_o})
set_tests_properties(cli.fit_icor.outputs_clean PROPERTIES FIXTURES_SETUP cli_fit_icor_clean)
add_test(NAME cli.fit_icor.outputs
         COMMAND ${_np} fit-icor ${_d}/good.csv --out ${_o} --json ${_o}/summary.json --hamaker-sigma 5e-20)
set_tests_properties(cli.fit_icor.outputs PROPERTIES FIXTURES_REQUIRED cli_fit_icor_clean
  FIXTURES_SETUP cli_fit_icor_out)
add_test(NAME cli.fit_icor.json COMMAND ${CMAKE_COMMAND} -E cat ${_o}/summary.json)
set_tests_properties(cli.fit_icor.json PROPERTIES FIXTURES_REQUIRED cli_fit_icor_out PASS_REGULAR_EXPRESSION
  "\"known\": {\n    \"mu\": {\n      \"value\": 0\\.(2|19999999999[0-9]*|2000000000[0-9]*),\n      \"stderr\": 0\\.0[0-9]+\n    },\n    \"stderr_statistical\": [^\n]*\n    \"stderr_systematic\": 0\\.0[0-9]+,.*\"chi2_dof\": [0-9.e-]+,.*\"unknown\": {\n    \"mu\": {\n      \"value\": ")
add_test(NAME cli.fit_icor.table COMMAND ${CMAKE_COMMAND} -E cat ${_o}/fit_icor.csv)
set_tests_properties(cli.fit_icor.table PROPERTIES FIXTURES_REQUIRED cli_fit_icor_out PASS_REGULAR_EXPRESSION
  "^row,line,F,sigma_F,yn,sigma_yn,R,sigma_R,mu_known,sigma_known,equation_known,weight_known,pull_known,mu_unknown,sigma_unknown,equation_unknown,weight_unknown,pull_unknown\n1,3,")
add_test(NAME cli.fit_icor.sidecar COMMAND ${CMAKE_COMMAND} -DDIR=${_o} -DMIN_FILES=1
         -P ${CMAKE_CURRENT_LIST_DIR}/scripts/check_sidecars.cmake)
set_tests_properties(cli.fit_icor.sidecar PROPERTIES FIXTURES_REQUIRED cli_fit_icor_out)

add_test(NAME cli.fit_icor.inconsistent_is_reported COMMAND ${_np} fit-icor ${_d}/inconsistent.csv
         --sigma F=1e-8 --sigma R=2e-9 --pressure known)
set_tests_properties(cli.fit_icor.inconsistent_is_reported PROPERTIES PASS_REGULAR_EXPRESSION
  "INCONSISTENT at alpha = 0\\.01; Birge-scaled stderr")

# Bad data: exit 2 (docs/errors.md), the message naming the row, the line and the column.
function(_fit_icor_bad name regex)
  add_test(NAME cli.fit_icor.bad_${name} COMMAND ${_np} ${ARGN})
  set_tests_properties(cli.fit_icor.bad_${name} PROPERTIES PASS_REGULAR_EXPRESSION "${regex}")
  add_test(NAME cli.fit_icor.bad_${name}_exit
           COMMAND sh -c [=["$0" "$@" >/dev/null 2>&1; test $? -eq 2]=] ${_np} ${ARGN})
endfunction()
_fit_icor_bad(nan "nan\\.csv: row 2 \\(line 3\\), column yn = nan: must be a finite number"
              fit-icor ${_d}/nan.csv)
_fit_icor_bad(sigma_zero "sigma_zero\\.csv: row 3 \\(line 4\\), column sigma_F = 0: must be > 0 \\(N\\)"
              fit-icor ${_d}/sigma_zero.csv)
_fit_icor_bad(missing_force "no_force\\.csv: column F = missing: the push force column F \\[N\\] is required"
              fit-icor ${_d}/no_force.csv)
_fit_icor_bad(missing_sigma "yn_only\\.csv: column sigma_F = missing: give the column or --sigma F=VALUE"
              fit-icor ${_d}/yn_only.csv)
_fit_icor_bad(too_few_rows "one_row\\.csv: rows = 1: need at least 2 observations"
              fit-icor ${_d}/one_row.csv)
_fit_icor_bad(unknown_column "typo\\.csv: column 3 = yN: must be one of F, yn, R"
              fit-icor ${_d}/typo.csv)
_fit_icor_bad(yn_beyond_rod "beyond\\.csv: row 2 \\(line 3\\): yn = 4e-07: must be in \\[0, 2\\.95e-07\\]"
              fit-icor ${_d}/beyond.csv)
_fit_icor_bad(unknown_needs_yn "R_only\\.csv: column yn = missing: the unknown pressure distribution"
              fit-icor ${_d}/R_only.csv --sigma F=1e-8 --sigma R=1e-9)
_fit_icor_bad(sigma_twice "--sigma F = 1e-08: contradicts the column sigma_F"
              fit-icor ${_d}/good.csv --sigma F=1e-8)
_fit_icor_bad(no_file "DATA = [^\n]*absent\\.csv: must be an existing regular file"
              fit-icor ${_d}/absent.csv)

# The same capability through the C API (bit for bit against the C++ library) and the Fortran
# module (against the one-observation estimates and the line-contact model).
add_executable(capi_test_fit_icor ${CMAKE_CURRENT_SOURCE_DIR}/capi/test_capi_fit_icor.cpp)
target_link_libraries(capi_test_fit_icor PRIVATE nanopush_capi nanopush_warnings)
add_test(NAME capi.fit_icor_c COMMAND capi_test_fit_icor)
set_tests_properties(capi.fit_icor_c PROPERTIES PASS_REGULAR_EXPRESSION "capi fit-icor: all checks hold")
add_executable(capi_test_fit_icor_fortran ${CMAKE_CURRENT_SOURCE_DIR}/capi/test_fortran_fit_icor.f90)
target_link_libraries(capi_test_fit_icor_fortran PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_fit_icor_fortran PROPERTIES
  Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_fit_icor_fortran)
add_test(NAME capi.fit_icor_fortran COMMAND capi_test_fit_icor_fortran)
set_tests_properties(capi.fit_icor_fortran PROPERTIES PASS_REGULAR_EXPRESSION "fortran fit-icor: all checks hold")

# The trajectory fit (`nanopush fit`, layer cxx/fitting) through the C API (bit for bit against
# nanopush::fit::fit_trajectory) and the Fortran module (noise-free data: the truth back).
set(_fit_scene ${PROJECT_SOURCE_DIR}/drivers/scenes/thesis/fig3_6a.toml)
add_executable(capi_test_fit ${CMAKE_CURRENT_SOURCE_DIR}/capi/test_capi_fit.cpp)
target_link_libraries(capi_test_fit PRIVATE nanopush_capi nanopush_fitting nanopush_warnings)
add_test(NAME capi.fit_c COMMAND capi_test_fit ${_fit_scene} ${CMAKE_CURRENT_BINARY_DIR}/capi_fit)
set_tests_properties(capi.fit_c PROPERTIES PASS_REGULAR_EXPRESSION "capi fit: all checks hold")
add_executable(capi_test_fit_fortran ${CMAKE_CURRENT_SOURCE_DIR}/capi/test_fortran_fit.f90)
target_link_libraries(capi_test_fit_fortran PRIVATE nanopush_fortran nanopush_warnings)
set_target_properties(capi_test_fit_fortran PROPERTIES Fortran_MODULE_DIRECTORY ${NANOPUSH_MODDIR}/capi_test_fit_fortran)
add_test(NAME capi.fit_fortran COMMAND capi_test_fit_fortran ${_fit_scene} ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(capi.fit_fortran PROPERTIES PASS_REGULAR_EXPRESSION "fortran fit: all checks hold")

# --format svg draws fit_icor.svg.
add_test(NAME cli.fit_icor.format_svg COMMAND ${_np} fit-icor ${_d}/good.csv --out ${_d}/svg --format svg)
set_tests_properties(cli.fit_icor.format_svg PROPERTIES FIXTURES_SETUP fit_icor_svg)
add_test(NAME cli.fit_icor.format_svg_written COMMAND ${CMAKE_COMMAND} -E cat ${_d}/svg/fit_icor.svg)
set_tests_properties(cli.fit_icor.format_svg_written PROPERTIES FIXTURES_REQUIRED fit_icor_svg PASS_REGULAR_EXPRESSION "<svg")
