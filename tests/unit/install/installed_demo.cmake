# SPDX-License-Identifier: MIT
# cmake -P script: `cmake --install --component demo` into a scratch prefix, then the installed
# racer and ssam-bench, run from an unrelated working directory, take their content from
# <prefix>/share/ssam (what --help shows as the default) and racer renders a frame with it.
#   -DBUILD_DIR= -DPREFIX= -DWORK=
include(${CMAKE_CURRENT_LIST_DIR}/install_steps.cmake)
file(REMOVE_RECURSE ${PREFIX} ${WORK})
file(MAKE_DIRECTORY ${WORK})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX} --component demo)
foreach(file bin/racer bin/ssam-bench share/ssam/models/car.glb share/ssam/textures/ground.png share/ssam/lod/levels.json)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "${file} was not installed")
  endif()
endforeach()

file(REAL_PATH ${PREFIX}/share/ssam content)
foreach(program racer ssam-bench)
  execute_process(COMMAND ${PREFIX}/bin/${program} --help WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${out}" "${content}" at)
  if(NOT rc EQUAL 0 OR at LESS 0)
    message(FATAL_ERROR "installed ${program} --help (exit ${rc}) does not show ${content} as its content:\n${out}${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env DISPLAY= WAYLAND_DISPLAY=
                        ${PREFIX}/bin/racer --headless --frames 1 --size 64x36 --capture frame.png
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/frame.png)
  message(FATAL_ERROR "the installed racer failed in ${WORK} (exit ${rc}):\n${out}${err}")
endif()
