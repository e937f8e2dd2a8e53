// SPDX-License-Identifier: MIT
// The exact ground truth every technique is judged against: every foliage fragment
// that passes the opaque depth test, none alpha-tested, sorted per pixel by depth and
// composited front to back with straight-alpha "over" ([Hargreaves 2009]) onto the opaque colour.
//
// How: the soft backend's fragment capture (Backend::fragmentCapture, setFragmentSink) runs the foliage
// with MaskedLit, the program every other technique shades foliage with, so the
// reference differs from them only in how the fragments are combined. Each pixel's list
// arrives in submission order (one thread per tile, triangles in order), is stable-sorted
// nearest first, so fragments at exactly the same depth (coplanar, or crossing exactly at
// the pixel centre) keep submission order: the earlier-submitted one is in front, as it
// would be under a depth test that rejects equal depths (LESS / GREATER: the first fragment
// at a depth wins). Per pixel, front to back:
//   C += T * a_i * c_i,  T *= (1 - a_i)       (a_i clamped to [0, 1]; non-finite c_i -> 0)
// and the result, C + T * opaque, is blended onto the opaque colour by the GPU (the Composite
// program with mask = T, blend ONE / SRC_ALPHA), so the target's encoding (sRGB) is handled
// exactly as for every other technique. Fragments with a = 0 change nothing and are not kept.
//
// Bounded memory: the screen is processed in bands of rows (the foliage is drawn once per
// band, scissored to it) and each pixel keeps at most referenceFragmentsPerPixel fragments,
// so a band holds at most kBandFragments. A deeper pixel keeps its nearest fragments, is
// counted in referenceReport() and logged: never truncated silently.
//
// GL: refused (fragment capture is a soft-backend feature). ssam-bench compares GL images
// against the soft reference, which is deterministic for any thread count.
#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "engine/render/screen_bounds.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

// Fragment slots one band may hold (at 20 bytes each: 320 MiB at most, usually far less as
// pixel lists only grow to the fragments they get).
constexpr std::size_t kBandFragments = std::size_t(1) << 24;

class BandSink final : public FragmentSink {
public:
    BandSink(int width, int y0, int rows, std::size_t cap, CompareFunc func)
        : width_(width), y0_(y0), cap_(cap), func_(func), pixels_(std::size_t(width) * rows),
          counts_(std::size_t(width) * rows, 0) {}

    void add(int x, int y, const CapturedFragment& f) override {
        if (!(f.color.a > 0.0f)) return;  // a = 0 (or NaN) changes nothing under "over"
        const std::size_t i = std::size_t(y - y0_) * width_ + x;
        ++counts_[i];
        std::vector<CapturedFragment>& list = pixels_[i];
        if (list.size() < cap_) {
            list.push_back(f);
            return;
        }
        // Over the cap: keep the nearest cap fragments (replace the farthest, the last one
        // in order among equals), the pixel is reported.
        auto farthest = list.begin();
        for (auto it = list.begin(); it != list.end(); ++it)
            if (!isCloser(func_, it->depth, farthest->depth)) farthest = it;
        if (isCloser(func_, f.depth, farthest->depth)) *farthest = f;
    }

    std::vector<CapturedFragment>& pixel(std::size_t i) { return pixels_[i]; }
    std::uint64_t count(std::size_t i) const { return counts_[i]; }

private:
    int width_, y0_;
    std::size_t cap_;
    CompareFunc func_;
    std::vector<std::vector<CapturedFragment>> pixels_;
    std::vector<std::uint64_t> counts_;
};

float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

