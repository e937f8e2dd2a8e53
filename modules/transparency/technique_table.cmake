# SPDX-License-Identifier: MIT
# The technique registry: one ssam_technique() line per technique in CMakeLists.txt, from
# which ssam_technique_table() generates the TechniqueKind enum (transparency/technique_kind.hpp)
# and the table createTechnique(), techniqueName() and allTechniques() read (technique_table.cpp).
# Generated, not filled by static self-registration: a static library drops an object file
# that nothing refers to, and its registration with it.

# ssam_technique(<name> KIND <Enumerator> SOURCE <file> ABOUT <one line>)
# <name> is how racer --technique and ssam-bench spell it; <file> defines
#   std::unique_ptr<Technique> transparency::detail::make<Enumerator>Technique(Backend&, const TechniqueOptions&);
# The order of the lines is the order of allTechniques() (tables, racer's keys 1-8).
function(ssam_technique name)
  ssam_parse_required("ssam_technique(${name})" T "KIND;SOURCE;ABOUT" ${ARGN})
  set_property(DIRECTORY APPEND PROPERTY SSAM_TECHNIQUES ${name})
  set_property(DIRECTORY PROPERTY SSAM_TECHNIQUE_${name}_KIND ${T_KIND})
  set_property(DIRECTORY PROPERTY SSAM_TECHNIQUE_${name}_SOURCE ${T_SOURCE})
  set_property(DIRECTORY PROPERTY SSAM_TECHNIQUE_${name}_ABOUT "${T_ABOUT}")
endfunction()

# ssam_technique_table(<target>): adds every recorded technique's source and the generated
# enum and table to <target>, the transparency library.
function(ssam_technique_table target)
  get_property(techniques DIRECTORY PROPERTY SSAM_TECHNIQUES)
  list(LENGTH techniques TECHNIQUE_COUNT)
  set(TECHNIQUE_ENUMERATORS "")
  set(TECHNIQUE_FACTORIES "")
  set(TECHNIQUE_ROWS "")
  foreach(name IN LISTS techniques)
    get_property(kind DIRECTORY PROPERTY SSAM_TECHNIQUE_${name}_KIND)
    get_property(source DIRECTORY PROPERTY SSAM_TECHNIQUE_${name}_SOURCE)
    get_property(about DIRECTORY PROPERTY SSAM_TECHNIQUE_${name}_ABOUT)
    string(APPEND TECHNIQUE_ENUMERATORS "    ${kind},  // ${name}: ${about}\n")
    string(APPEND TECHNIQUE_FACTORIES
           "std::unique_ptr<Technique> make${kind}Technique(engine::render::Backend& backend, const TechniqueOptions& options);\n")
    string(APPEND TECHNIQUE_ROWS "    TechniqueRow{TechniqueKind::${kind}, \"${name}\", &make${kind}Technique},\n")
    target_sources(${target} PRIVATE ${source})
  endforeach()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/technique_table)
  configure_file(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/technique_kind.hpp.in ${dir}/transparency/technique_kind.hpp @ONLY)
  configure_file(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/technique_table.cpp.in ${dir}/technique_table.cpp @ONLY)
  target_sources(${target} PRIVATE ${dir}/technique_table.cpp)
  target_include_directories(${target} PUBLIC ${dir} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)  # src: technique_table.hpp
endfunction()
