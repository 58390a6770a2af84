# mobility_add_pytests(): Python tests under pytest, for packages that find_package(mobility_testing).
#
# catkin 0.8.10 (Debian 12 and 13) declares Python tests for nose only, and Debian 13 has no
# nose: catkin_add_nosetests() then says "skipping nosetests" and the tests vanish from the
# results. pytest runs the same unittest classes (python3-pytest, Debian 12 and 13).

#
# Run one test file (or a folder of them) under pytest, as a catkin test: part of
# `run_tests`, a ctest entry `_ctest_<package>_pytests_<name>`, and a JUnit result
# `<CATKIN_TEST_RESULTS_DIR>/<package>/pytests-<name>.xml` that catkin_test_results reads
# (<name> is the path below the package with '/' turned to '.', as catkin names nosetests).
# Without pytest the test fails (catkin's run_tests.py reports the missing result): it is
# never skipped quietly.
#
# :param path: a test file or folder, relative to the calling CMakeLists.txt or absolute
# :param DEPENDENCIES: targets to build before the test runs
# :param WORKING_DIRECTORY: the folder the test runs in (default: the package's build folder)
#
function(mobility_add_pytests path)
  cmake_parse_arguments(_pytest "" "WORKING_DIRECTORY" "DEPENDENCIES" ${ARGN})
  if(_pytest_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "mobility_add_pytests(${path}): unknown arguments: ${_pytest_UNPARSED_ARGUMENTS}")
  endif()
  if(IS_ABSOLUTE "${path}")
    set(_pytest_path "${path}")
  else()
    set(_pytest_path "${CMAKE_CURRENT_SOURCE_DIR}/${path}")
  endif()
  if(NOT EXISTS "${_pytest_path}")
    message(FATAL_ERROR "mobility_add_pytests(${path}): no such file or folder in ${CMAKE_CURRENT_SOURCE_DIR}")
  endif()
  _mobility_find_pytest()

  file(RELATIVE_PATH _pytest_name "${PROJECT_SOURCE_DIR}" "${_pytest_path}")
  if(_pytest_name STREQUAL "")
    set(_pytest_name ".")
  endif()
  string(REPLACE "/" "." _pytest_name "${_pytest_name}")
  string(REPLACE ":" "." _pytest_name "${_pytest_name}")
  set(_pytest_results "${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}")
  get_filename_component(_pytest_results "${_pytest_results}" ABSOLUTE)
  set(_pytest_xml "pytests-${_pytest_name}.xml")

  # catkin's run_tests.py runs each COMMAND string through the shell, in turn. -ra lists
  # every skip with its reason in the test's output; no cache folder is left in the sources.
  set(_pytest_cmd
    "\"${CMAKE_COMMAND}\" -E make_directory \"${_pytest_results}\""
    "\"${PYTHON_EXECUTABLE}\" -m pytest -ra -p no:cacheprovider --junitxml=\"${_pytest_results}/${_pytest_xml}\" \"${_pytest_path}\"")
  catkin_run_tests_target("pytests" ${_pytest_name} ${_pytest_xml}
    COMMAND ${_pytest_cmd}
    DEPENDENCIES ${_pytest_DEPENDENCIES}
    WORKING_DIRECTORY ${_pytest_WORKING_DIRECTORY})
endfunction()

# Says once per configuration which pytest runs the tests, or that none was found.
function(_mobility_find_pytest)
  get_property(_pytest_checked GLOBAL PROPERTY MOBILITY_PYTEST_CHECKED)
  if(_pytest_checked)
    return()
  endif()
  set_property(GLOBAL PROPERTY MOBILITY_PYTEST_CHECKED TRUE)
  execute_process(COMMAND "${PYTHON_EXECUTABLE}" -c "import pytest; print(pytest.__version__)"
    RESULT_VARIABLE _pytest_status OUTPUT_VARIABLE _pytest_version
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(_pytest_status EQUAL 0)
    message(STATUS "Using pytest ${_pytest_version} (${PYTHON_EXECUTABLE} -m pytest)")
  else()
    message(WARNING "${PYTHON_EXECUTABLE} has no pytest module (Debian: python3-pytest): "
      "the Python tests will fail")
  endif()
endfunction()
