# Installs the headers and an exported package, so that a consumer writes
#   find_package(cgal_policies) and target_link_libraries(app PRIVATE cgal_policies::cgal_policies),
# and, when the apps are built, the io library (find_package(cgal_policies COMPONENTS io),
# cgal_policies::io; headers under <cgal_policies/io/>).
include(CMakePackageConfigHelpers)

set(CGAL_POLICIES_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/cgal_policies")
install(TARGETS cgal_policies EXPORT cgal_policiesTargets)
set(CGAL_POLICIES_HAS_IO FALSE)
if(TARGET cgal_policies_io)
  set(CGAL_POLICIES_HAS_IO TRUE)
  install(TARGETS cgal_policies_io EXPORT cgal_policiesTargets
          ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/apps/io/"
          DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/cgal_policies/io" FILES_MATCHING PATTERN "*.h")
endif()
install(DIRECTORY "${PROJECT_SOURCE_DIR}/cgal_policies" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.h")
install(EXPORT cgal_policiesTargets NAMESPACE cgal_policies:: DESTINATION "${CGAL_POLICIES_CMAKE_DIR}")
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/cgal_policiesConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cgal_policiesConfig.cmake" INSTALL_DESTINATION "${CGAL_POLICIES_CMAKE_DIR}")
# Header-only, the package fits any architecture; the io library ties it to this one.
set(CGAL_POLICIES_ARCH_INDEPENDENT ARCH_INDEPENDENT)
if(CGAL_POLICIES_HAS_IO)
  set(CGAL_POLICIES_ARCH_INDEPENDENT "")
endif()
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cgal_policiesConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion ${CGAL_POLICIES_ARCH_INDEPENDENT})
install(FILES "${PROJECT_BINARY_DIR}/cgal_policiesConfig.cmake"
              "${PROJECT_BINARY_DIR}/cgal_policiesConfigVersion.cmake"
        DESTINATION "${CGAL_POLICIES_CMAKE_DIR}")
