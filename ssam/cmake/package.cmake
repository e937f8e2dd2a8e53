# SPDX-License-Identifier: MIT
# The installed package: what another engine finds with
#   find_package(ssam 0.3 REQUIRED COMPONENTS soft render_gl gl vk)                   (CMake)
#   pkg-config --static --cflags --libs ssam ssam-soft ssam-render-gl ssam-gl ssam-vk  (anything else)
# Included by ssam/CMakeLists.txt once every library of the package exists. Layout:
#   include/ssam/            ssam's headers and the generated version.hpp
#   include/ssam/engine/     the engine headers ssam's API is written in (core errors and log,
#                            render, the soft and GL backends); the ECS is not part of it
#   lib/libssam*.a           ssam, ssam_core, ssam_render, ssam_render_soft, ssam_render_gl, ssam_gl, ssam_vk
#   lib/cmake/ssam/          ssamConfig.cmake and one targets file per component
#   lib/pkgconfig/           ssam.pc, ssam-soft.pc, ssam-render-gl.pc, ssam-gl.pc, ssam-vk.pc
# Everything here belongs to the install component `library` (the demo's is `demo`).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# SSAM_VERSION_MAJOR/MINOR/PATCH for code that must know which ssam it compiles against.
set(_ssam_generated ${CMAKE_CURRENT_BINARY_DIR}/generated)
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.hpp.in ${_ssam_generated}/ssam/version.hpp @ONLY)
target_include_directories(ssam PUBLIC $<BUILD_INTERFACE:${_ssam_generated}>)
target_include_directories(ssam_gl PUBLIC $<BUILD_INTERFACE:${_ssam_generated}>)
target_include_directories(ssam_vk PUBLIC $<BUILD_INTERFACE:${_ssam_generated}>)

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
  set_target_properties(${_target} PROPERTIES EXPORT_NAME ${_name} OUTPUT_NAME ssam_${_name})
  add_library(ssam::${_name} ALIAS ${_target})
endforeach()

# One export set per component, so a consumer loads (and needs the dependencies of) only
# the components it asks for.
set(_ssam_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/ssam)
set(_ssam_engine_includes ${CMAKE_INSTALL_INCLUDEDIR}/ssam)
install(TARGETS ssam engine_render engine_core EXPORT ssamTargets COMPONENT library
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${_ssam_engine_includes})
install(TARGETS engine_render_soft EXPORT ssamSoftTargets COMPONENT library
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${_ssam_engine_includes})
install(TARGETS engine_render_gl EXPORT ssamRenderGlTargets COMPONENT library
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${_ssam_engine_includes})
install(TARGETS ssam_gl EXPORT ssamGlTargets COMPONENT library INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ssam_vk EXPORT ssamVkTargets COMPONENT library INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT ssamTargets NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir} FILE ssam-targets.cmake
        COMPONENT library)
install(EXPORT ssamSoftTargets NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir} FILE ssam-soft-targets.cmake
        COMPONENT library)
install(EXPORT ssamRenderGlTargets NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir}
        FILE ssam-render_gl-targets.cmake COMPONENT library)
install(EXPORT ssamGlTargets NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir} FILE ssam-gl-targets.cmake
        COMPONENT library)
install(EXPORT ssamVkTargets NAMESPACE ssam:: DESTINATION ${_ssam_cmake_dir} FILE ssam-vk-targets.cmake
        COMPONENT library)

install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ssam ${_ssam_generated}/ssam
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT library)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/core/include/engine
        DESTINATION ${_ssam_engine_includes} COMPONENT library PATTERN ecs EXCLUDE)
foreach(_dir render render/soft render/gl)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/${_dir}/include/engine
          DESTINATION ${_ssam_engine_includes} COMPONENT library)
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/ssamConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/ssamConfig.cmake
                              INSTALL_DESTINATION ${_ssam_cmake_dir})
# 0.x: a minor version may change the API, so 0.3 accepts only 0.3.*.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ssamConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
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
foreach(_pc ssam ssam-soft ssam-render-gl ssam-gl ssam-vk)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/${_pc}.pc.in ${CMAKE_CURRENT_BINARY_DIR}/${_pc}.pc @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${_pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
          COMPONENT library)
endforeach()
