# SPDX-License-Identifier: MIT
# cmake -P script: an engine's use of the package through one embedding component alone, in
# C++17: ssam::gl (a raw-OpenGL engine) or ssam::vk (a Vulkan engine). Its configure runs with
# every other package ssam's components use hidden (glm, Threads, oneTBB, pkg-config, Imath;
# pkg-config's search path empty, so libepoxy too; none is even looked for, so CMake's "not used
# by the project" note is silenced), then it builds (-Werror) and runs, and must print EXPECT;
# then the same program from `pkg-config --static ssam-COMPONENT` alone (plus ENGINE_LIBS, the
# engine's own libraries: -lvulkan for ssam::vk), as C++17.
#   -DCOMPONENT=gl|vk -DEXPECT= [-DENGINE_LIBS=] -DBUILD_DIR= -DPREFIX= -DCONSUMER_SOURCE=
#   -DCONSUMER_BUILD= -DOUT= -DCXX= -DPKG_CONFIG= [-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=]
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})
set(program ssam_${COMPONENT}_consumer)

file(REMOVE_RECURSE ${CONSUMER_BUILD})
run(${CMAKE_COMMAND} -E env PKG_CONFIG_LIBDIR= PKG_CONFIG_PATH=
    ${CMAKE_COMMAND} --no-warn-unused-cli -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -DCMAKE_PREFIX_PATH=${PREFIX}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON -DCMAKE_DISABLE_FIND_PACKAGE_Threads=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_Imath=ON ${consumer_cmake_flags})
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${CONSUMER_BUILD})
run(${CONSUMER_BUILD}/${program})
if(NOT run_output MATCHES "${EXPECT}")
  message(FATAL_ERROR "the ssam::${COMPONENT} consumer did not print '${EXPECT}':\n${run_output}")
endif()

# pkg-config: ssam-COMPONENT alone, with only the prefix's files to find.
file(GLOB_RECURSE pc_files ${PREFIX}/ssam-${COMPONENT}.pc)
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_LIBDIR} ${pc_dir})
set(ENV{PKG_CONFIG_PATH} "")
run(${PKG_CONFIG} --static --cflags --libs ssam-${COMPONENT})
separate_arguments(flags UNIX_COMMAND "${run_output}")
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
run(${CXX} -std=c++17 -O3 -Wall -Wextra -Wpedantic -Werror ${CONSUMER_SOURCE}/main.cpp -o ${OUT}/${program}
    ${flags} ${ENGINE_LIBS} ${consumer_compile_flags})
run(${OUT}/${program})
