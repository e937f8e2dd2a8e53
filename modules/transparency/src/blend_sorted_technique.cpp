// SPDX-License-Identifier: MIT
// Straight-alpha blending sorted per object ([Moore 2015] "order dependence": sort back to
// front, then blend "over"). An object is one instance: every visible instance is keyed by
// the view depth of its bounds' centre, the instances are stable-sorted farthest first
// (ties keep submission order: batch, then instance), and consecutive instances of the same
// batch are merged into one draw whose instances are uploaded per frame in sorted order.
// Exact for objects that do not interpenetrate and whose centres order them correctly;
// intersecting or long objects still blend in the wrong order where they overlap.
#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/owned.hpp"
#include "engine/render/pass_scope.hpp"
#include "foliage_draws.hpp"
#include "single_pass_technique.hpp"
#include "technique_table.hpp"

namespace transparency::detail {

namespace {

using namespace engine::render;

struct SortedInstance {
    bool behindEye = false;  // centre at or behind the eye plane (clip w <= 0): drawn last
    float depth = 0.0f;      // clip z / w of the centre
    std::uint32_t draw = 0;  // index in the visible draws
    std::uint32_t instance = 0;
};

// One merged draw: `count` sorted instances of the same batch, uploaded into one buffer.
struct Run {
    std::uint32_t draw = 0;
    std::size_t first = 0;
    std::size_t count = 0;
};

class BlendSortedTechnique final : public SinglePassTechnique {
public:
    BlendSortedTechnique(Backend& backend, const TechniqueOptions& options)
        : SinglePassTechnique({TechniqueKind::BlendSorted}), backend_(backend), depthFunc_(options.depthFunc) {
        pipeline_ = Owned<PipelineHandle>(
            backend_, backend_.createPipeline(blendOverPipeline("foliage blend (sorted)", depthFunc_)));
    }

    void drawFrame(engine::render::FrameTargets& opaque, const FoliageFrame& frame,
                   std::span<const engine::render::TextureHandle> /*targets*/) override {
        opaque.resolve();
        const auto visible = visibleDraws(frame, opaque.desc().width, opaque.desc().height);
        if (visible.empty()) return;
        sort(frame, visible);
        PassScope scope(backend_, resolvedPass(opaque, "foliage blend (sorted)"));
        std::size_t bufferIndex = 0;
        for (const Run& run : runs_) {
            const FoliageDraw& draw = *visible[run.draw];
            DrawDesc d = batchDraw(draw.batch, pipeline_, surfaceParams(frame, draw.batch));
            d.instances = upload(bufferIndex++, std::span(sortedInstances_).subspan(run.first, run.count));
            d.instanceCount = static_cast<std::uint32_t>(run.count);
            backend_.draw(d);
        }
        scope.end();
    }

private:
    static Instance instanceOf(const FoliageDraw& draw, std::uint32_t i) {
        if (!draw.batch.instances) return Instance{};  // a batch without instances is one identity instance
        return draw.instances[i];
    }

    void sort(const FoliageFrame& frame, const std::vector<const FoliageDraw*>& visible) {
        keys_.clear();
        for (std::uint32_t d = 0; d < visible.size(); ++d) {
            const FoliageDraw& draw = *visible[d];
            if (draw.batch.instances && draw.instances.size() != draw.batch.instanceCount)
                throw engine::Error("blend-sorted: draw " + std::to_string(d) + " has " +
                                    std::to_string(draw.instances.size()) + " CPU instances for instanceCount " +
                                    std::to_string(draw.batch.instanceCount));
            const glm::vec3 centre = (draw.meshBounds.min + draw.meshBounds.max) * 0.5f;
            for (std::uint32_t i = 0; i < draw.batch.instanceCount; ++i) {
                const glm::vec4 clip = frame.viewProj * (instanceOf(draw, i).model * glm::vec4(centre, 1.0f));
                SortedInstance key{true, 0.0f, d, i};
                const float z = clip.z / clip.w;
                if (clip.w > 0.0f && std::isfinite(z)) key = {false, z, d, i};
                keys_.push_back(key);
            }
        }
        // Farthest first; the eye-plane ones last (they can only be nearer than the rest).
        const CompareFunc func = depthFunc_;
        std::stable_sort(keys_.begin(), keys_.end(), [func](const SortedInstance& a, const SortedInstance& b) {
            if (a.behindEye != b.behindEye) return b.behindEye;
            return !a.behindEye && isCloser(func, b.depth, a.depth);
        });
        sortedInstances_.clear();
        runs_.clear();
        for (const SortedInstance& key : keys_) {
            if (runs_.empty() || runs_.back().draw != key.draw) runs_.push_back({key.draw, sortedInstances_.size(), 0});
            sortedInstances_.push_back(instanceOf(*visible[key.draw], key.instance));
            ++runs_.back().count;
        }
    }

    // The index-th per-frame instance buffer, grown when too small and reused across frames.
    BufferHandle upload(std::size_t index, std::span<const Instance> instances) {
        const auto bytes = std::as_bytes(instances);
        if (index == buffers_.size()) buffers_.emplace_back(), bufferSizes_.push_back(0);
        if (bufferSizes_[index] < bytes.size()) {
            buffers_[index].reset();
            bufferSizes_[index] = 0;  // a create that throws below leaves an empty slot, not a stale handle
            buffers_[index] = Owned<BufferHandle>(
                backend_, backend_.createBuffer({"sorted instances", BufferKind::Instance, bytes.size()}, bytes));
            bufferSizes_[index] = bytes.size();
        } else {
            backend_.updateBuffer(buffers_[index], 0, bytes);
        }
        return buffers_[index];
    }

    Backend& backend_;
    CompareFunc depthFunc_;
    Owned<PipelineHandle> pipeline_;
    std::vector<SortedInstance> keys_;
    std::vector<Instance> sortedInstances_;
    std::vector<Run> runs_;
    std::vector<Owned<BufferHandle>> buffers_;
    std::vector<std::size_t> bufferSizes_;
};

}  // namespace

std::unique_ptr<Technique> makeBlendSortedTechnique(Backend& backend, const TechniqueOptions& options) {
    return std::make_unique<BlendSortedTechnique>(backend, options);
}

}  // namespace transparency::detail
