// SPDX-License-Identifier: MIT
#pragma once
// The render backend interface, chosen at run time (--backend soft|gl|vk). In the spirit of
// bgfx's RendererContextI and Filament's driver API: typed generation-checked handles,
// plain descriptor structs whose defaults are the sensible choice, state as data.
// Every misuse (stale handle, wrong format, bad size) throws engine::Error naming it.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/render/buffer.hpp"
#include "engine/render/fragment_capture.hpp"
#include "engine/render/handles.hpp"
#include "engine/render/pass.hpp"
#include "engine/render/pipeline.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace engine::render {

// What a pipeline became after creation-time simplification, so callers and tests can
// see which work was skipped ([PCSX2] "alpha testing is useless here").
struct PipelineInfo {
    bool alphaTestDropped = false;   // the test could not change the result
    bool blendIsPlainWrite = false;  // ONE/ZERO ADD on every target: the no-blend path
    bool exact = true;               // false where a backend can only approximate the state (GL fail modes)
    std::string note;                // why, when not exact
};

// Texels read back, one float per stored channel, row 0 at the top. Normalized formats
// give stored/255 (sRGB values are NOT decoded), float formats their value, D32F depth.
struct Readback {
    int width = 0;
    int height = 0;
    int channels = 0;
    Format format = Format::RGBA8_UNORM;
    std::vector<float> values;
    float at(int x, int y, int c) const { return values[(std::size_t(y) * width + x) * channels + c]; }
};

struct PassTiming {
    std::string pass;
    double milliseconds = 0.0;  // soft: wall time of the pass; GL: GL_TIME_ELAPSED
    bool skipped = false;       // its PassDesc::drawOnlyIfSamplesIn found no sample: no draw ran
};

// Which of a pixel's samples a multisampled depth resolves to; never an average, which would
// invent surfaces between foreground and background ([Hathaway 2010] §3.5.1).
enum class DepthResolve : std::uint8_t {
    Closest,    // the sample closest to the observer under ResolveDesc::depthFunc (§3.5.1)
    AnySample,  // one of the pixel's samples, the implementation's choice: all OpenGL ES 3.0's
                // glBlitFramebuffer offers (ES 3.0 §4.3.3), so at a silhouette it may be the
                // farther one. A driver that keeps the closest keeps it here too (it is a sample).
};

struct ResolveDesc {
    TextureHandle source;       // multisampled colour or depth
    TextureHandle destination;  // single-sampled, same format and size
    // Depth resolve keeps the sample `depthResolve` names (the closest under this depth
    // function by default); colour resolve averages the samples.
    CompareFunc depthFunc = CompareFunc::Less;
    DepthResolve depthResolve = DepthResolve::Closest;
};

class Backend {
public:
    virtual ~Backend() = default;
    virtual std::string name() const = 0;

    virtual TextureHandle createTexture(const TextureDesc& desc, const TextureData* data = nullptr) = 0;
    virtual BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) = 0;
    virtual void updateBuffer(BufferHandle buffer, std::uint64_t offset, std::span<const std::byte> data) = 0;
    // A module's program (program_desc.hpp); pipelines run it through PipelineDesc::program.
    // Throws engine::Error when the description lacks this backend's part or does not compile.
    virtual ProgramHandle createProgram(const ProgramDesc& desc) = 0;
    virtual PipelineHandle createPipeline(const PipelineDesc& desc) = 0;
    virtual void destroy(TextureHandle texture) = 0;
    virtual void destroy(BufferHandle buffer) = 0;
    virtual void destroy(PipelineHandle pipeline) = 0;
    // A program still used by a pipeline stays alive until that pipeline is destroyed.
    virtual void destroy(ProgramHandle program) = 0;

    // Occlusion queries, filled by a pass's PassDesc::countSamplesInto and read by another's
    // drawOnlyIfSamplesIn (sun visibility for light shafts, as lens flares use them).
    virtual QueryHandle createQuery(const std::string& name) = 0;
    virtual void destroy(QueryHandle query) = 0;
    // Whether the last pass that counted into `query` found a sample; GL waits for the
    // result. Throws when no pass has counted into it yet.
    virtual bool anySamplesPassed(QueryHandle query) = 0;

    virtual const TextureDesc& describe(TextureHandle texture) const = 0;
    virtual PipelineInfo pipelineInfo(PipelineHandle pipeline) const = 0;

    virtual void beginPass(const PassDesc& pass) = 0;
    virtual void draw(const DrawDesc& draw) = 0;
    virtual void endPass() = 0;
    // Ends the open pass without running what was recorded in it; nothing when no pass is
    // open. PassScope calls it when an error unwinds through a pass, so the backend is never
    // left inside one. A query the pass counted into reads as never counted.
    virtual void abortPass() noexcept = 0;

    virtual void resolve(const ResolveDesc& resolve) = 0;
    virtual Readback readback(TextureHandle texture) = 0;

    // Per-pass timings since the last call, in execution order.
    virtual std::vector<PassTiming> takeTimings() = 0;

    // The end of a frame, called by the game loop and the benchmark after the frame graph ran: a
    // backend with per-frame resources in flight (Vulkan's ring of fenced frame slots) submits
    // the frame here; soft and GL have nothing to do. Never inside a pass.
    virtual void endFrame() {}

    // Capabilities only some backends have: null where this one has none (asked for through
    // the interface, so no caller downcasts a Backend).
    virtual FragmentCapture* fragmentCapture() { return nullptr; }
};

}  // namespace engine::render
