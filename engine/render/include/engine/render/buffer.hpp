// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>
#include <string>

#include "engine/render/vertex.hpp"

namespace engine::render {

enum class BufferKind : std::uint8_t { Vertex, Index, Instance };

struct BufferDesc {
    std::string name;
    BufferKind kind = BufferKind::Vertex;
    std::uint64_t size = 0;  // bytes; Vertex: multiple of sizeof(Vertex), Index: of 4, Instance: of sizeof(Instance)
};

// The size of one element of a buffer of `kind`: BufferDesc::size is a multiple of it.
constexpr std::uint64_t elementSize(BufferKind kind) {
    return kind == BufferKind::Vertex  ? sizeof(Vertex)
           : kind == BufferKind::Index ? sizeof(std::uint32_t)
                                       : sizeof(Instance);
}

}  // namespace engine::render
