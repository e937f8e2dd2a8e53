// SPDX-License-Identifier: MIT
#pragma once
// The frame graph: a frame described as passes that create, read and write virtual
// textures, so that the engine can drop work whose result nobody uses, order what is
// left, and give transient textures only the lifetime they need. Modelled on Filament's
// FrameGraph (filament/src/fg/FrameGraph.h), reduced to textures.
//
// Building. addPass<Data>(name, setup, execute) runs `setup(Builder&, Data&)` at once; it
// declares what the pass creates, reads and writes, and stores the handles it will need in
// Data. Handles are versioned: write() returns a new version, and read() and write() only
// accept the latest one, so every read refers to a pass declared earlier and the graph can
// have no cycle. The one way to try (a pass reading what it itself wrote) throws, as do
// reads of a texture nothing has written and stale handles.
//
// compile() decides, in this order:
//   1. Empty passes. A pass that called markEmpty() in setup has nothing to draw this
//      frame. It does not execute, and since it leaves its targets untouched, a version it
//      "wrote" holds whatever the previous version held: for an in-place write (say a
//      composite into the scene colour) that is the untouched previous contents; for a
//      texture nobody else wrote (a fresh mask) it is nothing. A pass that reads such a
//      version has no input, so it is skipped too (InputEmpty), and that propagates. So
//      with no foliage in view, an empty mask pass skips the composite that reads the
//      mask, and a present reading the scene colour after the composite presents the
//      opaque colour. (Reading a texture that no pass even declared writing is a bug, not
//      an empty frame: that throws at read().)
//   2. Culling, by Filament's reference counting over the passes still running: a pass is
//      referenced by each version it writes that a running pass reads; passes that reach
//      zero are culled and release their own inputs in turn. sideEffect() passes are never
//      culled. Empty and InputEmpty passes hold no references, so a producer whose only
//      consumer was skipped is culled too.
//   3. Order: the surviving passes in declaration order, and each transient texture's
//      lifetime, from its first to its last surviving user.
//
// execute(allocator) runs the surviving passes, allocating each transient just before its
// first user and releasing it just after its last. Imported textures are never allocated
// or released by the graph. The graph owns the frame's intermediates this way: a pass
// declares what it creates (Builder::create: a size relative to the frame, a format,
// samples) and the allocator (a TransientTexturePool) backs it only for its lifetime;
// keeping one longer (a capture of it) is one more pass reading it.
//
// A graph runs once. It is built for one frame and execute() refuses a second call
// (engine::Error): execute callbacks may therefore capture by reference what lives as long
// as that frame (the frame's draw lists, the technique's per-frame view), which a second
// run, a frame later, would find changed or gone.
#include "engine/render/frame_graph/builder.hpp"
#include "engine/render/frame_graph/compile_results.hpp"
#include "engine/render/frame_graph/graph_nodes.hpp"
#include "engine/render/frame_graph/resources.hpp"
#include "engine/render/frame_graph/texture_allocator.hpp"
#include "engine/render/frame_graph/texture_desc.hpp"
#include "engine/render/frame_graph/texture_handle.hpp"

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace engine::render {

class FrameGraph {
public:
    using Builder = FrameGraphBuilder;
    using Resources = FrameGraphResources;

    FrameGraph();
    ~FrameGraph();
    FrameGraph(const FrameGraph&) = delete;
    FrameGraph& operator=(const FrameGraph&) = delete;
    FrameGraph(FrameGraph&&) noexcept;
    FrameGraph& operator=(FrameGraph&&) noexcept;

    // Declares a pass; `setup(Builder&, Data&)` runs now, `execute(const Resources&, const
    // Data&)` during execute(). Names must be unique: errors and queries use them. Returns
    // the pass's Data, valid for the graph's lifetime, so later passes can use its handles.
    // If setup throws, the graph is left as it was before the call.
    template <typename Data, typename Setup, typename Execute>
    const Data& addPass(std::string name, Setup&& setup, Execute&& execute);

    // A texture that exists before the graph (the backbuffer, an engine-owned texture). Its
    // version 0 has contents, so passes may read it straight away.
    FrameGraphTexture importTexture(std::string name, const FrameGraphTextureDesc& desc, ConcreteTexture texture);

    const FrameGraphTextureDesc& desc(FrameGraphTexture texture) const;
    std::string_view name(FrameGraphTexture texture) const;

    // Idempotent; after it, no more passes or imports.
    void compile();
    bool isCompiled() const { return compiled_; }

    // Compiles if needed, then runs the surviving passes. Throws before running anything if
    // a transient texture is needed and the allocator lacks a callback, or if the graph has
    // already run (a graph runs once: see above). If a pass throws, the transients
    // allocated so far are released and the exception propagates.
    void execute(const TextureAllocator& allocator = {});
    bool hasExecuted() const { return ran_; }

    // After compile():
    PassStatus passStatus(std::string_view pass) const;
    std::vector<std::string> executionOrder() const;
    // Empty when no running pass uses the texture (imported textures get one too, for information).
    std::optional<ResourceLifetime> lifetime(FrameGraphTexture texture) const;

    // The transients some running pass uses, in the order they are allocated, each with the
    // first and last pass of its lifetime.
    std::vector<TransientInfo> transients() const;
    // The most bytes the transients hold at once during execute(): the largest sum, over
    // the running passes, of the transients alive while that pass runs. Textures the
    // allocator hands back within the frame are counted once per transient, so this is
    // what the frame needs, not what a pool happens to keep.
    std::uint64_t peakTransientBytes(const TextureBytes& bytesOf) const;

    // The passes the last execute() ran, in order (empty before any execute()).
    const std::vector<std::string>& executedPassNames() const { return executed_; }

    // Graphviz dot: passes are boxes, textures' versions are ellipses (imported ones with a
    // double border), reads and writes are edges. Culled passes and unused versions are
    // grey; empty and input-empty passes are grey and dashed, and a dotted edge links a
    // version such a pass wrote to the older version whose contents it still holds. Works
    // before compile(), when everything is drawn as alive. After compile() the graph's label
    // lists each transient's lifetime (first and last pass) and, given `bytesOf`, its bytes
    // and the frame's peak transient bytes.
    void dumpGraphviz(std::ostream& out, const TextureBytes& bytesOf = {}) const;
    // A line the compiled graph's label ends with: what the frame drew beside its passes
    // (racer: how many instances drew each level of detail).
    void addNote(std::string line) { notes_.push_back(std::move(line)); }

private:
    friend class FrameGraphBuilder;
    friend class FrameGraphResources;

    // Where the graph stood before a pass was declared, so a failing setup can be undone.
    struct DeclarationMark {
        std::uint32_t pass;
        std::size_t resourceCount;
        std::size_t nodeCount;
    };

    DeclarationMark beginPass(std::string name, std::unique_ptr<frame_graph_detail::PassExecutor> executor);
    void rollBack(const DeclarationMark& mark);
    void requireNotCompiled(std::string_view what) const;
    void requireCompiled(std::string_view what) const;

    // Builder operations, on behalf of pass `pass`.
    FrameGraphTexture createTexture(std::string name, const FrameGraphTextureDesc& desc);
    FrameGraphTexture readTexture(std::uint32_t pass, FrameGraphTexture texture);
    FrameGraphTexture writeTexture(std::uint32_t pass, FrameGraphTexture texture);

    // The version node behind a handle, or an engine::Error saying what `who` did wrong.
    std::uint32_t versionNode(FrameGraphTexture texture, std::string_view who, std::string_view verb) const;
    const frame_graph_detail::VirtualResource& resource(FrameGraphTexture texture, std::string_view who) const;
    std::uint32_t previousVersion(std::uint32_t node) const;
    std::uint32_t passIndex(std::string_view pass) const;

    // compile() steps.
    void resolveEmptyPasses();
    void cullUnreferencedPasses();
    void orderPassesAndLifetimes();

    static FrameGraphTexture handle(std::uint32_t resource, std::uint32_t version) { return {resource, version}; }

    std::vector<frame_graph_detail::PassNode> passes_;
    std::vector<frame_graph_detail::VirtualResource> resources_;
    std::vector<frame_graph_detail::VersionNode> nodes_;
    bool compiled_ = false;

    std::vector<std::uint32_t> executionOrder_;               // pass indices
    std::vector<std::vector<std::uint32_t>> allocateBefore_;  // per executionOrder_ position: transients
    std::vector<std::vector<std::uint32_t>> releaseAfter_;
    std::vector<std::string> executed_;
    std::vector<std::string> notes_;
    bool ran_ = false;
};

// `name` is moved into beginPass below; clang-tidy 14 misses a move made inside this template.
template <typename Data, typename Setup, typename Execute>
// NOLINTNEXTLINE(performance-unnecessary-value-param)
const Data& FrameGraph::addPass(std::string name, Setup&& setup, Execute&& execute) {
    using ExecuteFn = std::decay_t<Execute>;
    static_assert(std::is_default_constructible_v<Data>, "a pass's Data must be default-constructible");
    static_assert(std::is_invocable_v<Setup&, Builder&, Data&>, "setup must be callable as setup(Builder&, Data&)");
    static_assert(std::is_invocable_v<ExecuteFn&, const Resources&, const Data&>,
                  "execute must be callable as execute(const Resources&, const Data&)");

    auto executor = std::make_unique<frame_graph_detail::TypedPassExecutor<Data, ExecuteFn>>(
        ExecuteFn(std::forward<Execute>(execute)));
    Data& data = executor->data;
    const DeclarationMark mark = beginPass(std::move(name), std::move(executor));
    try {
        Builder builder(*this, mark.pass);
        setup(builder, data);
    } catch (...) {
        rollBack(mark);
        throw;
    }
    return data;
}

}  // namespace engine::render
