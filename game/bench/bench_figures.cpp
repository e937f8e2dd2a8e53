// SPDX-License-Identifier: MIT
#include "bench_figures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "bench_goals.hpp"
#include "bench_verdict.hpp"
#include "report_text.hpp"

namespace bench {

namespace {

std::vector<std::string> distinctScenes(const std::vector<BenchRow>& rows) {
    std::vector<std::string> out;
    for (const BenchRow& r : rows)
        if (std::find(out.begin(), out.end(), r.scene) == out.end()) out.push_back(r.scene);
    return out;
}

// The command that wrote both pages and what the run measured.
void writeRun(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& in) {
    out << "**This file is generated** by `ssam-bench --figures` (game/bench/bench_figures.cpp) from one run; do "
           "not edit it by hand: run the command again and commit what it writes. This one was written by\n\n`"
        << in.run.command << "`\n\n";
    if (!rows.empty())
        out << rows.front().width << "x" << rows.front().height << ", " << in.run.reps << " timed repetition(s) after "
            << in.run.warmup << " warm-up, flicker over " << in.run.panFrames
            << " pan frames, the per-frame error over " << in.temporalFrames << " pan frames, " << in.run.threads
            << " thread(s) (soft tiles; LP_NUM_THREADS for gl). Technique `ssam` runs preset `" << in.run.ssamPreset
            << "`.\n\n";
    out << "Wall times scatter from run to run on a shared machine; errors and memory are deterministic on the "
           "soft backend. Every GL figure is Mesa llvmpipe's, a CPU rasterizer.\n\n";
}

void writeIntro(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& in) {
    out << "# Current figures\n\n"
           "The figures that more than one README quotes live here, once each; the READMEs link to this page "
           "instead of restating them. Every row they come from is in ["
        << in.rowsPage << "](" << in.rowsPage << "). ";
    writeRun(out, rows, in);
    out << "| section | what |\n|---|---|\n"
           "| [Speed: soft against llvmpipe](#speed-soft-against-llvmpipe) | game/bench/speed_table.sh, given "
           "with `--speed-table` |\n"
           "| [Goals](#goals) | SSAM against alpha testing, still, in motion and along the dolly: met or not, "
           "and what limits those not met |\n"
           "| [Along the dolly](#along-the-dolly) | popping at the levels of detail's changes |\n"
           "| [SSAM and what engines ship](#ssam-and-what-engines-ship) | SSAM beside hashed+taa, alpha-test+taa "
           "and sharpened A2C, and which is better at what |\n"
           "| [SSAM against its rivals]("
        << in.rowsPage
        << "#ssam-against-its-rivals) | every technique per "
           "scene: time, error, flicker, error per frame of a pan |\n"
           "| [In motion]("
        << in.rowsPage
        << "#in-motion) | every technique in the forest's pan, dolly and "
           "wind: flicker, error per frame, ghosting |\n\n";
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

// The section's heading; false, and says so, when its run was not part of this one.
bool openSection(std::ostream& out, const char* heading, bool ran) {
    out << "## " << heading << "\n\n";
    if (!ran) out << "Not part of this run: `ssam-bench --figures` runs it after the comparison.\n\n";
    return ran;
}

// A section over runs of `frames` frames: the text before and after the frame count (the
// table's head at its end), then one table line per row.
template <class Row, class WriteRow>
void writeFramesSection(std::ostream& out, const char* heading, const std::vector<Row>& rows, const char* before,
                        const char* after, WriteRow writeRow) {
    if (!openSection(out, heading, !rows.empty())) return;
    out << before << rows.front().frames << after;
    for (const Row& r : rows) writeRow(r);
    out << "\n";
}

void writeMotion(std::ostream& out, const std::vector<MotionRow>& motion) {
    writeFramesSection(
        out, "In motion", motion,
        "The forest through the motions of `ssam-bench --motion` (game/docs/motion.md): the sideways "
        "pan, the dolly toward the trees, the wind under a still camera and the car crossing it, ",
        " measured frames each, every frame against that frame's reference over the foliage pixels. "
        "Converged: the median over the last half of the frames; worst: the worst frame; ghosting: the "
        "error on the pixels whose surface moved; flicker: the change between frames less the "
        "reference's. The temporal techniques reproject by motion vectors; the levels of detail are the "
        "comparison's (the command above).\n\n"
        "| motion | technique | flicker | ꟻLIP converged | ꟻLIP worst | RMSE converged | ghosting converged | "
        "ghosting worst |\n|---|---|---:|---:|---:|---:|---:|---:|\n",
        [&out](const MotionRow& r) {
            out << "| " << r.motion << " | `" << r.technique << "` | " << num(r.flicker, "%.5f") << " | "
                << num(r.flip, "%.4f") << " | " << num(r.flipWorst, "%.4f") << " | " << num(r.rmse, "%.5f") << " | "
                << num(r.ghost, "%.4f") << " | " << num(r.ghostWorst, "%.4f") << " |\n";
        });
}

void writeDolly(std::ostream& out, const std::vector<DollyRow>& dolly) {
    writeFramesSection(
        out, "Along the dolly", dolly,
        "Popping at the levels of detail's changes (`ssam-bench --dolly`, game/docs/levels_of_detail.md): "
        "the forest's dolly, ",
        " frames, drawn with the levels of detail and at full detail. pop: the largest ꟻLIP between "
        "consecutive frames; pop_lod: the largest change the levels add to the motion's own, and its frame; "
        "median: the same in the median frame, the floor a level switching rises above (each frame in the "
        "run's dolly_frames.csv); LOD ꟻLIP: the LOD frame against the full-detail frame over the plant "
        "pixels, mean and worst.\n\n"
        "| technique | pop | pop_lod | frame | pop_lod median | LOD ꟻLIP mean | LOD ꟻLIP worst |\n"
        "|---|---:|---:|---:|---:|---:|---:|\n",
        [&out](const DollyRow& r) {
            out << "| `" << r.technique << "` | " << num(r.pop, "%.4f") << " | " << num(r.popLod, "%.4f") << " | "
                << r.popLodFrame << " | " << num(r.popLodMedian, "%.4f") << " | " << num(r.lodFlipMean, "%.4f") << " | "
                << num(r.lodFlipWorst, "%.4f") << " |\n";
        });
}

void writeGoalsOrAbsence(std::ostream& out, const std::vector<Goal>& goals) {
    if (goals.empty()) out << "Not part of this run.\n";
    else writeGoalTable(out, goals);
}

void writeGoals(std::ostream& out, const std::vector<BenchRow>& rows, const FiguresInput& in) {
    out << "## Goals\n\nSSAM against alpha testing, from the rows of [SSAM against its rivals](" << in.rowsPage
        << "#ssam-against-its-rivals) (" << primaryBackend(rows)
        << " backend): the recommended preset's ꟻLIP at or below alpha testing's at no more than 1.25x the "
           "paper preset's time, SSAM+'s ꟻLIP at most 0.6x alpha testing's, and SSAM's flicker in the forest "
           "pan at most 0.3x alpha testing's. The time is not the rows' (each technique timed after the other, "
           "so a change in the machine's speed lands on one): the two presets' frames are timed alternately, "
           "A B A B, after the rows.";
    const std::string lodName = in.lodRowsHaveLevelsOfDetail ? "LOD on" : "LOD off";
    if (!in.lodRows.empty())
        out << " The last two columns: the same goals from a run of their techniques with the levels of detail "
            << (in.lodRowsHaveLevelsOfDetail ? "on" : "off") << ".";
    out << "\n\n";
    const std::vector<Goal> still = rivalGoals(rows), beside = rivalGoals(in.lodRows);
    writeGoalTable(out, still, in.lodRows.empty() ? nullptr : &beside, lodName);
    out << "\nIn motion ([In motion](" << in.rowsPage
        << "#in-motion)): on the forest, for each motion, SSAM's flicker at most 0.3x alpha testing's and SSAM+'s "
           "converged ꟻLIP at most 0.6x alpha testing's.\n\n";
    const std::vector<Goal> inMotion = motionGoals(in.motion);
    writeGoalsOrAbsence(out, inMotion);
    out << "\nAlong the dolly ([Along the dolly](#along-the-dolly)): SSAM's popping below alpha testing's and "
           "below hashed alpha's, and its LOD frame's ꟻLIP against full detail at most 0.02.\n\n";
    const std::vector<Goal> alongTheDolly = dollyGoals(in.dolly);
    writeGoalsOrAbsence(out, alongTheDolly);
    out << "\n";
    std::vector<Goal> all = still;
    all.insert(all.end(), inMotion.begin(), inMotion.end());
    all.insert(all.end(), alongTheDolly.begin(), alongTheDolly.end());
    writeGoalLimits(out, all);
    out << "\n";
}

}  // namespace

std::string rowsPagePath(const std::string& figuresPath) {
    std::filesystem::path page(figuresPath);
    page.replace_filename(page.stem().string() + "_ROWS" + page.extension().string());
    return page.string();
}

void writeFigures(std::ostream& out, std::ostream& rowsOut, const std::vector<BenchRow>& rows,
                  const FiguresInput& input) {
    writeIntro(out, rows, input);
    writeSpeed(out, input);
    writeGoals(out, rows, input);
    writeDolly(out, input.dolly);
    writeWhatEnginesShip(out, rows, input.motion, input.rowsPage);

    rowsOut << "# Every row of the current figures\n\n"
               "The rows [FIGURES.md](FIGURES.md)'s goals and verdict come from: every technique per scene, and "
               "every technique in the forest's motions. ";
    writeRun(rowsOut, rows, input);
    writeRivals(rowsOut, rows, input);
    writeMotion(rowsOut, input.motion);
}

}  // namespace bench
