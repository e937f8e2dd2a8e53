// SPDX-License-Identifier: MIT
#include "render_size.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/render/texture.hpp"

namespace racer {

FrameSize renderSizeFor(int framebufferWidth, int framebufferHeight) {
    using engine::render::kMaxTextureDimension;
    const int longest = std::max(framebufferWidth, framebufferHeight);
    if (longest <= kMaxTextureDimension) return {framebufferWidth, framebufferHeight};
    // Scaled as a whole, so the camera's aspect still matches the window's.
    const double scale = double(kMaxTextureDimension) / longest;
    auto side = [&](int n) { return std::clamp(int(std::lround(n * scale)), 1, kMaxTextureDimension); };
    return {side(framebufferWidth), side(framebufferHeight)};
}

void RenderSize::follow(glm::ivec2 framebuffer) {
    if (framebuffer == seen_) return;
    seen_ = framebuffer;
    const FrameSize wanted = renderSizeFor(framebuffer.x, framebuffer.y);
    if (wanted == current()) return;
    try {
        frame_.resize(wanted.width, wanted.height);
    } catch (const engine::Error& e) {
        refused(wanted, e);
        return;
    }
    const bool clamped = wanted != FrameSize{framebuffer.x, framebuffer.y};
    std::printf("racer: render size %dx%d (window framebuffer %dx%d%s)\n", wanted.width, wanted.height, framebuffer.x,
                framebuffer.y, clamped ? ", scaled down to the largest render target" : "");
}

bool RenderSize::recover(const engine::Error& e) {
    const FrameSize failed = current();
    if (failed == rendered_) return false;
    frame_.resize(rendered_.width, rendered_.height);
    refused(failed, e);
    return true;
}

void RenderSize::refused(FrameSize size, const engine::Error& e) const {
    std::printf("racer: cannot render at %dx%d (%s); keeping %dx%d, scaled to the window\n", size.width, size.height,
                e.what(), frame_.width(), frame_.height());
}

}  // namespace racer
