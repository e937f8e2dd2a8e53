# SPDX-License-Identifier: MIT
# cmake -P script: a Vulkan engine's use of the package, ssam::vk alone, in C++17. Its configure
# runs with every other package ssam's components use hidden (glm, Threads, oneTBB, pkg-config,
# Imath; pkg-config's search path empty), then it builds (-Werror) and runs; then the same
# program from `pkg-config --static ssam-vk` alone (and the engine's own -lvulkan), as C++17.
#   -DBUILD_DIR= -DPREFIX= -DCONSUMER_SOURCE= -DCONSUMER_BUILD= -DOUT= -DCXX= -DPKG_CONFIG=
#   [-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=]
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})

file(REMOVE_RECURSE ${CONSUMER_BUILD})
run(${CMAKE_COMMAND} -E env PKG_CONFIG_LIBDIR= PKG_CONFIG_PATH=
    ${CMAKE_COMMAND} --no-warn-unused-cli -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -DCMAKE_PREFIX_PATH=${PREFIX}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON -DCMAKE_DISABLE_FIND_PACKAGE_Threads=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_Imath=ON ${consumer_cmake_flags})
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD})
run(${CONSUMER_BUILD}/ssam_vk_consumer)
if(NOT run_output MATCHES "initialize without a device: invalid argument")
  message(FATAL_ERROR "the ssam::vk consumer did not report the empty device description:\n${run_output}")
endif()

file(GLOB_RECURSE pc_files ${PREFIX}/ssam-vk.pc)
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_LIBDIR} ${pc_dir})
set(ENV{PKG_CONFIG_PATH} "")
run(${PKG_CONFIG} --static --cflags --libs ssam-vk)
separate_arguments(flags UNIX_COMMAND "${run_output}")
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
run(${CXX} -std=c++17 -O3 -Wall -Wextra -Wpedantic -Werror ${CONSUMER_SOURCE}/main.cpp -o ${OUT}/ssam_vk_consumer
    ${flags} -lvulkan ${consumer_compile_flags})
run(${OUT}/ssam_vk_consumer)
