// SPDX-License-Identifier: MIT
#include "bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "engine/core/error.hpp"
#include "bench_frame.hpp"
#include "bench_goals.hpp"
#include "report_text.hpp"

namespace bench {

namespace {

std::vector<std::string> distinct(const std::vector<BenchRow>& rows, std::string BenchRow::*field) {
    std::vector<std::string> out;
    for (const BenchRow& r : rows)
        if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
    return out;
}

// The temporal measures (bench_temporal.hpp), one table for every backend that has them.
void writeTemporalMarkdown(std::ostream& out, const std::vector<BenchRow>& rows) {
    bool any = false;
    for (const BenchRow& r : rows) any = any || r.temporalFrames > 0;
    if (!any) return;
    out << "## temporal: error per frame of a pan\n\n"
           "Each frame of a sideways pan against that frame's exact reference, over the foliage pixels (where "
           "the reference differs from the opaque-only frame): converged = median over the last half of the "
           "frames, worst = the worst frame. Techniques with history start the pan after "
        << kHistoryFrames
        << " frames of its first view, so none is measured on its first frame. The reprojection sees the "
           "camera, not the wind: what the temporal pass would ghost under wind is not in these (static) scenes.\n\n";
    out << "| scene | technique | backend | frames | ꟻLIP converged | ꟻLIP worst | RMSE converged | RMSE worst |\n"
           "|---|---|---|---:|---:|---:|---:|---:|\n";
    for (const BenchRow& r : rows) {
        if (r.temporalFrames == 0) continue;
        out << "| " << r.scene << " | " << r.technique << " | " << r.backend << " | " << r.temporalFrames << " | "
            << num(r.temporalFlip, "%.4f") << " | " << num(r.temporalFlipWorst, "%.4f") << " | "
            << num(r.temporalRmse, "%.5f") << " | " << num(r.temporalRmseWorst, "%.5f") << " |\n";
    }
    out << "\n";
}

}  // namespace

const std::vector<std::string>& csvColumns() {
    static const std::vector<std::string> columns{"scene",         "technique",
                                                  "backend",       "width",
                                                  "height",        "time_ms_median",
                                                  "time_ms_min",   "time_ms_max",
                                                  "cpu_ms_median", "rmse_linear",
                                                  "psnr_linear",   "rmse_srgb",
                                                  "psnr_srgb",     "ssim",
                                                  "flip_mean",     "flicker",
                                                  "flicker_raw",   "peak_mem_mb",
                                                  "peak_rss_mb",   "temporal_frames",
                                                  "temporal_flip", "temporal_flip_worst",
                                                  "temporal_rmse", "temporal_rmse_worst",
                                                  "note"};
    return columns;
}

void writeCsv(std::ostream& out, const std::vector<BenchRow>& rows) {
    writeCsvHeader(out, csvColumns());
    for (const BenchRow& r : rows) {
        out << csvField(r.scene) << ',' << csvField(r.technique) << ',' << r.backend << ',' << r.width << ','
            << r.height << ',' << num(r.timeMedianMs, "%.3f") << ',' << num(r.timeMinMs, "%.3f") << ','
            << num(r.timeMaxMs, "%.3f") << ',' << num(r.cpuMedianMs, "%.3f") << ',' << num(r.rmseLinear) << ','
            << num(r.psnrLinear) << ',' << num(r.rmseSrgb) << ',' << num(r.psnrSrgb) << ',' << num(r.ssim) << ','
            << num(r.flipMean) << ',' << num(r.flicker) << ',' << num(r.flickerRaw) << ',' << num(r.peakMemMb, "%.3f")
            << ',' << num(r.peakRssMb, "%.1f") << ',' << r.temporalFrames << ',' << num(r.temporalFlip) << ','
            << num(r.temporalFlipWorst) << ',' << num(r.temporalRmse) << ',' << num(r.temporalRmseWorst) << ','
            << csvField(r.note) << "\n";
    }
}

void writePassesCsv(std::ostream& out, const std::vector<BenchRow>& rows) {
    out << "scene,technique,backend,pass,time_ms_median\n";
    for (const BenchRow& r : rows)
        for (const PassTime& p : r.passes)
            out << csvField(r.scene) << ',' << csvField(r.technique) << ',' << r.backend << ',' << csvField(p.pass)
                << ',' << num(p.medianMs, "%.3f") << "\n";
}

void writeMarkdown(std::ostream& out, const std::vector<BenchRow>& rows, const RunInfo& info) {
    out << "# ssam-bench\n\n`" << info.command << "`\n\n";
    if (!rows.empty())
        out << rows.front().width << "x" << rows.front().height << ", " << info.reps << " timed repetition(s) after "
            << info.warmup << " warm-up, flicker over " << info.panFrames << " pan frames, " << info.threads
            << " thread(s) (soft backend; LP_NUM_THREADS for gl).\n\n";
    if (!info.ssamPreset.empty())
        out << "Technique `ssam` runs preset `" << info.ssamPreset
            << "` (`--ssam-preset`; `measured` is the knob sweep's best across tree, forest and vista within 1.25x "
               "the paper's time: ssam/docs/knobs.md \"Presets\").\n\n";
    out << "Time: wall clock of one frame (opaque pass + the technique, including its resolve; GL waits for the "
           "frame's timer queries), median (min-max). Errors against the exact reference (technique `reference` "
           "on the soft backend). Flicker: mean |change| of sRGB luma between consecutive frames of a slow sideways "
           "pan, minus the reference's ([Hathaway 2010] §3.4). Memory: peak MiB of targets and buffers the technique "
           "and its opaque targets allocated through the backend (exact, deterministic); RSS: growth of the "
           "process's peak resident memory while the technique ran (CPU-side memory too, e.g. the reference's "
           "fragment lists; noisy). `opaque-only`: the frame without foliage (its errors: what leaving "
           "the foliage out costs).\n\n";

    for (const std::string& backend : distinct(rows, &BenchRow::backend)) {
        out << "## backend " << backend << "\n\n";
        out << "| scene | technique | time ms | CPU ms | RMSE lin | PSNR sRGB | SSIM | ꟻLIP | flicker | mem MiB | RSS MiB | note |\n";
        out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
        for (const BenchRow& r : rows) {
            if (r.backend != backend) continue;
            const std::string time = r.ran ? num(r.timeMedianMs, "%.2f") + " (" + num(r.timeMinMs, "%.2f") + "-" +
                                                 num(r.timeMaxMs, "%.2f") + ")"
                                           : "";
            out << "| " << r.scene << " | " << r.technique << " | " << time << " | " << num(r.cpuMedianMs, "%.1f")
                << " | " << num(r.rmseLinear, "%.5f") << " | " << num(r.psnrSrgb, "%.2f") << " | "
                << num(r.ssim, "%.4f") << " | " << num(r.flipMean, "%.4f") << " | " << num(r.flicker, "%.5f") << " | "
                << num(r.peakMemMb, "%.2f") << " | " << num(r.peakRssMb, "%.1f") << " | " << mdCell(r.note) << " |\n";
        }
        out << "\n";
    }

    writeTemporalMarkdown(out, rows);

    // Goal ratios (SSAM against its rivals, game/bench/FIGURES.md), from this run.
    const std::string primary = primaryBackend(rows);
    auto value = [&](const std::string& scene, const std::string& technique, double BenchRow::*field,
                     const std::string& backend) -> std::optional<double> {
        const BenchRow* r = findRow(rows, scene, technique, backend);
        if (!r || !has(r->*field)) return std::nullopt;
        return r->*field;
    };
    out << "## goals (" << primary
        << " backend)\n\nStatus from the ratio (wall time for time goals); for time goals "
           "the ratio of median CPU times is shown too, which other processes on the machine disturb less.\n\n"
           "| goal | ratio | CPU-time ratio | target | status |\n|---|---:|---:|---|---|\n";
    auto goal = [&](const std::string& what, std::optional<double> a, std::optional<double> b, bool atMost,
                    double target, std::optional<double> cpuA = std::nullopt,
                    std::optional<double> cpuB = std::nullopt) {
        const std::string cpuRatio = cpuA && cpuB && *cpuB > 0.0 ? num(*cpuA / *cpuB, "%.3f") : "";
        std::string ratio = "n/a", status = "not measured";
        if (a && b && *b != 0.0) {
            const double q = *a / *b;
            ratio = num(q, "%.3f");
            status = (atMost ? q <= target : q >= target) ? "met" : "not met";
        } else if (a && b) {
            status = "undefined (division by zero)";
        }
        out << "| " << what << " | " << ratio << " | " << cpuRatio << " | " << (atMost ? "<= " : ">= ")
            << num(target, "%.2f") << " | " << status << " |\n";
    };
    // The ratios of one measure between two techniques on one scene that FIGURES.md sets as
    // goals; a time goal shows the ratio of median CPU times too.
    struct RatioGoal {
        const char* what;
        const char* scene;
        const char* technique;
        const char* against;
        double BenchRow::*field;
        bool atMost;
        double target;
    };
    const RatioGoal goals[] = {
        {"forest: ꟻLIP ssam / alpha-test", "forest", "ssam", "alpha-test", &BenchRow::flipMean, true, 0.5},
        {"forest: RMSE ssam / alpha-test", "forest", "ssam", "alpha-test", &BenchRow::rmseLinear, true, 0.5},
        {"forest: ꟻLIP ssam / wboit", "forest", "ssam", "wboit", &BenchRow::flipMean, true, 1.0},
        {"forest: RMSE ssam / wboit", "forest", "ssam", "wboit", &BenchRow::rmseLinear, true, 1.0},
        {"forest: flicker ssam / alpha-test", "forest", "ssam", "alpha-test", &BenchRow::flicker, true, 0.3},
        {"forest: time ssam / alpha-test", "forest", "ssam", "alpha-test", &BenchRow::timeMedianMs, true, 1.5},
        {"forest: time reference / ssam", "forest", "reference", "ssam", &BenchRow::timeMedianMs, false, 10.0},
        {"forest: ꟻLIP ssam-plus / ssam (30% lower)", "forest", "ssam-plus", "ssam", &BenchRow::flipMean, true, 0.7},
        {"forest: RMSE ssam-plus / ssam (30% lower)", "forest", "ssam-plus", "ssam", &BenchRow::rmseLinear, true, 0.7},
        {"forest: time ssam-plus / ssam", "forest", "ssam-plus", "ssam", &BenchRow::timeMedianMs, true, 1.2},
        {"empty: time ssam / opaque-only", "empty", "ssam", kOpaqueOnly, &BenchRow::timeMedianMs, true, 1.05}};
    for (const RatioGoal& g : goals) {
        auto v = [&](const char* technique, double BenchRow::*field) {
            return value(g.scene, technique, field, primary);
        };
        if (g.field == &BenchRow::timeMedianMs)
            goal(g.what, v(g.technique, g.field), v(g.against, g.field), g.atMost, g.target,
                 v(g.technique, &BenchRow::cpuMedianMs), v(g.against, &BenchRow::cpuMedianMs));
        else goal(g.what, v(g.technique, g.field), v(g.against, g.field), g.atMost, g.target);
    }
    const auto backends = distinct(rows, &BenchRow::backend);
    const bool both = std::find(backends.begin(), backends.end(), "soft") != backends.end() &&
                      std::find(backends.begin(), backends.end(), "gl") != backends.end();
    if (both)
        for (const std::string& scene : distinct(rows, &BenchRow::scene))
            goal(scene + ": time ssam soft / gl", value(scene, "ssam", &BenchRow::timeMedianMs, "soft"),
                 value(scene, "ssam", &BenchRow::timeMedianMs, "gl"), true, 0.5,
                 value(scene, "ssam", &BenchRow::cpuMedianMs, "soft"),
                 value(scene, "ssam", &BenchRow::cpuMedianMs, "gl"));
    else out << "| time ssam soft / gl | n/a |  | <= 0.50 | not measured (run with --backend soft,gl) |\n";
    out << "\n## goals against the techniques engines ship (" << primary
        << " backend)\n\nThe recommended preset's ꟻLIP at or below alpha testing's at no more than 1.25x the paper "
           "preset's time (row `"
        << kSsamPaperRow
        << "`, added by --with-paper-ssam; the two presets' frames timed alternately), SSAM+'s ꟻLIP at most 0.6x "
           "alpha testing's, SSAM's flicker in the forest pan at most 0.3x alpha testing's.\n\n";
    writeGoalTable(out, rivalGoals(rows));
    out << "\n";

    if (both) {
        out << "## soft / gl time per technique\n\n| scene | technique | soft ms | gl ms | soft / gl |\n"
               "|---|---|---:|---:|---:|\n";
        for (const BenchRow& r : rows) {
            if (r.backend != "soft") continue;
            const BenchRow* g = findRow(rows, r.scene, r.technique, "gl");
            const double s = r.timeMedianMs, gms = g ? g->timeMedianMs : kMissing;
            out << "| " << r.scene << " | " << r.technique << " | " << num(s, "%.2f") << " | " << num(gms, "%.2f")
                << " | " << (has(s) && has(gms) && gms > 0 ? num(s / gms, "%.3f") : "") << " |\n";
        }
        out << "\n";
    }
    out << "Chart: [bench.svg](bench.svg). Per-pass medians: bench_passes.csv.\n";
}

}  // namespace bench
