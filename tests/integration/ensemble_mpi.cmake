# `poinsot ensemble` on two MPI ranks against one process (tests/cli/test_cli_ensemble_mpi.py), when the
# command-line tool was built with MPI (POINSOT_MPI, apps/poinsot/CMakeLists.txt). OpenMPI refuses to run as
# root without --allow-run-as-root; --oversubscribe lets two ranks share fewer cores.
if(TARGET poinsot_cli AND POINSOT_HAVE_MPI)
  find_program(POINSOT_MPIEXEC NAMES mpirun mpiexec)
  if(POINSOT_MPIEXEC)
    add_test(NAME cli.ensemble_mpi
             COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider
                     ${PROJECT_SOURCE_DIR}/tests/cli/test_cli_ensemble_mpi.py)
    set(_mpi_env "POINSOT_CLI=$<TARGET_FILE:poinsot_cli>;POINSOT_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
    list(APPEND _mpi_env "POINSOT_MPIEXEC=${POINSOT_MPIEXEC}")
    if(POINSOT_SANITIZE)
      # OpenMPI's run-time components (dlopen'ed, unloaded at MPI_Finalize) leak a few kB that LeakSanitizer
      # reports with no symbol to suppress them by; the leak check is off for this test only, the address
      # and undefined-behaviour checks stay on.
      list(APPEND _mpi_env "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1")
    endif()
    set_tests_properties(cli.ensemble_mpi PROPERTIES ENVIRONMENT "${_mpi_env}")
  endif()
endif()
