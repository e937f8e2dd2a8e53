// SPDX-License-Identifier: MIT
#include "engine/render/device.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/render/memory_budget.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/validation.hpp"
#include "texture_params.hpp"

namespace engine::render {

Device::Device(std::unique_ptr<Driver> driver)
    : driver_(std::move(driver)),
      lookup_{[this](TextureHandle h) -> const TextureDesc& { return textures_.get(h).desc; },
              [this](BufferHandle h) -> const BufferDesc& { return buffers_.get(h).desc; },
              [this](BufferHandle h) { return std::span<const std::byte>(buffers_.get(h).indices); },
              [this](BufferHandle h) { return buffers_.get(h).maxIndex; },
              [this](PipelineHandle h) -> const PipelineDesc& { return pipelines_.get(h).desc; },
              [this](PipelineHandle h) -> const ProgramDesc& { return *pipelines_.get(h).program->desc; }} {
    if (!driver_) throw Error("render device: no driver");
    driver_->attach(*this);
}

Device::~Device() { abortPass(); }

TextureHandle Device::createTexture(const TextureDesc& desc, const TextureData* data) {
    const std::string what = "texture " + quotedName(desc.name);
    validateTexture(desc, what);
    driver_->checkTexture(desc, data, what);
    if (data) validateTextureData(desc, *data, what);
    checkFitsInMemory(driver_->textureFootprint(desc), what + ": " + describeSize(desc), driver_->memoryProbe());
    return textures_.add({desc, driver_->createTexture(desc, data, what)});
}

TextureHandle Device::adoptTexture(const TextureDesc& desc, const std::string& what,
                                   const std::function<NativeId()>& wrap) {
    validateTexture(desc, what);
    return textures_.add({desc, wrap()});
}

BufferHandle Device::createBuffer(const BufferDesc& desc, std::span<const std::byte> data) {
    const std::string what = "buffer " + quotedName(desc.name);
    validateBuffer(desc, data, what);
    DeviceBuffer b{desc, kNoNative, {}, 0};
    if (desc.kind == BufferKind::Index) {
        b.indices.assign(std::size_t(desc.size), std::byte{0});
        std::copy(data.begin(), data.end(), b.indices.begin());
        b.maxIndex = largestIndex(b.indices);
    }
    b.native = driver_->createBuffer(desc, data, what);
    return buffers_.add(std::move(b));
}

void Device::updateBuffer(BufferHandle handle, std::uint64_t offset, std::span<const std::byte> data) {
    DeviceBuffer& b = buffers_.get(handle);
    validateBufferUpdate(b.desc, offset, data.size());
    if (data.empty()) return;
    driver_->updateBuffer(b.native, offset, data);
    if (b.desc.kind == BufferKind::Index) {
        std::copy(data.begin(), data.end(), b.indices.begin() + std::ptrdiff_t(offset));
        b.maxIndex = largestIndex(b.indices);
    }
}

ProgramHandle Device::createProgram(const ProgramDesc& desc) {
    auto shared = std::make_shared<const ProgramDesc>(desc);
    const NativeId native = driver_->createProgram(shared);
    return programs_.add(std::make_shared<const DeviceProgram>(*driver_, std::move(shared), native));
}

std::shared_ptr<const Device::DeviceProgram> Device::programFor(const ProgramRef& ref) {
    if (ref.created) return programs_.get(ref.created);
    const auto index = std::size_t(ref.standard);
    if (index >= standardPrograms_.size()) throw Error("unknown standard program " + std::to_string(index));
    std::shared_ptr<const DeviceProgram>& slot = standardPrograms_[index];
    if (!slot) {
        ProgramDesc neutral = standardProgramDesc(ref.standard);
        auto desc = std::make_shared<const ProgramDesc>(neutral);
        const NativeId native = driver_->createStandardProgram(ref.standard, std::move(neutral));
        slot = std::make_shared<const DeviceProgram>(*driver_, std::move(desc), native);
    }
    return slot;
}

PipelineHandle Device::createPipeline(const PipelineDesc& desc) {
    const std::string what = "pipeline " + quotedName(desc.name);
    if (desc.alphaTest.enabled && !std::isfinite(desc.alphaTest.reference))
        throw Error(what + ": alpha reference is not finite");
    std::shared_ptr<const DeviceProgram> program = programFor(desc.program);
    if (program->desc->vertexInput == VertexInput::Fullscreen && desc.depth.test)
        throw Error(what + ": full-screen program " + program->desc->name + " cannot depth-test");
    ResolvedPipeline resolved = resolvePipeline(desc, driver_->failModeEmulation());
    driver_->notePipeline(desc, resolved);
    return pipelines_.add({desc, std::move(resolved.info), std::move(program)});
}

template <typename Tag>
void Device::refuseIfTheOpenPassUses(Handle<Tag> handle, const std::vector<Handle<Tag>>& used, const char* kind,
                                     const std::string& name) const {
    if (pass_ && std::find(used.begin(), used.end(), handle) != used.end())
        throw Error(std::string("destroy of ") + kind + " " + quotedName(name) + " while pass " +
                    quotedName(pass_->name) + " uses it");
}

void Device::destroy(TextureHandle h) {
    refuseIfTheOpenPassUses(h, passTextures_, "texture", textures_.get(h).desc.name);
    const NativeId native = textures_.get(h).native;
    textures_.remove(h);
    driver_->destroyTexture(native);
}

void Device::destroy(BufferHandle h) {
    refuseIfTheOpenPassUses(h, passBuffers_, "buffer", buffers_.get(h).desc.name);
    const NativeId native = buffers_.get(h).native;
    buffers_.remove(h);
    driver_->destroyBuffer(native);
}

void Device::destroy(PipelineHandle h) {
    refuseIfTheOpenPassUses(h, passPipelines_, "pipeline", pipelines_.get(h).desc.name);
    pipelines_.remove(h);
}
void Device::destroy(ProgramHandle h) { programs_.remove(h); }

QueryHandle Device::createQuery(const std::string& name) {
    return queries_.add({name, driver_->createQuery(name), false});
}

void Device::destroy(QueryHandle h) {
    const DeviceQuery& q = queries_.get(h);
    checkQueryUse(h, q.name, pass_ ? &*pass_ : nullptr, true);
    const NativeId native = q.native;
    queries_.remove(h);
    driver_->destroyQuery(native);
}

bool Device::anySamplesPassed(QueryHandle h) {
    const DeviceQuery& q = queries_.get(h);
    checkQueryUse(h, q.name, pass_ ? &*pass_ : nullptr, false);
    if (!q.counted) throw uncountedQueryError(q.name);
    return driver_->anySamplesPassed(q.native);
}

void Device::beginPass(const PassDesc& pass) {
    if (pass_)
        throw Error("pass " + quotedName(pass.name) + " begun while pass " + quotedName(pass_->name) + " is open");
    DriverPass p;
    p.extent = validatePass(pass, lookup_);
    if (pass.countSamplesInto) p.countSamplesInto = queries_.get(pass.countSamplesInto).native;
    if (pass.drawOnlyIfSamplesIn) {
        const DeviceQuery& q = queries_.get(pass.drawOnlyIfSamplesIn);
        if (!q.counted) throw uncountedQueryError(q.name);
        p.drawOnlyIfSamplesIn = q.native;
    }
    p.targets = {{}, 0, pass.depth.texture.valid(), p.extent.samples, p.extent.width, p.extent.height};
    p.color.reserve(pass.color.size());
    for (const ColorAttachment& c : pass.color) {
        if (!c.texture) {
            p.color.push_back(kNoNative);
            continue;
        }
        const DeviceTexture& t = textures_.get(c.texture);
        p.color.push_back(t.native);
        p.targets.colorFormats[std::size_t(p.targets.colorTargetCount++)] = t.desc.format;
    }
    if (pass.depth.texture) p.depth = textures_.get(pass.depth.texture).native;
    pass_ = pass;
    p.desc = &*pass_;
    p.serial = ++passSerial_;
    try {
        driver_->beginPass(p);
    } catch (...) {
        pass_.reset();
        throw;
    }
    driverPass_ = std::move(p);
    begunPasses_.push_back({driverPass_.serial, pass.name});
    passTextures_.clear();
    passBuffers_.clear();
    passPipelines_.clear();
    for (const ColorAttachment& c : pass.color)
        if (c.texture) passTextures_.push_back(c.texture);
    if (pass.depth.texture) passTextures_.push_back(pass.depth.texture);
}

void Device::draw(const DrawDesc& d) {
    if (!pass_) throw Error("draw outside a pass");
    validateDraw(d, *pass_, driverPass_.extent, lookup_);
    const DevicePipeline& pipeline = pipelines_.get(d.pipeline);
    const ResolvedDrawState state =
        resolveDrawState(pipeline.desc, driverPass_.targets, d.scissor, driver_->failModeEmulation());
    DriverDraw draw;
    draw.desc = &d;
    draw.pipeline = &pipeline.desc;
    draw.state = &state;
    draw.program = pipeline.program->native;
    draw.fullscreen = pipeline.program->desc->vertexInput == VertexInput::Fullscreen;
    if (!draw.fullscreen) {
        draw.vertices = nativeBuffer(d.vertices);
        draw.indices = nativeBuffer(d.indices);
        draw.instances = nativeBuffer(d.instances);
    }
    driver_->draw(draw);
    passPipelines_.push_back(d.pipeline);
    for (BufferHandle b : {d.vertices, d.indices, d.instances})
        if (b && !draw.fullscreen) passBuffers_.push_back(b);
    forEachTextureParam(*pipeline.program->desc, d.params, [&](const TextureField&, TextureHandle t) {
        if (t) passTextures_.push_back(t);
    });
}

void Device::endPass() {
    if (!pass_) throw Error("endPass without beginPass");
    // The pass is over even when the driver's end throws (say a resource it uses was destroyed
    // after being recorded): the error must not leave the device stuck in it.
    struct Close {
        Device& self;
        ~Close() { self.pass_.reset(); }
    } close{*this};
    driver_->endPass();
    if (pass_->countSamplesInto) queries_.get(pass_->countSamplesInto).counted = true;
}

void Device::abortPass() noexcept {
    if (!pass_) return;
    if (pass_->countSamplesInto && queries_.alive(pass_->countSamplesInto))
        queries_.get(pass_->countSamplesInto).counted = false;
    driver_->abortPass();
    pass_.reset();
}

void Device::requireNoOpenPass(const std::string& what) const {
    if (pass_) throw Error(what + " while pass " + quotedName(pass_->name) + " is open");
}

void Device::resolve(const ResolveDesc& r) {
    const DeviceTexture& src = textures_.get(r.source);
    const DeviceTexture& dst = textures_.get(r.destination);
    const std::string what = validateResolve(src.desc, dst.desc);
    requireNoOpenPass(what);
    if (formatInfo(src.desc.format).isDepth && src.desc.samples > 1 && r.depthResolve == DepthResolve::Closest) {
        const std::string why = driver_->whyNoClosestDepthResolve();
        if (!why.empty())
            throw Error(what + ": " + why +
                        ", so the closest-sample depth resolve ([Hathaway 2010] §3.5.1) cannot run on the " +
                        driver_->name() + " driver; resolve with DepthResolve::AnySample (racer --msaa-depth any) " +
                        "or render depth at 1x");
    }
    driver_->resolve(src.native, dst.native, r, what);
}

Readback Device::readback(TextureHandle h) {
    const DeviceTexture& t = textures_.get(h);
    validateReadback(t.desc);
    const std::string what = "readback of " + quotedName(t.desc.name);
    requireNoOpenPass(what);
    checkFitsInMemory(std::uint64_t(t.desc.width) * std::uint64_t(t.desc.height) *
                          std::uint64_t(formatInfo(t.desc.format).channels) * sizeof(float),
                      what + " as float", hostMemoryAvailable);
    return driver_->readback(t.native, t.desc);
}

bool Device::present(TextureHandle h) {
    const DeviceTexture& t = textures_.get(h);
    const std::string what = "present of " + quotedName(t.desc.name);
    if (t.desc.samples != 1) throw Error(what + ": multisampled; resolve it first");
    if (formatInfo(t.desc.format).isDepth) throw Error(what + ": a depth texture");
    requireNoOpenPass(what);
    return driver_->present(t.native, t.desc);
}

std::vector<PassTiming> Device::takeTimings() {
    requireNoOpenPass("takeTimings");
    std::vector<PassTiming> out;
    for (const DriverTiming& timing : driver_->takeTimings()) {
        // Passes before this one that have no timing (aborted, or their end threw) are dropped.
        while (!begunPasses_.empty() && begunPasses_.front().serial < timing.serial) begunPasses_.pop_front();
        if (begunPasses_.empty() || begunPasses_.front().serial != timing.serial)
            throw Error(driver_->name() + " driver: a timing for pass number " + std::to_string(timing.serial) +
                        ", which was never begun");
        out.push_back({std::move(begunPasses_.front().name), timing.milliseconds, timing.skipped});
        begunPasses_.pop_front();
    }
    return out;
}

void Device::endFrame() {
    requireNoOpenPass("endFrame");
    driver_->endFrame();
}

}  // namespace engine::render
