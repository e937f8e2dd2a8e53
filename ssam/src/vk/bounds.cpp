// SPDX-License-Identifier: MIT
#include "bounds.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "engine/render/screen_bounds.hpp"

namespace ssam::vk::detail {

// engine::render::screenBounds() expects z in [0, w] (Vulkan's too) and NDC +y at row 0; Vulkan
// puts NDC -y at row 0, so the host's viewProj is flipped in y first. Its rows then count from the
// top, as Vulkan's framebuffer rows do.
std::optional<Rect> compositeRegion(const FrameDesc& frame) {
    const int width = static_cast<int>(frame.width), height = static_cast<int>(frame.height);
    if (!frame.foliageBounds || frame.foliageBoundsCount == 0) return Rect{0, 0, width, height};
    glm::mat4 flipY(1.0f);
    flipY[1][1] = -1.0f;
    const glm::mat4 viewProj = flipY * glm::make_mat4(frame.viewProj);
    engine::render::Rect region;
    bool any = false;
    for (std::size_t i = 0; i < frame.foliageBoundsCount; ++i) {
        const Box& box = frame.foliageBounds[i];
        const engine::render::BoundingBox bounds{glm::make_vec3(box.min), glm::make_vec3(box.max)};
        const std::optional<engine::render::Rect> r = engine::render::screenBounds(bounds, viewProj, width, height);
        if (!r) continue;
        region = engine::render::unite(region, *r);
        any = true;
    }
    if (!any) return std::nullopt;
    return Rect{region.x, region.y, region.width, region.height};
}

}  // namespace ssam::vk::detail
