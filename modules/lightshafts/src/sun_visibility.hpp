// SPDX-License-Identifier: MIT
#pragma once
// Is any sky near the sun visible? An occlusion query over the sun's glow disc (as lens
// flares ask the GPU whether the sun is seen): a depth-only draw of the disc at the far
// plane counts the pixels whose depth still holds the clear value, i.e. the sky between
// the opaque and foliage layers. The light-shafts pass is made conditional on it, so a
// sun hidden behind the canopy costs one small depth-tested disc and no shaft pass, and
// the CPU never waits for the answer.
#include <optional>

#include <glm/glm.hpp>

#include "engine/render/backend.hpp"
#include "engine/render/compare_func.hpp"
#include "engine/render/owned.hpp"

namespace lightshafts {

class SunVisibilityProbe {
public:
    explicit SunVisibilityProbe(engine::render::Backend& backend);
    SunVisibilityProbe(const SunVisibilityProbe&) = delete;
    SunVisibilityProbe& operator=(const SunVisibilityProbe&) = delete;

    // Counts the sky pixels whose centres lie within `radius` pixels of `sunPixel` in
    // `depth` (cleared to the far value of `depthFunc`). Returns the query holding the
    // answer, or nothing when the disc misses the frame, so no pixel can be sky near the sun.
    std::optional<engine::render::QueryHandle> probe(engine::render::TextureHandle depth, int width, int height,
                                                     engine::render::CompareFunc depthFunc, glm::vec2 sunPixel,
                                                     float radius);

private:
    engine::render::Backend& backend_;
    // Owned, in the order they are made: a create that throws destroys those made before it.
    engine::render::Owned<engine::render::PipelineHandle> standardZ_, reverseZ_;
    engine::render::Owned<engine::render::QueryHandle> query_;
    engine::render::Owned<engine::render::BufferHandle> disc_;
};

}  // namespace lightshafts
