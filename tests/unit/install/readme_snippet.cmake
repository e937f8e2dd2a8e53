# SPDX-License-Identifier: MIT
# cmake -P script: the README's embedding program (the ```cpp block that starts with
# "// leaves.cpp"), taken from README.md unchanged, built against an installed prefix twice,
# with find_package(ssam 0.2 COMPONENTS soft) and with pkg-config, at -O3 with warnings as
# errors, and run. A README edit that breaks the snippet, or drops it, fails this test.
#   -DBUILD_DIR= -DPREFIX= -DREADME= -DWORK= -DCXX= -DPKG_CONFIG=
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})
file(REMOVE_RECURSE ${WORK})

file(READ ${README} readme)
if(NOT readme MATCHES "```cpp\n(// leaves\\.cpp\n[^`]*)```")
  message(FATAL_ERROR "${README} has no ```cpp block starting with '// leaves.cpp'")
endif()
file(WRITE ${WORK}/src/leaves.cpp "${CMAKE_MATCH_1}")
file(WRITE ${WORK}/src/CMakeLists.txt [=[
cmake_minimum_required(VERSION 3.25)
project(leaves CXX)
find_package(ssam 0.2 REQUIRED COMPONENTS soft)
add_executable(leaves leaves.cpp)
target_compile_options(leaves PRIVATE -Wall -Wextra -Werror)
target_link_libraries(leaves PRIVATE ssam::ssam ssam::render_soft)
]=])

run(${CMAKE_COMMAND} -S ${WORK}/src -B ${WORK}/cmake-build -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release)
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${WORK}/cmake-build)
run(${WORK}/cmake-build/leaves)
if(NOT run_output MATCHES "centre: red")
  message(FATAL_ERROR "the README's program printed no centre pixel:\n${run_output}")
endif()

file(GLOB_RECURSE pc_files ${PREFIX}/ssam.pc)
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
run(${PKG_CONFIG} --static --cflags --libs ssam ssam-soft)
separate_arguments(flags UNIX_COMMAND "${run_output}")
run(${CXX} -std=c++20 -O3 -Wall -Wextra -Werror ${WORK}/src/leaves.cpp -o ${WORK}/leaves-pkg-config ${flags})
run(${WORK}/leaves-pkg-config)
if(NOT run_output MATCHES "centre: red")
  message(FATAL_ERROR "the README's program (pkg-config build) printed no centre pixel:\n${run_output}")
endif()
