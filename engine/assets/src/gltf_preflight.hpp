// SPDX-License-Identifier: MIT
#pragma once
// Private: the checks that must pass before tinygltf is allowed to look at a file.
// tinygltf trusts much of what a file says (it indexes bufferViews and buffers it has not
// range-checked, reads external files relative to the working directory as well as the
// glTF's directory, and takes GLB chunk lengths loosely), so the container, every URI,
// every buffer and bufferView range and the extension lists are checked here first, on our
// own parse of the JSON.
#include <cstdint>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "gltf_context.hpp"

namespace engine::assets::detail {

// Deepest JSON nesting accepted: tinygltf converts extras/extensions recursively, so a
// hostile file nesting arrays a million deep would otherwise overflow the stack.
inline constexpr int kMaxJsonDepth = 64;

struct Container {
    bool binary = false;                 // a GLB
    std::span<const std::uint8_t> json;  // the JSON text
    std::span<const std::uint8_t> bin;   // the GLB BIN chunk's payload; empty if none
    bool hasBin = false;
};

// Splits a GLB into its chunks, checking the header and every chunk length against the
// file; anything else is taken as JSON text.
Container splitContainer(const LoadContext& ctx, std::span<const std::uint8_t> file);

struct Preflight {
    // The JSON tinygltf is given: the file's own (jsonForParser empty), or a rewrite without
    // the "indices" of Draco primitives. tinygltf 2.7 insists that every indices accessor has
    // a bufferView, which a Draco primitive's never has (the indices are in the compressed
    // data), so with tinygltf's own Draco decoding off it would refuse every valid Draco file.
    // The indices accessors are kept here instead, per (mesh, primitive).
    std::string jsonForParser;
    std::map<std::pair<std::size_t, std::size_t>, int> dracoIndices;
};

// Parses the JSON (depth-limited) and checks the document-level rules listed above.
// Warnings (extensions only used, unknown GLB chunks) go to ctx.
Preflight preflight(const LoadContext& ctx, const Container& container);

bool isDataUri(std::string_view uri);

// Checks a URI found at `field` (e.g. "buffers[0].uri"): a data: URI passes as is; anything
// else must be a relative path without "..", without a scheme and not absolute (also after
// percent-decoding). Returns the percent-decoded relative path ("" for data: URIs).
std::string checkUri(const LoadContext& ctx, const std::string& field, const std::string& uri);

// The canonical path of `relative` under ctx.baseDir; fails naming `field` when the file does
// not exist or resolves (through symbolic links) outside the base directory.
std::filesystem::path resolveConfined(const LoadContext& ctx, const std::string& field, const std::string& uri,
                                      const std::string& relative);

// True when `path` exists and canonically lies under ctx.baseDir.
bool isConfined(const LoadContext& ctx, const std::filesystem::path& path);

}  // namespace engine::assets::detail
