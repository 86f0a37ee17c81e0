# Helpers that give every core module the same shape: one shared library `vdc_<module>` built from
# src/<module>/, its public headers in include/view_direction_classification/<module>/, its tests
# in test/<module>/ (one gtest binary `vdc_<module>_tests`).

set(VDC_WARNINGS -Wall -Wextra -Wpedantic -Wno-deprecated-copy)

# Libraries a core module must never link: the core runs without ROS (test/common checks the
# includes, this the link interface).
set(VDC_ROS_LIBRARY_PATTERN "roscpp|rosconsole|roslib|tf2|catkin|message_runtime|nodelet|pcl_ros")

# vdc_add_module(<module> SOURCES <files...> [DEPENDS <public deps...>] [PRIVATE_DEPENDS <...>])
# DEPENDS are what the module's headers need (and so its users); PRIVATE_DEPENDS what only its
# sources need.
function(vdc_add_module module)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  set(target vdc_${module})
  add_library(${target} SHARED ${ARG_SOURCES})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>)
  target_compile_options(${target} PRIVATE ${VDC_WARNINGS})
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  # A module links everything it uses: an undeclared dependency fails here, not in its users.
  # Not in sanitizer builds: clang links the sanitizer runtimes into executables only, so a
  # library's references to them are undefined until then (the ordinary build checks).
  if(NOT VDC_SANITIZE)
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
  foreach(dependency IN LISTS ARG_DEPENDS ARG_PRIVATE_DEPENDS)
    if(dependency MATCHES "${VDC_ROS_LIBRARY_PATTERN}")
      message(FATAL_ERROR "${target} is core and must not link ROS, but links ${dependency}")
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY VDC_CORE_LIBRARIES ${target})
endfunction()

# vdc_add_module_tests(<module> SOURCES <files...> [NAME <binary>] [LINKS <extra libraries...>])
# One gtest binary for a module's tests, run from the source tree; test/ is on the include path
# for the shared helpers in test/support/.
function(vdc_add_module_tests module)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LINKS" ${ARGN})
  set(name vdc_${module}_tests)
  if(ARG_NAME)
    set(name ${ARG_NAME})
  endif()
  catkin_add_gtest(${name} ${ARG_SOURCES} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  if(NOT TARGET ${name})
    return()
  endif()
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/test)
  target_compile_options(${name} PRIVATE ${VDC_WARNINGS})
  target_compile_definitions(${name} PRIVATE
    VDC_SOURCE_DIR="${PROJECT_SOURCE_DIR}" VDC_BINARY_DIR="${PROJECT_BINARY_DIR}")
  # catkin links gtest itself but not its main().
  target_link_libraries(${name} vdc_${module} ${ARG_LINKS} OpenMP::OpenMP_CXX GTest::gtest_main)
endfunction()
