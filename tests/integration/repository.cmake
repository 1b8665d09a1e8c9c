# Checks of the repository itself, not of a build: the layering rules of docs/architecture.md read from the
# #include lines (scripts/check_layers.py). Registered in the release tree only: the sources are the same in
# every tree.
if(NOT POINSOT_SANITIZE)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter for the poinsot module")
  endif()
  find_package(Python 3.11 REQUIRED COMPONENTS Interpreter)
  add_test(NAME repository.layers COMMAND ${Python_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check_layers.py
                                          --root ${PROJECT_SOURCE_DIR})
endif()
