// SPDX-License-Identifier: MIT
// Plain alpha testing, the baseline SSAM replaces ([Hathaway 2010] §3.2, [Moore 2015]): foliage drawn
// into the opaque targets before their resolve, discarding fragments below the material's
// alphaCutoff (glTF 2.0 alphaMode MASK) or one reference for all,
// with depth test and write and no culling. Only RGB is written: the texture's alpha decides
// coverage, the frame's alpha stays the opaque 1.
#include <map>
#include <string>
#include <utility>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class AlphaTestTechnique final : public SinglePassTechnique {
public:
    AlphaTestTechnique(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::AlphaTest}), backend_(backend), reference_(options.alphaTestReference),
          depthFunc_(options.depthFunc) {
        if (reference_) checkReference(*reference_, "alphaTestReference");
    }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const engine::render::TextureHandle> /*targets*/) override {
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (!visible.empty()) {
            PassDesc pass = opaque.loadPassDesc();
            pass.name = "foliage alpha test";
            PassScope passScope(backend_, pass);
            for (const FoliageDraw* draw : visible) {
                const float reference = reference_.value_or(draw->alphaCutoff);
                const SurfaceParams s = surfaceParams(frame, draw->batch);
                const LodDither dither = lodDitherOf(*draw);
                if (dither == LodDither::Off) {
                    backend_.draw(batchDraw(draw->batch, pipelineFor(reference, false), s));
                    continue;
                }
                const DitheredSurfaceParams dithered{s.viewProj, s.baseColorFactor, s.baseColor, s.light, dither};
                backend_.draw(batchDraw(draw->batch, pipelineFor(reference, true), dithered));
            }
            passScope.end();
        }
        opaque.resolve();
    }

private:
    static void checkReference(float reference, const char* what) {
        if (!(reference >= 0.0f && reference <= 1.0f))
            throw engine::Error(std::string("alpha-test: ") + what + " " + std::to_string(reference) +
                                " is outside [0, 1]");
    }

    // One pipeline per distinct reference (materials rarely differ), and per crossfade dither
    // (DitheredMaskedLit, made with the first crossfading batch). Made before it is entered,
    // so a refused reference or a create that throws leaves no empty entry behind.
    PipelineHandle pipelineFor(float reference, bool dithered) {
        const auto key = std::make_pair(reference, dithered);
        if (const auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
        checkReference(reference, "alphaCutoff");
        PipelineDesc p;
        p.name = dithered ? "foliage alpha test, crossfade dithered" : "foliage alpha test";
        p.program = ProgramKind::MaskedLit;
        if (dithered) {
            if (!ditheredProgram_.get())
                ditheredProgram_ = Owned<ProgramHandle>(backend_, backend_.createProgram(ditheredMaskedLitProgram()));
            p.program = ditheredProgram_.get();
        }
        p.depth = DepthState::testAndWrite(depthFunc_);
        p.raster.cull = CullMode::None;
        p.alphaTest = AlphaTest::discardBelow(reference);
        p.blend[0].writeMask = WriteRGB;
        Owned<PipelineHandle> pipeline(backend_, backend_.createPipeline(p));
        return pipelines_.emplace(key, std::move(pipeline)).first->second;
    }

    Backend& backend_;
    std::optional<float> reference_;
    CompareFunc depthFunc_;
    Owned<ProgramHandle> ditheredProgram_;  // before the pipelines that use it, so released after them
    std::map<std::pair<float, bool>, Owned<PipelineHandle>> pipelines_;
};

}  // namespace

std::unique_ptr<SinglePassTechnique> makeAlphaTestPass(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<AlphaTestTechnique>(backend, options);
}

std::unique_ptr<Technique> makeAlphaTestTechnique(Backend& backend, const TechniqueOptions& options) {
    return makeAlphaTestPass(backend, options);
}

}  // namespace transparency::detail
