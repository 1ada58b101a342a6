# The Python package's tests (pytest, tests/python/test_*.py): one CTest per file, run by the
# interpreter the package was built for. The command line and the plain C++ friction loop
# are passed in by path, so the tests compare the package against them bit for bit: tier
# regression (tests/CMakeLists.txt).
set(_np_py_env
    "PYTHONPATH=${NANOPUSH_PYTHON_DIR}"
    "PYTHONDONTWRITEBYTECODE=1"
    "MPLBACKEND=Agg"
    "NANOPUSH_CLI=$<TARGET_FILE:nanopush>"
    "NANOPUSH_PY_FRICTION_LOOP=$<TARGET_FILE:nanopush_py_friction_loop>"
    "NANOPUSH_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
    "NANOPUSH_BUILD_DIR=${PROJECT_BINARY_DIR}"
    "NANOPUSH_CMAKE=${CMAKE_COMMAND}")
file(GLOB _np_py_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/test_*.py)
foreach(_t IN LISTS _np_py_tests)
  get_filename_component(_name ${_t} NAME_WE)
  string(REGEX REPLACE "^test_" "" _name ${_name})
  add_test(NAME python.${_name}
           COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${_t}
           WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
  set_tests_properties(python.${_name} PROPERTIES ENVIRONMENT "${_np_py_env}" LABELS "python;regression")
endforeach()
