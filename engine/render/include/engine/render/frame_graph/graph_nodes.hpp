// SPDX-License-Identifier: MIT
#pragma once
// The frame graph's internal bookkeeping: passes, virtual textures and the versions of
// their contents. Only FrameGraph and its .cpp files use these; they live in a header
// because FrameGraph stores them by value and addPass() is a template.
#include "engine/render/frame_graph/compile_results.hpp"
#include "engine/render/frame_graph/texture_allocator.hpp"
#include "engine/render/frame_graph/texture_desc.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace engine::render {
class FrameGraphResources;
}

namespace engine::render::frame_graph_detail {

inline constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A pass's execute lambda and its Data, with the types erased so passes of different
// Data can sit in one vector. Data lives here so its address is stable for the graph's life.
class PassExecutor {
public:
    virtual ~PassExecutor() = default;
    virtual void execute(const FrameGraphResources& resources) = 0;
};

template <typename Data, typename Execute>
class TypedPassExecutor final : public PassExecutor {
public:
    explicit TypedPassExecutor(Execute execute) : execute_(std::move(execute)) {}
    void execute(const FrameGraphResources& resources) override { execute_(resources, std::as_const(data)); }

    Data data{};

private:
    Execute execute_;
};

struct PassNode {
    std::string name;
    std::unique_ptr<PassExecutor> executor;
    std::vector<std::uint32_t> reads;   // version nodes
    std::vector<std::uint32_t> writes;  // version nodes this pass produced
    bool sideEffect = false;
    bool markedEmpty = false;

    // Decided by compile().
    PassStatus status = PassStatus::Executes;
    std::uint32_t missingInput = kNone;  // the read that made it InputEmpty
    std::size_t refCount = 0;            // written versions something still reads
};

// One state of a texture's contents. Every write makes a new one, so the graph is a DAG
// of passes and versions in which declaration order is already a topological order.
struct VersionNode {
    std::uint32_t resource = kNone;
    std::uint32_t version = 0;
    std::uint32_t writer = kNone;  // kNone for version 0 (as created or imported)

    // Decided by compile(): the version whose contents this one really holds. It is this
    // node when its writer runs, an older version when the writer is empty (the texture
    // was left untouched), and kNone when nothing ever put contents there.
    std::uint32_t content = kNone;
    std::size_t refCount = 0;  // running passes that read this content
};

struct VirtualResource {
    std::string name;
    FrameGraphTextureDesc desc;
    bool imported = false;
    ConcreteTexture importedTexture = 0;
    std::vector<std::uint32_t> versions;  // version node per version number

    // Decided by compile(); empty when no running pass touches it.
    std::optional<ResourceLifetime> lifetime;
};

}  // namespace engine::render::frame_graph_detail
