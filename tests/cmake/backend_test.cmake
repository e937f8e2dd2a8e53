# SPDX-License-Identifier: MIT
# ssam_backend_test(<name> BACKEND gl|gles|vk SOURCES <file>... LIBS <target>...
#                   [TEST_FILTER <gtest filter>] [ALSO_LABELS <label>...])
# One GoogleTest binary in build/bin for a GPU backend, each TEST one ctest test, as ssam_test
# but with the backend's probing main and the skip code:
#   gl  tests/unit/gl/gl_test_main.cpp: without a headless EGL context it says why and exits 77.
#   gles tests/conformance/gles/gles_test_main.cpp: as gl, for a headless EGL OpenGL ES 3.0 context
#       with what the GLES driver needs. Its tests are labelled gl as well as gles: the GL
#       label's runs (CI's sanitizer pass) cover both GL drivers.
#   vk  tests/unit/vk/vk_test_main.cpp: without a Vulkan 1.3 device and the validation layer it
#       says why and exits 77, or 1 with CI=true (CI cannot pass without running them).
# Both mains point Mesa's shader cache into the build tree. ctest reports exit 77 as skipped
# (SKIP_RETURN_CODE). The tests carry the backend's name as their label (`ctest -L gl`, `-L vk`
# run every test of a backend, whatever its layer).
#
# ALSO_LABELS adds labels (e.g. `unit`, so that the sanitizer pass's label set reaches them).
# gtest_discover_tests cannot pass two labels (its PROPERTIES flatten "a;b" into separate
# arguments), so a second ctest include file, read after the discovery's, sets the whole list on
# the discovered tests (<name>_TESTS, the list the discovery leaves).
function(ssam_backend_test name)
  cmake_parse_arguments(T "" "TEST_FILTER;BACKEND" "SOURCES;LIBS;ALSO_LABELS" ${ARGN})
  if(T_BACKEND STREQUAL "gl")
    set(main ${PROJECT_SOURCE_DIR}/tests/unit/gl/gl_test_main.cpp)
    set(backend_lib engine_render_gl)
  elseif(T_BACKEND STREQUAL "gles")
    set(main ${PROJECT_SOURCE_DIR}/tests/conformance/gles/gles_test_main.cpp)
    set(backend_lib engine_render_gles)
    list(APPEND T_ALSO_LABELS gl)
  elseif(T_BACKEND STREQUAL "vk")
    set(main ${PROJECT_SOURCE_DIR}/tests/unit/vk/vk_test_main.cpp)
    set(backend_lib engine_render_vk)
  else()
    message(FATAL_ERROR "ssam_backend_test(${name}): BACKEND must be gl, gles or vk, not '${T_BACKEND}'")
  endif()
  if(NOT T_TEST_FILTER)
    set(T_TEST_FILTER "*")
  endif()
  add_executable(${name} ${T_SOURCES} ${main})
  target_link_libraries(${name} PRIVATE ${T_LIBS} ${backend_lib} GTest::gtest GTest::gmock)
  target_compile_definitions(${name} PRIVATE SSAM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                             SSAM_BINARY_DIR="${PROJECT_BINARY_DIR}")
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests/support)
  ssam_warnings(${name})
  gtest_discover_tests(${name}
    DISCOVERY_MODE PRE_TEST
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}
    TEST_FILTER "${T_TEST_FILTER}"
    PROPERTIES LABELS ${T_BACKEND} SKIP_RETURN_CODE 77)
  if(T_ALSO_LABELS)
    ssam_discovered_test_labels(${name} ${T_BACKEND} ${T_ALSO_LABELS})
  endif()
endfunction()

# ssam_discovered_test_labels(<name> <label>...): the whole list on the tests that
# gtest_discover_tests(<name>) found, as ALSO_LABELS does (why: above).
function(ssam_discovered_test_labels name)
  set(script ${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake)
  file(WRITE ${script} "if(${name}_TESTS)\n  set_tests_properties(\${${name}_TESTS} PROPERTIES LABELS \"${ARGN}\")\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${script})
endfunction()
