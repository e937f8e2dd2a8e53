// SPDX-License-Identifier: MIT
#pragma once
// Writes an example's frame as a compressed PNG through libpng (Debian: libpng-dev).
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace gl_example {

// `rgba` holds height rows of width * 4 bytes, the first row the top of the image. The file is
// written whole or not at all: to a temporary file beside `path`, renamed over it once
// complete. Returns "" on success, else why the file could not be written.
std::string writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// Proves before any rendering that `path` can be written, by creating (and removing) a
// temporary file beside it: access() would answer yes to root even on /proc. Returns "" or why not.
std::string checkWritable(const std::string& path);
// checkWritable for each path given (an empty one is an output not asked for): the first reason, or "".
std::string checkWritable(std::initializer_list<std::string> paths);

}  // namespace gl_example
