// SPDX-License-Identifier: MIT
#pragma once
// What a render driver implements: the narrow half under the one front end (device.hpp), in
// the spirit of bgfx's RendererContextI and Filament's DriverAPI. The Device owns every handle,
// checks every call (validation.hpp), resolves every draw's state (resolved_draw_state.hpp),
// asks the memory budget and keeps the pass timings' names; a driver receives only what was
// validated and resolved, with its resources named by the indices it gave them (NativeId).
// A driver still refuses what only it cannot do (a sample count its API lacks, a program
// without its part), naming the resource as the Device does.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/memory_budget.hpp"
#include "engine/render/resolved_draw_state.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/validation.hpp"

namespace engine::render {

// A driver's own index of a resource it made (a texture, buffer, program or query slot).
using NativeId = std::uint32_t;
inline constexpr NativeId kNoNative = ~NativeId(0);

// How a driver reaches the native index behind a handle found inside a draw's parameter
// block (a texture a program samples); the Device implements it. Throws for a stale handle.
class NativeTextures {
public:
    virtual ~NativeTextures() = default;
    virtual NativeId texture(TextureHandle texture) const = 0;
};

// A pass the Device validated: its attachments as native indices, in attachment order.
struct DriverPass {
    const PassDesc* desc = nullptr;  // names, load operations and clear values
    std::uint64_t serial = 0;        // its number, which its DriverTiming repeats
    PassExtent extent;
    std::vector<NativeId> color;            // per PassDesc::color entry; kNoNative where it is empty
    NativeId depth = kNoNative;             // kNoNative: no depth attachment
    NativeId countSamplesInto = kNoNative;  // occlusion queries (kNoNative: none)
    NativeId drawOnlyIfSamplesIn = kNoNative;
    DrawTargets targets;  // what the draws' resolved state was resolved against
};

// A draw the Device validated, with its state resolved for the open pass.
struct DriverDraw {
    const DrawDesc* desc = nullptr;
    const PipelineDesc* pipeline = nullptr;
    const ResolvedDrawState* state = nullptr;
    NativeId program = kNoNative;
    NativeId vertices = kNoNative, indices = kNoNative, instances = kNoNative;  // kNoNative: none
    bool fullscreen = false;                                                    // the program's VertexInput::Fullscreen
};

// A pass's time as the driver measured it (soft: wall time; GL: GL_TIME_ELAPSED; Vulkan:
// timestamps) and whether its drawOnlyIfSamplesIn skipped its draws.
struct DriverTiming {
    std::uint64_t serial = 0;  // DriverPass::serial of the pass
    double milliseconds = 0.0;
    bool skipped = false;
};

// The calls every driver carries out itself, listed once: the interface below declares them pure
// and each driver's class declares its overrides with ENGINE_DRIVER_CALLS(ENGINE_DRIVER_OVERRIDE),
// so a signature is written here alone. X(result, name, parameters, qualifiers):
//   createProgram          a module's program: throws when it lacks this driver's part or does
//                          not compile
//   createStandardProgram  `neutral` is the backend-neutral description, which the driver
//                          completes with its own part (its GLSL, its CPU kernel)
//   anySamplesPassed       the result of the last pass that counted into a query the Device
//                          knows was counted
//   endPass                the open pass's query (if any) was counted; its timing is taken later
//   takeTimings            one entry per pass ended since the last call, in order (a pass whose
//                          endPass threw or that was aborted may have none)
#define ENGINE_DRIVER_CALLS(X)                                                                                       \
    X(NativeId, createTexture, (const TextureDesc& desc, const TextureData* data, const std::string& what), )        \
    X(NativeId, createBuffer, (const BufferDesc& desc, std::span<const std::byte> data, const std::string& what), )  \
    X(void, updateBuffer, (NativeId buffer, std::uint64_t offset, std::span<const std::byte> data), )                \
    X(NativeId, createProgram, (std::shared_ptr<const ProgramDesc> desc), )                                          \
    X(NativeId, createStandardProgram, (ProgramKind kind, ProgramDesc neutral), )                                    \
    X(void, destroyTexture, (NativeId texture), )                                                                    \
    X(void, destroyBuffer, (NativeId buffer), )                                                                      \
    X(void, destroyProgram, (NativeId program), )                                                                    \
    X(void, destroyQuery, (NativeId query), )                                                                        \
    X(bool, anySamplesPassed, (NativeId query), )                                                                    \
    X(void, beginPass, (const DriverPass& pass), )                                                                   \
    X(void, draw, (const DriverDraw& draw), )                                                                        \
    X(void, endPass, (), )                                                                                           \
    X(void, abortPass, (), noexcept)                                                                                 \
    X(void, resolve, (NativeId source, NativeId destination, const ResolveDesc& resolve, const std::string& what), ) \
    X(Readback, readback, (NativeId texture, const TextureDesc& desc), )                                             \
    X(std::vector<DriverTiming>, takeTimings, (), )
#define ENGINE_DRIVER_PURE(result, name, parameters, qualifiers) virtual result name parameters qualifiers = 0;
#define ENGINE_DRIVER_OVERRIDE(result, name, parameters, qualifiers) result name parameters qualifiers override;

class Driver {
public:
    virtual ~Driver() = default;
    // As --backend spells it: "soft", "gl", "vk".
    virtual std::string name() const = 0;
    // One line naming what it runs on, for logs: "soft: 2 thread(s), avx2", GL's renderer.
    virtual std::string describe() const { return name(); }
    // Called once by the Device before anything else.
    virtual void attach(const NativeTextures& textures) = 0;
    // How the alpha test's fail modes are carried out (the resolver plans them for a driver
    // that emulates them).
    virtual FailModeEmulation failModeEmulation() const = 0;

    // The memory budget (memory_budget.hpp): what a texture costs this driver, and what it can
    // still allocate. The Device refuses a texture that does not fit before the driver sees it.
    virtual std::uint64_t textureFootprint(const TextureDesc& desc) const { return textureBytes(desc); }
    virtual MemoryProbe memoryProbe() const { return hostMemoryAvailable; }

    // What only this driver refuses of a texture the shared rules accepted (sample counts and
    // sizes its API lacks), checked before its initial data and the memory budget.
    virtual void checkTexture(const TextureDesc& /*desc*/, const TextureData* /*data*/, const std::string& /*what*/) {}
    // Why this driver cannot keep the closest sample of a multisampled depth (DepthResolve::Closest),
    // or empty where it can; the Device then refuses such a resolve with this reason.
    virtual std::string whyNoClosestDepthResolve() const { return {}; }
    // A pipeline about to be made: the driver may only add what it cannot do exactly to `info`.
    virtual void notePipeline(const PipelineDesc& /*desc*/, ResolvedPipeline& /*resolved*/) {}
    virtual NativeId createQuery(const std::string& name) = 0;

    // The calls every driver carries out itself (ENGINE_DRIVER_CALLS above).
    ENGINE_DRIVER_CALLS(ENGINE_DRIVER_PURE)

    virtual void endFrame() {}
    // Shows a single-sampled colour texture in the driver's window; false when there is none
    // to show it in (or it is minimised).
    virtual bool present(NativeId /*texture*/, const TextureDesc& /*desc*/) { return false; }
    virtual FragmentCapture* fragmentCapture() { return nullptr; }
};

}  // namespace engine::render
