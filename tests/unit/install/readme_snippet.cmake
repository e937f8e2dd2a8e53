# SPDX-License-Identifier: MIT
# cmake -P script: the README's embedding program (the ```cpp block that starts with
# "// leaves.cpp"), taken from README.md unchanged, built against an installed prefix twice,
# with find_package(ssam 0.4 COMPONENTS soft gl) (gl: the raw-OpenGL snippets) and with pkg-config, at -O3 with warnings as
# errors, and run. The raw-OpenGL snippets ("// host_foliage.cpp" in README.md,
# "// host_shaders.cpp" in ssam/README.md, "// loaders.cpp" in ssam/docs/gl_hosts.md: functions
# a host calls, no main) are compiled the same way against ssam::gl, and the Vulkan one
# ("// vk_host.cpp" in ssam/docs/vk_hosts.md) against ssam::vk. A README edit that breaks a
# snippet, or drops it, fails this test.
#   -DBUILD_DIR= -DPREFIX= -DREADME= -DSSAM_README= -DGL_HOSTS= -DVK_HOSTS= -DWORK= -DCXX= -DPKG_CONFIG=
#   [-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=]
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})
file(REMOVE_RECURSE ${WORK})

file(READ ${README} readme)
if(NOT readme MATCHES "```cpp\n(// leaves\\.cpp\n[^`]*)```")
  message(FATAL_ERROR "${README} has no ```cpp block starting with '// leaves.cpp'")
endif()
file(WRITE ${WORK}/src/leaves.cpp "${CMAKE_MATCH_1}")
# The raw-OpenGL snippets, each from its README.
foreach(pair "${README}:host_foliage" "${SSAM_README}:host_shaders" "${GL_HOSTS}:loaders" "${VK_HOSTS}:vk_host")
  string(REGEX MATCH "^(.*):([a-z_]+)$" _ "${pair}")
  set(snippet_readme ${CMAKE_MATCH_1})
  set(snippet ${CMAKE_MATCH_2})
  file(READ ${snippet_readme} text)
  if(NOT text MATCHES "```cpp\n(// ${snippet}\\.cpp\n[^`]*)```")
    message(FATAL_ERROR "${snippet_readme} has no ```cpp block starting with '// ${snippet}.cpp'")
  endif()
  file(WRITE ${WORK}/src/${snippet}.cpp "${CMAKE_MATCH_1}")
endforeach()
file(WRITE ${WORK}/src/CMakeLists.txt [=[
cmake_minimum_required(VERSION 3.25)
project(leaves CXX)
find_package(ssam 0.4 REQUIRED COMPONENTS soft gl vk)
add_executable(leaves leaves.cpp)
target_compile_options(leaves PRIVATE -Wall -Wextra -Werror)
target_link_libraries(leaves PRIVATE ssam::ssam ssam::render_soft)
# The raw-OpenGL snippets: compiled (they are functions a host calls), with the host's loader.
find_package(PkgConfig REQUIRED)
pkg_check_modules(HOST_EPOXY REQUIRED IMPORTED_TARGET epoxy)
add_library(raw_gl_snippets OBJECT host_foliage.cpp host_shaders.cpp loaders.cpp)
target_compile_options(raw_gl_snippets PRIVATE -Wall -Wextra -Werror)
target_link_libraries(raw_gl_snippets PRIVATE ssam::gl PkgConfig::HOST_EPOXY)
# The Vulkan snippet: compiled against ssam::vk (the host's own <vulkan/vulkan.h>).
add_library(vk_snippet OBJECT vk_host.cpp)
target_compile_options(vk_snippet PRIVATE -Wall -Wextra -Werror)
target_link_libraries(vk_snippet PRIVATE ssam::vk)
]=])

run(${CMAKE_COMMAND} -S ${WORK}/src -B ${WORK}/cmake-build -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
    ${consumer_cmake_flags})
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
run(${CXX} -std=c++20 -O3 -Wall -Wextra -Werror ${WORK}/src/leaves.cpp -o ${WORK}/leaves-pkg-config ${flags}
    ${consumer_compile_flags})
run(${WORK}/leaves-pkg-config)
if(NOT run_output MATCHES "centre: red")
  message(FATAL_ERROR "the README's program (pkg-config build) printed no centre pixel:\n${run_output}")
endif()
run(${PKG_CONFIG} --cflags ssam-gl epoxy)
separate_arguments(flags UNIX_COMMAND "${run_output}")
foreach(snippet host_foliage host_shaders loaders)
  run(${CXX} -std=c++17 -O3 -Wall -Wextra -Werror -c ${WORK}/src/${snippet}.cpp -o ${WORK}/${snippet}.o ${flags})
endforeach()
run(${PKG_CONFIG} --cflags ssam-vk)
separate_arguments(flags UNIX_COMMAND "${run_output}")
run(${CXX} -std=c++17 -O3 -Wall -Wextra -Werror -c ${WORK}/src/vk_host.cpp -o ${WORK}/vk_host.o ${flags})
