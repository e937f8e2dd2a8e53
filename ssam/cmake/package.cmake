# SPDX-License-Identifier: MIT
# The installed package: what another engine finds with
#   find_package(ssam 0.4 REQUIRED COMPONENTS soft render_gl gl vk)                   (CMake)
#   pkg-config --static --cflags --libs ssam ssam-soft ssam-render-gl ssam-gl ssam-vk  (anything else)
# Included by ssam/CMakeLists.txt once every library of the package exists. Layout:
#   include/ssam/            ssam's headers and the generated version.hpp
#   include/ssam/engine/     the engine headers ssam's API is written in (core errors and log,
#                            render, the soft and GL backends); the ECS is not part of it
#   lib/libssam*.a           ssam, ssam_core, ssam_render, ssam_render_soft, ssam_render_gl, ssam_gl, ssam_vk
#   lib/cmake/ssam/          ssamConfig.cmake and one targets file per component
#   lib/pkgconfig/           ssam.pc, ssam-soft.pc, ssam-render-gl.pc, ssam-gl.pc, ssam-vk.pc
# Everything here belongs to the install component `library` (the demo's is `demo`).
# SSAM_WITH_GL=OFF leaves out render_gl and gl (libraries, headers, targets and .pc files),
# SSAM_WITH_VK=OFF leaves out vk; ssamConfig.cmake then names the missing component as not built.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# SSAM_VERSION_MAJOR/MINOR/PATCH for code that must know which ssam it compiles against.
set(_ssam_generated ${CMAKE_CURRENT_BINARY_DIR}/generated)
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.hpp.in ${_ssam_generated}/ssam/version.hpp @ONLY)
target_include_directories(ssam PUBLIC $<BUILD_INTERFACE:${_ssam_generated}>)
foreach(_target IN ITEMS ssam_gl ssam_vk)
  if(TARGET ${_target})
    target_include_directories(${_target} PUBLIC $<BUILD_INTERFACE:${_ssam_generated}>)
  endif()
endforeach()

# The engine's and ssam's public headers use C++20 (std::span, designated initialisers): their
# consumers get it from the targets. ssam::gl's header is C++17 and asks for no more
# (ssam/CMakeLists.txt).
target_compile_features(engine_core PUBLIC cxx_std_20)

# Target names as a consumer sees them (ssam::core, ...), the same in this tree through
# aliases, and library files named for the package rather than the generic engine_*.
foreach(_pair engine_core:core engine_render:render engine_render_soft:render_soft engine_render_gl:render_gl)
  string(REPLACE ":" ";" _pair "${_pair}")
  list(GET _pair 0 _target)
  list(GET _pair 1 _name)
  if(NOT TARGET ${_target})
    continue()  # engine_render_gl without SSAM_WITH_GL
  endif()
  set_target_properties(${_target} PROPERTIES EXPORT_NAME ${_name} OUTPUT_NAME ssam_${_name})
  add_library(ssam::${_name} ALIAS ${_target})
endforeach()

# One export set per component, so a consumer loads (and needs the dependencies of) only
# the components it asks for. SSAM_BUILT_COMPONENTS (ssamConfig.cmake) lists those this build
# installs, so that a request for one left out says so rather than "not found".
set(_ssam_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/ssam)
set(_ssam_engine_includes ${CMAKE_INSTALL_INCLUDEDIR}/ssam)
install(TARGETS ssam engine_render engine_core EXPORT ssamTargets COMPONENT library
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${_ssam_engine_includes})
install(EXPORT ssamTargets NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir} FILE ssam-targets.cmake
        COMPONENT library)
set(SSAM_BUILT_COMPONENTS soft)
set(_ssam_pc_files ssam ssam-soft)
# component:target:export set:pc file (targets with engine headers also get include/ssam/).
set(_ssam_components soft:engine_render_soft:ssamSoftTargets:ssam-soft
                     render_gl:engine_render_gl:ssamRenderGlTargets:ssam-render-gl
                     gl:ssam_gl:ssamGlTargets:ssam-gl
                     vk:ssam_vk:ssamVkTargets:ssam-vk)
