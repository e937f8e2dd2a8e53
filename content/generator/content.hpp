#pragma once
// The committed content, generated: `generateContent(dir)` writes every file under dir
// (textures/*.png, models/*.glb) and returns their paths relative to dir, in a fixed order.
// Deterministic: fixed seeds, our own PRNG (prng.hpp), fixed encoder settings; the same
// toolchain and libraries (OpenImageIO/libpng/zlib, Draco) give byte-identical files, which
// a unit test checks against the committed copies.
#include <filesystem>
#include <vector>

namespace content {

std::vector<std::filesystem::path> generateContent(const std::filesystem::path& dir);

}  // namespace content
