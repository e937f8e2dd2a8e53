# SPDX-License-Identifier: MIT
# The living-scene module registry. A module is its folder plus one ssam_module() line; the
# line builds the folder and records the module, and ssam_feature_table() turns every module
# recorded so far into a C++ table (engine/scene/feature_module.hpp) that programs read for the
# module's name, racer flag, default and factory. A generated table, not static
# self-registration: a static library drops an object file that nothing refers to, and its
# registration with it.

# ssam_module(<name> FLAG <racer flag> DEFAULT ON|OFF HELP <flag help>)
# Builds ./<name> (unless -DSSAM_MODULE_<NAME>=OFF), which must define the library ssam_<name>
# and the header <name>/<name>_module.hpp declaring
#   std::unique_ptr<engine::scene::Feature> <name>::makeFeature(const engine::scene::FeatureContext&);
# The order of the lines is the frame order of the features' passes.
function(ssam_module name)
  ssam_parse_required("ssam_module(${name})" M "FLAG;DEFAULT;HELP" ${ARGN})
  string(TOUPPER ${name} upper)
  option(SSAM_MODULE_${upper} "build the living-scene module ${name}" ON)
  set(built OFF)
  if(SSAM_MODULE_${upper} AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/CMakeLists.txt)
    add_subdirectory(${name})
    if(NOT TARGET ssam_${name})
      message(FATAL_ERROR "ssam_module(${name}): ${CMAKE_CURRENT_SOURCE_DIR}/${name} defines no library ssam_${name}")
    endif()
    set(built ON)
  endif()
  if(M_DEFAULT)
    set(enabled true)
  else()
    set(enabled false)
  endif()
  string(REPLACE "\\" "\\\\" help "${M_HELP}")
  string(REPLACE "\"" "\\\"" help "${help}")
  set_property(GLOBAL APPEND PROPERTY SSAM_FEATURE_MODULES ${name})
  set_property(GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_FLAG "${M_FLAG}")
  set_property(GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_HELP "${help}")
  set_property(GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_ENABLED ${enabled})
  set_property(GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_BUILT ${built})
endfunction()

# ssam_feature_table(<target> FUNCTION <namespace>::<name>)
# A static library <target> holding every module recorded so far, in their order, as
#   std::span<const engine::scene::FeatureModule> <namespace>::<name>();
# declared in <target>.hpp. It links the modules that are built; one left out of the build
# keeps its row with no factory, so its flag still parses and a program can say it is missing.
# A later ssam_module() (a test-only module) goes into a later table only.
function(ssam_feature_table target)
  cmake_parse_arguments(T "" "FUNCTION" "" ${ARGN})
  if(NOT T_FUNCTION MATCHES "^(.+)::([A-Za-z_][A-Za-z0-9_]*)$")
    message(FATAL_ERROR "ssam_feature_table(${target}): FUNCTION must be namespace::name, not '${T_FUNCTION}'")
  endif()
  set(TABLE_NAMESPACE ${CMAKE_MATCH_1})
  set(TABLE_FUNCTION ${CMAKE_MATCH_2})
  set(TABLE_HEADER ${target}.hpp)
  get_property(modules GLOBAL PROPERTY SSAM_FEATURE_MODULES)
  list(LENGTH modules TABLE_COUNT)
  set(TABLE_INCLUDES "")
  set(TABLE_ROWS "")
  set(libraries "")
  foreach(name IN LISTS modules)
    get_property(flag GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_FLAG)
    get_property(help GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_HELP)
    get_property(enabled GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_ENABLED)
    get_property(built GLOBAL PROPERTY SSAM_FEATURE_MODULE_${name}_BUILT)
    set(factory nullptr)
    if(built)
      string(APPEND TABLE_INCLUDES "#include \"${name}/${name}_module.hpp\"\n")
      set(factory "&::${name}::makeFeature")
      list(APPEND libraries ssam_${name})
    endif()
    string(APPEND TABLE_ROWS "    FeatureModule{\"${name}\", \"${flag}\", \"${help}\", ${enabled}, ${factory}},\n")
  endforeach()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/${target})
  configure_file(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/feature_table.hpp.in ${dir}/${target}.hpp @ONLY)
  configure_file(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/feature_table.cpp.in ${dir}/${target}.cpp @ONLY)
  add_library(${target} STATIC ${dir}/${target}.cpp)
  target_include_directories(${target} PUBLIC ${dir})
  target_link_libraries(${target} PUBLIC engine_scene ${libraries})
  ssam_warnings(${target})
endfunction()
