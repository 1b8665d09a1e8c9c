# The command-line tool's tests: pytest files in tests/cli/ run the built binary (path in POINSOT_CLI) and check
# its output, its files and its exit status. One CTest entry per file, cli.<file> (cli.test_cli_run, ...), so that
# `ctest -j` spreads them over the cores (under the sanitizers they take minutes together). The two-rank MPI file
# has its own entry, cli.ensemble_mpi (ensemble_mpi.cmake).
if(TARGET poinsot_cli)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the poinsot module")
  endif()
  find_package(Python 3.11 REQUIRED COMPONENTS Interpreter)
  file(GLOB _cli_tests CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/cli/test_*.py)
  list(FILTER _cli_tests EXCLUDE REGEX "/test_cli_ensemble_mpi\\.py$")
  foreach(f IN LISTS _cli_tests)
    get_filename_component(_name ${f} NAME_WE)
    add_test(NAME cli.${_name} COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${f})
    # COST: without timings of an earlier run (a fresh CI), ctest starts the costliest tests first; these take
    # seconds each (minutes under the sanitizers), the GoogleTest cases mostly milliseconds.
    set_tests_properties(cli.${_name} PROPERTIES COST 10 ENVIRONMENT
      "POINSOT_CLI=$<TARGET_FILE:poinsot_cli>;POINSOT_SOURCE_DIR=${PROJECT_SOURCE_DIR};PYTHONPATH=${CMAKE_BINARY_DIR}/python")
  endforeach()
endif()
