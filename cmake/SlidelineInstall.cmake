include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
install(TARGETS slideline EXPORT slidelineTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/slideline DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT slidelineTargets NAMESPACE slideline:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/slideline)
configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/slidelineConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/slidelineConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/slideline)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/slidelineConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/slidelineConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/slidelineConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/slideline)
