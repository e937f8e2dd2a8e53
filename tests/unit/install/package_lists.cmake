# SPDX-License-Identifier: MIT
# cmake -P script: README.md's Debian package list of each library-only variant is exactly what
# that variant's configure looks for. The variants are README's own table rows in "Embedding SSAM"
#   | <variant> | `<cmake -D options>` | `g++ cmake <Debian packages>` |
# and each is configured as written (into WORK/<n>) with a JSON trace. Every find_package,
# pkg_check_modules, find_path, find_file, find_program and find_library call made from the
# project's own CMake files (not CMake's modules) is resolved to the file it found (a package's
# CMake config, a module's .pc file, the header, the program, the library), and the file to the
# Debian package that ships it (dpkg-query -S). A find added to the CMake files without README's
# list learning of it fails here, as does a package README lists that no configure looks for. So
# the list is derived, not kept in step by hand; the hidden-package builds
# (LibraryGlOnlyBuildNeedsNoVulkan, LibraryVkOnlyBuildNeedsNoGl) prove the other direction.
# The toolchain (g++, cmake: what compiles and runs this) is not looked for by the project and
# must lead each list as written.
#   -DSOURCE_DIR= -DREADME= -DWORK= -DDPKG_QUERY= -DPKG_CONFIG=
cmake_minimum_required(VERSION 3.25)  # IN_LIST, string(JSON)
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# The variants: README's rows whose second cell is CMake options and third a package list.
file(STRINGS ${README} rows REGEX "^\\| [^|`]+ \\| `-D[^`]*` \\| `[^`]+` \\|$")
list(LENGTH rows variant_count)
if(variant_count LESS 3)
  message(FATAL_ERROR "README.md has ${variant_count} package-list rows ('| variant | `-D...` | `g++ cmake ...` |'); "
                      "expected one per variant (all, OpenGL only, Vulkan only)")
endif()

# Calls whose result is optional to the build (the configure goes on without it): not a package
# the README must list. CCACHE_PROGRAM: a compiler launcher, used when present.
set(optional_results CCACHE_PROGRAM)
# Modules found through CMake's own Find modules (no package config to trace to a file): the file
# that stands for each; Threads is the C library's, part of the toolchain.
set(module_PkgConfig PKG_CONFIG_EXECUTABLE)
set(module_Threads "")

# cache_value(<build dir> <name> <out var>): a cache entry's value ("" when absent).
function(cache_value build name out)
  file(STRINGS ${build}/CMakeCache.txt line REGEX "^${name}:[A-Z]+=")
  string(REGEX REPLACE "^${name}:[A-Z]+=" "" line "${line}")
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

# debian_package(<file> <out var> <out provides>): the package that ships the file, and the names
# it also answers to (Debian 12's pkgconf provides pkg-config).
function(debian_package path out provides_out)
  set(owner "")
  foreach(candidate "${path}" "")
    if(candidate STREQUAL "")
      file(REAL_PATH "${path}" candidate)  # a symlink dpkg does not know (merged /usr)
    endif()
    execute_process(COMMAND ${DPKG_QUERY} -S "${candidate}" RESULT_VARIABLE rc OUTPUT_VARIABLE owner_line ERROR_QUIET)
    if(rc EQUAL 0)
      string(REGEX MATCH "^[^:, \n]+" owner "${owner_line}")  # "libfoo-dev:amd64: /path"
      break()
    endif()
  endforeach()
  if(owner STREQUAL "")
    message(FATAL_ERROR "no Debian package ships ${path} (dpkg-query -S): README cannot list it")
  endif()
  execute_process(COMMAND ${DPKG_QUERY} -W -f=\${Provides} ${owner} OUTPUT_VARIABLE provides ERROR_QUIET)
  string(REGEX REPLACE "\\([^)]*\\)" "" provides "${provides}")  # "pkg-config (= 1.8.1-1)"
  string(REGEX REPLACE "[ ,]+" ";" provides "${provides}")
  list(FILTER provides EXCLUDE REGEX "^$")
  set(${out} ${owner} PARENT_SCOPE)
  set(${provides_out} ${provides} PARENT_SCOPE)
endfunction()

