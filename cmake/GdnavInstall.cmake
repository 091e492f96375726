# `cmake --install BUILD --prefix P` installs what an external member needs (docs/external.md): the gdnav program,
# the client library with the runtime, the generated IDL types and the public control/guidance models (static
# libraries), their headers under include/gdnav (client: include/gdnav/client), config/ and idl/ under share/gdnav,
# and the CMake package `gdnav` (find_package(gdnav CONFIG)).
include(CMakePackageConfigHelpers)
set(GDNAV_SHARE_DIR share/gdnav)
set(_gdnav_exported gdnav_client gdnav_runtime gdnav_core gdnav_msgs gdnav_control_model gdnav_guidance_model)
set_target_properties(gdnav_msgs PROPERTIES EXPORT_NAME msgs)
install(TARGETS ${_gdnav_exported} EXPORT gdnavTargets ARCHIVE DESTINATION lib)
install(TARGETS gdnav RUNTIME DESTINATION bin)
install(EXPORT gdnavTargets NAMESPACE gdnav:: DESTINATION lib/cmake/gdnav)
install(DIRECTORY common/ DESTINATION include/gdnav FILES_MATCHING PATTERN "*.hpp" PATTERN "client" EXCLUDE)
install(DIRECTORY common/client/include/ DESTINATION include)
install(DIRECTORY components/control/model/ DESTINATION include/gdnav/control/model FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY components/guidance/model/ DESTINATION include/gdnav/guidance/model FILES_MATCHING PATTERN "*.hpp")
get_target_property(_gdnav_gen gdnav_msgs GDNAV_GENERATED_DIR)
install(DIRECTORY ${_gdnav_gen}/ DESTINATION include/gdnav FILES_MATCHING PATTERN "*.h")
install(DIRECTORY config/ DESTINATION ${GDNAV_SHARE_DIR}/config)
install(FILES idl/gdnav.idl DESTINATION ${GDNAV_SHARE_DIR}/idl)
configure_package_config_file(cmake/gdnavConfig.cmake.in ${CMAKE_BINARY_DIR}/gdnavConfig.cmake
  INSTALL_DESTINATION lib/cmake/gdnav PATH_VARS GDNAV_SHARE_DIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/gdnavConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/gdnavConfig.cmake ${CMAKE_BINARY_DIR}/gdnavConfigVersion.cmake DESTINATION lib/cmake/gdnav)
