# SPDX-License-Identifier: MIT
# The web page's third-party headers (the WebAssembly build, make web). Emscripten looks for
# packages in its own sysroot only, and Debian's header-only libraries (GLM, Imath's half, nlohmann
# JSON, tinygltf, stb) are the same text for any target: each is linked into a folder of this
# build (never copied into the tree) and given the imported target name the native configure's
# find_package would give it, so the engine's CMakeLists build unchanged. Imath's half is used
# without its library's lookup table (IMATH_HALF_NO_LOOKUP_TABLE: the same conversions, computed).
set(SSAM_WEB_HEADERS ${CMAKE_BINARY_DIR}/web_headers)
file(MAKE_DIRECTORY ${SSAM_WEB_HEADERS})
foreach(header IN ITEMS glm Imath nlohmann stb tiny_gltf.h)
  if(NOT EXISTS /usr/include/${header})
    message(FATAL_ERROR "the web build needs Debian's /usr/include/${header} "
                        "(packages libglm-dev libimath-dev nlohmann-json3-dev libstb-dev libtinygltf-dev)")
  endif()
  file(CREATE_LINK /usr/include/${header} ${SSAM_WEB_HEADERS}/${header} SYMBOLIC)
endforeach()

function(ssam_web_header_target name)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${name} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${ARGN}"
                                           INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${ARGN}")
endfunction()
ssam_web_header_target(glm::glm ${SSAM_WEB_HEADERS})
ssam_web_header_target(PkgConfig::IMATH ${SSAM_WEB_HEADERS}/Imath)
set_target_properties(PkgConfig::IMATH PROPERTIES INTERFACE_COMPILE_DEFINITIONS IMATH_HALF_NO_LOOKUP_TABLE)
ssam_web_header_target(nlohmann_json::nlohmann_json ${SSAM_WEB_HEADERS})
ssam_web_header_target(ssam_web_stb ${SSAM_WEB_HEADERS}/stb)
# engine_core's threads: the page's build is single-threaded (no -pthread, no SharedArrayBuffer).
add_library(Threads::Threads INTERFACE IMPORTED GLOBAL)
# Natively these headers sit in /usr/include, a system directory, so our warnings never judge
# them even where a target names their folder with a plain -I: the same here.
include_directories(SYSTEM ${SSAM_WEB_HEADERS} ${SSAM_WEB_HEADERS}/Imath)
# The engine reports bad input and refusals as engine::Error exceptions (a technique the GLES
# driver refuses is named on the page, not a crash): Emscripten leaves C++ exceptions off unless
# asked, at compile and at link time.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)
# oneTBB: none for WebAssembly. The engine's loops run in order without it (SSAM_WITH_TBB off,
# parallel_for.hpp), so the modules that link TBB::tbb for those loops build unchanged against
# this empty target.
add_library(TBB::tbb INTERFACE IMPORTED GLOBAL)
set(SSAM_STB_INCLUDE_DIR ${SSAM_WEB_HEADERS} CACHE PATH "stb headers (the web build links Debian's)" FORCE)
# The page is one program over the engine's libraries: no GL 4.5 or Vulkan package components,
# no installed library, none of the native demo's tools or tests (game/web builds what it needs).
set(SSAM_LIBRARY_ONLY ON)
set(SSAM_WITH_GL OFF)
set(SSAM_WITH_VK OFF)
