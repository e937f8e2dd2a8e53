// SPDX-License-Identifier: MIT
#pragma once
// Typed, generation-checked resource handles (sokol_gfx / bgfx style): plain values,
// zero means "none", and a destroyed-then-reused slot never aliases an old handle.
#include <cstdint>
#include <functional>

namespace engine::render {

template <typename Tag>
struct Handle {
    std::uint32_t index = 0;
    std::uint32_t generation = 0;  // 0: the null handle

    bool valid() const { return generation != 0; }
    explicit operator bool() const { return valid(); }
    friend bool operator==(Handle, Handle) = default;
};

using TextureHandle = Handle<struct TextureTag>;
using BufferHandle = Handle<struct BufferTag>;
using PipelineHandle = Handle<struct PipelineTag>;
using QueryHandle = Handle<struct QueryTag>;
using ProgramHandle = Handle<struct ProgramTag>;

}  // namespace engine::render
