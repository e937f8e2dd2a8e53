// SPDX-License-Identifier: MIT
#pragma once
// `ssam-bench --sweep`: SSAM's error against the exact reference under a grid of its knobs
// (ssam::Settings: maskLerp §3.5.4, squareMask §3.6.2, colorAlphaReference §3.5.3,
// maskPrecision §3.5.2). The paper chose them by eye for Pure's look (§3.5.3: "exposed to the
// artists for tweaking"); the sweep measures which minimise the error and what each costs.
#include <string>
#include <vector>

#include "bench_result.hpp"
#include "bench_runner.hpp"
#include "ssam/core/settings.hpp"

namespace bench {

// The values swept for each knob: by default the paper's value and others on either side of it.
struct SweepGrid {
    std::vector<float> maskLerp{0.0f, 0.25f, 0.5f, 0.85f, 1.0f};
    std::vector<bool> squareMask{true, false};
    std::vector<float> colorAlphaReference{16.0f / 255.0f, 64.0f / 255.0f, 128.0f / 255.0f};
    std::vector<ssam::MaskPrecision> maskPrecision{ssam::MaskPrecision::Rgba8, ssam::MaskPrecision::Rgba16f};
    std::vector<bool> colorBlur{false};  // Settings::colorBlur: off unless asked (--sweep-blur)
    bool full = false;                   // every combination; otherwise around the defaults (see sweepSettings)
};

struct SweepSetting {
    ssam::Settings config;
    std::string name;        // file-safe, e.g. "ssam-lerp0.85-sq-ref64-rgba8": rows' technique, image names
    bool isDefault = false;  // ssam::Settings{}: the paper's defaults, what technique `ssam` runs
};

// The settings to measure, the defaults first, none twice. Full grid: the defaults, then the
// product of every knob's values. Otherwise (around the defaults): every maskLerp x squareMask
// combination with the other knobs at their defaults (the two knobs that together form the
// composite's coverage, §3.5.4 and §3.6.2), then each value of colorAlphaReference and of
// maskPrecision alone. Throws engine::Error for an empty list or an invalid value (the
// message names the knob: ssam::Settings::validate).
std::vector<SweepSetting> sweepSettings(const SweepGrid& grid);

// The runner's subjects for the settings: technique `ssam` with each setting's config.
std::vector<BenchSubject> sweepSubjects(const std::vector<SweepSetting>& settings);

// The name a setting's row and images carry.
std::string settingName(const ssam::Settings& config);

struct SweepResult {
    SweepSetting setting;
    BenchRow row;
};

struct SweepRun {
    std::vector<SweepResult> results;  // scene, backend, then the settings in order
    std::vector<BenchRow> comparison;  // the techniques measured beside them, same order
};

// Measures every setting, and the `comparison` subjects, on options' scenes and backends
// (options.subjects is replaced), against each scene's exact reference computed once.
SweepRun runSweep(BenchOptions options, const std::vector<SweepSetting>& settings,
                  const std::vector<BenchSubject>& comparison);

}  // namespace bench
