# Optional dependencies of individual layers, included by src/CMakeLists.txt after the poinsot target exists.

# multibody (issue 8): scenario files are TOML, read with toml++ (header-only; a private dependency).
find_package(tomlplusplus REQUIRED)
target_link_libraries(poinsot PRIVATE tomlplusplus::tomlplusplus)