set(failures "")
set(index 0)
foreach(row IN LISTS rows)
  math(EXPR index "${index} + 1")
  string(REGEX MATCH "^\\| ([^|`]+) \\| `(-D[^`]*)` \\| `([^`]+)` \\|$" _ "${row}")
  string(STRIP "${CMAKE_MATCH_1}" variant)
  set(flags "${CMAKE_MATCH_2}")
  separate_arguments(options UNIX_COMMAND "${flags}")
  separate_arguments(listed UNIX_COMMAND "${CMAKE_MATCH_3}")
  if(NOT "-DSSAM_LIBRARY_ONLY=ON" IN_LIST options)
    message(FATAL_ERROR "README's package list '${variant}' is not a library-only build: ${flags}")
  endif()
  list(GET listed 0 first)
  list(GET listed 1 second)
  if(NOT first STREQUAL "g++" OR NOT second STREQUAL "cmake")
    message(FATAL_ERROR "README's package list '${variant}' must start with the toolchain, `g++ cmake`")
  endif()
  list(REMOVE_AT listed 0 1)

  set(build ${WORK}/${index})
  set(trace ${WORK}/trace-${index}.json)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} ${options} --trace-expand --trace-format=json-v1
      --trace-redirect=${trace})
  # Only the project's own calls: CMake's modules make finds of their own (the compiler's tools).
  file(STRINGS ${trace} calls
       REGEX "\"cmd\":\"(find_package|pkg_check_modules|find_path|find_file|find_program|find_library)\"")

  set(found "")           # Debian packages, one per found file
  set(found_names "")     # each with the names it provides, for README's spelling
  set(found_reasons "")   # "package <- call at file:line (what)"
  foreach(call IN LISTS calls)
    string(JSON file GET "${call}" file)
    if(NOT file MATCHES "^${SOURCE_DIR}/" OR file MATCHES "^${build}/")
      continue()
    endif()
    string(JSON cmd GET "${call}" cmd)
    string(JSON line GET "${call}" line)
    string(JSON argc LENGTH "${call}" args)
    set(args "")
    math(EXPR last "${argc} - 1")
    foreach(i RANGE ${last})
      string(JSON arg GET "${call}" args ${i})
      list(APPEND args "${arg}")
    endforeach()
    list(GET args 0 first_arg)
    file(RELATIVE_PATH where ${SOURCE_DIR} ${file})
    set(results "")  # files found by this call
    if(cmd STREQUAL "find_package")
      if(DEFINED module_${first_arg})
        foreach(entry IN LISTS module_${first_arg})
          cache_value(${build} ${entry} value)
          list(APPEND results "${value}")
        endforeach()
      else()
        cache_value(${build} ${first_arg}_DIR dir)
        file(GLOB configs ${dir}/${first_arg}Config.cmake ${dir}/*-config.cmake)
        if(NOT configs)
          message(FATAL_ERROR "find_package(${first_arg}) (${where}:${line}): no package config in '${dir}'; a module-mode "
                              "find needs its file named in package_lists.cmake (module_${first_arg})")
        endif()
        list(GET configs 0 config)
        list(APPEND results "${config}")
      endif()
    elseif(cmd STREQUAL "pkg_check_modules")
      list(REMOVE_AT args 0)  # the prefix
      list(FILTER args EXCLUDE REGEX "^(REQUIRED|QUIET|NO_CMAKE_PATH|NO_CMAKE_ENVIRONMENT_PATH|IMPORTED_TARGET|GLOBAL)$")
      foreach(module IN LISTS args)
        string(REGEX REPLACE "[<>=].*" "" module "${module}")
        execute_process(COMMAND ${PKG_CONFIG} --variable=pcfiledir ${module} OUTPUT_VARIABLE dir
                        OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
        if(NOT rc EQUAL 0)
          message(FATAL_ERROR "pkg-config does not know ${module}, which ${where}:${line} found")
        endif()
        list(APPEND results "${dir}/${module}.pc")
      endforeach()
    else()  # find_path / find_file / find_program / find_library (<VAR> name | NAMES name...)
      if(first_arg IN_LIST optional_results)
        continue()
      endif()
      cache_value(${build} ${first_arg} value)
      if(value STREQUAL "" OR value MATCHES "-NOTFOUND$")
        continue()  # not found, and the configure went on: optional
      endif()
      if(cmd STREQUAL "find_path")
        list(GET args 1 name)
        if(name STREQUAL "NAMES")
          list(GET args 2 name)
        endif()
        set(value "${value}/${name}")
      endif()
      list(APPEND results "${value}")
    endif()
    foreach(result IN LISTS results)
      debian_package("${result}" package provides)
      if(NOT package IN_LIST found)
        list(APPEND found ${package})
        list(APPEND found_names "${package}=${package},${provides}")
        list(APPEND found_reasons "  ${package}: ${cmd}(${first_arg}) at ${where}:${line} found ${result}")
      endif()
    endforeach()
  endforeach()

  # Both ways: every package found is listed (by its name or one it provides), every one listed found.
  set(satisfied "")
  foreach(entry IN LISTS found_names)
    string(REGEX REPLACE "^([^=]+)=(.*)$" "\\1;\\2" entry "${entry}")
    list(GET entry 0 package)
    list(GET entry 1 names)
    string(REPLACE "," ";" names "${names}")
    set(hit "")
    foreach(name IN LISTS names)
      if(name IN_LIST listed)
        set(hit ${name})
      endif()
    endforeach()
    if(hit STREQUAL "")
      string(APPEND failures "\n'${variant}' (${flags}): the configure needs ${package}; README does not list it")
    else()
      list(APPEND satisfied ${hit})
    endif()
  endforeach()
  foreach(name IN LISTS listed)
    if(NOT name IN_LIST satisfied)
      string(APPEND failures "\n'${variant}' (${flags}): README lists ${name}; the configure looks for nothing in it")
    endif()
  endforeach()
  list(JOIN found_reasons "\n" reasons)
  list(JOIN satisfied " " satisfied)
  message(STATUS "'${variant}' (${flags}) needs g++ cmake ${satisfied}:\n${reasons}")
endforeach()
if(failures)
  message(FATAL_ERROR "README.md's package lists and the configure disagree:${failures}")
endif()
