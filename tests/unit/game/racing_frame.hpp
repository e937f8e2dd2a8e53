// SPDX-License-Identifier: MIT
#pragma once
// The racing frame as racer's headless loop builds it (racer.cpp), for tests that count
// what a frame creates: every living-scene module on, at a small size.
#include <gtest/gtest.h>

#include "camera_rig.hpp"
#include "content_dir.hpp"
#include "engine/scene/draw_lists.hpp"
#include "engine/scene/rigid_motion.hpp"
#include "failing_backend.hpp"
#include "frame_renderer.hpp"
#include "living_scene.hpp"
#include "plant_levels.hpp"
#include "racing_scene.hpp"

namespace racer::testing {

constexpr int kWidth = 96, kHeight = 54;
constexpr float kDt = 1.0f / 30.0f;

// racer's headless loop (racer.cpp) for `frames` frames from `first`, chase camera.
struct RacingFrame {
    // levelsOfDetail: racer's default --lod on (each frame picks the plants' levels first).
    explicit RacingFrame(engine::render::Backend& backend, bool levelsOfDetail = false)
        : scene(backend, SceneOptions{defaultContentDir(), 1, {}, levelsOfDetail}), lod(levelsOfDetail),
          renderer(backend, scene.library(), rendererOptions()),
          living(scene.registry(), scene.library(), LivingSceneOptions{.seed = 1, .track = &scene.track()}) {
        renderer.setLivingScene(&living);
    }
    static RendererOptions rendererOptions() {
        RendererOptions o;
        o.width = kWidth;
        o.height = kHeight;
        return o;
    }
    // Frames first .. first + frames - 1; paused: the clock stands at `first` (dt 0, as the
    // window's pause key does), so every frame shows the same scene.
    void run(int first, int frames, CameraMode camera = CameraMode::Chase, bool paused = false) {
        for (int i = first; i < first + frames; ++i) {
            const float time = float(paused ? first : i) * kDt, dt = paused ? 0.0f : kDt;
            scene.update(dt);
            const CameraView view = cameraView(camera, scene, time, float(kWidth) / float(kHeight), FreeCamera{});
            if (lod)
                engine::scene::selectLevelsOfDetail(
                    scene.registry(), scene.library(),
                    {view.eye, engine::scene::focalPixels(view.projection, kHeight), 0.1f, racer::kLodCrossfade});
            living.update(time, dt, view, renderer.needsMotionVectors());
            rigidMotion.update(scene.registry(), renderer.needsMotionVectors());
            renderer.render(engine::scene::extractDrawLists(scene.registry(), scene.library(), view.viewProj, view.eye),
                            view);
        }
    }

    RacingScene scene;
    bool lod;
    FrameRenderer renderer;
    LivingScene living;
    engine::scene::RigidMotion rigidMotion{scene.library()};
};

// A steady frame is one the frame before it needed as much as: here the paused scene (the
// same view, the same plants bent, the same dust), which still re-uploads every per-frame
// buffer and rebuilds its graph each frame. Before pooling, each such frame created one
// instance buffer per batch and the particles' buffers.
inline void expectNoCreationsInSteadyState(engine::render::Backend& inner, bool levelsOfDetail = false) {
    // Never fails (failAt -1): it only counts creations and live resources.
    ssam::testing::FailingBackend backend(inner);
    RacingFrame frame(backend, levelsOfDetail);
    frame.run(0, 30);  // the car drives off, the dust rises, plants bend; pools fill
    const int createsBefore = backend.creates, liveBefore = backend.live;
    frame.run(30, 100, CameraMode::Chase, /*paused=*/true);
    EXPECT_EQ(backend.creates - createsBefore, 0) << "textures or buffers created in 100 steady-state frames";
    // Pools may retire what an earlier frame outgrew (FrameBufferPool::kRetireAfterFrames):
    // fewer resources, never more.
    EXPECT_LE(backend.live, liveBefore);
}

}  // namespace racer::testing
