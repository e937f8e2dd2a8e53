// SPDX-License-Identifier: MIT
// Hashed alpha testing [Wyman & McGuire 2017] (transparency/hashed_alpha.hpp): alpha testing,
// drawn like `alpha-test` into the opaque targets before their resolve with depth test and
// write and no culling, but each fragment is kept when its alpha reaches a threshold hashed
// from its texture coordinate at about one pixel's scale, seeded per instance. Coverage is
// right on average (a leaf of alpha 0.3 keeps 30% of its pixels, in a pattern fixed to the
// leaf), where a fixed reference keeps all or nothing.
//
// The per-instance seed comes from the instance's transform (seedOfInstance): the instance's
// index is no use, since extraction renumbers the visible instances every frame and draws a
// wind-bent plant as a batch of its own. So each instance is drawn alone with its seed as a
// uniform, from its own one-instance buffer (reused across frames): one draw per instance.
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "hashed_technique.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"
#include "transparency/hashed_alpha.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class HashedAlphaTechnique final : public SinglePassTechnique {
public:
    HashedAlphaTechnique(Backend& backend, const TechniqueOptions& options, bool seedPerFrame)
        : SinglePassTechnique({TechniqueKind::Hashed}), backend_(backend), options_(options.hashed),
          seedPerFrame_(seedPerFrame), program_(backend, backend.createProgram(hashedLitProgram())) {
        if (!(options_.hashScale > 0.0f && options_.hashScale < 1e6f))
            throw engine::Error("hashed: hashScale " + std::to_string(options_.hashScale) + " must be in (0, 1e6)");
        PipelineDesc p = foliagePipeline("foliage hashed alpha test");
        p.program = program_.get();
        p.depth = DepthState::testAndWrite(options.depthFunc);
        p.alphaTest = AlphaTest::discardBelow(0.5f);  // HashedLit outputs alpha 0 or 1
        p.blend[0].writeMask = WriteRGB;              // the frame's alpha stays 1
        pipeline_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(p));
    }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const engine::render::TextureHandle> /*targets*/) override {
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (!visible.empty()) {
            // Under TAA the threshold changes every frame, so that the history averages it.
            const std::uint32_t frameSeed =
                seedPerFrame_ ? pcg3d({std::uint32_t(frame.frameIndex), std::uint32_t(frame.frameIndex >> 32u), 7u}).x
                              : 0u;
            PassDesc pass = opaque.loadPassDesc();
            pass.name = "foliage hashed alpha test";
            PassScope passScope(backend_, pass);
            std::size_t slot = 0;
            for (const FoliageDraw* draw : visible) {
                const SurfaceParams s = surfaceParams(frame, draw->batch);
                HashedLitParams params{s.viewProj,         s.baseColorFactor,    s.baseColor, s.light,           0u,
                                       options_.hashScale, options_.anisotropic, false,       lodDitherOf(*draw)};
                if (!draw->batch.instances) {  // one identity instance
                    params.seed = seedOfInstance(glm::mat4(1.0f)) ^ frameSeed;
                    backend_.draw(batchDraw(draw->batch, pipeline_, params));
                    continue;
                }
                if (draw->instances.size() != draw->batch.instanceCount)
                    throw engine::Error("hashed: a draw has " + std::to_string(draw->instances.size()) +
                                        " CPU instances for instanceCount " +
                                        std::to_string(draw->batch.instanceCount));
                for (const Instance& instance : draw->instances) {
                    params.seed = seedOfInstance(instance.model) ^ frameSeed;
                    DrawDesc d = batchDraw(draw->batch, pipeline_, params);
                    d.instances = instanceBuffer(slot++, instance);
                    d.instanceCount = 1;
                    backend_.draw(d);
                }
            }
            passScope.end();
        }
        opaque.resolve();
    }

private:
    // The slot-th one-instance buffer, made on first use and rewritten every frame.
    BufferHandle instanceBuffer(std::size_t slot, const Instance& instance) {
        const auto bytes = std::as_bytes(std::span(&instance, 1));
        if (slot == buffers_.size()) {
            buffers_.push_back(Owned<BufferHandle>(
                backend_, backend_.createBuffer({"hashed instance", BufferKind::Instance, bytes.size()}, bytes)));
            return buffers_.back();
        }
        backend_.updateBuffer(buffers_[slot], 0, bytes);
        return buffers_[slot];
    }

    Backend& backend_;
    HashedOptions options_;
    bool seedPerFrame_;
    Owned<ProgramHandle> program_;
    Owned<PipelineHandle> pipeline_;
    std::vector<Owned<BufferHandle>> buffers_;
};

}  // namespace

std::unique_ptr<SinglePassTechnique> makeHashedTechniqueFor(Backend& backend, const TechniqueOptions& options,
                                                            bool seedPerFrame) {
    return std::make_unique<HashedAlphaTechnique>(backend, options, seedPerFrame);
}

std::unique_ptr<Technique> makeHashedTechnique(Backend& backend, const TechniqueOptions& options) {
    return makeHashedTechniqueFor(backend, options, false);
}

}  // namespace transparency::detail
