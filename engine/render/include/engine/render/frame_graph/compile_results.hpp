// SPDX-License-Identifier: MIT
#pragma once
// What FrameGraph::compile() decides about each pass and each transient texture.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "engine/render/frame_graph/texture_desc.hpp"

namespace engine::render {

enum class PassStatus {
    Executes,    // survives compile() and runs in execute()
    Culled,      // nothing that runs reads what it writes, and it is not a side-effect pass
    Empty,       // declared itself empty in setup (Builder::markEmpty()): nothing to draw
    InputEmpty,  // reads a texture whose only producers were empty, so it has nothing to work on
};

constexpr std::string_view toString(PassStatus status) {
    switch (status) {
        case PassStatus::Executes: return "executes";
        case PassStatus::Culled: return "culled";
        case PassStatus::Empty: return "empty";
        case PassStatus::InputEmpty: return "input empty";
    }
    return "?";
}

// When a texture must exist, as positions in FrameGraph::executionOrder(): a transient is
// allocated just before pass `first` runs and released just after pass `last` has run.
struct ResourceLifetime {
    std::size_t first = 0;
    std::size_t last = 0;

    bool operator==(const ResourceLifetime&) const = default;
};

// A transient texture of the compiled frame, named by the passes that bound its life.
struct TransientInfo {
    std::string name;
    FrameGraphTextureDesc desc;
    std::string firstPass;  // allocated just before this pass runs
    std::string lastPass;   // released just after this pass has run
};

// What a texture of a descriptor weighs in bytes; only the backend knows its formats
// (backend_textures.hpp backendTextureBytes).
using TextureBytes = std::function<std::uint64_t(const FrameGraphTextureDesc&)>;

}  // namespace engine::render
