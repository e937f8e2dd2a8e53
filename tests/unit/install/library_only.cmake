# SPDX-License-Identifier: MIT
# cmake -P script: configures the source tree with -DSSAM_LIBRARY_ONLY=ON in a scratch
# directory with every demo/tool/test dependency hidden from find_package (a REQUIRED search
# for one would fail the configure; CMake reports each as never used), builds it (Release: -O3),
# checks that only the library's sources were compiled, installs it and builds + runs the
# consumer against that install.
# The build is an embedder's plain one: SSAM_WERROR at its default (off), as a different
# compiler version may warn where the project's own does not.
#   -DSOURCE_DIR= -DWORK= -DCONSUMER_SOURCE=
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
file(REMOVE_RECURSE ${WORK})
set(hidden "")
foreach(package OpenImageIO glfw3 CLI11 GTest benchmark draco nlohmann_json)
  list(APPEND hidden -DCMAKE_DISABLE_FIND_PACKAGE_${package}=ON)
endforeach()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK}/build -DSSAM_LIBRARY_ONLY=ON -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON ${hidden})
# CMake names each hidden package's variable as unused: proof that nothing even asked for it.
string(REGEX MATCH "Manually-specified variables were not used by the project:[^\n]*\n(\n|  +[^\n]*\n)*" unused
       "${run_output}")
foreach(package OpenImageIO glfw3 CLI11 GTest benchmark draco nlohmann_json)
  if(NOT unused MATCHES "CMAKE_DISABLE_FIND_PACKAGE_${package}\n")
    message(FATAL_ERROR "the library-only configure looked for ${package}")
  endif()
endforeach()
if(run_output MATCHES "does not exist|PyImath")
  message(FATAL_ERROR "the library-only configure printed a dependency's warning:\n${run_output}")
endif()
run(${CMAKE_COMMAND} --build ${WORK}/build -j2)

# What was compiled: the engine core, render and its backends, and ssam; no tinygltf
# implementation, no image I/O, no scene, demo, module or test.
file(READ ${WORK}/build/compile_commands.json commands)
string(REGEX MATCHALL "\"file\": \"[^\"]+\"" compiled "${commands}")
list(LENGTH compiled count)
if(count EQUAL 0)
  message(FATAL_ERROR "compile_commands.json lists no source")
endif()
foreach(entry IN LISTS compiled)
  string(REGEX REPLACE "^\"file\": \"(.*)\"$" "\\1" file "${entry}")
  file(RELATIVE_PATH file ${SOURCE_DIR} ${file})
  if(NOT file MATCHES "^(engine/core|engine/render|ssam/src)/")
    message(FATAL_ERROR "the library-only build compiled ${file}")
  endif()
  if(file MATCHES "glfw")
    message(FATAL_ERROR "the library-only build compiled the GLFW window code (${file})")
  endif()
endforeach()
message(STATUS "${count} sources compiled, all the library's")

run(${CMAKE_COMMAND} --install ${WORK}/build --prefix ${WORK}/prefix)
if(EXISTS ${WORK}/prefix/bin OR EXISTS ${WORK}/prefix/share/ssam)
  message(FATAL_ERROR "the library-only install holds programs or demo content")
endif()
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${WORK}/consumer -DCMAKE_PREFIX_PATH=${WORK}/prefix
    -DCMAKE_BUILD_TYPE=Release)
expect_clean_configure("${run_output}")
run(${CMAKE_COMMAND} --build ${WORK}/consumer)
run(${WORK}/consumer/ssam_consumer)
