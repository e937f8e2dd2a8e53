// SPDX-License-Identifier: MIT
#pragma once
// The rows of `ssam-bench`'s results. BenchRow: a technique (or the opaque-only frame) on one scene and
// backend. Missing values (no reference yet, no pan, a skipped technique) are NaN and are
// written as empty CSV cells; `note` says why.
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace bench {

inline constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();
inline constexpr const char* kOpaqueOnly = "opaque-only";  // the technique column of the opaque frame

struct PassTime {
    std::string pass;
    double medianMs = 0.0;
};

struct BenchRow {
    std::string scene, technique, backend;
    int width = 0, height = 0;
    bool ran = false;  // false: skipped, `note` says why
    double timeMedianMs = kMissing, timeMinMs = kMissing, timeMaxMs = kMissing;
    // Median CPU time of the process (all threads, llvmpipe's included) per frame: unlike wall
    // time it barely moves when other processes compete for the cores.
    double cpuMedianMs = kMissing;
    // Median wall time when timed alternately with its pair (ssam against ssam-paper,
    // bench_alternate.hpp): the time goal's measure. Missing for the other rows.
    double timeAlternatedMs = kMissing;
    std::vector<PassTime> passes;  // median per pass name over the timed repetitions, in execution order
    // Against the exact reference of the same view (soft backend).
    double rmseLinear = kMissing, psnrLinear = kMissing, rmseSrgb = kMissing, psnrSrgb = kMissing;
    double ssim = kMissing, flipMean = kMissing;
    double flickerRaw = kMissing;  // temporalFlicker over the pan
    double flicker = kMissing;     // flickerRaw minus the reference's over the same pan
    double peakMemMb = kMissing;   // peak bytes of targets/buffers the technique allocated, MiB
    double peakRssMb = kMissing;   // growth of the process's peak RSS while it ran, MiB (CPU memory too)
    // The temporal measures (bench_temporal.hpp): ꟻLIP and RMSE of each frame of a pan against
    // that frame's reference, over the foliage pixels; converged = the median over the last
    // half of the frames, worst = the largest.
    int temporalFrames = 0;
    double temporalFlip = kMissing, temporalFlipWorst = kMissing;
    double temporalRmse = kMissing, temporalRmseWorst = kMissing;
    std::string note;
};

// One technique through one motion of ssam-bench --motion (bench_motion.hpp, which defines
// the measures).
struct MotionRow {
    std::string scene, motion, technique, backend = "soft";
    bool motionVectors = true;
    int frames = 0;       // frames measured (those with foliage in view)
    int ghostFrames = 0;  // of those, the ones with moved pixels (the ghost columns' frames)
    double flicker = 0.0, flip = 0.0, flipWorst = 0.0, rmse = 0.0, rmseWorst = 0.0, ghost = 0.0, ghostWorst = 0.0;
};

// One frame of the dolly, for one technique: the measures whose worst or mean DollyRow keeps
// (change and excess from the frame before; NaN on the first frame).
struct DollyFrame {
    double change = kMissing, excess = kMissing, lodFlip = 0.0;
};

// One technique along the dolly of ssam-bench --dolly (bench_dolly.hpp, which defines the
// measures).
struct DollyRow {
    std::string scene, technique, backend = "soft";
    int frames = 0;
    double pop = 0.0, popLod = 0.0;
    int popFrame = 0, popLodFrame = 0;  // the later frame of the worst pair
    double popLodMedian = 0.0;          // the median frame's excess: the floor a level switch rises above
    double lodFlipMean = 0.0, lodFlipWorst = 0.0, lodFrameFlipMean = 0.0;
    float crossfade = 0.0f;
    std::vector<DollyFrame> perFrame = {};  // frame k at index k
};

inline bool has(double v) { return std::isfinite(v); }

}  // namespace bench
