// SPDX-License-Identifier: MIT
#pragma once
// ssam-bench --scaling: how each backend's SSAM and alpha-test frame time grows with the
// frame's pixels (the forest scene from 360p to 2160p) and with foliage depth complexity (the
// layers scene, 1 to 64 full-view leaf cards at one size). Timings only: no reference, no error.
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "engine/render/kernel/simd_isa.hpp"

namespace bench {

struct ScalingSize {
    int width = 0, height = 0;
};

struct ScalingOptions {
    std::vector<std::string> backends;                  // "soft", "gl", "vk"
    int threads = 0;                                    // soft threads and LP_NUM_THREADS; 0: all
    std::optional<engine::render::soft::SimdIsa> simd;  // the soft kernels' instruction set; unset: the widest
    int reps = 2, warmup = 1;
    std::vector<ScalingSize> sizes;  // the resolution axis (forest)
    std::vector<int> layers;         // the depth-complexity axis (layers scene)
    ScalingSize layersSize;          // the size the layers axis is measured at
    std::filesystem::path contentDir;
};

// The full set (360p..2160p; 1..64 layers at 720p) or the quick one a test runs in seconds.
ScalingOptions defaultScaling(bool quick);

struct ScalingRow {
    std::string axis;  // "pixels" or "layers"
    std::string backend, technique;
    int width = 0, height = 0, layers = 0;  // layers: 0 on the pixels axis (the forest scene)
    double medianMs = 0.0, cpuMedianMs = 0.0;
    std::string note;  // set when the point could not be measured (its times are then NaN)
};

// Rows by axis, backend, technique, then the axis's points in increasing order. Prints a
// progress line per point.
std::vector<ScalingRow> runScaling(const ScalingOptions& options);

// scaling.csv: one row per point; ms_per_mpixel and ms_per_layer are the time divided by the
// point's pixels (millions) and by its layers, the numbers that stay flat where cost is linear.
const std::vector<std::string>& scalingCsvColumns();
void writeScalingCsv(std::ostream& out, const std::vector<ScalingRow>& rows);
// scaling.svg: the two axes as two panels, time against pixels and against layers, a line
// per backend and technique.
void writeScalingSvg(std::ostream& out, const std::vector<ScalingRow>& rows);

}  // namespace bench
