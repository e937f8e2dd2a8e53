// SPDX-License-Identifier: MIT
#pragma once
// The render front end: the one Backend every driver (soft, GL, Vulkan) sits under, as bgfx's
// bgfx.cpp sits over its RendererContextI and sokol_gfx's validation layer over its backends.
// It owns the handles and their pools, checks every call with the shared rules
// (validation.hpp), resolves each draw's state (resolved_draw_state.hpp), applies the memory
// budget (memory_budget.hpp) and names the pass timings; the driver (driver.hpp) receives
// only validated, resolved work and its own native indices. A check therefore exists once,
// here, and a new driver implements only its API.
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/driver.hpp"
#include "engine/render/resource_pool.hpp"

namespace engine::render {

class Device final : public Backend, private NativeTextures {
public:
    explicit Device(std::unique_ptr<Driver> driver);
    ~Device() override;
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    std::string name() const override { return driver_->name(); }

    TextureHandle createTexture(const TextureDesc& desc, const TextureData* data = nullptr) override;
    BufferHandle createBuffer(const BufferDesc& desc, std::span<const std::byte> data) override;
    void updateBuffer(BufferHandle buffer, std::uint64_t offset, std::span<const std::byte> data) override;
    ProgramHandle createProgram(const ProgramDesc& desc) override;
    PipelineHandle createPipeline(const PipelineDesc& desc) override;
    void destroy(TextureHandle texture) override;
    void destroy(BufferHandle buffer) override;
    void destroy(PipelineHandle pipeline) override;
    void destroy(ProgramHandle program) override;
    QueryHandle createQuery(const std::string& name) override;
    void destroy(QueryHandle query) override;
    bool anySamplesPassed(QueryHandle query) override;
    const TextureDesc& describe(TextureHandle texture) const override { return textures_.get(texture).desc; }
    PipelineInfo pipelineInfo(PipelineHandle pipeline) const override { return pipelines_.get(pipeline).info; }

    void beginPass(const PassDesc& pass) override;
    void draw(const DrawDesc& draw) override;
    void endPass() override;
    void abortPass() noexcept override;
    void resolve(const ResolveDesc& resolve) override;
    Readback readback(TextureHandle texture) override;
    std::vector<PassTiming> takeTimings() override;
    void endFrame() override;
    FragmentCapture* fragmentCapture() override { return driver_->fragmentCapture(); }

    // Shows a single-sampled colour texture in the driver's window and swaps; false when the
    // driver has no window to show it in or the window is minimised.
    bool present(TextureHandle texture);

    // The driver, for what only it offers (soft's work counters, GL's context, Vulkan's
    // validation count): driverAs<gl::GlDriver>() throws, naming both, when it is another.
    Driver& driver() { return *driver_; }
    const Driver& driver() const { return *driver_; }
    template <typename D>
    D& driverAs() const {
        if (auto* d = dynamic_cast<D*>(driver_.get())) return *d;
        throw Error("the " + driver_->name() + " driver does not offer what was asked of it");
    }

    // A texture the driver wraps rather than makes (a host's texture): `desc` is checked as
    // createTexture checks it, then `wrap` makes the driver's slot; destroy() hands it back to
    // the driver like any other. `what` names it in messages.
    TextureHandle adoptTexture(const TextureDesc& desc, const std::string& what, const std::function<NativeId()>& wrap);
    // The driver's index behind a handle (for a driver's interop calls).
    NativeId nativeTexture(TextureHandle texture) const { return textures_.get(texture).native; }

private:
    struct DeviceTexture {
        TextureDesc desc;
        NativeId native = kNoNative;
    };
    struct DeviceBuffer {
        BufferDesc desc;
        NativeId native = kNoNative;
        std::vector<std::byte> indices;  // an index buffer's contents, for validateDraw's messages
        std::uint32_t maxIndex = 0;      // their largest (largestIndex), kept per write
    };
    // A program lives while its handle or a pipeline that runs it does.
    struct DeviceProgram {
        DeviceProgram(Driver& driver, std::shared_ptr<const ProgramDesc> desc, NativeId native)
            : driver(driver), desc(std::move(desc)), native(native) {}
        ~DeviceProgram() {
            try {
                driver.destroyProgram(native);
            } catch (...) {  // a driver that cannot release it now (no context) leaks it, never throws here
            }
        }
        DeviceProgram(const DeviceProgram&) = delete;
        DeviceProgram& operator=(const DeviceProgram&) = delete;
        Driver& driver;
        std::shared_ptr<const ProgramDesc> desc;  // the backend-neutral description (validation)
        NativeId native;
    };
    struct DevicePipeline {
        PipelineDesc desc;
        PipelineInfo info;
        std::shared_ptr<const DeviceProgram> program;
    };
    struct DeviceQuery {
        std::string name;
        NativeId native = kNoNative;
        bool counted = false;  // a pass has counted into it (and was not aborted)
    };
    struct BegunPass {
        std::uint64_t serial = 0;
        std::string name;
    };

    NativeId texture(TextureHandle texture) const override { return textures_.get(texture).native; }
    std::shared_ptr<const DeviceProgram> programFor(const ProgramRef& ref);
    NativeId nativeBuffer(BufferHandle buffer) const { return buffer ? buffers_.get(buffer).native : kNoNative; }
    void requireNoOpenPass(const std::string& what) const;
    // What the open pass's recorded draws use may not be destroyed before it ends: soft and
    // Vulkan run their draws at endPass.
    template <typename Tag>
    void refuseIfTheOpenPassUses(Handle<Tag> handle, const std::vector<Handle<Tag>>& used, const char* kind,
                                 const std::string& name) const;

    // Declared first, destroyed last: every resource below is handed back to it.
    std::unique_ptr<Driver> driver_;
    ResourcePool<TextureTag, DeviceTexture> textures_{"texture"};
    ResourcePool<BufferTag, DeviceBuffer> buffers_{"buffer"};
    ResourcePool<ProgramTag, std::shared_ptr<const DeviceProgram>> programs_{"program"};
    ResourcePool<PipelineTag, DevicePipeline> pipelines_{"pipeline"};
    ResourcePool<QueryTag, DeviceQuery> queries_{"occlusion query"};
    std::array<std::shared_ptr<const DeviceProgram>, kStandardProgramCount> standardPrograms_;
    ResourceLookup lookup_;  // what the shared validation reads

    std::optional<PassDesc> pass_;
    DriverPass driverPass_;
    std::vector<TextureHandle> passTextures_;  // attachments and what its draws sample
    std::vector<BufferHandle> passBuffers_;
    std::vector<PipelineHandle> passPipelines_;
    std::uint64_t passSerial_ = 0;
    std::deque<BegunPass> begunPasses_;  // names for takeTimings, by serial
};

}  // namespace engine::render
