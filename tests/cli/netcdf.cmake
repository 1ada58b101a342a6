# NetCDF-4 tables (docs/data.md): the converter read back with the netCDF C library
# (tests/netcdf/test_netcdf_readback.cpp), and `sweep --out` choosing the format by extension
# (tests/cli/scripts/netcdf_checks.sh). The Python side: tests/python/test_netcdf.py (xarray).
find_package(netCDF CONFIG REQUIRED)  # the reader of the test (the writer loads it at run time)
add_executable(netcdf_readback ${CMAKE_CURRENT_SOURCE_DIR}/netcdf/test_netcdf_readback.cpp)
target_link_libraries(netcdf_readback PRIVATE nanopush_outputs netCDF::netcdf nanopush_warnings)
add_test(NAME cli.netcdf.readback COMMAND netcdf_readback ${CMAKE_CURRENT_BINARY_DIR}/netcdf/readback)
set_tests_properties(cli.netcdf.readback PROPERTIES PASS_REGULAR_EXPRESSION "netcdf readback: all checks hold")
add_test(NAME cli.netcdf.sweep_out
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/netcdf_checks.sh $<TARGET_FILE:nanopush>
                 ${CMAKE_CURRENT_BINARY_DIR}/netcdf/sweep_out)
set_tests_properties(cli.netcdf.sweep_out PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "netcdf check: ok")
# Every other command that writes a table file (bench --out, friction --bench-csv, fit
# --synthesize, icor estimate-mu --out) and `nanopush convert` for the directories of tables:
# each .nc compared with its CSV by `netcdf_readback --compare` (tests/cli/scripts/netcdf_commands.sh).
find_package(nlohmann_json 3 REQUIRED)
target_link_libraries(netcdf_readback PRIVATE nlohmann_json::nlohmann_json)
add_test(NAME cli.netcdf.commands
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/scripts/netcdf_commands.sh $<TARGET_FILE:nanopush>
                 $<TARGET_FILE:netcdf_readback> ${CMAKE_CURRENT_BINARY_DIR}/netcdf/commands)
set_tests_properties(cli.netcdf.commands PROPERTIES ENVIRONMENT "NANOPUSH_SCENES=${NANOPUSH_SCENES}"
                     PASS_REGULAR_EXPRESSION "netcdf commands: ok")
