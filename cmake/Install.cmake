# Install and export (issue 8). After `cmake --install`, other projects use
#   find_package(nanopush CONFIG REQUIRED)
# and link nanopush::core (the C++ solver; also nanopush::numerics, ::models, ::scenes one by
# one), nanopush::engines (C++ and F77 engines), nanopush::outputs, nanopush::capi (C API,
# nanopush.h), nanopush::fortran (`use nanopush`), nanopush::f77 (FORTRAN 77 library) or
# nanopush::bridge (its bind(C) shims, f77_*.h). Layout under the prefix:
#   include/nanopush/<layer>/*.hpp, include/nanopush.h, include/nanopush/f77_*.h
#   include/nanopush/<CompilerID>-<version>/*.mod   (one compiler's .mod files never mix with another's)
#   lib/libnanopush_*.a (or .so with -DBUILD_SHARED_LIBS=ON), lib/cmake/nanopush/,
#   lib/pkgconfig/nanopush.pc (the C API for pkg-config),
#   bin/nanopush, bin/nanopush-mpi (with MPI), bin/nanobar, bin/nanobar_quad, share/nanopush/scenes/
# Nothing installed names the build or the source tree (cmake/Packaging.cmake): the prefix can
# be copied or moved.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
include(${CMAKE_CURRENT_LIST_DIR}/PkgConfig.cmake)

# Installed include directories (the build-tree ones are BUILD_INTERFACE in each CMakeLists.txt).
target_include_directories(nanopush_bridge PUBLIC
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/nanopush>
  $<INSTALL_INTERFACE:${NANOPUSH_INSTALL_MODDIR}>)
set_target_properties(nanopush_bridge PROPERTIES EXPORT_NAME bridge)
set_target_properties(nanopush_f77 PROPERTIES EXPORT_NAME f77)
# Linked PRIVATE by the static libraries, so it is exported as $<LINK_ONLY:...>: it gives
# consumers nothing (no flags), but CMake needs it in the export set.
set_target_properties(nanopush_warnings PROPERTIES EXPORT_NAME internal_warnings)

set(_nanopush_libraries nanopush_numerics nanopush_models nanopush_scenes nanopush_core
    nanopush_engines nanopush_outputs nanopush_bridge nanopush_f77 nanopush_capi nanopush_fortran nanopush_warnings)
# Libraries of newer layers, installed and exported when the tree has them (a shared `nanopush`
# linking a library that is not installed would not run from the prefix).
foreach(_t nanopush_sweeps nanopush_fitting nanopush_planning)
  if(TARGET ${_t})
    list(APPEND _nanopush_libraries ${_t})
  endif()
endforeach()
install(TARGETS ${_nanopush_libraries}
        EXPORT nanopushTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The command line and the legacy programs it runs (`nanopush legacy`: nanobar; the benchmark's
# rough-surface reference: nanobar_quad), found beside the running nanopush.
# nanopush-mpi (NANOPUSH_MPI): the same command line with MPI, for mpirun.
if(NANOPUSH_DRIVERS)
  install(TARGETS nanopush nanobar nanobar_quad RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  if(TARGET nanopush-mpi)
    install(TARGETS nanopush-mpi RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endif()

# outputs/json.hpp is the build's own (nlohmann-json), not part of the installed API.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cxx/include/nanopush DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "outputs/json.hpp" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/bindings/nanopush.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
file(GLOB _bridge_headers ${PROJECT_SOURCE_DIR}/fortran/bridge/f77_*.h)
install(FILES ${_bridge_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/nanopush)
install(DIRECTORY ${NANOPUSH_MODDIR}/nanopush/ ${NANOPUSH_MODDIR}/bridge/
        DESTINATION ${NANOPUSH_INSTALL_MODDIR} FILES_MATCHING PATTERN "*.mod")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/drivers/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/nanopush/scenes)

set(_cfgdir ${CMAKE_INSTALL_LIBDIR}/cmake/nanopush)
install(EXPORT nanopushTargets NAMESPACE nanopush:: DESTINATION ${_cfgdir})
set(NANOPUSH_WITH_SUNDIALS ${SUNDIALS_FOUND})
set(NANOPUSH_SHARED_LIBS ${BUILD_SHARED_LIBS})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/nanopushConfig.cmake.in
  ${PROJECT_BINARY_DIR}/nanopushConfig.cmake INSTALL_DESTINATION ${_cfgdir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/nanopushConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/nanopushConfig.cmake ${PROJECT_BINARY_DIR}/nanopushConfigVersion.cmake
        DESTINATION ${_cfgdir})
