# SPDX-License-Identifier: MIT
# Helpers shared by the install tests' cmake -P scripts.

# run(<command>...): runs it; any non-zero exit fails the test with the command's output.
# The combined output is left in `run_output` for the caller to inspect.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "step failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(run_output "${out}${err}" PARENT_SCOPE)
endfunction()

# install_library(<build dir> <prefix>): a fresh install of the `library` component.
function(install_library build prefix)
  file(REMOVE_RECURSE ${prefix})
  run(${CMAKE_COMMAND} --install ${build} --prefix ${prefix} --component library)
endfunction()

# expect_clean_configure(<output>): a consumer's configure must print no warning, ours or
# (through our package) a dependency's, e.g. Debian Imath's missing PyImath library.
function(expect_clean_configure output)
  if(output MATCHES "CMake Warning|CMake Deprecation Warning|does not exist|PyImath")
    message(FATAL_ERROR "the consumer's configure printed a warning:\n${output}")
  endif()
endfunction()

# The installing build's flags (-DBUILD_CXX_FLAGS= -DBUILD_LINKER_FLAGS=, empty unless given; the
# sanitizers in the asan preset): a program linked against its static libraries needs the same
# runtimes. `consumer_cmake_flags` for a CMake configure, `consumer_compile_flags` for a compiler
# run by hand.
set(consumer_cmake_flags "-DCMAKE_CXX_FLAGS=${BUILD_CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${BUILD_LINKER_FLAGS}")
separate_arguments(consumer_compile_flags UNIX_COMMAND "${BUILD_CXX_FLAGS} ${BUILD_LINKER_FLAGS}")