class ReferenceTechnique final : public SinglePassTechnique {
public:
    ReferenceTechnique(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::Reference}), backend_(backend), fragments_(backend.fragmentCapture()),
          cap_(options.referenceFragmentsPerPixel), depthFunc_(options.depthFunc) {
        if (!fragments_)
            throw engine::Error("reference: the exact reference needs the soft backend's fragment capture (backend '" +
                                backend.name() + "'); render it with --backend soft and compare against that image");
        if (cap_ == 0) throw engine::Error("reference: referenceFragmentsPerPixel must be at least 1");
        PipelineDesc capture = foliagePipeline("reference capture");
        capture.depth = DepthState::testOnly(depthFunc_);
        capture_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(capture));
        PipelineDesc composite;
        composite.name = "reference composite";
        // "over" for the whole sorted stack at once: C + T * opaque (programs.hpp).
        compositeProgram_ = Owned<ProgramHandle>(backend_, backend_.createProgram(transmittanceCompositeProgram()));
        composite.program = compositeProgram_.get();
        composite.blend[0] = {true,         BlendFactor::One,  BlendFactor::SrcAlpha,
                              BlendOp::Add, BlendFactor::Zero, BlendFactor::One,
                              BlendOp::Add, WriteRGB};
        composite_ = Owned<PipelineHandle>(backend_, backend_.createPipeline(composite));
    }

    std::optional<ReferenceReport> referenceReport() const override { return report_; }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const engine::render::TextureHandle> /*targets*/) override {
        opaque.resolve();
        report_ = {};
        const int width = opaque.desc().width, height = opaque.desc().height;
        const auto visible = visibleDraws(frame, width, height);
        if (visible.empty()) return;
        const Rect region = screenRegion(visible, frame, width, height);

        // Premultiplied foliage colour C (rgb) and transmittance T, per pixel.
        std::vector<float> color(std::size_t(width) * height * 4, 0.0f),
            transmittance(std::size_t(width) * height, 1.0f);
        const std::size_t perRow = std::max<std::size_t>(1, std::size_t(width) * std::min(cap_, kBandFragments));
        const int bandRows = int(std::clamp<std::size_t>(kBandFragments / perRow, 1, std::size_t(height)));
        for (int y0 = region.y; y0 < region.y + region.height; y0 += bandRows) {
            const int rows = std::min(bandRows, region.y + region.height - y0);
            BandSink sink(width, y0, rows, cap_, depthFunc_);
            fragments_->setFragmentSink(&sink);
            try {
                PassScope scope(backend_, resolvedPass(opaque, "reference capture"));
                for (const FoliageDraw* draw : visible) {
                    DrawDesc d = batchDraw(draw->batch, capture_, surfaceParams(frame, draw->batch));
                    d.scissor = Rect{region.x, y0, region.width, rows};
                    backend_.draw(d);
                }
                scope.end();
            } catch (...) {
                fragments_->setFragmentSink(nullptr);
                throw;
            }
            fragments_->setFragmentSink(nullptr);
            compositeBand(sink, width, y0, rows, color, transmittance);
        }
        if (report_.pixelsOverCap > 0)
            engine::log::warn("reference: ", report_.pixelsOverCap, " pixel(s) have more than ", cap_,
                              " fragments (deepest ", report_.maxFragmentsPerPixel, "); ", report_.fragmentsOverCap,
                              " farthest fragment(s) were left out, so the reference is not exact there");
        upload(width, height, color, transmittance);

        compositeOnto(backend_, opaque, "reference composite", composite_,
                      TransmittanceCompositeParams{colorTexture_, transmittanceTexture_}, region);
    }

    std::vector<NamedTarget> intermediates() const override {
        if (!colorTexture_.get()) return {};
        return {{"reference_foliage", colorTexture_}, {"reference_transmittance", transmittanceTexture_}};
    }

private:
    void compositeBand(BandSink& sink, int width, int y0, int rows, std::vector<float>& color,
                       std::vector<float>& transmittance) {
        const CompareFunc func = depthFunc_;
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * width + x;
                std::vector<CapturedFragment>& list = sink.pixel(i);
                const std::uint64_t count = sink.count(i);
                if (count == 0) continue;
                report_.maxFragmentsPerPixel = std::max<std::size_t>(report_.maxFragmentsPerPixel, count);
                if (count > list.size()) {
                    ++report_.pixelsOverCap;
                    report_.fragmentsOverCap += count - list.size();
                }
                report_.fragments += list.size();
                std::stable_sort(list.begin(), list.end(),
                                 [func](const auto& a, const auto& b) { return isCloser(func, a.depth, b.depth); });
                glm::vec3 c(0.0f);
                float t = 1.0f;
                for (const CapturedFragment& f : list) {
                    const float a = clamp01(f.color.a);
                    glm::vec3 rgb(f.color);
                    for (int k = 0; k < 3; ++k)
                        if (!std::isfinite(rgb[k])) rgb[k] = 0.0f;
                    c += rgb * (t * a);
                    t *= 1.0f - a;
                }
                const std::size_t p = std::size_t(y0 + y) * width + x;
                for (int k = 0; k < 3; ++k) color[p * 4 + k] = c[k];
                transmittance[p] = t;
            }
    }

    void upload(int width, int height, const std::vector<float>& color, const std::vector<float>& transmittance) {
        destroyTargets();
        auto texture = [&](const char* name, Format format, std::span<const float> texels) {
            TextureDesc t;
            t.name = name;
            t.width = width;
            t.height = height;
            t.format = format;
            t.usage = UsageSampled;
            TextureData data;
            data.levels.push_back(std::as_bytes(texels));
            return Owned<TextureHandle>(backend_, backend_.createTexture(t, &data));
        };
        colorTexture_ = texture("reference foliage (premultiplied)", Format::RGBA32F, color);
        transmittanceTexture_ = texture("reference transmittance", Format::R32F, transmittance);
    }

    void destroyTargets() {
        colorTexture_.reset();
        transmittanceTexture_.reset();
    }

    Backend& backend_;
    FragmentCapture* fragments_;  // the backend's (Backend::fragmentCapture)
    std::size_t cap_;
    CompareFunc depthFunc_;
    // Owned: a create that throws leaves nothing made before it behind.
    Owned<ProgramHandle> compositeProgram_;
    Owned<PipelineHandle> capture_, composite_;
    Owned<TextureHandle> colorTexture_, transmittanceTexture_;
    ReferenceReport report_;
};

}  // namespace

std::unique_ptr<Technique> makeReferenceTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<ReferenceTechnique>(backend, options);
}

}  // namespace transparency::detail
