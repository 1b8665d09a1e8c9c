# The viewer's tests: pytest files in tests/viewer/ run the built poinsot binary (POINSOT_CLI) on every example
# with --html and load each page in a headless Chromium (Debian's chromium, chromium-driver, python3-selenium);
# docs/viewer.md. One CTest entry, viewer.pytest. Under the sanitizers only the command-line tests run (they
# drive the C++ page writer, which is what the sanitizers watch; the browser tests check the page's JavaScript
# and take most of a minute of the CI's budget).
if(TARGET poinsot_cli)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the poinsot module")
  endif()
  find_package(Python 3.11 REQUIRED COMPONENTS Interpreter)
  set(_viewer_tests ${PROJECT_SOURCE_DIR}/tests/viewer)
  if(POINSOT_SANITIZE)
    set(_viewer_tests ${PROJECT_SOURCE_DIR}/tests/viewer/test_view_cli.py)
  endif()
  add_test(NAME viewer.pytest COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${_viewer_tests})
  set_tests_properties(viewer.pytest PROPERTIES COST 100 ENVIRONMENT  # the longest: first (cli.cmake)
    "POINSOT_CLI=$<TARGET_FILE:poinsot_cli>;POINSOT_SOURCE_DIR=${PROJECT_SOURCE_DIR};PYTHONPATH=${CMAKE_BINARY_DIR}/python")
endif()
