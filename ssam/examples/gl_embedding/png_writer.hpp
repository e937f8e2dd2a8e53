#pragma once
// Writes the example's frame as a compressed PNG through libpng (Debian: libpng-dev).
#include <cstdint>
#include <string>
#include <vector>

namespace gl_embedding {

// `rgba` holds height rows of width * 4 bytes, the first row the top of the image.
// Returns false when the file cannot be written.
bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba);

}  // namespace gl_embedding
