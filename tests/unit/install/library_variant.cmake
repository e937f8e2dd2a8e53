# SPDX-License-Identifier: MIT
# cmake -P script: a library-only build of one GPU side, with the other side's packages hidden:
#   VARIANT=gl  -DSSAM_WITH_VK=OFF: Vulkan's headers and glslc hidden
#   VARIANT=vk  -DSSAM_WITH_GL=OFF: EGL's, libepoxy's and GL's headers hidden
# as LibraryOnlyBuildNeedsNoDemoDependency does for the demo's packages: configure (the demo's
# packages hidden too), build (Release), install, consume. Hidden means: the cache variable of the
# project's own find_path / find_program for it is preset to a folder whose header is an #error
# (glslc: /bin/false), so any use fails the build, and must be reported by CMake as unused;
# libepoxy's .pc is out of pkg-config's reach (PKG_CONFIG_LIBDIR holds only Imath's); and no
# compiled file's dependency list names any of the hidden headers (the system's copies included).
# The install must lack the component left out (libraries, headers, targets, .pc files),
# find_package(ssam COMPONENTS <it>) must fail naming the option, and the component built must
# work for a consumer: the GL consumer (soft, render_gl, gl) or the Vulkan one (ssam::vk alone).
#   -DVARIANT=gl|vk -DSOURCE_DIR= -DWORK= -DCONSUMER_SOURCE= -DPROBE_SOURCE= -DPKG_CONFIG=
cmake_minimum_required(VERSION 3.25)  # IN_LIST
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
file(REMOVE_RECURSE ${WORK})
set(build ${WORK}/build)
set(prefix ${WORK}/prefix)

# A folder of headers that stop any compile including them.
set(poison ${WORK}/hidden-headers)
foreach(header vulkan/vulkan.h GL/glcorearb.h EGL/eglplatform.h)
  file(WRITE ${poison}/${header} "#error \"${header} is hidden from this build (library_variant.cmake)\"\n")
endforeach()

set(hidden "")
foreach(package OpenImageIO glfw3 CLI11 GTest benchmark draco nlohmann_json)
  list(APPEND hidden -DCMAKE_DISABLE_FIND_PACKAGE_${package}=ON)
endforeach()
set(env "")
if(VARIANT STREQUAL "gl")
  set(options -DSSAM_WITH_VK=OFF)
  list(APPEND hidden -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON -DSSAM_VULKAN_INCLUDE_DIR=${poison} -DSSAM_GLSLC=/bin/false)
  set(hidden_header_dirs vulkan vk_video)
  set(left_out_sources "^ssam/src/vk/")
  set(left_out vk)
  set(left_out_files include/ssam/vk lib/libssam_vk.a lib/cmake/ssam/ssam-vk-targets.cmake lib/pkgconfig/ssam-vk.pc)
  set(expect_targets "ssam::ssam;ssam::render;ssam::core;ssam::render_soft;ssam::render_gl;ssam::gl")
