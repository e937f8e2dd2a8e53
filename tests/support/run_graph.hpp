// SPDX-License-Identifier: MIT
#pragma once
// A one-off frame graph for tests, run the way the racer and the bench run a frame: the
// engine's textures imported, the passes under test added, a side-effect "present" pass
// reading the frame (so nothing that made it is culled), then compile and execute with a
// TransientTexturePool on the test's backend. Techniques (run_technique.hpp), features
// (run_feature.hpp) and the engine-hosted SSAM (run_ssam.hpp) are run only this way, so a
// test runs the path the product runs.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/frame_graph/backend_textures.hpp"
#include "engine/render/frame_graph/color_depth.hpp"
#include "engine/render/frame_graph/side_effect_pass.hpp"
#include "engine/render/frame_graph/transient_texture_pool.hpp"

namespace test_support {

class OneFrameGraph {
public:
    // The transients come from `pool` (kept across frames, as the racer keeps its pool), or
    // from a pool of this frame's own.
    explicit OneFrameGraph(engine::render::Backend& backend, engine::render::TransientTexturePool* pool = nullptr)
        : backend_(backend), ownPool_(pool ? nullptr : std::make_unique<engine::render::TransientTexturePool>(backend)),
          pool_(pool ? *pool : *ownPool_) {}

    engine::render::FrameGraph& graph() { return graph_; }
    engine::render::Backend& backend() const { return backend_; }

    // A texture of the backend's, imported: the graph reads and writes it, never frees it.
    engine::render::FrameGraphTexture import(engine::render::TextureHandle texture) {
        const engine::render::TextureDesc& d = backend_.describe(texture);
        return graph_.importTexture(d.name + " #" + std::to_string(imports_++), engine::render::graphDescOf(d),
                                    engine::render::toConcrete(texture));
    }
    engine::render::ColorDepth import(engine::render::TextureHandle color, engine::render::TextureHandle depth) {
        return {import(color), import(depth)};
    }

    // Calls `use` with the backend textures behind `textures` after every pass declared so
    // far (a capture pass, which keeps transients alive until it ran). An invalid texture
    // (a pass that had nothing to write) is given as a null handle.
    void use(const std::vector<engine::render::FrameGraphTexture>& textures,
             std::function<void(const std::vector<engine::render::TextureHandle>&)> use) {
        struct Data {
            std::vector<engine::render::FrameGraphTexture> read;
        };
        graph_.addPass<Data>(
            "test capture " + std::to_string(captures_++),
            [&](engine::render::FrameGraph::Builder& b, Data& d) {
                for (engine::render::FrameGraphTexture t : textures) d.read.push_back(t.isValid() ? b.read(t) : t);
                b.sideEffect();
            },
            [use = std::move(use)](const engine::render::FrameGraph::Resources& r, const Data& d) {
                std::vector<engine::render::TextureHandle> handles;
                for (engine::render::FrameGraphTexture t : d.read)
                    handles.push_back(t.isValid() ? engine::render::toTextureHandle(r.get(t))
                                                  : engine::render::TextureHandle{});
                use(handles);
            });
    }

    // use() that reads `textures` back: readBacks()[first + i] after run(), where `first` is
    // what this returns; a null texture reads back empty.
    std::size_t readBack(const std::vector<engine::render::FrameGraphTexture>& textures) {
        const std::size_t first = readBacks_.size();
        readBacks_.resize(first + textures.size());
        use(textures, [this, first](const std::vector<engine::render::TextureHandle>& handles) {
            for (std::size_t i = 0; i < handles.size(); ++i)
                if (handles[i].valid()) readBacks_[first + i] = backend_.readback(handles[i]);
        });
        return first;
    }

    // Adds "present" reading `frame`, then compiles and executes; returns the passes that ran.
    const std::vector<std::string>& run(const engine::render::ColorDepth& frame) {
        engine::render::addSideEffectPass(graph_, "present", frame);
        graph_.execute(pool_.allocator());
        pool_.endFrame();
        return graph_.executedPassNames();
    }

    // The same for a frame that is a colour alone (an overlay's target).
    const std::vector<std::string>& run(engine::render::FrameGraphTexture color) {
        use({color}, [](const std::vector<engine::render::TextureHandle>&) {});
        graph_.execute(pool_.allocator());
        pool_.endFrame();
        return graph_.executedPassNames();
    }

    const std::vector<engine::render::Readback>& readBacks() const { return readBacks_; }

private:
    engine::render::Backend& backend_;
    std::unique_ptr<engine::render::TransientTexturePool> ownPool_;
    engine::render::TransientTexturePool& pool_;
    engine::render::FrameGraph graph_;
    std::vector<engine::render::Readback> readBacks_;
    int imports_ = 0, captures_ = 0;
};

}  // namespace test_support
