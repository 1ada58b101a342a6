# Versioned shared libraries: libnanopush_X.so -> libnanopush_X.so.<major.minor> (the SONAME,
# what executables record) -> libnanopush_X.so.<version>. The SONAME changes with the minor
# version, as the package's compatibility does (nanopushConfigVersion: SameMinorVersion).
# Every nanopush_* library of the build (_nanopush_compiled_targets: cmake/ObjectReuse.cmake);
# static libraries ignore the properties.
_nanopush_compiled_targets(${PROJECT_SOURCE_DIR} _np_libraries)
foreach(_t IN LISTS _np_libraries)
  get_target_property(_type ${_t} TYPE)
  if(_t MATCHES "^nanopush_" AND _type MATCHES "^(SHARED|STATIC)_LIBRARY$")
    set_target_properties(${_t} PROPERTIES VERSION ${PROJECT_VERSION}
                          SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  endif()
endforeach()