else()
  set(options -DSSAM_WITH_GL=OFF)
  list(APPEND hidden -DSSAM_GLCOREARB_INCLUDE_DIR=${poison} -DSSAM_EGL_INCLUDE_DIR=${poison})
  # pkg-config sees Imath (the core's) and nothing else: no libepoxy, no egl or gl.
  execute_process(COMMAND ${PKG_CONFIG} --variable=pcfiledir Imath OUTPUT_VARIABLE imath_pc_dir
                  OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  file(COPY ${imath_pc_dir}/Imath.pc DESTINATION ${WORK}/pkgconfig)
  set(env PKG_CONFIG_LIBDIR=${WORK}/pkgconfig PKG_CONFIG_PATH=)
  set(hidden_header_dirs epoxy EGL KHR GL)
  set(left_out_sources "^(engine/render/gl|ssam/src/gl)/")
  set(left_out gl render_gl)
  set(left_out_files include/ssam/gl include/ssam/engine/render/gl lib/libssam_gl.a lib/libssam_render_gl.a
      lib/cmake/ssam/ssam-gl-targets.cmake lib/cmake/ssam/ssam-render_gl-targets.cmake lib/pkgconfig/ssam-gl.pc
      lib/pkgconfig/ssam-render-gl.pc)
  set(expect_targets "ssam::ssam;ssam::render;ssam::core;ssam::render_soft;ssam::vk")
endif()

run(${CMAKE_COMMAND} -E env ${env} ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -DSSAM_LIBRARY_ONLY=ON ${options}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_INSTALL_LIBDIR=lib ${hidden})
# CMake names each hidden package's variable as unused: proof that nothing even asked for it.
string(REGEX MATCH "Manually-specified variables were not used by the project:[^\n]*\n(\n|  +[^\n]*\n)*" unused
       "${run_output}")
foreach(variable IN LISTS hidden)
  string(REGEX REPLACE "^-D([^=]+)=.*$" "\\1" variable "${variable}")
  if(NOT unused MATCHES "  ${variable}\n")
    message(FATAL_ERROR "the ${VARIANT}-only configure used ${variable}, hidden from it")
  endif()
endforeach()
run(${CMAKE_COMMAND} --build ${build} -j2)

# What was compiled: the library's sources, none of the side left out, and no compiled file that
# includes one of its headers (the compiler's dependency files list every header each one read).
file(READ ${build}/compile_commands.json commands)
string(REGEX MATCHALL "\"file\": \"[^\"]+\"" compiled "${commands}")
list(LENGTH compiled count)
foreach(entry IN LISTS compiled)
  string(REGEX REPLACE "^\"file\": \"(.*)\"$" "\\1" file "${entry}")
  file(RELATIVE_PATH file ${SOURCE_DIR} ${file})
  if(NOT file MATCHES "^(engine/core|engine/render|ssam/src)/" OR file MATCHES "${left_out_sources}")
    message(FATAL_ERROR "the ${VARIANT}-only build compiled ${file}")
  endif()
endforeach()
file(GLOB_RECURSE depfiles ${build}/*.o.d)
list(LENGTH depfiles depfile_count)
if(NOT depfile_count EQUAL count)
  message(FATAL_ERROR "${depfile_count} dependency files for ${count} sources: the check needs the compiler's")
endif()
list(JOIN hidden_header_dirs "|" hidden_regex)
foreach(depfile IN LISTS depfiles)
  file(STRINGS ${depfile} hits REGEX "/include/(${hidden_regex})/")
  if(hits)
    message(FATAL_ERROR "${depfile}: a source of the ${VARIANT}-only build includes a hidden header:\n${hits}")
  endif()
endforeach()
message(STATUS "${count} sources compiled, none of them reading ${hidden_header_dirs} headers")

run(${CMAKE_COMMAND} --install ${build} --prefix ${prefix})
foreach(file IN LISTS left_out_files)
  if(EXISTS ${prefix}/${file})
    message(FATAL_ERROR "the ${VARIANT}-only install holds ${file}")
  endif()
endforeach()

# A request for a component left out fails naming the option; without COMPONENTS, what there is.
foreach(component IN LISTS left_out)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${PROBE_SOURCE} -B ${WORK}/probe-${component} -DCMAKE_PREFIX_PATH=${prefix}
                          -DSSAM_VERSION_WANTED=0.4 -DSSAM_COMPONENTS=${component}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT "${out}${err}" MATCHES "component '${component}': this ssam was built without it \\(SSAM_WITH_")
    message(FATAL_ERROR "find_package(ssam COMPONENTS ${component}) against the ${VARIANT}-only install:\n${out}${err}")
  endif()
endforeach()
run(${CMAKE_COMMAND} -S ${PROBE_SOURCE} -B ${WORK}/probe -DCMAKE_PREFIX_PATH=${prefix} -DSSAM_VERSION_WANTED=0.4)
if(NOT run_output MATCHES "ssam targets: ${expect_targets}\n")
  message(FATAL_ERROR "find_package(ssam) against the ${VARIANT}-only install did not give ${expect_targets}")
endif()

run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${WORK}/consumer -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${WORK}/consumer)
file(GLOB program ${WORK}/consumer/ssam_*consumer)
run(${program})
if(VARIANT STREQUAL "gl" AND NOT run_output MATCHES "soft: centre pixel[^\n]*: ok")
  message(FATAL_ERROR "the consumer did not check the soft backend's pixel:\n${run_output}")
elseif(VARIANT STREQUAL "vk" AND NOT run_output MATCHES "initialize without a device: invalid argument")
  message(FATAL_ERROR "the ssam::vk consumer did not run its checks:\n${run_output}")
endif()
