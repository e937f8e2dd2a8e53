// SPDX-License-Identifier: MIT
#pragma once
// modules/hud on any backend: a target filled with a gradient (so every pixel has its own
// value), an overlay's passes over it in a one-off frame graph (tests/support/run_graph.hpp), as
// the racer adds them, the result read back.
#include <memory>
#include <vector>

#include "engine/render/backend.hpp"
#include "engine/render/pass_scope.hpp"
#include "hud/overlay.hpp"
#include "run_graph.hpp"

namespace hud::testing {

constexpr int kW = 96, kH = 64;

// RGBA8 sRGB codes of a gradient: distinct neighbours, so a copy off by one texel shows.
inline std::vector<std::byte> gradient(int w, int h, int seed) {
    std::vector<std::byte> bytes(std::size_t(w) * std::size_t(h) * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::byte* p = &bytes[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
            p[0] = std::byte((x * 5 + seed) & 255);
            p[1] = std::byte((y * 7 + seed * 3) & 255);
            p[2] = std::byte((x * y + seed) & 255);
            p[3] = std::byte(255);
        }
    return bytes;
}

struct OverlayScene {
    explicit OverlayScene(std::unique_ptr<engine::render::Backend> b) : backend(std::move(b)), overlay(*backend) {
        using namespace engine::render;
        const std::vector<std::byte> backgroundBytes = gradient(kW, kH, 0), sourceBytes = gradient(kW, kH, 90);
        TextureData data;
        data.levels.push_back(backgroundBytes);
        background = backend->createTexture({"background", kW, kH, Format::RGBA8_SRGB, 1, 1, UsageSampled}, &data);
        TextureData other;
        other.levels.push_back(sourceBytes);
        source = backend->createTexture({"source", kW, kH, Format::RGBA8_SRGB, 1, 1, UsageSampled}, &other);
        target = backend->createTexture(renderTargetDesc("target", kW, kH, Format::RGBA8_SRGB));
    }
    ~OverlayScene() {
        for (auto t : {background, source, target}) backend->destroy(t);
    }

    // The background copied into the target by a zoom-1 panel, then `content`, read back.
    engine::render::Readback render(const OverlayContent& content) {
        overlay.beginFrame();
        OverlayContent copy;
        copy.images.push_back({background, {}, {0, 0, kW, kH}, {0, 0}, 1});
        test_support::OneFrameGraph frame(*backend);
        engine::render::FrameGraphTexture color = frame.import(target);
        color = overlay.addPass(frame.graph(), "background", color, target, kW, kH, copy);
        frame.run(overlay.addPass(frame.graph(), "overlay", color, target, kW, kH, content));
        return backend->readback(target);
    }

    std::unique_ptr<engine::render::Backend> backend;
    Overlay overlay;
    engine::render::TextureHandle background, source, target;
};

}  // namespace hud::testing
