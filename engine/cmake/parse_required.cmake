# SPDX-License-Identifier: MIT
# ssam_parse_required(<caller> <prefix> "<KEYWORD>;..." ${ARGN})
# cmake_parse_arguments for one-value keywords that are all required: sets <prefix>_<KEYWORD>
# and stops the configure with "<caller>: <KEYWORD> is missing" when one is not given. A macro,
# so that the variables land in the calling function (the registries' ssam_module() and
# ssam_technique()).
macro(ssam_parse_required caller prefix keywords)
  cmake_parse_arguments(${prefix} "" "${keywords}" "" ${ARGN})
  foreach(required IN ITEMS ${keywords})
    if(NOT DEFINED ${prefix}_${required})
      message(FATAL_ERROR "${caller}: ${required} is missing")
    endif()
  endforeach()
endmacro()
