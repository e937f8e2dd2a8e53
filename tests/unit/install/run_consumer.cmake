# SPDX-License-Identifier: MIT
# cmake -P script: installs the library into a scratch prefix, checks the layout, then
# configures (no warnings allowed), builds (-O3, warnings as errors) and runs the consumer with
# find_package(ssam 0.4 COMPONENTS soft render_gl gl); then the raw-OpenGL and Vulkan examples the same way.
#   -DBUILD_DIR= -DPREFIX= -DCONSUMER_SOURCE= -DCONSUMER_BUILD= [-DEXAMPLE_SOURCE= -DEXAMPLE_BUILD=]
#   [-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=]
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})

# Headers only under include/ssam/ (the engine's nested in include/ssam/engine/), no ECS;
# libraries named for the package.
file(GLOB top_level RELATIVE ${PREFIX}/include ${PREFIX}/include/*)
if(NOT top_level STREQUAL "ssam")
  message(FATAL_ERROR "include/ holds '${top_level}', expected only 'ssam'")
endif()
foreach(required ssam/ssam.hpp ssam/version.hpp ssam/engine/core/error.hpp ssam/engine/render/backend.hpp
                 ssam/engine/render/soft/soft_backend.hpp ssam/engine/render/gl/gl_backend.hpp)
  if(NOT EXISTS ${PREFIX}/include/${required})
    message(FATAL_ERROR "include/${required} was not installed")
  endif()
endforeach()
if(EXISTS ${PREFIX}/include/ssam/engine/core/ecs)
  message(FATAL_ERROR "the ECS headers were installed; ssam's API does not use them")
endif()
file(GLOB_RECURSE archives RELATIVE ${PREFIX} ${PREFIX}/*.a)
foreach(archive IN LISTS archives)
  get_filename_component(name ${archive} NAME)
  if(NOT name MATCHES "^libssam")
    message(FATAL_ERROR "${archive}: an installed library not named for the package")
  endif()
endforeach()

file(REMOVE_RECURSE ${CONSUMER_BUILD})
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
    ${consumer_cmake_flags})
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD})
run(${CONSUMER_BUILD}/ssam_consumer)
if(NOT run_output MATCHES "soft: centre pixel[^\n]*: ok")
  message(FATAL_ERROR "the consumer did not check the soft backend's pixel:\n${run_output}")
endif()

# The raw-OpenGL examples, stand-alone against the same prefix (find_package(ssam) + ssam::gl);
# each run headless when a context can be made (77 = none here, which is fine for this test).
if(EXAMPLE_SOURCE)
  file(REMOVE_RECURSE ${EXAMPLE_BUILD})
  run(${CMAKE_COMMAND} -S ${EXAMPLE_SOURCE} -B ${EXAMPLE_BUILD} -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
    ${consumer_cmake_flags})
  expect_clean_configure("${run_output}")
  run(${CMAKE_COMMAND} --build ${EXAMPLE_BUILD})
  # The GL examples headless; the Vulkan examples (ssam::vk), built by the same project when the
  # package has the vk component, have no window to leave.
  foreach(example ssam_gl_embedding ssam_gl_host_shaders ssam_vk_embedding ssam_vk_host_shaders)
    set(flags --out ${EXAMPLE_BUILD}/${example}.png)
    if(example MATCHES "^ssam_gl_")
      list(PREPEND flags --headless)
    endif()
    execute_process(COMMAND ${EXAMPLE_BUILD}/${example} ${flags}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message("${out}")
    if(NOT rc EQUAL 0 AND NOT rc EQUAL 77)
      message(FATAL_ERROR "the installed-package example ${example} failed (${rc}):\n${err}")
    endif()
  endforeach()
endif()
