# SPDX-License-Identifier: MIT
# cmake -P script: find_package(ssam) against an installed prefix with good and bad requests.
#   -DBUILD_DIR= -DPREFIX= -DPROBE_SOURCE= -DPROBE_BUILD=
# A missing component, one whose dependency is missing, or a wrong version must fail the
# consumer's configure with a message naming it; optional ones that cannot load must not.
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})

# probe(<expect: ok|fail> <message regex> <cmake -D arguments>...); `probe_env` (NAME=VALUE ...)
# is the configure's environment on top of this one.
set(probe_env "")
function(probe expect pattern)
  file(REMOVE_RECURSE ${PROBE_BUILD})
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${probe_env} ${CMAKE_COMMAND} -S ${PROBE_SOURCE} -B ${PROBE_BUILD}
                          -DCMAKE_PREFIX_PATH=${PREFIX} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  if(expect STREQUAL "ok" AND NOT rc EQUAL 0)
    message(FATAL_ERROR "find_package(ssam) with ${ARGN} failed:\n${all}")
  elseif(expect STREQUAL "fail" AND rc EQUAL 0)
    message(FATAL_ERROR "find_package(ssam) with ${ARGN} succeeded; it must fail:\n${all}")
  endif()
  if(NOT all MATCHES "${pattern}")
    message(FATAL_ERROR "find_package(ssam) with ${ARGN}: the output does not say '${pattern}':\n${all}")
  endif()
  message(STATUS "ok (${expect}): ${probe_env} ${ARGN}")
endfunction()

set(v -DSSAM_VERSION_WANTED=0.4)
set(all_targets "ssam::ssam;ssam::render;ssam::core;ssam::render_soft;ssam::render_gl;ssam::gl")
probe(ok "ssam targets: ${all_targets}\n" ${v} "-DSSAM_COMPONENTS=soft render_gl gl")
probe(ok "ssam targets: ${all_targets};ssam::vk\n" ${v})  # no COMPONENTS: every one that can load
probe(ok "ssam targets: ssam::ssam;ssam::render;ssam::core;ssam::render_soft\n" ${v} -DSSAM_COMPONENTS=soft)
probe(fail "no component 'vulkan'" ${v} "-DSSAM_COMPONENTS=soft vulkan")
probe(fail "no component 'vulkan'" ${v} -DSSAM_OPTIONAL=vulkan)
# A component whose dependency cannot be found here (oneTBB hidden from the search).
probe(fail "component 'soft': it needs oneTBB" ${v} -DSSAM_COMPONENTS=soft -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON)
probe(ok "optional component 'soft' not loaded: it needs oneTBB.*ssam targets: ssam::ssam;ssam::render;ssam::core;ssam::render_gl;ssam::gl\n"
      ${v} "-DSSAM_COMPONENTS=render_gl gl" -DSSAM_OPTIONAL=soft -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON)
# Each component needs only what it uses: with glm, Threads, oneTBB, pkg-config (and so Imath
# and libepoxy) hidden, `gl` or `vk` alone still loads; the others fail naming what they lack.
set(hidden -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON -DCMAKE_DISABLE_FIND_PACKAGE_Threads=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON -DCMAKE_DISABLE_FIND_PACKAGE_Imath=ON)
set(probe_env PKG_CONFIG_LIBDIR= PKG_CONFIG_PATH=)
probe(ok "ssam targets: ssam::gl\n" ${v} -DSSAM_COMPONENTS=gl ${hidden})
probe(ok "ssam targets: ssam::vk\n" ${v} -DSSAM_COMPONENTS=vk ${hidden})
probe(fail "component 'render_gl': it needs glm" ${v} "-DSSAM_COMPONENTS=render_gl gl" ${hidden})
probe(fail "ssam 0\\.4\\.0: it needs glm" ${v} ${hidden})  # no COMPONENTS: the core is required
set(probe_env "")
# 0.x: another minor version is another API (ssam/CHANGELOG.md): an older or newer request fails, saying
# why; any 0.4.x satisfies 0.4.
probe(ok "ssam targets: " -DSSAM_VERSION_WANTED=0.4.0)
probe(fail "ssam 0\\.4\\.0 \\([^)]*\\) does not satisfy a request for 0\\.3: while ssam is 0\\.x.*version: 0\\.4\\.0"
      -DSSAM_VERSION_WANTED=0.3)
probe(fail "does not satisfy a request for 0\\.5.*version: 0\\.4\\.0" -DSSAM_VERSION_WANTED=0.5)
probe(fail "version: 0\\.4\\.0" -DSSAM_VERSION_WANTED=0.2)
