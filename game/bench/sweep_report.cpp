// SPDX-License-Identifier: MIT
#include "sweep_report.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "report_text.hpp"

namespace bench {

namespace {

std::string referenceIn255ths(float reference) { return num(double(reference) * 255.0, "%.4g") + "/255"; }

// One knob of the sweep: its name, its value as a number (to order and compare) and as text.
struct Knob {
    const char* name;
    std::function<double(const ssam::Settings&)> value;
    std::function<std::string(const ssam::Settings&)> print;
};

const std::vector<Knob>& knobs() {
    static const std::vector<Knob> k{
        {"maskLerp", [](const ssam::Settings& c) { return double(c.maskLerp); },
         [](const ssam::Settings& c) { return num(double(c.maskLerp), "%g"); }},
        {"squareMask", [](const ssam::Settings& c) { return c.squareMask ? 1.0 : 0.0; },
         [](const ssam::Settings& c) { return std::string(c.squareMask ? "on" : "off"); }},
        {"colorAlphaReference", [](const ssam::Settings& c) { return double(c.colorAlphaReference); },
         [](const ssam::Settings& c) { return referenceIn255ths(c.colorAlphaReference); }},
        {"maskPrecision", [](const ssam::Settings& c) { return double(c.maskPrecision); },
         [](const ssam::Settings& c) { return std::string(ssam::maskPrecisionName(c.maskPrecision)); }},
        {"colorBlur", [](const ssam::Settings& c) { return c.colorBlur ? 1.0 : 0.0; },
         [](const ssam::Settings& c) { return std::string(c.colorBlur ? "on" : "off"); }},
    };
    return k;
}

// The value a row is ranked by; a missing one ranks last.
double rankValue(double v, bool higherIsBetter) {
    if (!has(v)) return INFINITY;
    return higherIsBetter ? -v : v;
}

const SweepResult* best(const std::vector<const SweepResult*>& results, double BenchRow::*field, bool higherIsBetter) {
    const SweepResult* b = nullptr;
    for (const SweepResult* r : results)
        if (has(r->row.*field) &&
            (!b || rankValue(r->row.*field, higherIsBetter) < rankValue(b->row.*field, higherIsBetter)))
            b = r;
    return b;
}

std::string range(const std::vector<const SweepResult*>& results, double BenchRow::*field, const char* format) {
    double lo = INFINITY, hi = -INFINITY;
    for (const SweepResult* r : results)
        if (has(r->row.*field)) {
            lo = std::min(lo, r->row.*field);
            hi = std::max(hi, r->row.*field);
        }
    if (!(lo <= hi)) return "";
    return num(lo, format) + " – " + num(hi, format) + " (Δ " + num(hi - lo, format) + ")";
}

void sweepTable(std::ostream& out, std::vector<const SweepResult*> results) {
    const SweepResult* bestFlip = best(results, &BenchRow::flipMean, false);
    const SweepResult* bestRmse = best(results, &BenchRow::rmseSrgb, false);
    const SweepResult* bestSsim = best(results, &BenchRow::ssim, true);
    std::stable_sort(results.begin(), results.end(), [](const SweepResult* a, const SweepResult* b) {
        return rankValue(a->row.flipMean, false) < rankValue(b->row.flipMean, false);
    });
    out << "| # | maskLerp | squareMask | colour ref | mask | colour blur | ꟻLIP | RMSE sRGB | RMSE lin | SSIM | flicker | "
           "time ms | |\n"
           "|---:|---:|---|---:|---|---|---:|---:|---:|---:|---:|---:|---|\n";
    int rank = 0;
    for (const SweepResult* r : results) {
        std::string marks;
        auto mark = [&](bool on, const char* what) {
            if (on) marks += std::string(marks.empty() ? "" : ", ") + what;
        };
        mark(r->setting.isDefault, "**defaults**");
        mark(r == bestFlip, "**best ꟻLIP**");
        mark(r == bestRmse, "**best RMSE sRGB**");
        mark(r == bestSsim, "**best SSIM**");
        if (!r->row.note.empty()) marks += std::string(marks.empty() ? "" : "; ") + mdCell(r->row.note);
        const ssam::Settings& c = r->setting.config;
        out << "| " << ++rank;
        for (const Knob& k : knobs()) out << " | " << k.print(c);
        out << " | " << num(r->row.flipMean, "%.4f") << " | " << num(r->row.rmseSrgb, "%.4f") << " | "
            << num(r->row.rmseLinear, "%.4f") << " | " << num(r->row.ssim, "%.4f") << " | "
            << num(r->row.flicker, "%.5f") << " | " << num(r->row.timeMedianMs, "%.1f") << " | " << marks << " |\n";
    }
    out << "\n";
}

// For each knob, the settings that differ from the defaults in that knob only (and the
// defaults): how far the knob alone moves the error.
void knobTable(std::ostream& out, const std::vector<const SweepResult*>& results) {
    const SweepResult* defaults = nullptr;
    for (const SweepResult* r : results)
        if (r->setting.isDefault) defaults = r;
    if (!defaults) return;
    out << "Each knob alone, the others at the defaults:\n\n"
           "| knob | value: ꟻLIP / RMSE sRGB | ꟻLIP range | RMSE sRGB range |\n|---|---|---|---|\n";
    for (std::size_t i = 0; i < knobs().size(); ++i) {
        std::vector<const SweepResult*> alone;
        for (const SweepResult* r : results) {
            bool othersAtDefaults = true;
            for (std::size_t j = 0; j < knobs().size(); ++j)
                if (j != i && knobs()[j].value(r->setting.config) != knobs()[j].value(defaults->setting.config))
                    othersAtDefaults = false;
            if (othersAtDefaults) alone.push_back(r);
        }
        std::stable_sort(alone.begin(), alone.end(), [&](const SweepResult* a, const SweepResult* b) {
            return knobs()[i].value(a->setting.config) < knobs()[i].value(b->setting.config);
        });
        std::string values;
        for (const SweepResult* r : alone)
            values += std::string(values.empty() ? "" : "; ") + knobs()[i].print(r->setting.config) + ": " +
                      num(r->row.flipMean, "%.4f") + " / " + num(r->row.rmseSrgb, "%.4f");
        out << "| " << knobs()[i].name << " | " << values << " | " << range(alone, &BenchRow::flipMean, "%.4f") << " | "
            << range(alone, &BenchRow::rmseSrgb, "%.4f") << " |\n";
    }
    out << "\n";
}

// Across scenes: each setting's geometric mean, over the scenes where the defaults have an
// error, of its error relative to the defaults' (1 = as the defaults, 0.7 = 30% lower), so
// one scene's larger errors do not outweigh the others'. Only settings measured everywhere.
void acrossScenesTable(std::ostream& out, const std::vector<SweepResult>& results, const std::string& backend) {
    std::map<std::string, const BenchRow*> defaults;  // per scene
    for (const SweepResult& r : results)
        if (r.row.backend == backend && r.setting.isDefault && has(r.row.flipMean) && r.row.flipMean > 0.0 &&
            has(r.row.rmseSrgb) && r.row.rmseSrgb > 0.0)
            defaults[r.row.scene] = &r.row;
    if (defaults.size() < 2) return;
    struct Summary {
        const SweepSetting* setting = nullptr;
        double logFlip = 0.0, logRmse = 0.0;
        std::size_t scenes = 0;
    };
    std::vector<Summary> summaries;
    std::map<std::string, std::size_t> index;
    for (const SweepResult& r : results) {
        if (r.row.backend != backend || !defaults.count(r.row.scene)) continue;
        if (!index.count(r.setting.name)) {
            index[r.setting.name] = summaries.size();
            summaries.push_back({&r.setting});
        }
        Summary& s = summaries[index[r.setting.name]];
        const BenchRow& d = *defaults[r.row.scene];
        if (!has(r.row.flipMean) || !has(r.row.rmseSrgb) || r.row.flipMean <= 0.0 || r.row.rmseSrgb <= 0.0) continue;
        s.logFlip += std::log(r.row.flipMean / d.flipMean);
        s.logRmse += std::log(r.row.rmseSrgb / d.rmseSrgb);
        ++s.scenes;
    }
    std::erase_if(summaries, [&](const Summary& s) { return s.scenes != defaults.size(); });
    std::stable_sort(summaries.begin(), summaries.end(),
                     [](const Summary& a, const Summary& b) { return a.logFlip < b.logFlip; });
    std::string scenes;
    for (const auto& [scene, row] : defaults) scenes += std::string(scenes.empty() ? "" : ", ") + scene;
    out << "## all scenes (" << backend
        << " backend)\n\nEach setting's error relative to the defaults', geometric "
           "mean over "
        << scenes
        << " (1 = as the defaults, 0.70 = 30% lower); sorted by ꟻLIP.\n\n"
           "| # | maskLerp | squareMask | colour ref | mask | ꟻLIP / defaults | RMSE sRGB / defaults | |\n"
           "|---:|---:|---|---:|---|---:|---:|---|\n";
    int rank = 0;
    for (const Summary& s : summaries) {
        out << "| " << ++rank;
        for (const Knob& k : knobs()) out << " | " << k.print(s.setting->config);
        const double n = double(s.scenes);
        out << " | " << num(std::exp(s.logFlip / n), "%.3f") << " | " << num(std::exp(s.logRmse / n), "%.3f") << " | "
            << (s.setting->isDefault ? "**defaults**" : "") << " |\n";
    }
    out << "\n";
}

}  // namespace

const std::vector<std::string>& sweepCsvColumns() {
    static const std::vector<std::string> columns{
        "scene",          "backend",     "setting",     "mask_lerp", "square_mask",    "color_alpha_reference",
        "mask_precision", "is_default",  "width",       "height",    "time_ms_median", "cpu_ms_median",
        "rmse_linear",    "psnr_linear", "rmse_srgb",   "psnr_srgb", "ssim",           "flip_mean",
        "flicker",        "flicker_raw", "peak_mem_mb", "note"};
    return columns;
}

void writeSweepCsv(std::ostream& out, const std::vector<SweepResult>& results) {
    writeCsvHeader(out, sweepCsvColumns());
    for (const SweepResult& s : results) {
        const BenchRow& r = s.row;
        const ssam::Settings& c = s.setting.config;
        out << csvField(r.scene) << ',' << r.backend << ',' << csvField(s.setting.name) << ','
            << num(double(c.maskLerp)) << ',' << (c.squareMask ? 1 : 0) << ',' << num(double(c.colorAlphaReference))
            << ',' << ssam::maskPrecisionName(c.maskPrecision) << ',' << (s.setting.isDefault ? 1 : 0) << ',' << r.width
            << ',' << r.height << ',' << num(r.timeMedianMs, "%.3f") << ',' << num(r.cpuMedianMs, "%.3f") << ','
            << num(r.rmseLinear) << ',' << num(r.psnrLinear) << ',' << num(r.rmseSrgb) << ',' << num(r.psnrSrgb) << ','
            << num(r.ssim) << ',' << num(r.flipMean) << ',' << num(r.flicker) << ',' << num(r.flickerRaw) << ','
            << num(r.peakMemMb, "%.3f") << ',' << csvField(r.note) << "\n";
    }
}

void writeSweepMarkdown(std::ostream& out, const SweepRun& run, const RunInfo& info) {
    out << "# ssam-bench --sweep\n\n`" << info.command << "`\n\n";
    if (!run.results.empty())
        out << run.results.front().row.width << "x" << run.results.front().row.height << ", " << info.reps
            << " timed repetition(s) after " << info.warmup << " warm-up, flicker over " << info.panFrames
            << " pan frames, " << info.threads << " thread(s).\n\n";
    out << "SSAM (technique `ssam`) under each setting of its knobs (`ssam::Settings`: maskLerp §3.5.4, squareMask "
           "§3.6.2, colour-pass alpha reference §3.5.3 in 255ths, mask precision §3.5.2; foliage clear colour at "
           "its default), judged against the exact reference like `ssam-bench`'s other rows. Sorted by mean ꟻLIP "
           "(lower is better); RMSE on sRGB-encoded and on linear colour; SSIM on luma (higher is better); "
           "flicker: the pan's flicker minus the reference's; time: median wall-clock frame (with few "
           "repetitions on a shared machine, a rough figure). The defaults row is what `ssam-bench --techniques "
           "ssam` measures.\n\n";

    std::vector<std::pair<std::string, std::string>> blocks;  // (scene, backend) in run order
    for (const SweepResult& r : run.results)
        if (std::find(blocks.begin(), blocks.end(), std::pair(r.row.scene, r.row.backend)) == blocks.end())
            blocks.emplace_back(r.row.scene, r.row.backend);
    for (const auto& [scene, backend] : blocks) {
        std::vector<const SweepResult*> results;
        for (const SweepResult& r : run.results)
            if (r.row.scene == scene && r.row.backend == backend) results.push_back(&r);
        out << "## " << scene << " (" << backend << " backend)\n\n";
        sweepTable(out, results);
        knobTable(out, results);
        bool any = false;
        for (const BenchRow& r : run.comparison) {
            if (r.scene != scene || r.backend != backend) continue;
            if (!any)
                out << "For comparison, the same run:\n\n| technique | ꟻLIP | RMSE sRGB | RMSE lin | SSIM | flicker | "
                       "time ms | note |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
            any = true;
            out << "| " << r.technique << " | " << num(r.flipMean, "%.4f") << " | " << num(r.rmseSrgb, "%.4f") << " | "
                << num(r.rmseLinear, "%.4f") << " | " << num(r.ssim, "%.4f") << " | " << num(r.flicker, "%.5f") << " | "
                << num(r.timeMedianMs, "%.1f") << " | " << mdCell(r.note) << " |\n";
        }
        if (any) out << "\n";
    }
    std::vector<std::string> backends;
    for (const auto& [scene, backend] : blocks)
        if (std::find(backends.begin(), backends.end(), backend) == backends.end()) backends.push_back(backend);
    for (const std::string& backend : backends) acrossScenesTable(out, run.results, backend);
}

}  // namespace bench
