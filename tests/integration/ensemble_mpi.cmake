# `poinsot ensemble` on two MPI ranks against one process (tests/cli/test_cli_ensemble_mpi.py), when the
# command-line tool was built with MPI (POINSOT_MPI, apps/poinsot/CMakeLists.txt). OpenMPI refuses to run as
# root without --allow-run-as-root; --oversubscribe lets two ranks share fewer cores.
if(TARGET poinsot_cli AND POINSOT_HAVE_MPI)
  find_program(POINSOT_MPIEXEC NAMES mpirun mpiexec)
  if(POINSOT_MPIEXEC)
    add_test(NAME cli.ensemble_mpi
             COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider
                     ${PROJECT_SOURCE_DIR}/tests/cli/test_cli_ensemble_mpi.py)
    set_tests_properties(cli.ensemble_mpi PROPERTIES ENVIRONMENT
      "POINSOT_CLI=$<TARGET_FILE:poinsot_cli>;POINSOT_SOURCE_DIR=${PROJECT_SOURCE_DIR};POINSOT_MPIEXEC=${POINSOT_MPIEXEC}")
  endif()
endif()
