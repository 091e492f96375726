# `cmake --install BUILD --prefix P` installs what an external member needs (docs/external.md): the gdnav program,
# the client library with the layers it stands on (dds, framework, core, the IDL types and their message library)
# and the public control/guidance models (static libraries), their headers under include/gdnav (client:
# include/gdnav/client), config/ and idl/ under share/gdnav, and the CMake package `gdnav` (find_package(gdnav
# CONFIG)). The launcher, plans, PKI and file formats are not installed: a member never links them.
include(CMakePackageConfigHelpers)
set(GDNAV_SHARE_DIR share/gdnav)
set(_gdnav_exported gdnav_client gdnav_runtime gdnav_dds gdnav_framework gdnav_core gdnav_gnc gdnav_msgs
  gdnav_control_model gdnav_guidance_model)
set_target_properties(gdnav_msgs PROPERTIES EXPORT_NAME msgs)
install(TARGETS ${_gdnav_exported} EXPORT gdnavTargets ARCHIVE DESTINATION lib)
install(TARGETS gdnav RUNTIME DESTINATION bin)
install(EXPORT gdnavTargets NAMESPACE gdnav:: DESTINATION lib/cmake/gdnav)
install(DIRECTORY common/core/ DESTINATION include/gdnav FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY common/framework common/dds DESTINATION include/gdnav FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY idl/msgs DESTINATION include/gdnav FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY common/client/include/ DESTINATION include)
install(DIRECTORY components/control/model/ DESTINATION include/gdnav/control/model FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY components/guidance/model/ DESTINATION include/gdnav/guidance/model FILES_MATCHING PATTERN "*.hpp")
get_target_property(_gdnav_gen gdnav_msgs GDNAV_GENERATED_DIR)
install(DIRECTORY ${_gdnav_gen}/ DESTINATION include/gdnav FILES_MATCHING PATTERN "*.h")
install(DIRECTORY config/ DESTINATION ${GDNAV_SHARE_DIR}/config)
install(FILES idl/gdnav.idl DESTINATION ${GDNAV_SHARE_DIR}/idl)

# Headers at their paths of gdnav 0.1 (include/gdnav/runtime/...), each forwarding to where it lives now, so a member
# built against the old headers needs only a rebuild (docs/external.md, "Include paths").
set(_gdnav_moved_headers
  runtime/clock.hpp dds/clock/clock.hpp
  runtime/component.hpp framework/component.hpp
  runtime/dds_context.hpp dds/dds_context.hpp
  runtime/dds_host.hpp dds/host/dds_host.hpp
  runtime/direct_executor.hpp framework/direct_executor.hpp
  runtime/faults/fault_schedule.hpp framework/faults/fault_schedule.hpp
  runtime/faults/input_faults.hpp framework/faults/input_faults.hpp
  runtime/fields/field_table.hpp framework/fields/field_table.hpp
  runtime/graph.hpp framework/graph.hpp
  runtime/lateness.hpp framework/lateness.hpp
  runtime/lockstep.hpp framework/lockstep.hpp
  runtime/message_traits.hpp msgs/message_ops_impl.hpp
  runtime/messages.hpp msgs/messages.hpp
  runtime/mirror.hpp dds/host/mirror.hpp
  runtime/msg_eigen.hpp framework/msg_eigen.hpp
  runtime/process_priority.hpp dds/process/process_priority.hpp
  runtime/process_signals.hpp dds/process/process_signals.hpp
  runtime/registry.hpp framework/registry.hpp
  runtime/run_config.hpp framework/run_config.hpp
  runtime/scenario_generator.hpp framework/scenario_generator.hpp
  runtime/security/security.hpp dds/security/security.hpp
  runtime/status_filter.hpp dds/filters/status_filter.hpp
  runtime/stride_filter.hpp dds/filters/stride_filter.hpp
  runtime/topic_types.hpp framework/topic_types.hpp
  guidance/model/mission.hpp gnc/mission.hpp
  guidance/model/mission_yaml.hpp gnc/mission_yaml.hpp)
file(REMOVE_RECURSE ${CMAKE_BINARY_DIR}/compat_headers)  # only the forwarding headers of this list
while(_gdnav_moved_headers)
  list(POP_FRONT _gdnav_moved_headers _old _new)
  set(_fwd ${CMAKE_BINARY_DIR}/compat_headers/${_old})
  file(WRITE ${_fwd}.tmp "#pragma once\n// Moved to ${_new} (docs/external.md, \"Include paths\"): kept for members built against gdnav 0.1.\n#include \"${_new}\"\n")
  configure_file(${_fwd}.tmp ${_fwd} COPYONLY)
endwhile()
install(DIRECTORY ${CMAKE_BINARY_DIR}/compat_headers/ DESTINATION include/gdnav FILES_MATCHING PATTERN "*.hpp")

configure_package_config_file(cmake/gdnavConfig.cmake.in ${CMAKE_BINARY_DIR}/gdnavConfig.cmake
  INSTALL_DESTINATION lib/cmake/gdnav PATH_VARS GDNAV_SHARE_DIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/gdnavConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/gdnavConfig.cmake ${CMAKE_BINARY_DIR}/gdnavConfigVersion.cmake DESTINATION lib/cmake/gdnav)
