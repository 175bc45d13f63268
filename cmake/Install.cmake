# install() rules and a CMake package so a host engine can find_package(caustics).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY rhi/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Every library's public include folder; all headers live under include/caustics/ so none collides
# with a host engine's own rhi/, scene/ or common/ headers. shaders/common is private (no public
# header includes it).
file(GLOB engineIncludeDirs LIST_DIRECTORIES true "${CMAKE_CURRENT_SOURCE_DIR}/engine/*/include")
foreach(dir ${engineIncludeDirs} "${CMAKE_CURRENT_SOURCE_DIR}/passes/include")
  if(IS_DIRECTORY "${dir}")
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endforeach()

get_property(causticsInstallTargets GLOBAL PROPERTY CAUSTICS_INSTALL_TARGETS)
# Exported as the in-tree aliases are spelled: caustics_passes -> caustics::passes.
foreach(target ${causticsInstallTargets})
  string(REGEX REPLACE "^caustics_" "" exportName "${target}")
  set_target_properties(${target} PROPERTIES EXPORT_NAME "${exportName}")
endforeach()
install(TARGETS ${causticsInstallTargets} EXPORT causticsTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT causticsTargets NAMESPACE caustics:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/caustics)
get_property(CAUSTICS_PACKAGE_NEEDS_DIRECTX_GUIDS GLOBAL PROPERTY CAUSTICS_PACKAGE_NEEDS_DIRECTX_GUIDS)
if(NOT CAUSTICS_PACKAGE_NEEDS_DIRECTX_GUIDS)
  set(CAUSTICS_PACKAGE_NEEDS_DIRECTX_GUIDS OFF)
endif()
configure_package_config_file(cmake/causticsConfig.cmake.in "${CMAKE_CURRENT_BINARY_DIR}/causticsConfig.cmake"
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/caustics)
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/causticsConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/causticsConfig.cmake" "${CMAKE_CURRENT_BINARY_DIR}/causticsConfigVersion.cmake"
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/caustics)
