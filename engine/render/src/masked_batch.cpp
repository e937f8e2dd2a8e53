// SPDX-License-Identifier: MIT
#include "engine/render/masked_batch.hpp"

namespace engine::render {

DrawDesc maskedBatchDraw(const MaskedBatch& batch, PipelineHandle pipeline, DrawParams params) {
    DrawDesc d;
    d.pipeline = pipeline;
    d.params = params;
    d.vertices = batch.vertices;
    d.indices = batch.indices;
    d.first = batch.first;
    d.count = batch.count;
    d.instances = batch.instances;
    d.instanceCount = batch.instanceCount;
    return d;
}

}  // namespace engine::render
