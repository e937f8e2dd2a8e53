# SPDX-License-Identifier: MIT
# cmake -P script: every header the package installs compiles on its own and links through the
# target of the component that installs it, and includes no other package's header that target
# does not bring. Installs the library, sorts each installed header to its component:
#   core       ssam::ssam        include/ssam/*.hpp, include/ssam/engine/ (not soft/, gl/ below)
#   soft       ssam::render_soft include/ssam/engine/render/soft/
#   render_gl  ssam::render_gl   include/ssam/engine/render/gl/
#   gl         ssam::gl          include/ssam/gl/
#   vk         ssam::vk          include/ssam/vk/
#   every one of core, gl, vk    include/ssam/version.hpp, include/ssam/core/ (the host-neutral core,
#                                whose objects each of the three archives carries)
# (a header in none of these fails the test: a new folder must say whose it is), then builds one
# program per component from one translation unit per header (the header included alone, twice:
# its include guard too) and an empty main, linked against that component's target only; -Werror,
# and no C++ standard of its own, so ssam::gl's and ssam::vk's headers compile as C++17. Then each
# translation unit's dependency file is read: a header reaching oneTBB, libepoxy, EGL, GL or Vulkan
# headers through a target that does not link them (engine/core/parallel_for.hpp and oneTBB under
# ssam::ssam was the case) fails, naming the header and the package.
#   -DBUILD_DIR= -DPREFIX= -DWORK= [-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=]
cmake_minimum_required(VERSION 3.25)  # IN_LIST
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
install_library(${BUILD_DIR} ${PREFIX})
file(REMOVE_RECURSE ${WORK})
set(source ${WORK}/src)
file(MAKE_DIRECTORY ${source})

set(components core soft render_gl gl vk)
set(target_core ssam::ssam)
set(target_soft ssam::render_soft)
set(target_render_gl ssam::render_gl)
set(target_gl ssam::gl)
set(target_vk ssam::vk)
# Other packages' header folders, and the components whose targets bring them (a public or
# link-only dependency, or for vk the consumer's own <vulkan/vulkan.h>, which ssamConfig looks for).
set(package_dirs glm Imath tbb oneapi epoxy EGL KHR GL vulkan vk_video)
set(package_glm glm)
set(package_Imath Imath)
set(package_tbb oneTBB)
set(package_oneapi oneTBB)
set(package_epoxy libepoxy)
set(package_EGL EGL)
set(package_KHR EGL)
set(package_GL GL)
set(package_vulkan Vulkan)
set(package_vk_video Vulkan)
set(allowed_core glm Imath)
set(allowed_soft glm Imath oneTBB)
set(allowed_render_gl glm Imath libepoxy EGL GL)
set(allowed_gl "")
set(allowed_vk Vulkan)

# The components this install has (a build without SSAM_WITH_GL / SSAM_WITH_VK has fewer).
set(installed core)
foreach(component soft render_gl gl vk)
  file(GLOB_RECURSE targets_file ${PREFIX}/*/ssam-${component}-targets.cmake)
  if(targets_file)
    list(APPEND installed ${component})
  endif()
endforeach()

file(GLOB_RECURSE headers RELATIVE ${PREFIX}/include ${PREFIX}/include/*)
foreach(component IN LISTS components)
  set(headers_${component} "")
endforeach()
foreach(header IN LISTS headers)
  if(header MATCHES "^ssam/(version\\.hpp|core/.+\\.hpp)$")
    set(owners core gl vk)
  elseif(header MATCHES "^ssam/gl/.+\\.hpp$")
    set(owners gl)
  elseif(header MATCHES "^ssam/vk/.+\\.hpp$")
    set(owners vk)
  elseif(header MATCHES "^ssam/engine/render/soft/.+\\.hpp$")
    set(owners soft)
  elseif(header MATCHES "^ssam/engine/render/gl/.+\\.hpp$")
    set(owners render_gl)
  elseif(header MATCHES "^ssam/(engine/(core|render)/.+|[^/]+)\\.hpp$")
    set(owners core)
  else()
    message(FATAL_ERROR "include/${header}: no component owns this installed file (installed_headers.cmake)")
  endif()
  foreach(owner IN LISTS owners)
    if(NOT owner IN_LIST installed)
      if(owners STREQUAL owner)
        message(FATAL_ERROR "include/${header} is installed without its component ${owner}")
      endif()
      continue()
    endif()
    list(APPEND headers_${owner} ${header})
  endforeach()
endforeach()

# The project: one program per component.
set(project "cmake_minimum_required(VERSION 3.25)\nproject(ssam_headers CXX)\nset(CMAKE_CXX_EXTENSIONS OFF)\n")
list(REMOVE_ITEM installed core)
string(APPEND project "find_package(ssam 0.4 REQUIRED COMPONENTS ${installed})\n")
list(PREPEND installed core)
file(WRITE ${source}/main.cpp "int main() { return 0; }\n")
set(total 0)
foreach(component IN LISTS installed)
  set(units "")
  set(index 0)
  foreach(header IN LISTS headers_${component})
    math(EXPR index "${index} + 1")
    set(unit ${component}_${index}.cpp)
    # The header's name in the unit too, for the dependency check's message.
    file(WRITE ${source}/${unit} "// ${header}\n#include <${header}>\n#include <${header}>\n")
    list(APPEND units ${unit})
  endforeach()
  list(LENGTH units count)
  math(EXPR total "${total} + ${count}")
  list(JOIN units " " units)
  string(APPEND project "add_executable(headers_${component} main.cpp ${units})\n"
                        "target_link_libraries(headers_${component} PRIVATE ${target_${component}})\n"
                        "target_compile_options(headers_${component} PRIVATE -Wall -Wextra -Wpedantic -Werror)\n")
endforeach()
file(WRITE ${source}/CMakeLists.txt "${project}")

run(${CMAKE_COMMAND} -S ${source} -B ${WORK}/build -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release
    ${consumer_cmake_flags})
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${WORK}/build -j2)

# What each unit included: only the packages its component's target brings.
set(failures "")
foreach(component IN LISTS installed)
  set(index 0)
  foreach(header IN LISTS headers_${component})
    math(EXPR index "${index} + 1")
    set(depfile ${WORK}/build/CMakeFiles/headers_${component}.dir/${component}_${index}.cpp.o.d)
    if(NOT EXISTS ${depfile})
      message(FATAL_ERROR "no dependency file ${depfile}: the check needs the compiler's (GCC/Clang, Makefiles)")
    endif()
    file(READ ${depfile} deps)
    string(REGEX MATCHALL "/include/([A-Za-z_]+)/" dirs "${deps}")
    list(REMOVE_DUPLICATES dirs)
    foreach(dir IN LISTS dirs)
      string(REGEX REPLACE "^/include/([A-Za-z_]+)/$" "\\1" dir "${dir}")
      if(dir IN_LIST package_dirs AND NOT package_${dir} IN_LIST allowed_${component})
        string(APPEND failures "\n  include/${header} (component ${component}) includes ${package_${dir}}'s "
                               "<${dir}/...>, which ${target_${component}} does not link")
      endif()
    endforeach()
  endforeach()
  list(LENGTH headers_${component} count)
  message(STATUS "${component}: ${count} headers, each alone, through ${target_${component}}")
endforeach()
if(failures)
  message(FATAL_ERROR "installed headers that need another component's packages:${failures}")
endif()
message(STATUS "${total} header inclusions compiled and linked")
