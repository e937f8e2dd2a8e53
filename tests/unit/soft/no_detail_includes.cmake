# SPDX-License-Identifier: MIT
# Fails when code outside the engine includes one of the kernel library's detail/ headers: a
# program kernel is written against kernel/program_kernel.hpp and the headers beside it (and
# kernel/simd/); detail/ is the rasterizer's own and may change with it.
# cmake -DROOT=<source dir> -P no_detail_includes.cmake
file(GLOB_RECURSE sources LIST_DIRECTORIES false
  ${ROOT}/modules/*.hpp ${ROOT}/modules/*.cpp ${ROOT}/modules/*.h
  ${ROOT}/ssam/*.hpp ${ROOT}/ssam/*.cpp ${ROOT}/ssam/*.h
  ${ROOT}/game/*.hpp ${ROOT}/game/*.cpp ${ROOT}/game/*.h)
set(offenders "")
foreach(file IN LISTS sources)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]engine/render/kernel/detail/")
  foreach(line IN LISTS lines)
    file(RELATIVE_PATH rel ${ROOT} ${file})
    string(APPEND offenders "\n  ${rel}: ${line}")
  endforeach()
endforeach()
list(LENGTH sources count)
if(offenders)
  message(FATAL_ERROR "kernel/detail/ headers included outside the engine (include kernel/program_kernel.hpp and the headers beside it instead):${offenders}")
endif()
message(STATUS "${count} files of modules/, ssam/ and game/ include no kernel/detail/ header")
if(count LESS 50)
  message(FATAL_ERROR "only ${count} source files found under ${ROOT}: wrong ROOT?")
endif()
