// SPDX-License-Identifier: MIT
// FIGURES.md's generator (bench_figures.hpp) and the goals it shares with bench.md
// (bench_goals.hpp): the command that wrote the file is at its top, every table is well
// formed (each row as many cells as its header), every row of the run is in its scene's table
// on the rows page beside FIGURES.md, each goal not met names what limits it,
// each goal's ratio and verdict come from the rows (still, in motion, along the dolly, and the
// still goals of the other levels-of-detail run beside), SSAM beside what engines ship names the
// lowest of each line, the speed table is copied in whole, and a run that lacks a row says so
// instead of inventing a number.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bench_figures.hpp"
#include "bench_goals.hpp"

namespace {

using namespace bench;

BenchRow row(const std::string& scene, const std::string& technique, double ms, double flip, double flicker) {
    BenchRow r;
    r.scene = scene;
    r.technique = technique;
    r.backend = "soft";
    r.width = 320;
    r.height = 180;
    r.ran = true;
    r.timeMedianMs = ms;
    r.flipMean = flip;
    r.rmseLinear = flip / 2;
    r.flicker = flicker;
    r.peakMemMb = 1.5;
    r.temporalFrames = 8;
    r.temporalFlip = flip * 1.1;
    r.temporalFlipWorst = flip * 1.2;
    r.temporalRmse = flip / 3;
    return r;
}

std::vector<BenchRow> run() {
    std::vector<BenchRow> rows;
    for (const char* scene : {"tree", "forest", "vista"}) {
        rows.push_back(row(scene, kOpaqueOnly, 10, 0.4, 0.001));
        rows.push_back(row(scene, "ssam", 50, 0.05, 0.0005));
        rows.push_back(row(scene, kSsamPaperRow, 48, 0.07, 0.0006));
        rows.push_back(row(scene, "ssam-plus", 55, 0.03, 0.0004));
        rows.push_back(row(scene, "alpha-test", 20, 0.06, 0.002));
        rows.push_back(row(scene, "hashed+taa", 40, 0.055, 0.0001));
        rows.push_back(row(scene, "a2c-sharp", 30, 0.045, 0.0003));
        rows.push_back(row(scene, "reference", 90, 0.0, 0.0));
    }
    rows[4 + 8].flipMean = 0.04;  // forest alpha-test: ssam's 0.05 is above it, ssam-plus's 0.03 above 0.6x
    // The time goal reads the pair's alternated timing, not their rows' medians (50 / 48 would pass).
    for (BenchRow& r : rows)
        if (r.technique == "ssam" || r.technique == kSsamPaperRow) r.timeAlternatedMs = r.technique == "ssam" ? 52 : 40;
    return rows;
}

MotionRow motionRow(const char* motion, const char* technique, double flicker, double flip, double ghost) {
    MotionRow r;
    r.scene = "forest";
    r.motion = motion;
    r.technique = technique;
    r.frames = 8;
    r.flicker = flicker;
    r.flip = flip;
    r.flipWorst = flip * 1.5;
    r.rmse = flip / 3;
    r.ghost = ghost;
    r.ghostWorst = ghost * 2;
    return r;
}

// The forest in motion: ssam flickers 0.2x alpha testing's in the pan, 0.5x in the wind; ssam-plus's
// ꟻLIP is 0.5x alpha testing's in the pan, 0.75x in the wind.
std::vector<MotionRow> motion() {
    return {motionRow("pan", "ssam", 0.0002, 0.10, 0.12),       motionRow("pan", "ssam-plus", 0.0001, 0.07, 0.08),
            motionRow("pan", "alpha-test", 0.0010, 0.14, 0.20), motionRow("pan", "hashed+taa", -0.0003, 0.11, 0.19),
            motionRow("wind", "ssam", 0.0002, 0.10, 0.15),      motionRow("wind", "ssam-plus", 0.0001, 0.09, 0.06),
            motionRow("wind", "alpha-test", 0.0004, 0.12, 0.24)};
}

std::vector<DollyRow> dolly() {
    std::vector<DollyRow> rows;
    for (auto [technique, popLod, lodFlip] :
         {std::tuple{"ssam", 0.02, 0.015}, std::tuple{"alpha-test", 0.04, 0.03}, std::tuple{"hashed", 0.02, 0.02}}) {
        DollyRow r;
        r.scene = "forest";
        r.technique = technique;
        r.frames = 117;
        r.pop = popLod * 2;
        r.popLod = popLod;
        r.popLodFrame = 7;
        r.popLodMedian = popLod / 4;
        r.lodFlipMean = lodFlip;
        r.lodFlipWorst = lodFlip * 2;
        rows.push_back(r);
    }
    return rows;
}

// FIGURES.md and the rows page beside it.
struct Pages {
    std::string figures, rows;
};

Pages pages(const std::vector<BenchRow>& rows, const std::string& speed = "", bool withRuns = false) {
    FiguresInput in;
    if (withRuns) {
        in.lodRows = rows;
        for (BenchRow& r : in.lodRows) r.flipMean *= 2;  // the other levels of detail: twice the error
        in.lodRowsHaveLevelsOfDetail = true;
        in.motion = motion();
        in.dolly = dolly();
    }
    in.run = {"ssam-bench --size 320x180 --figures F", 2, 1, 0, 3, "measured"};
    in.temporalFrames = 8;
    in.speedTable = speed;
    in.speedTableSource = "out/bench/speed_table.md";
    std::ostringstream out, rowsOut;
    writeFigures(out, rowsOut, rows, in);
    return {out.str(), rowsOut.str()};
}

std::string figures(const std::vector<BenchRow>& rows, const std::string& speed = "", bool withRuns = false) {
    return pages(rows, speed, withRuns).figures;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// Cells of a Markdown table row: '|' not escaped as "\|".
int cells(const std::string& line) {
    int n = -1;
    for (std::size_t i = 0; i < line.size(); ++i)
        if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++n;
    return n;
}

// The tables of a page (a header line after a line that is not a table's), each row as many
// cells as its header.
int wellFormedTables(const std::string& text) {
    const auto l = lines(text);
    int tables = 0;
    for (std::size_t i = 0; i + 1 < l.size(); ++i) {
        if (l[i].rfind("|", 0) != 0 || (i > 0 && l[i - 1].rfind("|", 0) == 0)) continue;  // a table's header
        ++tables;
        EXPECT_EQ(l[i + 1].rfind("|---", 0), 0u) << l[i];
        const int n = cells(l[i]);
        for (std::size_t k = i + 1; k < l.size() && l[k].rfind("|", 0) == 0; ++k) EXPECT_EQ(cells(l[k]), n) << l[k];
    }
    return tables;
}

TEST(BenchFigures, TheCommandIsAtTheTopAndEveryTableIsWellFormed) {
    const Pages p = pages(run(), "| measure | soft / gl |\n|---|---:|\n| pan | 0.78 |\n", true);
    const auto l = lines(p.figures);
    ASSERT_FALSE(l.empty());
    EXPECT_EQ(l[0], "# Current figures");
    EXPECT_EQ(lines(p.rows).at(0), "# Every row of the current figures");
    for (const std::string& text : {p.figures, p.rows}) {
        EXPECT_NE(text.find("generated"), std::string::npos);
        EXPECT_NE(text.find("`ssam-bench --size 320x180 --figures F`"), std::string::npos);
        EXPECT_NE(text.find("320x180"), std::string::npos);
    }
    // Contents, speed, the three goal tables, dolly, what engines ship; beside it tree, forest,
    // vista and the motions.
    EXPECT_EQ(wellFormedTables(p.figures), 7);
    EXPECT_EQ(wellFormedTables(p.rows), 4);
    EXPECT_NE(p.figures.find("| pan | 0.78 |"), std::string::npos);
    EXPECT_NE(p.figures.find("out/bench/speed_table.md"), std::string::npos);
    // FIGURES.md links the rows page's sections by the name it was given.
    EXPECT_NE(p.figures.find("](FIGURES_ROWS.md#ssam-against-its-rivals)"), std::string::npos);
    EXPECT_NE(p.figures.find("](FIGURES_ROWS.md#in-motion)"), std::string::npos);
    EXPECT_NE(p.rows.find("\n## SSAM against its rivals\n"), std::string::npos);
    EXPECT_NE(p.rows.find("\n## In motion\n"), std::string::npos);
}

TEST(BenchFigures, TheRowsPageIsNamedBesideFigures) {
    EXPECT_EQ(rowsPagePath("game/bench/FIGURES.md"), "game/bench/FIGURES_ROWS.md");
    EXPECT_EQ(rowsPagePath("out.d/figures"), "out.d/figures_ROWS");
    EXPECT_EQ(rowsPagePath("F.md"), "F_ROWS.md");
}

TEST(BenchFigures, EveryRowIsInItsScenesTable) {
    const Pages p = pages(run());
    const std::string& text = p.rows;
    for (const char* scene : {"tree", "forest", "vista"}) {
        const std::size_t at = text.find(std::string("### ") + scene + ", soft");
        ASSERT_NE(at, std::string::npos) << scene;
        const std::size_t end = text.find("\n\n", text.find("|---", at));
        const std::string table = text.substr(at, end - at);
        for (const char* t : {"`ssam`", "`ssam-paper`", "`ssam-plus`", "`alpha-test`", "`hashed+taa`", "`reference`"})
            EXPECT_NE(table.find(std::string("| ") + t + " |"), std::string::npos) << scene << " " << t;
        EXPECT_NE(table.find("| opaque-only |"), std::string::npos);
    }
    EXPECT_NE(p.figures.find("Not part of this run"), std::string::npos);  // no --speed-table: says how to get it
}

TEST(BenchFigures, GoalsComeFromTheRows) {
    const auto goals = rivalGoals(run());
    ASSERT_EQ(goals.size(), 10u);  // 3 scenes x (ꟻLIP, time), 3 x SSAM+, the forest's flicker
    auto find = [&](const std::string& what) -> const Goal& {
        for (const Goal& g : goals)
            if (g.what == what) return g;
        ADD_FAILURE() << "no goal " << what;
        return goals.front();
    };
    EXPECT_TRUE(find("tree: ꟻLIP ssam / alpha-test").met());
    EXPECT_FALSE(find("forest: ꟻLIP ssam / alpha-test").met());
    EXPECT_NEAR(*find("forest: ꟻLIP ssam / alpha-test").ratio, 0.05 / 0.04, 1e-12);
    EXPECT_NEAR(*find("vista: time ssam / ssam-paper, frames alternated").ratio, 52.0 / 40.0, 1e-12);
    EXPECT_FALSE(find("vista: time ssam / ssam-paper, frames alternated").met());
    EXPECT_TRUE(find("vista: ꟻLIP ssam-plus / alpha-test").met());
    EXPECT_FALSE(find("forest: ꟻLIP ssam-plus / alpha-test").met());
    EXPECT_NEAR(*find("forest: flicker ssam / alpha-test").ratio, 0.25, 1e-12);
    EXPECT_TRUE(find("forest: flicker ssam / alpha-test").met());
    const std::string text = figures(run());
    EXPECT_NE(text.find("| forest: ꟻLIP ssam / alpha-test | 1.250x | <= 1.00x | not met |"), std::string::npos);
    // SSAM beside what engines ship: ssam, hashed+taa, alpha-test+taa (not run), a2c-sharp; the lowest named.
    EXPECT_NE(text.find("| forest | flicker, pan | 0.00050 | 0.00010 |  | 0.00030 | hashed+taa |"), std::string::npos);
    EXPECT_NE(text.find("| tree | time ms | 50.00 | 40.00 |  | 30.00 | a2c-sharp |"), std::string::npos);
    EXPECT_NE(text.find("| tree | memory MiB | 1.5 | 1.5 |  | 1.5 | ssam = hashed+taa = a2c-sharp |"),
              std::string::npos);
    EXPECT_NE(text.find("- `a2c-sharp` is lowest at "), std::string::npos);
    EXPECT_NE(text.find("time ms (tree, forest, vista)"), std::string::npos);
    EXPECT_NE(text.find("- `alpha-test+taa` is lowest at nothing measured here."), std::string::npos);
    // What limits each goal not met is named, those met are not listed.
    EXPECT_NE(text.find("What limits each goal not met in this run is worked out in:\n\n"
                        "- tree: time ssam / ssam-paper, frames alternated (1.300x): ssam/docs/knobs.md, "),
              std::string::npos);
    EXPECT_NE(text.find("\n- forest: ꟻLIP ssam / alpha-test (1.250x): ssam/docs/knobs.md, "), std::string::npos);
    EXPECT_NE(text.find("- forest: ꟻLIP ssam-plus / alpha-test (0.750x): ssam/docs/ssam_plus.md, "), std::string::npos);
    EXPECT_EQ(text.find("- tree: ꟻLIP ssam / alpha-test ("), std::string::npos);
    for (const Goal& g : goals) EXPECT_FALSE(g.limitedBy.empty()) << g.what;
}

TEST(BenchFigures, GoalsInMotionAndAlongTheDollyComeFromTheirRows) {
    const auto goals = motionGoals(motion());
    ASSERT_EQ(goals.size(), 4u);  // pan and wind (no dolly rows) x (flicker, ꟻLIP)
    EXPECT_EQ(goals[0].what, "forest pan: flicker ssam / alpha-test");
    EXPECT_NEAR(*goals[0].ratio, 0.2, 1e-12);
    EXPECT_TRUE(goals[0].met());
    EXPECT_NEAR(*goals[1].ratio, 0.5, 1e-12);
    EXPECT_TRUE(goals[1].met());
    EXPECT_NEAR(*goals[2].ratio, 0.5, 1e-12);
    EXPECT_FALSE(goals[2].met());
    EXPECT_NEAR(*goals[3].ratio, 0.75, 1e-12);
    EXPECT_FALSE(goals[3].met());
    const auto popping = dollyGoals(dolly());
    ASSERT_EQ(popping.size(), 3u);
    EXPECT_NEAR(*popping[0].ratio, 0.5, 1e-12);  // against alpha testing: below
    EXPECT_TRUE(popping[0].met());
    EXPECT_NEAR(*popping[1].ratio, 1.0, 1e-12);  // against hashed alpha: equal is not below
    EXPECT_FALSE(popping[1].met());
    EXPECT_NEAR(*popping[2].ratio, 0.015, 1e-12);
    EXPECT_TRUE(popping[2].met());
    const Pages p = pages(run(), "", true);
    const std::string& text = p.figures;
    EXPECT_NE(text.find("- forest dolly: popping (pop_lod) ssam / hashed (1.000x): game/docs/levels_of_detail.md"),
              std::string::npos);
    EXPECT_NE(text.find("| forest dolly: popping (pop_lod) ssam / hashed | 1.000x | < 1.00x | not met |"),
              std::string::npos);
    EXPECT_NE(text.find("| forest dolly: LOD frame ꟻLIP against full detail, ssam | 0.0150 | <= 0.02 | met |"),
              std::string::npos);
    EXPECT_NE(text.find("| forest wind: ꟻLIP converged ssam-plus / alpha-test | 0.750x | <= 0.60x | not met |"),
              std::string::npos);
    // The still goals with the other levels of detail beside: twice the error on both sides of each ratio.
    EXPECT_NE(text.find("| goal | measured | target | met? | LOD on | met? |"), std::string::npos);
    EXPECT_NE(text.find("| forest: ꟻLIP ssam / alpha-test | 1.250x | <= 1.00x | not met | 1.250x | not met |"),
              std::string::npos);
    EXPECT_NE(p.rows.find("| pan | `ssam` | 0.00020 | 0.1000 | 0.1500 | 0.03333 | 0.1200 | 0.2400 |"),
              std::string::npos);
    EXPECT_NE(text.find("| `alpha-test` | 0.0800 | 0.0400 | 7 | 0.0100 | 0.0300 | 0.0600 |"), std::string::npos);
    // No motion or dolly run: said, not invented.
    const Pages bare = pages(run());
    EXPECT_NE(bare.rows.find("## In motion\n\nNot part of this run"), std::string::npos);
    EXPECT_NE(bare.figures.find("## Along the dolly\n\nNot part of this run"), std::string::npos);
    EXPECT_EQ(motionGoals({}).size(), 0u);
    EXPECT_EQ(dollyGoals({}).size(), 0u);
}

TEST(BenchFigures, AMissingRowIsSaidNotInvented) {
    std::vector<BenchRow> rows;
    for (const BenchRow& r : run())
        if (r.technique != kSsamPaperRow && r.technique != "hashed+taa" && r.scene != "vista") rows.push_back(r);
    const std::string noneShipped = figures({});
    EXPECT_NE(noneShipped.find("not measured: the run lacked `ssam` and the shipped techniques"), std::string::npos);
    const auto goals = rivalGoals(rows);
    EXPECT_EQ(goals.size(), 7u);  // vista's goals left out with the scene
    for (const Goal& g : goals)
        if (g.what.find("ssam-paper") != std::string::npos) {
            EXPECT_FALSE(g.ratio);
            EXPECT_NE(g.missing.find("--with-paper-ssam"), std::string::npos);
        }
    const std::string text = figures(rows);
    // hashed+taa and alpha-test+taa did not run: their cells are empty, not invented.
    EXPECT_NE(text.find("| tree | time ms | 50.00 |  |  | 30.00 | a2c-sharp |"), std::string::npos);
    EXPECT_NE(text.find("| n/a |"), std::string::npos);
    // Both rows but no alternated timing: the medians timed one after the other are not used instead.
    std::vector<BenchRow> untimed = run();
    for (BenchRow& r : untimed) r.timeAlternatedMs = kMissing;
    int timeGoals = 0;
    for (const Goal& g : rivalGoals(untimed))
        if (g.what.find("frames alternated") != std::string::npos) {
            ++timeGoals;
            EXPECT_FALSE(g.ratio);
            EXPECT_EQ(g.missing, "not measured in this run");
        }
    EXPECT_EQ(timeGoals, 3);
}

}  // namespace
