// SPDX-License-Identifier: MIT
#include "bench_sweep.hpp"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "engine/core/error.hpp"

namespace bench {

namespace {

bool sameKnobs(const ssam::Settings& a, const ssam::Settings& b) {
    return a.maskLerp == b.maskLerp && a.squareMask == b.squareMask && a.colorAlphaReference == b.colorAlphaReference &&
           a.maskPrecision == b.maskPrecision &&
           std::equal(std::begin(a.foliageClearColor), std::end(a.foliageClearColor), b.foliageClearColor) &&
           a.depthTest == b.depthTest && a.depthMaskThreshold == b.depthMaskThreshold && a.colorFade == b.colorFade &&
           a.colorBlur == b.colorBlur;
}

template <typename T>
void requireValues(const std::vector<T>& values, const char* knob) {
    if (values.empty()) throw engine::Error(std::string("ssam-bench --sweep: no value for ") + knob);
}

}  // namespace

std::string settingName(const ssam::Settings& c) {
    char buf[96];
    // The reference in 255ths, as the paper counts it (§3.5.3: "≈ 64", "≈ 128").
    std::snprintf(buf, sizeof buf, "ssam-lerp%g-%s-ref%.4g-%s%s", double(c.maskLerp), c.squareMask ? "sq" : "nosq",
                  double(c.colorAlphaReference) * 255.0, ssam::maskPrecisionName(c.maskPrecision),
                  c.colorBlur ? "-blur" : "");
    return buf;
}

std::vector<SweepSetting> sweepSettings(const SweepGrid& grid) {
    requireValues(grid.maskLerp, "maskLerp");
    requireValues(grid.squareMask, "squareMask");
    requireValues(grid.colorAlphaReference, "colorAlphaReference");
    requireValues(grid.maskPrecision, "maskPrecision");
    requireValues(grid.colorBlur, "colorBlur");
    const ssam::Settings defaults;
    std::vector<SweepSetting> settings;
    auto add = [&](const ssam::Settings& c) {
        if (const std::string error = ssam::settingsError(c); !error.empty()) throw engine::Error(error);
        for (const SweepSetting& s : settings)
            if (sameKnobs(s.config, c)) return;
        settings.push_back({c, settingName(c), sameKnobs(c, defaults)});
    };
    add(defaults);
    if (grid.full) {
        for (float lerp : grid.maskLerp)
            for (bool square : grid.squareMask)
                for (float reference : grid.colorAlphaReference)
                    for (ssam::MaskPrecision precision : grid.maskPrecision)
                        for (bool blur : grid.colorBlur) {
                            ssam::Settings c = defaults;
                            c.maskLerp = lerp;
                            c.squareMask = square;
                            c.colorAlphaReference = reference;
                            c.maskPrecision = precision;
                            c.colorBlur = blur;
                            add(c);
                        }
        return settings;
    }
    for (float lerp : grid.maskLerp)
        for (bool square : grid.squareMask) {
            ssam::Settings c = defaults;
            c.maskLerp = lerp;
            c.squareMask = square;
            add(c);
        }
    // The other knobs one at a time from the defaults.
    auto vary = [&](const auto& values, auto knob) {
        for (auto value : values) {
            ssam::Settings c = defaults;
            c.*knob = value;
            add(c);
        }
    };
    vary(grid.colorAlphaReference, &ssam::Settings::colorAlphaReference);
    vary(grid.maskPrecision, &ssam::Settings::maskPrecision);
    vary(grid.colorBlur, &ssam::Settings::colorBlur);
    return settings;
}

std::vector<BenchSubject> sweepSubjects(const std::vector<SweepSetting>& settings) {
    std::vector<BenchSubject> subjects;
    for (const SweepSetting& s : settings) {
        transparency::TechniqueOptions options;
        options.ssam = s.config;
        subjects.push_back({s.name, transparency::TechniqueKind::Ssam, options});
    }
    return subjects;
}

SweepRun runSweep(BenchOptions options, const std::vector<SweepSetting>& settings,
                  const std::vector<BenchSubject>& comparison) {
    options.subjects = sweepSubjects(settings);
    options.subjects.insert(options.subjects.end(), comparison.begin(), comparison.end());
    const std::vector<BenchRow> rows = runBench(options);
    // runBench's rows: per scene and backend, one block of the subjects in order.
    const std::size_t block = options.subjects.size();
    if (rows.size() % block != 0)
        throw engine::Error("ssam-bench --sweep: " + std::to_string(rows.size()) + " rows for " +
                            std::to_string(block) + " subjects");
    SweepRun run;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::size_t k = i % block;
        if (k < settings.size()) run.results.push_back({settings[k], rows[i]});
        else run.comparison.push_back(rows[i]);
    }
    return run;
}

}  // namespace bench
