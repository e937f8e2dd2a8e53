# SPDX-License-Identifier: MIT
# GLSL in .glsl files, embedded at build time: the one way the engine, ssam and every module
# keep their shader text out of C++ (included by the top-level CMakeLists.txt, so each of them
# reaches it without depending on another).
#
#   engine_embed_glsl(<name> NAMESPACE <ns> DIRECTORY <folder>)
#     Every <folder>/*.glsl becomes `inline constexpr const char k<Name>[]` (particle_depth.glsl ->
#     kParticleDepth) in namespace <ns> of the generated header <name>.hpp; the custom target
#     <name> writes it.
#   engine_uses_glsl(<target> <name>)
#     <target> includes <name>.hpp (and is built after it).
set(ENGINE_EMBED_GLSL_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_glsl.cmake)

function(engine_embed_glsl name)
  cmake_parse_arguments(G "" "NAMESPACE;DIRECTORY" "" ${ARGN})
  if(NOT G_NAMESPACE OR NOT G_DIRECTORY)
    message(FATAL_ERROR "engine_embed_glsl(${name}): NAMESPACE and DIRECTORY are required")
  endif()
  get_filename_component(folder "${G_DIRECTORY}" ABSOLUTE)
  file(GLOB files CONFIGURE_DEPENDS ${folder}/*.glsl)
  if(NOT files)
    message(FATAL_ERROR "engine_embed_glsl(${name}): no .glsl file in ${folder}")
  endif()
  set(include_dir ${CMAKE_CURRENT_BINARY_DIR}/generated_glsl/${name})
  set(header ${include_dir}/${name}.hpp)
  file(RELATIVE_PATH from ${PROJECT_SOURCE_DIR} ${folder})
  string(REPLACE ";" "|" inputs "${files}")  # one argument
  add_custom_command(OUTPUT ${header}
    COMMAND ${CMAKE_COMMAND} -DOUT=${header} -DNAMESPACE=${G_NAMESPACE} -DFROM=${from}/ "-DINPUTS=${inputs}"
            -P ${ENGINE_EMBED_GLSL_SCRIPT}
    DEPENDS ${files} ${ENGINE_EMBED_GLSL_SCRIPT}
    COMMENT "${name}: embedding ${from}/*.glsl" VERBATIM)
  add_custom_target(${name} DEPENDS ${header})
  set_target_properties(${name} PROPERTIES ENGINE_GLSL_INCLUDE_DIR ${include_dir})
endfunction()

function(engine_uses_glsl target name)
  get_target_property(include_dir ${name} ENGINE_GLSL_INCLUDE_DIR)
  add_dependencies(${target} ${name})
  target_include_directories(${target} PRIVATE $<BUILD_INTERFACE:${include_dir}>)
endfunction()
