// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>
#include <string>

namespace engine::render {

enum class BufferKind : std::uint8_t { Vertex, Index, Instance };

struct BufferDesc {
    std::string name;
    BufferKind kind = BufferKind::Vertex;
    std::uint64_t size = 0;  // bytes; Vertex: multiple of sizeof(Vertex), Index: of 4, Instance: of sizeof(Instance)
};

}  // namespace engine::render
