// SPDX-License-Identifier: MIT
#pragma once
// The committed content, generated: `generateContent(dir)` writes every file under dir
// (textures/*.png, models/*.glb) and returns their paths relative to dir, in a fixed order.
// Deterministic: fixed seeds, our own PRNG (prng.hpp), fixed encoder settings; the same
// toolchain and libraries (OpenImageIO/libpng/zlib, Draco) give byte-identical files, which
// a unit test checks against the committed copies.
#include <filesystem>
#include <vector>

namespace content {

// The set is written whole or not at all: every file to a temporary name first, then all
// renamed into place together (engine/core/output_file.hpp). draco false writes the plants'
// meshes plain (the web page's content, game/web: no Draco decoder there); the rest is the same.
std::vector<std::filesystem::path> generateContent(const std::filesystem::path& dir, bool draco = true);

// The paths generateContent() writes, relative to its dir, without making anything: for a
// tool to check every place it will write before the work.
std::vector<std::filesystem::path> contentFiles();

}  // namespace content
