// SPDX-License-Identifier: MIT
#include "bench_figures.hpp"

#include <algorithm>
#include <cmath>

#include "bench_goals.hpp"
#include "report_text.hpp"

namespace bench {

namespace {

std::vector<std::string> distinctScenes(const std::vector<BenchRow>& rows) {
    std::vector<std::string> out;
    for (const BenchRow& r : rows)
        if (std::find(out.begin(), out.end(), r.scene) == out.end()) out.push_back(r.scene);
    return out;
}

void writeIntro(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& in) {
    out << "# Current figures\n\n"
           "The figures that more than one README quotes live here, once each; the READMEs link to this page "
           "instead of restating them. **This file is generated** by `ssam-bench --figures` "
           "(game/bench/bench_figures.cpp) from one run; do not edit it by hand: run the command again and commit "
           "what it writes. This one was written by\n\n`"
        << in.run.command << "`\n\n";
    if (!rows.empty())
        out << rows.front().width << "x" << rows.front().height << ", " << in.run.reps << " timed repetition(s) after "
            << in.run.warmup << " warm-up, flicker over " << in.run.panFrames
            << " pan frames, the per-frame error over " << in.temporalFrames << " pan frames, " << in.run.threads
            << " thread(s) (soft tiles; LP_NUM_THREADS for gl). Technique `ssam` runs preset `" << in.run.ssamPreset
            << "`.\n\n";
    out << "| section | what |\n|---|---|\n"
           "| [Speed: soft against llvmpipe](#speed-soft-against-llvmpipe) | game/bench/speed_table.sh, given "
           "with `--speed-table` |\n"
           "| [SSAM against its rivals](#ssam-against-its-rivals) | every technique per scene: time, error, "
           "flicker, error per frame of a pan |\n"
           "| [Goals](#goals) | SSAM against alpha testing, met or not |\n"
           "| [SSAM and hashed+taa](#ssam-and-hashedtaa) | the two side by side, and which is better at what |\n\n"
           "Wall times scatter from run to run on a shared machine; errors and memory are deterministic "
           "on the soft backend. Every GL figure is Mesa llvmpipe's, a CPU rasterizer.\n\n";
}

void writeSpeed(std::ostream& out, const FiguresInput& in) {
    out << "## Speed: soft against llvmpipe\n\n";
    if (in.speedTable.empty()) {
        out << "Not part of this run. `make bench` runs game/bench/speed_table.sh first and passes its table "
               "here with `--speed-table out/bench/speed_table.md`.\n\n";
        return;
    }
    out << "From `" << in.speedTableSource
        << "`, written by game/bench/speed_table.sh (racer's whole frame and ssam-bench's SSAM frame on "
           "both backends with the same threads, each the median of its rounds). What limits each goal: "
           "[engine/render/docs/soft_backend.md](../../engine/render/docs/soft_backend.md#what-limits-each-goal)."
           "\n\n"
        << in.speedTable;
    if (in.speedTable.back() != '\n') out << "\n";
    out << "\n";
}

void writeRivals(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& in) {
    out << "## SSAM against its rivals\n\n"
           "Time: the median frame (opaque pass and the technique). RMSE (linear) and ꟻLIP: the still frame "
           "against the exact reference (technique `reference`: every fragment sorted and composited). "
           "Flicker: mean change of sRGB luma between frames of a slow sideways pan, minus the reference's "
           "([Hathaway 2010] §3.4). Pan ꟻLIP and RMSE: each of "
        << in.temporalFrames
        << " pan frames against that frame's reference over the foliage pixels; converged is the median of "
           "the last half, worst the worst frame, and a technique with history is never measured on its first "
           "frame. Memory: targets and buffers the technique allocated. Bold: the best of the scene's "
           "techniques (the reference left out) where no other shares it.\n\n";
    std::vector<std::string> backends;
    for (const BenchRow& r : rows)
        if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) backends.push_back(r.backend);
    for (const std::string& scene : distinctScenes(rows))
        for (const std::string& backend : backends) {
            std::vector<const BenchRow*> here;
            for (const BenchRow& r : rows)
                if (r.scene == scene && r.backend == backend) here.push_back(&r);
            if (here.empty()) continue;
            // The best value of a column among the techniques compared (not the reference, not the
            // frame without foliage): printed bold.
            auto best = [&](double BenchRow::*field, bool absolute) {
                double b = kMissing;
                for (const BenchRow* r : here) {
                    if (r->technique == "reference" || r->technique == kOpaqueOnly || !has(r->*field)) continue;
                    const double v = absolute ? std::abs(r->*field) : r->*field;
                    if (!has(b) || v < b) b = v;
                }
                return b;
            };
            auto compared = [](const BenchRow* r) {
                return r->technique != "reference" && r->technique != kOpaqueOnly;
            };
            // Bold only a best value no other technique shares (no bold column where all tie).
            auto cell = [&](const BenchRow* r, double BenchRow::*field, const char* format, bool absolute = false) {
                const std::string text = num(r->*field, format);
                const double b = best(field, absolute);
                auto isBest = [&](const BenchRow* x) {
                    return compared(x) && has(x->*field) && (absolute ? std::abs(x->*field) : x->*field) == b;
                };
                const bool bold = isBest(r) && std::count_if(here.begin(), here.end(), isBest) == 1;
                return bold ? "**" + text + "**" : text;
            };
            out << "### " << scene << ", " << backend << "\n\n"
                << "| technique | time ms | RMSE | ꟻLIP | flicker | pan ꟻLIP converged | pan ꟻLIP worst | "
                   "pan RMSE converged | memory MiB | note |\n"
                   "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
            for (const BenchRow* r : here)
                out << "| " << (r->technique == kOpaqueOnly ? r->technique : "`" + r->technique + "`") << " | "
                    << cell(r, &BenchRow::timeMedianMs, "%.2f") << " | " << cell(r, &BenchRow::rmseLinear, "%.5f")
                    << " | " << cell(r, &BenchRow::flipMean, "%.4f") << " | "
                    << cell(r, &BenchRow::flicker, "%.5f", true) << " | " << cell(r, &BenchRow::temporalFlip, "%.4f")
                    << " | " << cell(r, &BenchRow::temporalFlipWorst, "%.4f") << " | "
                    << cell(r, &BenchRow::temporalRmse, "%.5f") << " | " << num(r->peakMemMb, "%.1f") << " | "
                    << mdCell(r->note) << " |\n";
            out << "\n";
        }
}

void writeSideBySide(std::ostream& out, const std::vector<BenchRow>& rows) {
    out << "## SSAM and hashed+taa\n\n"
           "Technique `ssam` (its preset above) beside `hashed+taa` (hashed alpha testing [Wyman & McGuire 2017] "
           "resolved by the temporal pass), on the "
        << primaryBackend(rows)
        << " backend; the last column names the lower (better) of the two for each measure. Memory counts "
           "the temporal pass's history.\n\n"
           "| scene | measure | ssam | hashed+taa | lower |\n|---|---|---:|---:|---|\n";
    struct Measure {
        const char* name;
        double BenchRow::*field;
        const char* format;
    };
    const Measure measures[] = {{"time ms", &BenchRow::timeMedianMs, "%.2f"},
                                {"ꟻLIP, still frame", &BenchRow::flipMean, "%.4f"},
                                {"ꟻLIP, pan converged", &BenchRow::temporalFlip, "%.4f"},
                                {"ꟻLIP, pan worst frame", &BenchRow::temporalFlipWorst, "%.4f"},
                                {"RMSE, pan converged", &BenchRow::temporalRmse, "%.5f"},
                                {"flicker", &BenchRow::flicker, "%.5f"},
                                {"memory MiB", &BenchRow::peakMemMb, "%.1f"}};
    const std::string backend = primaryBackend(rows);
    bool any = false;
    for (const std::string& scene : distinctScenes(rows)) {
        const BenchRow* s = findRow(rows, scene, "ssam", backend);
        const BenchRow* h = findRow(rows, scene, "hashed+taa", backend);
        if (!s || !h) continue;
        for (const Measure& m : measures) {
            const double a = s->*m.field, b = h->*m.field;
            if (!has(a) && !has(b)) continue;
            any = true;
            const bool signedMeasure = m.field == &BenchRow::flicker;  // less than the reference's: |x|
            const double ka = signedMeasure ? std::abs(a) : a, kb = signedMeasure ? std::abs(b) : b;
            const std::string lower = !has(a) || !has(b) ? "" : ka < kb ? "ssam" : kb < ka ? "hashed+taa" : "equal";
            out << "| " << scene << " | " << m.name << " | " << num(a, m.format) << " | " << num(b, m.format) << " | "
                << lower << " |\n";
        }
    }
    if (!any) out << "| | not measured: the run lacked `ssam` or `hashed+taa` | | | |\n";
    out << "\n";
}

}  // namespace

void writeFigures(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& input) {
    writeIntro(out, rows, input);
    writeSpeed(out, input);
    writeRivals(out, rows, input);
    out << "## Goals\n\nSSAM against alpha testing, from the rows above (" << primaryBackend(rows)
        << " backend): the recommended preset's ꟻLIP at or below alpha testing's at no more than 1.25x the "
           "paper preset's time, SSAM+'s ꟻLIP at most 0.6x alpha testing's, and SSAM's flicker in the forest "
           "pan at most 0.3x alpha testing's. The time is not the rows' (each technique timed after the other, "
           "so a change in the machine's speed lands on one): the two presets' frames are timed alternately, "
           "A B A B, after the rows.\n\n";
    writeGoalTable(out, rivalGoals(rows));
    out << "\n";
    writeSideBySide(out, rows);
}

}  // namespace bench
