# gdnav_add_subdirectories(): adds every direct sub-folder that holds a CMakeLists.txt, in sorted order,
# so that each area (common/core/earth, components/nav_att, tests/unit/…) owns its own build file.
# GDNAV_SKIP_DIRS: folder names to leave out (a developer's partial build), empty by default.
set(GDNAV_SKIP_DIRS "" CACHE STRING "Sub-folder names to skip")
macro(gdnav_add_subdirectories)
  file(GLOB _gdnav_children LIST_DIRECTORIES true RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT _gdnav_children)
  foreach(_child ${_gdnav_children})
    if(_child IN_LIST GDNAV_SKIP_DIRS)
      message(STATUS "gdnav: skipping ${CMAKE_CURRENT_SOURCE_DIR}/${_child} (GDNAV_SKIP_DIRS)")
    elseif(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${_child} AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_child}/CMakeLists.txt)
      add_subdirectory(${_child})
    endif()
  endforeach()
endmacro()

# gdnav_test(<name> <sources...> LIBS <libs...>): one GoogleTest executable registered with CTest.
function(gdnav_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${T_SOURCES} ${T_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest_main)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS "${T_LABELS}")
endfunction()
