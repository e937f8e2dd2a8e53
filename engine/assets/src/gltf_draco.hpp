// SPDX-License-Identifier: MIT
#pragma once
// Private: KHR_draco_mesh_compression decoding with the Draco library.
//
// tinygltf 2.7 can decode Draco itself (TINYGLTF_ENABLE_DRACO), but it does so while parsing,
// before anything can be checked: it indexes the bufferView and buffer without range checks,
// dereferences a missing Draco attribute, ignores its own failures, and overwrites the
// accessors' counts with whatever Draco produced, so a count mismatch can no longer be seen.
// (Debian's prebuilt libtinygltf is built without Draco at all.) We therefore compile
// tinygltf without it and decode here, after the preflight checks, comparing Draco's output
// with what the accessors declare.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "gltf_context.hpp"

namespace engine::assets::detail {

inline constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

struct DracoPrimitive {
    std::size_t vertexCount = 0;
    std::vector<std::uint32_t> indices;                    // triangle list, every index < vertexCount
    std::map<std::string, std::vector<float>> attributes;  // glTF name -> vertexCount * components
};

// Decodes the primitive's Draco data; `field` names the primitive ("meshes[0].primitives[1]"),
// `indicesAccessor` is its indices accessor (-1: none), which preflight kept from tinygltf.
// Fails when the data does not decode to a triangle mesh, or when its index count, vertex
// count or attribute component counts disagree with the primitive's accessors.
DracoPrimitive decodeDraco(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                           int indicesAccessor, const std::string& field);

}  // namespace engine::assets::detail
