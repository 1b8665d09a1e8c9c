# The command-line tool's tests: pytest files in tests/cli/ run the built binary (path in POINSOT_CLI) and check
# its output, its files and its exit status. One CTest entry, cli.pytest.
if(TARGET poinsot_cli)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the poinsot module")
  endif()
  find_package(Python 3.11 REQUIRED COMPONENTS Interpreter)
  add_test(NAME cli.pytest
           COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${PROJECT_SOURCE_DIR}/tests/cli)
  set_tests_properties(cli.pytest PROPERTIES ENVIRONMENT
    "POINSOT_CLI=$<TARGET_FILE:poinsot_cli>;POINSOT_SOURCE_DIR=${PROJECT_SOURCE_DIR};PYTHONPATH=${CMAKE_BINARY_DIR}/python")
endif()
