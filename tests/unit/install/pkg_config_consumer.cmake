# SPDX-License-Identifier: MIT
# cmake -P script: the consumer built without CMake, from `pkg-config ssam ssam-soft ssam-render-gl ssam-gl`
# against an installed prefix, at -O3 with warnings as errors, then run.
#   -DBUILD_DIR= -DPREFIX= -DCONSUMER_SOURCE= -DOUT= -DCXX= -DPKG_CONFIG=
#   [-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=]
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})
file(GLOB_RECURSE pc_files ${PREFIX}/ssam.pc)
if(NOT pc_files)
  message(FATAL_ERROR "no ssam.pc installed under ${PREFIX}")
endif()
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})

run(${PKG_CONFIG} --exists --print-errors "ssam >= 0.4" ssam-soft ssam-render-gl ssam-gl)
run(${PKG_CONFIG} --modversion ssam)
string(STRIP "${run_output}" version)
# The static archives' private needs (oneTBB, libepoxy) only with --static, as pkg-config means.
run(${PKG_CONFIG} --libs ssam-soft)
if(run_output MATCHES "-ltbb")
  message(FATAL_ERROR "ssam-soft lists oneTBB as a public dependency: ${run_output}")
endif()
run(${PKG_CONFIG} --static --cflags --libs ssam ssam-soft ssam-render-gl ssam-gl)
separate_arguments(flags UNIX_COMMAND "${run_output}")

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
run(${CXX} -std=c++20 -O3 -Wall -Wextra -Wpedantic -Werror "-DEXPECTED_SSAM_VERSION=\"${version}\""
    ${CONSUMER_SOURCE}/main.cpp -o ${OUT}/ssam_consumer ${flags} ${consumer_compile_flags})
run(${OUT}/ssam_consumer)
if(NOT run_output MATCHES "soft: centre pixel[^\n]*: ok")
  message(FATAL_ERROR "the consumer did not check the soft backend's pixel:\n${run_output}")
endif()