foreach(_entry IN LISTS _ssam_components)
  string(REPLACE ":" ";" _entry "${_entry}")
  list(GET _entry 0 _component)
  list(GET _entry 1 _target)
  list(GET _entry 2 _export)
  list(GET _entry 3 _pc)
  if(NOT TARGET ${_target})
    continue()
  endif()
  set(_includes ${CMAKE_INSTALL_INCLUDEDIR})
  if(_target MATCHES "^engine_")
    list(APPEND _includes ${_ssam_engine_includes})
  endif()
  install(TARGETS ${_target} EXPORT ${_export} COMPONENT library INCLUDES DESTINATION ${_includes})
  install(EXPORT ${_export} NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir}
          FILE ssam-${_component}-targets.cmake COMPONENT library)
  list(APPEND SSAM_BUILT_COMPONENTS ${_component})
  list(APPEND _ssam_pc_files ${_pc})
endforeach()
list(REMOVE_DUPLICATES SSAM_BUILT_COMPONENTS)

# Headers: each component's with it, and only what a consumer of its target can compile and
# link (Install.HeadersBuildThroughTheirComponent includes each one alone through its target):
#   include/ssam/*.hpp, version.hpp, ssam/core/   every component (ssam/core/ is the host-neutral
#                                                 core, C++17 and dependency-free, whose objects
#                                                 are in each of libssam, libssam_gl, libssam_vk)
#   include/ssam/gl/, include/ssam/vk/            gl, vk
#   include/ssam/engine/{core,render}             the core (ssam::ssam; render/kernel/ too): no ECS, and not
#                                                 parallel_for.hpp, which needs oneTBB (linked by
#                                                 the soft backend's library only, and included by
#                                                 its sources, not by any installed header)
#   include/ssam/engine/render/{soft,gl}          soft, render_gl
set(_ssam_header_excludes "")
if(NOT TARGET ssam_gl)
  list(APPEND _ssam_header_excludes REGEX "/include/ssam/gl(/.*)?$" EXCLUDE)
endif()
if(NOT TARGET ssam_vk)
  list(APPEND _ssam_header_excludes REGEX "/include/ssam/vk(/.*)?$" EXCLUDE)
endif()
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ssam ${_ssam_generated}/ssam
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT library ${_ssam_header_excludes})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/core/include/engine
        DESTINATION ${_ssam_engine_includes} COMPONENT library PATTERN ecs EXCLUDE
        PATTERN parallel_for.hpp EXCLUDE)
set(_ssam_engine_header_dirs render render/kernel render/soft)
if(TARGET engine_render_gl)
  list(APPEND _ssam_engine_header_dirs render/gl)
endif()
foreach(_dir IN LISTS _ssam_engine_header_dirs)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/${_dir}/include/engine
          DESTINATION ${_ssam_engine_includes} COMPONENT library)
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ssamConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/ssamConfig.cmake
                              INSTALL_DESTINATION ${_ssam_cmake_dir})
# 0.x: a minor version may change the API (ssam/CHANGELOG.md lists each change and how to migrate), so
# 0.4 accepts only 0.4.*: find_package(ssam 0.3) fails against it, naming both versions. From 1.0
# on, SameMajorVersion.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ssamConfigVersion-basic.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
file(READ ${CMAKE_CURRENT_BINARY_DIR}/ssamConfigVersion-basic.cmake SSAM_BASIC_VERSION_CHECK)
configure_file(${CMAKE_CURRENT_LIST_DIR}/ssamConfigVersion.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/ssamConfigVersion.cmake
               @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ssamConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/ssamConfigVersion.cmake
        DESTINATION ${_ssam_cmake_dir} COMPONENT library)

# pkg-config files locate the prefix from their own directory (${pcfiledir}), so the package
# works wherever `cmake --install --prefix` puts it.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(SSAM_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH _rel "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
  string(REGEX REPLACE "/$" "" _rel "${_rel}")
  set(SSAM_PC_PREFIX "\${pcfiledir}/${_rel}")
endif()
set(SSAM_PC_DL_LIBS "")
if(CMAKE_DL_LIBS)
  set(SSAM_PC_DL_LIBS "-l${CMAKE_DL_LIBS}")
endif()
foreach(_pc IN LISTS _ssam_pc_files)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/${_pc}.pc.in ${CMAKE_CURRENT_BINARY_DIR}/${_pc}.pc @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${_pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
          COMPONENT library)
endforeach()
