# install() rules and a CMake package so a host engine can find_package(caustics).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY rhi/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(dir engine/include passes/include)
  if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/${dir}")
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()

get_property(causticsInstallTargets GLOBAL PROPERTY CAUSTICS_INSTALL_TARGETS)
install(TARGETS ${causticsInstallTargets} EXPORT causticsTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT causticsTargets NAMESPACE caustics:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/caustics)
configure_package_config_file(cmake/causticsConfig.cmake.in "${CMAKE_CURRENT_BINARY_DIR}/causticsConfig.cmake"
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/caustics)
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/causticsConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/causticsConfig.cmake" "${CMAKE_CURRENT_BINARY_DIR}/causticsConfigVersion.cmake"
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/caustics)
