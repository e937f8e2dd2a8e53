// SPDX-License-Identifier: MIT
#include "engine/render/masked_batch.hpp"

namespace engine::render {

DrawDesc maskedBatchDraw(const MaskedBatch& batch, PipelineHandle pipeline, DrawParams params) {
    return {.pipeline = pipeline,
            .params = params,
            .vertices = batch.vertices,
            .indices = batch.indices,
            .first = batch.first,
            .count = batch.count,
            .instances = batch.instances,
            .instanceCount = batch.instanceCount,
            .scissor = std::nullopt};
}

}  // namespace engine::render
