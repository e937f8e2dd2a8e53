// Plain alpha testing, the baseline SSAM replaces (seeds/000 §3.2, seeds/001): foliage drawn
// into the opaque targets before their resolve, discarding fragments below the reference,
// with depth test and write and no culling. Only RGB is written: the texture's alpha decides
// coverage, the frame's alpha stays the opaque 1.
#include <string>

#include "engine/core/error.hpp"
#include "foliage_draws.hpp"
#include "techniques.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

class AlphaTestTechnique final : public Technique {
public:
    AlphaTestTechnique(Backend& backend, const TechniqueOptions& options) : backend_(backend) {
        if (!(options.alphaTestReference >= 0.0f && options.alphaTestReference <= 1.0f))
            throw engine::Error("alpha-test: alphaTestReference " + std::to_string(options.alphaTestReference) +
                                " is outside [0, 1]");
        PipelineDesc p;
        p.name = "foliage alpha test";
        p.program = ProgramKind::FoliageColor;
        p.depth = DepthState::testAndWrite(options.ssam.depthFunc);
        p.raster.cull = CullMode::None;
        p.alphaTest = AlphaTest::discardBelow(options.alphaTestReference);
        p.blend[0].writeMask = WriteRGB;
        pipeline_ = backend_.createPipeline(p);
    }
    ~AlphaTestTechnique() override { backend_.destroy(pipeline_); }

    TechniqueKind kind() const override { return TechniqueKind::AlphaTest; }

    void render(ssam::OpaqueTargets& opaque, const FoliageFrame& frame) override {
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (!visible.empty()) {
            PassDesc pass = opaque.loadPassDesc();
            pass.name = "foliage alpha test";
            backend_.beginPass(pass);
            for (const FoliageDraw* draw : visible)
                backend_.draw(batchDraw(draw->batch, pipeline_, surfaceParams(frame, draw->batch)));
            backend_.endPass();
        }
        opaque.resolve();
    }

private:
    Backend& backend_;
    PipelineHandle pipeline_;
};

}  // namespace

std::unique_ptr<Technique> makeAlphaTestTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<AlphaTestTechnique>(backend, options);
}

}  // namespace transparency::detail
