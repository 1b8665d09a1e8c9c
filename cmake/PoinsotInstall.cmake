# Installation and export of poinsot::poinsot for find_package(poinsot).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS poinsot EXPORT poinsotTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/poinsot DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/generated/poinsot/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/poinsot)
install(EXPORT poinsotTargets NAMESPACE poinsot:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/poinsot)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/poinsotConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/poinsotConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/poinsot)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/poinsotConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/poinsotConfig.cmake ${PROJECT_BINARY_DIR}/poinsotConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/poinsot)
