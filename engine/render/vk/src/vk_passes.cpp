// SPDX-License-Identifier: MIT
// Vulkan driver: passes. Draws have their parameters captured when recorded (the
// uniform block packed into the frame's arena, the texture set written), and the pass is
// recorded at endPass: barriers for every image it samples or renders into, then the render
// pass with its clears, its occlusion query and its draws, each fail-mode step a pipeline.
#include <algorithm>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/render/pixel_codec.hpp"
#include "engine/render/vk/vk_results.hpp"
#include "vk_backend_impl.hpp"

namespace engine::render::vk {

// The barrier an image needs before its next use (Vulkan "Synchronization and Cache Control"):
// a write, or a change of layout (itself a write), waits for every earlier access; a read waits
// for the last write unless that write was already made visible to the reading stage.
void VulkanDriverImpl::use(VkCommandBuffer cmd, VulkanTexture& t, VkImageLayout layout, VkPipelineStageFlags stage,
                           VkAccessFlags access, bool writes) {
    ImageState& s = t.state;
    const bool transition = s.layout != layout;
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = s.layout;
    b.newLayout = layout;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = t.image;
    b.subresourceRange = {t.aspect, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
    b.dstAccessMask = access;
    VkPipelineStageFlags src = 0;
    if (writes || transition) {
        src = s.writeStages | s.readStages;
        b.srcAccessMask = s.writeAccess;
        s.writeStages = stage;
        s.writeAccess = writes ? access : 0;
        s.visibleTo = writes ? 0 : stage;
        s.readStages = writes ? 0 : stage;
    } else {
        if (s.writeAccess && !(s.visibleTo & stage)) {
            src = s.writeStages;
            b.srcAccessMask = s.writeAccess;
            s.visibleTo |= stage;
        }
        s.readStages |= stage;
        if (!src && !transition) return;
    }
    s.layout = layout;
    if (!src) src = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    vkCmdPipelineBarrier(cmd, src, stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

void VulkanDriverImpl::beginPass(const DriverPass& pass) {
    actualSamples_ = 1;
    for (NativeId c : pass.color)
        if (c != kNoNative) actualSamples_ = textures_[c].actualSamples;
    if (pass.depth != kNoNative) actualSamples_ = textures_[pass.depth].actualSamples;
    extent_ = pass.extent;
    draws_.clear();
    // Whether the draws run, read now (a result wait) rather than at endPass: the submission it
    // needs moves the frame ring on, and the draws' uniform blocks and descriptor sets must come
    // from the slot that records them.
    drawsRun_ = pass.drawOnlyIfSamplesIn != kNoNative ? anySamplesPassed(pass.drawOnlyIfSamplesIn) : true;
    pass_ = pass;
}

void VulkanDriverImpl::draw(const DriverDraw& d) {
    if (!drawsRun_) return;  // checked, not recorded: the pass's condition found no sample
    RecordedDraw r;
    r.pipeline = *d.pipeline;
    r.program = programs_[d.program];
    r.state = *d.state;
    if (r.state.scissor.empty()) return;  // nothing drawn, as on GL
    const VulkanProgram& program = *r.program;
    const GlslProgram& gl = program.desc->gl;
    const std::uint64_t serial = frames_->recordingSerial();
    if (!d.fullscreen) {
        VulkanBuffer& v = buffers_[d.vertices];
        v.lastUse = serial;
        r.vertices = v.buffer;
        if (d.indices != kNoNative) {
            VulkanBuffer& i = buffers_[d.indices];
            i.lastUse = serial;
            r.indices = i.buffer;
        }
        if (d.instances != kNoNative) {
            VulkanBuffer& i = buffers_[d.instances];
            i.lastUse = serial;
            r.instances = i.buffer;
        } else {
            r.instances = identityInstance_.buffer;
        }
    }
    r.first = d.desc->first;
    r.count = d.desc->count;
    r.instanceCount = d.desc->instanceCount;
    const DrawParams& params = d.desc->params;

    // The uniform block, packed now: the draw's parameters as they are when it is recorded.
    if (!program.block.empty()) {
        const ArenaAllocation a =
            frames_->allocate(program.block.size, context_->properties.limits.minUniformBufferOffsetAlignment);
        std::memset(a.data, 0, program.block.size);
        packUniformBlock(
            program.block, gl, params.data(),
            [this](TextureHandle h) { return textures_[natives_->texture(h)].desc.alpha == AlphaMode::Premultiplied; },
            std::span<std::byte>(a.data, program.block.size));
        r.uniforms = a.buffer;
        r.uniformOffset = std::uint32_t(a.offset);
        r.uniformSet = a.uniformSet;
    }
    // The texture set: every unit the program declares gets an image (a null optional texture
    // reads a 1x1 zero image: the program does not sample it, but Vulkan wants it valid).
    if (!gl.textures.empty()) {
        r.textureSet = frames_->allocateSet(program.textureLayout);
        std::vector<VkDescriptorImageInfo> infos(gl.textures.size());
        std::vector<VkWriteDescriptorSet> writes(gl.textures.size());
        const auto* bytes = static_cast<const std::byte*>(params.data());
        for (std::size_t i = 0; i < gl.textures.size(); ++i) {
            const TextureField& field = gl.textures[i];
            TextureHandle handle;
            SamplerState samplerState{Filter::Nearest, AddressMode::Clamp, AddressMode::Clamp};
            if (field.read == TextureRead::Sampled) {
                TextureBinding binding;
                std::memcpy(&binding, bytes + field.offset, sizeof binding);
                handle = binding.texture;
                samplerState = binding.sampler;
            } else {
                std::memcpy(&handle, bytes + field.offset, sizeof handle);
            }
            if (!handle && dummy_ == kNoNative) {
                TextureDesc desc;
                desc.name = "vk: absent texture";
                desc.width = desc.height = 1;
                dummy_ = createTexture(desc, nullptr, "texture " + quotedName(desc.name));
            }
            const NativeId native = handle ? natives_->texture(handle) : dummy_;
            r.sampled.push_back(native);
            infos[i] = {sampler(samplerState), textures_[native].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            VkWriteDescriptorSet& w = writes[i];
            w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            w.dstSet = r.textureSet;
            w.dstBinding = std::uint32_t(field.unit);
            w.descriptorCount = 1;
            w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            w.pImageInfo = &infos[i];
        }
        vkUpdateDescriptorSets(context_->device, std::uint32_t(writes.size()), writes.data(), 0, nullptr);
    }
    draws_.push_back(std::move(r));
}

void VulkanDriverImpl::endPass() {
    try {
        recordPass();
    } catch (...) {
        abortPass();
        throw;
    }
    pass_.reset();
    draws_.clear();
}

void VulkanDriverImpl::abortPass() noexcept {
    pass_.reset();
    draws_.clear();
}

void VulkanDriverImpl::recordPass() {
    const PassDesc& pass = *pass_->desc;
    const bool drawsRun = drawsRun_;
    const VkCommandBuffer cmd = frames_->cmd();

    // Barriers first: sampled images to shader reads, attachments to their layouts.
    if (drawsRun)
        for (const RecordedDraw& r : draws_)
            for (NativeId h : r.sampled)
                use(cmd, textures_[h], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT, false);
    RenderPassKey key;
    std::vector<VkImageView> views;
    std::vector<VkClearValue> clears;
    for (std::size_t i = 0; i < pass.color.size(); ++i) {
        if (pass_->color[i] == kNoNative) continue;
        const ColorAttachment& c = pass.color[i];
        VulkanTexture& t = textures_[pass_->color[i]];
        use(cmd, t, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, true);
        key.color[key.colorCount] = t.format;
        key.load[key.colorCount] = c.load == LoadOp::Load;
        ++key.colorCount;
        views.push_back(t.view);
        // The clear value as the target will hold it (UNORM and sRGB codes, halves): any
        // conversion the implementation makes of an exactly representable value is exact,
        // so the stored bits are the soft backend's.
        const glm::vec4 q = quantize(c.clear, t.desc.format);
        VkClearValue v{};
        v.color = {{q.r, q.g, q.b, q.a}};
        clears.push_back(v);
    }
    if (pass_->depth != kNoNative) {
        VulkanTexture& t = textures_[pass_->depth];
        use(cmd, t, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, true);
        key.depth = t.format;
        key.depthLoad = pass.depth.load == LoadOp::Load;
        views.push_back(t.view);
        VkClearValue v{};
        // Vulkan clears depth within [0, 1] only (no VK_EXT_depth_range_unrestricted assumed).
        v.depthStencil = {std::clamp(pass.depth.clear, 0.0f, 1.0f), 0};
        clears.push_back(v);
    }
    key.samples = std::uint8_t(actualSamples_);
    const bool counts = pass_->countSamplesInto != kNoNative;
    const std::uint32_t query = counts ? queries_[pass_->countSamplesInto].slot : 0;
    if (counts) vkCmdResetQueryPool(cmd, occlusion_, query, 1);
    std::uint32_t stamp = UINT32_MAX;
    if (context_->timestampValidBits > 0 && nextTimestamp_ + 2 <= kTimestampSlots) {  // 0 bits: no timestamps
        stamp = nextTimestamp_;
        nextTimestamp_ += 2;
        vkCmdResetQueryPool(cmd, timestamps_, stamp, 2);
        // BOTTOM_OF_PIPE, not TOP_OF_PIPE: a top-of-pipe stamp is written as soon as the
        // command is reached, while the passes before are still running (a GPU overlaps them;
        // lavapipe writes it with no flush), so pass intervals overlapped and their sum
        // exceeded the frame. At the bottom of the pipe it is written once everything before
        // has completed: the pass's interval starts where the previous one ended (its barriers
        // and clears included), and the passes' times add up to at most the span they cover.
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, stamp);
    }

    const VkRenderPass rp = renderPass(key);
    VkRenderPassBeginInfo bi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    bi.renderPass = rp;
    bi.framebuffer = framebuffer(rp, views, extent_.width, extent_.height);
    bi.renderArea = {{0, 0}, {std::uint32_t(extent_.width), std::uint32_t(extent_.height)}};
    bi.clearValueCount = std::uint32_t(clears.size());
    bi.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &bi, VK_SUBPASS_CONTENTS_INLINE);
    if (counts) vkCmdBeginQuery(cmd, occlusion_, query, 0);
    // Row 0 at the top with NDC +y up: a negative-height viewport (vk_backend.hpp).
    const VkViewport viewport{0.0f, float(extent_.height), float(extent_.width), -float(extent_.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    if (drawsRun)
        for (const RecordedDraw& r : draws_) {
            const VulkanProgram& program = *r.program;
            const ResolvedDrawState& state = r.state;
            const bool fullscreen = program.desc->vertexInput == VertexInput::Fullscreen;
            const VkRect2D scissor{{state.scissor.x, state.scissor.y},
                                   {std::uint32_t(state.scissor.width), std::uint32_t(state.scissor.height)}};
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            vkCmdSetBlendConstants(cmd, &state.blendConstant.r);
            if (r.textureSet)
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, program.layout, kTextureSet, 1,
                                        &r.textureSet, 0, nullptr);
            if (r.uniformSet)
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, program.layout, kUniformSet, 1,
                                        &r.uniformSet, 1, &r.uniformOffset);
            if (!fullscreen) {
                const VkBuffer buffers[] = {r.vertices, r.instances};
                const VkDeviceSize offsets[] = {0, 0};
                vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
                if (r.indices) vkCmdBindIndexBuffer(cmd, r.indices, 0, VK_INDEX_TYPE_UINT32);
            }
            TailConstants tail;
            tail.alphaFunc = int(r.pipeline.alphaTest.func);
            tail.alphaRef = r.pipeline.alphaTest.reference;
            tail.a2cSamples = state.alphaToCoverage ? extent_.samples : 0;
            tail.a2cActual = actualSamples_;
            // lavapipe shares llvmpipe's rasterizer and its multisampled scissor defect
            // (glsl::kFinish): the scissor is tested again per pixel there.
            if (actualSamples_ > 1) {
                tail.scissor[0] = state.scissor.x, tail.scissor[1] = state.scissor.y;
                tail.scissor[2] = state.scissor.x + state.scissor.width;
                tail.scissor[3] = state.scissor.y + state.scissor.height;
            }
            auto issue = [&](std::uint32_t first, std::uint32_t count, std::uint32_t instance, std::uint32_t n) {
                if (fullscreen) vkCmdDraw(cmd, 3, 1, 0, 0);
                else if (r.indices) vkCmdDrawIndexed(cmd, count, n, first, 0, instance);
                else vkCmdDraw(cmd, count, n, first, instance);
            };
            auto applyStep = [&](const PlanStep& step) {
                // A step that writes nothing is not drawn, unless an occlusion query counts it.
                bool writes = step.depthWrite || counts;
                for (int i = 0; i < state.colorTargetCount; ++i)
                    writes = writes || (state.blend[std::size_t(i)].writeMask & step.channels);
                if (!writes) return false;
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                  pipeline(program, r.pipeline, state, step, key));
                tail.alphaSelect = step.select == FragmentSelect::All       ? 0
                                   : step.select == FragmentSelect::Passing ? 1
                                                                            : 2;
                vkCmdPushConstants(cmd, program.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof tail, &tail);
                return true;
            };
            const FailModePlan& plan = state.failModes;
            if (fullscreen) {
                for (const PlanStep& step : plan.steps)
                    if (applyStep(step)) issue(0, 3, 0, 1);
            } else if (r.count > 0) {
                if (plan.perTriangle) {
                    // Exact fail modes: a triangle's fragments never overlap, so its steps
                    // commute; triangles in the soft backend's order (instance-major).
                    for (std::uint32_t instance = 0; instance < r.instanceCount; ++instance)
                        for (std::uint32_t tri = 0; tri < r.count / 3; ++tri)
                            for (const PlanStep& step : plan.steps)
                                if (applyStep(step)) issue(r.first + tri * 3, 3, instance, 1);
                } else {
                    for (const PlanStep& step : plan.steps)
                        if (applyStep(step)) issue(r.first, r.count, 0, r.instanceCount);
                }
            }
        }
    if (counts) vkCmdEndQuery(cmd, occlusion_, query);
    vkCmdEndRenderPass(cmd);
    if (stamp != UINT32_MAX) {
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, stamp + 1);
        pendingTimings_.push_back({pass_->serial, pass.name, stamp, !drawsRun});
    } else {
        pendingTimings_.push_back({pass_->serial, pass.name, UINT32_MAX, !drawsRun});
    }
}

NativeId VulkanDriverImpl::createQuery(const std::string& name) {
    std::uint32_t slot;
    if (!freeOcclusionSlots_.empty()) {
        slot = freeOcclusionSlots_.back();
        freeOcclusionSlots_.pop_back();
    } else {
        if (occlusionSlots_ >= kOcclusionSlots)
            throw Error("occlusion query " + quotedName(name) + ": the Vulkan backend holds at most " +
                        std::to_string(kOcclusionSlots) + " at once");
        slot = occlusionSlots_++;
    }
    return queries_.add({name, slot});
}

void VulkanDriverImpl::destroyQuery(NativeId h) {
    const VulkanQuery q = queries_[h];
    queries_.remove(h);
    frames_->retire([this, slot = q.slot] { freeOcclusionSlots_.push_back(slot); });
}

bool VulkanDriverImpl::anySamplesPassed(NativeId h) {
    const VulkanQuery& q = queries_[h];
    // The result needs a submission, and an open pass's recorded draws hold the recording
    // slot's uniform blocks and sets: results are read between passes on Vulkan.
    if (pass_)
        throw Error("occlusion query " + quotedName(q.name) + " read while pass " + quotedName(pass_->desc->name) +
                    " is open: the Vulkan backend reads results between passes");
    frames_->submit(true);  // the result of what is recorded: a result wait (when there is any)
    std::uint64_t samples = 0;
    check(vkGetQueryPoolResults(context_->device, occlusion_, q.slot, 1, sizeof samples, &samples, sizeof samples,
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "occlusion query " + quotedName(q.name) + ": reading its result");
    return samples != 0;
}

std::vector<DriverTiming> VulkanDriverImpl::takeTimings() {
    std::vector<DriverTiming> out;
    if (pendingTimings_.empty()) return out;
    frames_->submit(true);
    const double period = double(context_->properties.limits.timestampPeriod);  // ns per tick
    const std::uint32_t validBits = context_->timestampValidBits;
    for (const PendingTiming& p : pendingTimings_) {
        double ms = 0.0;
        if (p.first != UINT32_MAX) {
            std::uint64_t ticks[2] = {};
            check(vkGetQueryPoolResults(context_->device, timestamps_, p.first, 2, sizeof ticks, ticks, sizeof ticks[0],
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  "pass " + quotedName(p.pass) + ": reading its timestamps");
            ms = timestampMilliseconds(ticks[0], ticks[1], validBits, period);
        }
        out.push_back({p.serial, ms, p.skipped});
    }
    pendingTimings_.clear();
    nextTimestamp_ = 0;
    return out;
}

}  // namespace engine::render::vk
