// SPDX-License-Identifier: MIT
#pragma once
// Private: reading accessors with every range checked. Offsets and lengths from the file are
// combined in 64 bits with overflow checks before any byte is touched (glTF 2.0 §3.6.2).
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "gltf_context.hpp"

namespace engine::assets::detail {

// Bit for a TINYGLTF_COMPONENT_TYPE_* value in a component-type mask.
constexpr std::uint32_t componentBit(int componentType) { return 1u << (componentType - TINYGLTF_COMPONENT_TYPE_BYTE); }
inline constexpr std::uint32_t kFloatOnly = componentBit(TINYGLTF_COMPONENT_TYPE_FLOAT);
inline constexpr std::uint32_t kSmallInts =
    componentBit(TINYGLTF_COMPONENT_TYPE_BYTE) | componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) |
    componentBit(TINYGLTF_COMPONENT_TYPE_SHORT) | componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);

const char* componentTypeName(int componentType);  // "FLOAT", "UNSIGNED_SHORT", ... or "unknown"
int componentSize(int componentType);              // bytes; 0 for a type glTF 2.0 does not have
int componentCount(int type);                      // TINYGLTF_TYPE_*: 1..16; 0 for an unknown type

struct AccessorRequest {
    std::string usage;                 // what reads it, for messages: "meshes[0].primitives[1].attributes.POSITION"
    std::initializer_list<int> types;  // accepted TINYGLTF_TYPE_* values
    std::uint32_t componentTypes;      // mask of accepted component types (componentBit)
    std::uint64_t maxCount;            // refused above this (bounds accessors without a bufferView)
};

// The bytes [offset, offset + length) of bufferViews[view], after checking the view against its
// buffer's actual data and the range against the view. `field` names what refers to the view.
const std::uint8_t* bufferViewBytes(const LoadContext& ctx, const tinygltf::Model& model, int view,
                                    std::uint64_t offset, std::uint64_t length, const std::string& field,
                                    const tinygltf::BufferView** viewOut);

// "accessors[3] (meshes[0].primitives[1].attributes.POSITION)"
std::string accessorField(int accessor, const std::string& usage);

// Checks the accessor's type, component type, normalisation, bufferView and byte range (and its
// sparse substitution), then converts every element to float (normalised integers to [0,1] or
// [-1,1], glTF 2.0 §3.11; other integers as their value, KHR_mesh_quantization).
// Returns count * componentCount(type) floats.
std::vector<float> readFloats(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                              const AccessorRequest& request);

// An index accessor: SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not normalised.
std::vector<std::uint32_t> readIndices(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                                       const std::string& usage, std::uint64_t maxCount);

}  // namespace engine::assets::detail
