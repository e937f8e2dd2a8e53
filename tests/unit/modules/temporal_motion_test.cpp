// SPDX-License-Identifier: MIT
// The temporal pass's motion vectors (transparency/temporal.hpp): a card that moves a pixel a
// frame under a still camera ends with the image of a card that stood still where it ends,
// bit for bit: every pixel fetches its history where the card's surface was. Without motion
// vectors (the camera alone, TemporalOptions::motionVectors off) the same card ghosts: the
// history it fetches in place is the card's colour of a pixel before.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>

#include "engine/render/soft/soft_backend.hpp"
#include "moving_card_scene.hpp"

namespace {

using namespace engine::render;
using namespace transparency;
using transparency::testing::MovingCardScene;

constexpr int kFrames = 12;
constexpr float kPixel = MovingCardScene::kPixel;

using Surface = MovingCardScene::Surface;

// The last of kFrames frames of a card that moves right a pixel a frame and ends 11 pixels right.
Readback moving(Backend& backend, TechniqueKind kind, bool motionVectors, Surface surface = Surface::Foliage) {
    MovingCardScene scene(backend, kind, 0.5f, motionVectors, surface);
    Readback r;
    for (int i = 0; i < kFrames; ++i) r = scene.frame(std::uint64_t(i), float(i) * kPixel);
    return r;
}

Readback still(Backend& backend, TechniqueKind kind, Surface surface = Surface::Foliage) {
    MovingCardScene scene(backend, kind, 0.5f, true, surface);
    Readback r;
    for (int i = 0; i < kFrames; ++i) r = scene.frame(std::uint64_t(i), float(kFrames - 1) * kPixel);
    return r;
}

TEST(TemporalMotion, AMovingCardConvergesToTheStillCardsImage) {
    for (TechniqueKind kind : {TechniqueKind::HashedTaa, TechniqueKind::AlphaTestTaa}) {
        auto backend = soft::createSoftBackend({.threads = 2});
        const Readback s = still(*backend, kind), m = moving(*backend, kind, true);
        int off = 0;
        float worst = 0.0f;
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            off += s.values[i] != m.values[i];
            worst = std::max(worst, std::abs(s.values[i] - m.values[i]));
        }
        std::printf("%s with motion vectors: %d values off the still card's image, worst %g\n", techniqueName(kind),
                    off, worst);
        EXPECT_EQ(off, 0) << techniqueName(kind) << ": with motion vectors, the still card's image bit for bit";
        // Without them, pixels the card entered keep history from its previous place and pixels
        // it left keep its colour: the images part (by more than 0.05 somewhere).
        const Readback ghost = moving(*backend, kind, false);
        int ghosted = 0;
        for (std::size_t i = 0; i < s.values.size(); i += 4) ghosted += std::abs(s.values[i] - ghost.values[i]) > 0.05f;
        std::printf("%s: %d pixels of the camera-only TAA off the still card's image by > 0.05\n", techniqueName(kind),
                    ghosted);
        EXPECT_GT(ghosted, 100) << techniqueName(kind) << ": the camera alone leaves a trail";
    }
}

// The same with an opaque box (the car's case: drawn by the opaque pass, its motion given as
// FoliageFrame::movingOpaque): with its motion the temporal pass ends on the still box's image,
// with the camera alone the box leaves a trail.
TEST(TemporalMotion, AMovingOpaqueBoxConvergesToTheStillBoxsImage) {
    for (TechniqueKind kind : {TechniqueKind::HashedTaa, TechniqueKind::AlphaTestTaa}) {
        auto backend = soft::createSoftBackend({.threads = 2});
        const Readback s = still(*backend, kind, Surface::Opaque), m = moving(*backend, kind, true, Surface::Opaque);
        int off = 0;
        float worst = 0.0f;
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            off += s.values[i] != m.values[i];
            worst = std::max(worst, std::abs(s.values[i] - m.values[i]));
        }
        std::printf("%s, opaque box with its motion: %d values off the still box's image, worst %g\n",
                    techniqueName(kind), off, worst);
        EXPECT_EQ(off, 0) << techniqueName(kind) << ": with the box's motion, the still box's image bit for bit";
        const Readback ghost = moving(*backend, kind, false, Surface::Opaque);
        int ghosted = 0;
        for (std::size_t i = 0; i < s.values.size(); i += 4) ghosted += std::abs(s.values[i] - ghost.values[i]) > 0.05f;
        std::printf("%s: %d pixels of the camera-only TAA off the still box's image by > 0.05\n", techniqueName(kind),
                    ghosted);
        EXPECT_GT(ghosted, 100) << techniqueName(kind) << ": the camera alone leaves a trail";
    }
}

}  // namespace
