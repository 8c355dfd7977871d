# Installs the headers and an exported package, so that a consumer writes
#   find_package(cgal_policies) and target_link_libraries(app PRIVATE cgal_policies::cgal_policies).
include(CMakePackageConfigHelpers)

set(CGAL_POLICIES_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/cgal_policies")
install(TARGETS cgal_policies EXPORT cgal_policiesTargets)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/cgal_policies" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.h")
install(EXPORT cgal_policiesTargets NAMESPACE cgal_policies:: DESTINATION "${CGAL_POLICIES_CMAKE_DIR}")
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/cgal_policiesConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cgal_policiesConfig.cmake" INSTALL_DESTINATION "${CGAL_POLICIES_CMAKE_DIR}")
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cgal_policiesConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES "${PROJECT_BINARY_DIR}/cgal_policiesConfig.cmake"
              "${PROJECT_BINARY_DIR}/cgal_policiesConfigVersion.cmake"
        DESTINATION "${CGAL_POLICIES_CMAKE_DIR}")
