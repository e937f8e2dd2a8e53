// SPDX-License-Identifier: MIT
// ssam-bench: every transparency technique's run time against its error from the exact
// reference (modules/transparency: every fragment sorted and composited). Writes bench.csv,
// bench_passes.csv, bench.md and bench.svg into --out; with --sweep, SSAM under a grid of its
// knobs instead, into sweep.csv and sweep.md; with --scaling, each backend's SSAM and
// alpha-test frame time against pixels and foliage layers, into scaling.csv and scaling.svg. Keeps the command-line contract (game/README.md):
// exit 2 for a bad flag, 1 for a failed run; --out is checked before the first frame.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <regex>
#include <string>
#include <vector>

#include "bench_chart.hpp"
#include "bench_dolly.hpp"
#include "bench_motion.hpp"
#include "bench_figures.hpp"
#include "bench_figures_runs.hpp"
#include "bench_goals.hpp"
#include "bench_report.hpp"
#include "bench_runner.hpp"
#include "bench_scaling.hpp"
#include "bench_sweep.hpp"
#include "content_dir.hpp"
#include "engine/cli/command_line.hpp"
#include "engine/core/error.hpp"
#include "engine/core/output_file.hpp"
#include "engine/core/usage_error.hpp"
#include "engine/render/devices/create_device.hpp"
#include "on_off_option.hpp"
#include "report_text.hpp"
#include "simd_flag.hpp"
#include "ssam/core/settings.hpp"
#include "sweep_report.hpp"

namespace {

using namespace bench;

struct Options {
    std::string scenes = "tree,forest,vista,empty";
    std::string techniques = "all";
    std::string ssamPreset = ssam::presetName(ssam::kRecommendedPreset);
    std::string backends = "soft";
    std::string size = "1280x720";
    int reps = 5;
    int warmup = 1;
    int panFrames = 8;
    int temporalFrames = 32;
    int threads = 0;
    std::string simd = "auto";
    bool quick = false;
    bool images = false;
    bool sweep = false;
    bool sweepFull = false;
    bool scaling = false;
    bool withPaperSsam = false;
    std::string ssamPlusBlur = "on";         // SSAM+'s composite blur (transparency::SsamPlusOptions)
    std::string ssamPlusFrontLayers = "on";  // SSAM+'s front-layers pass (transparency::SsamPlusOptions)
    std::string figures;                     // FIGURES.md to write from the run; empty: none
    std::string speedTable;                  // speed_table.sh's table to copy into it
    std::string sweepLerp = "0,0.25,0.5,0.85,1";
    std::string sweepSquare = "on,off";
    std::string sweepBlur = "off";
    std::string sweepReference = "16,64,128";
    std::string sweepPrecision = "rgba8,rgba16f";
    std::string out = "out/bench";
    std::string contentDir = racer::defaultContentDir().string();
    std::string lod = "on";
    std::string crossfade = "on";
    bool dolly = false;
    int dollyFrames = kDollyFrames;
    std::string motion;  // --motion: empty, or a list of pan, dolly, wind
    int motionFrames = 32;
    std::string motionVectors = "on";
    std::vector<std::string> ssamSettings;  // --ssam-setting NAME=VALUE, over the preset's knobs
};

std::vector<std::string> splitList(const std::string& list, const char* flag) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string item = list.substr(start, comma - start);
        if (item.empty())
            throw engine::UsageError(std::string(flag) + " '" + list + "': empty entry in the comma list");
        items.push_back(item);
        start = comma + 1;
    }
    return items;
}

// A comma list of on / off for a boolean knob of the sweep.
std::vector<bool> onOffList(const std::string& list, const char* flag, const char* knob) {
    std::vector<bool> values;
    for (const std::string& item : splitList(list, flag)) {
        if (item != "on" && item != "off")
            throw engine::UsageError(std::string(flag) + ": '" + item + "' for " + knob + " (known: on, off)");
        values.push_back(item == "on");
    }
    return values;
}

std::string allTechniqueNames() {
    std::string names;
    for (auto k : transparency::allTechniques())
        names += std::string(names.empty() ? "" : ", ") + transparency::techniqueName(k);
    return names;
}

std::vector<transparency::TechniqueKind> parseTechniques(const std::string& list, bool noneAllowed) {
    std::vector<transparency::TechniqueKind> kinds;
    if (list == "all") return {transparency::allTechniques().begin(), transparency::allTechniques().end()};
    if (noneAllowed && list == "none") return kinds;
    for (const std::string& name : splitList(list, "--techniques")) {
        const auto kind = transparency::parseTechnique(name);
        if (!kind)
            throw engine::UsageError("--techniques: unknown technique '" + name + "' (known: " + allTechniqueNames() +
                                     (noneAllowed ? "; or all, none)" : "; or all)"));
        kinds.push_back(*kind);
    }
    return kinds;
}

float parseNumber(const std::string& item, const char* flag) {
    char* end = nullptr;
    errno = 0;
    const float v = std::strtof(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || errno == ERANGE)
        throw engine::UsageError(std::string(flag) + ": '" + item + "' is not a number");
    return v;
}

// Each value is checked on its own, with the other knobs at their defaults, so the message
// names both the flag and the knob (ssam::settingsError).
void validateKnob(const ssam::Settings& c, const char* flag) {
    if (const std::string error = ssam::settingsError(c); !error.empty())
        throw engine::UsageError(std::string(flag) + ": " + error);
}

// --ssam-setting NAME=VALUE: one knob of ssam::Settings over the preset's, checked by
// ssam::settingsError (the steadiness ideas are measured this way: ssam/docs/steady_in_motion.md).
void applySsamSetting(ssam::Settings& c, const std::string& item) {
    const std::size_t eq = item.find('=');
    const std::string name = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (eq == std::string::npos || value.empty())
        throw engine::UsageError("--ssam-setting '" + item + "': expected NAME=VALUE, e.g. colorAlphaReference=0.5");
    if (name == "squareMask" || name == "colorBlur") {
        if (value != "on" && value != "off")
            throw engine::UsageError("--ssam-setting: '" + value + "' for " + name + " (known: on, off)");
        (name == "squareMask" ? c.squareMask : c.colorBlur) = value == "on";
    } else if (name == "maskLerp") {
        c.maskLerp = parseNumber(value, "--ssam-setting");
    } else if (name == "colorAlphaReference") {
        c.colorAlphaReference = parseNumber(value, "--ssam-setting");
    } else if (name == "colorFade") {
        c.colorFade = parseNumber(value, "--ssam-setting");
    } else {
        throw engine::UsageError("--ssam-setting: unknown knob '" + name +
                                 "' (known: maskLerp, colorAlphaReference, colorFade, squareMask, colorBlur)");
    }
    validateKnob(c, "--ssam-setting");
}

SweepGrid parseSweepGrid(const Options& o) {
    SweepGrid g;
    g.full = o.sweepFull;
    g.maskLerp.clear();
    for (const std::string& item : splitList(o.sweepLerp, "--sweep-lerp")) {
        ssam::Settings c;
        c.maskLerp = parseNumber(item, "--sweep-lerp");
        validateKnob(c, "--sweep-lerp");
        g.maskLerp.push_back(c.maskLerp);
    }
    g.squareMask = onOffList(o.sweepSquare, "--sweep-square", "squareMask");
    g.colorBlur = onOffList(o.sweepBlur, "--sweep-blur", "colorBlur");
    g.colorAlphaReference.clear();
    for (const std::string& item : splitList(o.sweepReference, "--sweep-reference")) {
        ssam::Settings c;
        c.colorAlphaReference = parseNumber(item, "--sweep-reference") / 255.0f;  // given in 255ths (§3.5.3)
        validateKnob(c, "--sweep-reference");
        g.colorAlphaReference.push_back(c.colorAlphaReference);
    }
    g.maskPrecision.clear();
    for (const std::string& item : splitList(o.sweepPrecision, "--sweep-precision")) {
        bool known = false;
        for (auto p : {ssam::MaskPrecision::Rgba8, ssam::MaskPrecision::Rgba16f, ssam::MaskPrecision::Rg16f})
            if (item == ssam::maskPrecisionName(p)) {
                g.maskPrecision.push_back(p);
                known = true;
            }
        if (!known)
            throw engine::UsageError("--sweep-precision: '" + item +
                                     "' for maskPrecision (known: rgba8, rgba16f, rg16f)");
    }
    return g;
}

BenchOptions parse(const Options& o) {
    BenchOptions b;
    for (const std::string& name : splitList(o.scenes, "--scenes")) {
        SceneKind kind;
        if (!parseScene(name, kind))
            throw engine::UsageError("--scenes: unknown scene '" + name + "' (known: tree, forest, vista, empty)");
        b.scenes.push_back(kind);
    }
    // With --sweep the techniques are measured beside the settings, for comparison only.
    const auto techniques = parseTechniques(o.techniques, o.sweep);
    if (o.sweep) {
        for (transparency::TechniqueKind k : techniques) b.subjects.push_back({transparency::techniqueName(k), k, {}});
    } else {
        b.subjects = techniqueSubjects(techniques);
    }
    // Technique ssam's knobs (CLI11 checked the name); the sweep's settings carry their own.
    for (BenchSubject& subject : b.subjects)
        if (subject.kind == transparency::TechniqueKind::Ssam || subject.kind == transparency::TechniqueKind::SsamTaa) {
            subject.options.ssam = ssam::presetSettings(*ssam::parsePreset(o.ssamPreset));
            for (const std::string& item : o.ssamSettings) applySsamSetting(subject.options.ssam, item);
        }
    for (BenchSubject& subject : b.subjects)
        if (subject.kind == transparency::TechniqueKind::SsamPlus) {
            subject.options.ssamPlus.compositeBlur = o.ssamPlusBlur == "on";
            subject.options.ssamPlus.frontLayers = o.ssamPlusFrontLayers == "on";
        }
    // The paper preset beside the recommended one: the time goal's denominator (bench_goals.hpp).
    if (o.withPaperSsam && !o.sweep) {
        BenchSubject paper{kSsamPaperRow, transparency::TechniqueKind::Ssam, {}};
        paper.options.ssam = ssam::presetSettings(ssam::Preset::Paper);
        const auto ssamAt =
            std::find_if(b.subjects.begin(), b.subjects.end(), [](const BenchSubject& s) { return s.name == "ssam"; });
        b.subjects.insert(ssamAt == b.subjects.end() ? b.subjects.end() : ssamAt + 1, paper);
    }
    for (const std::string& name : splitList(o.backends, "--backend")) {
        if (!engine::render::parseDeviceKind(name))
            throw engine::UsageError("--backend: unknown backend '" + name +
                                     "' (known: " + engine::render::deviceKindNames() + ")");
        b.backends.push_back(name);
    }
    std::smatch m;
    static const std::regex sizePattern(R"((\d{1,5})x(\d{1,5}))");
    if (!std::regex_match(o.size, m, sizePattern))
        throw engine::UsageError("--size '" + o.size + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    b.width = std::stoi(m[1]);
    b.height = std::stoi(m[2]);
    // SSIM's 11x11 window needs at least 11 pixels each way.
    if (b.width < 11 || b.height < 11 || b.width > 16384 || b.height > 16384)
        throw engine::UsageError("--size '" + o.size + "': each dimension must be in 11..16384");
    b.reps = o.reps;
    b.warmup = o.warmup;
    b.panFrames = o.panFrames;
    b.temporalFrames = o.temporalFrames;
    b.threads = o.threads;
    b.simd = racer::simdFromFlag(o.simd);
    b.contentDir = o.contentDir;
    b.levelsOfDetail = o.lod == "on";
    b.crossfade = o.crossfade == "on" ? racer::kLodCrossfade : 0.0f;
    if (o.dolly && !b.levelsOfDetail)
        throw engine::UsageError("--dolly measures the levels of detail: not with --lod off");
    if ((o.dolly || !o.figures.empty()) && (o.dollyFrames < 2 || o.dollyFrames > kDollyFrames))
        throw engine::UsageError("--dolly-frames " + std::to_string(o.dollyFrames) + ": expected 2.." +
                                 std::to_string(kDollyFrames));
    if (!o.motion.empty()) parseMotions(o.motion);  // a bad name fails before the first frame
    if (!o.motion.empty() && (o.motionFrames < 2 || o.motionFrames > kDollyFrames))
        throw engine::UsageError("--motion-frames " + std::to_string(o.motionFrames) + ": expected 2.." +
                                 std::to_string(kDollyFrames));
    return b;
}

// The report of a run whose rows make one CSV (--motion, --dolly): stages it in `files` beside
// what is already staged there, puts them all in place together, then prints its table and
// where it went.
template <typename Row>
int writeCsvAndTable(engine::PendingFiles& files, const std::filesystem::path& csv, const std::vector<Row>& rows,
                     void (*writeRows)(std::ostream&, const std::vector<Row>&),
                     void (*printTable)(const std::vector<Row>&)) {
    stageReport(files, csv, [&](std::ostream& s) { writeRows(s, rows); });
    files.commit();
    printTable(rows);
    std::printf("ssam-bench: wrote %s (%zu rows)\n", csv.string().c_str(), rows.size());
    return 0;
}

int run(const CLI::App& app, Options o, int argc, char** argv) {
    if (o.sweep && !app.count("--techniques")) o.techniques = "alpha-test,ssam-plus";
    if (app.count("--motion")) parseMotions(o.motion);  // an empty or bad list fails before the first frame
    if (o.dolly || !o.motion.empty()) {                 // the whole path on every technique: a small frame, the forest
        if (!app.count("--size")) o.size = "320x180";
        if (!app.count("--scenes")) o.scenes = "forest";
    }
    if (o.quick) {
        if (!app.count("--size")) o.size = "160x90";
        if (!app.count("--reps")) o.reps = 1;
        if (!app.count("--warmup")) o.warmup = 0;
        if (!app.count("--pan-frames")) o.panFrames = 3;
        if (!app.count("--temporal-frames")) o.temporalFrames = 4;
    }
    // Every flag and sweep value is checked before the first frame (a bad one costs no
    // reference render), and so is every output: the directory is made and proven writable,
    // so a bad --out fails at once (game/README.md "Command-line contract").
    const BenchOptions options = parse(o);
    const std::vector<SweepSetting> settings = o.sweep ? sweepSettings(parseSweepGrid(o)) : std::vector<SweepSetting>{};
    if (!std::filesystem::is_directory(o.contentDir))
        throw engine::Error("--content '" + o.contentDir + "': no such directory");
    const std::filesystem::path out(o.out);
    const std::vector<const char*> reports =
        o.scaling           ? std::vector<const char*>{"scaling.csv", "scaling.svg"}
        : o.dolly           ? std::vector<const char*>{"dolly.csv", "dolly_frames.csv"}
        : !o.motion.empty() ? std::vector<const char*>{"motion.csv"}
        : o.sweep           ? std::vector<const char*>{"sweep.csv", "sweep.md"}
                            : std::vector<const char*>{"bench.csv", "bench_passes.csv", "bench.md", "bench.svg"};
    engine::requireWritableDirectory(out, /*create=*/true);
    for (const char* name : reports) engine::requireWritableFile(out / name, /*createDirectory=*/false);
    const std::string rowsPage = o.figures.empty() ? "" : rowsPagePath(o.figures);
    for (const std::string& page : {o.figures, rowsPage})
        if (!page.empty()) engine::requireWritableFile(page, /*createDirectory=*/false);
    if (!o.figures.empty()) engine::requireWritableFile(out / "dolly_frames.csv", /*createDirectory=*/false);
    std::string speedTable;
    if (!o.speedTable.empty()) {
        std::ifstream in(o.speedTable, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in || text.str().empty())
            throw engine::Error("--speed-table '" + o.speedTable + "': cannot read it, or it is empty");
        speedTable = text.str();
    }
    BenchOptions run = options;
    if (o.images) {
        run.imagesDir = out / "images";
        engine::requireWritableDirectory(run.imagesDir, /*create=*/true);
    }

    std::string command = "ssam-bench";
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    const RunInfo info{command,     resolvedThreads(options.threads), options.reps, options.warmup, options.panFrames,
                       o.ssamPreset};
    engine::PendingFiles files;  // the reports appear together, each whole, or none does
    if (o.scaling) {
        ScalingOptions scaling = defaultScaling(o.quick);
        scaling.backends = options.backends;
        scaling.threads = options.threads;
        scaling.simd = options.simd;
        scaling.contentDir = options.contentDir;
        if (app.count("--reps")) scaling.reps = o.reps;
        if (app.count("--warmup")) scaling.warmup = o.warmup;
        std::printf("ssam-bench --scaling: %zu sizes and %zu layer counts per backend, %d rep(s) after %d warm-up\n",
                    scaling.sizes.size(), scaling.layers.size(), scaling.reps, scaling.warmup);
        const std::vector<ScalingRow> rows = runScaling(scaling);
        stageReport(files, out / "scaling.csv", [&](std::ostream& s) { writeScalingCsv(s, rows); });
        stageReport(files, out / "scaling.svg", [&](std::ostream& s) { writeScalingSvg(s, rows); });
        files.commit();
        std::printf("ssam-bench: wrote %s/scaling.csv, scaling.svg (%zu rows)\n", out.string().c_str(), rows.size());
        return 0;
    }
    if (!o.motion.empty())
        return writeCsvAndTable(files, out / "motion.csv",
                                runMotion(run, parseMotions(o.motion), o.motionFrames, o.motionVectors == "on"),
                                writeMotionCsv, printMotionTable);
    if (o.dolly) {
        const std::vector<DollyRow> rows = runDolly(run, o.dollyFrames, options.crossfade);
        stageReport(files, out / "dolly_frames.csv", [&](std::ostream& s) { writeDollyFramesCsv(s, rows); });
        return writeCsvAndTable(files, out / "dolly.csv", rows, writeDollyCsv, printDollyTable);
    }
    if (o.sweep) {
        std::printf("ssam-bench --sweep: %zu setting(s) per scene\n", settings.size());
        const SweepRun sweepRun = runSweep(run, settings, options.subjects);
        stageReport(files, out / "sweep.csv", [&](std::ostream& s) { writeSweepCsv(s, sweepRun.results); });
        stageReport(files, out / "sweep.md", [&](std::ostream& s) { writeSweepMarkdown(s, sweepRun, info); });
        files.commit();
        std::printf("ssam-bench: wrote %s/sweep.csv, sweep.md (%zu settings x %zu scene(s) x %zu backend(s))\n",
                    out.string().c_str(), settings.size(), options.scenes.size(), options.backends.size());
        return 0;
    }
    const std::vector<BenchRow> rows = runBench(run);
    stageReport(files, out / "bench.csv", [&](std::ostream& s) { writeCsv(s, rows); });
    stageReport(files, out / "bench_passes.csv", [&](std::ostream& s) { writePassesCsv(s, rows); });
    stageReport(files, out / "bench.md", [&](std::ostream& s) { writeMarkdown(s, rows, info); });
    stageReport(files, out / "bench.svg", [&](std::ostream& s) { writeSvg(s, rows); });
    if (!o.figures.empty()) {
        // --quick checks the page's making, not its figures: the first 16 frames of the dolly.
        FiguresRuns runs = runFiguresRuns(run, o.quick && !app.count("--dolly-frames") ? 16 : o.dollyFrames);
        const FiguresInput figures{info,
                                   options.temporalFrames,
                                   speedTable,
                                   o.speedTable,
                                   std::move(runs.lodRows),
                                   runs.lodRowsHaveLevelsOfDetail,
                                   std::move(runs.motion),
                                   std::move(runs.dolly),
                                   std::filesystem::path(rowsPage).filename().string()};
        std::ostringstream rowsText;
        stageReport(files, o.figures, [&](std::ostream& s) { writeFigures(s, rowsText, rows, figures); });
        stageReport(files, rowsPage, [&](std::ostream& s) { s << rowsText.str(); });
        stageReport(files, out / "dolly_frames.csv", [&](std::ostream& s) { writeDollyFramesCsv(s, figures.dolly); });
    }
    files.commit();
    if (!o.figures.empty())
        std::printf("ssam-bench: wrote %s, %s and %s/dolly_frames.csv\n", o.figures.c_str(), rowsPage.c_str(),
                    out.string().c_str());
    std::printf("ssam-bench: wrote %s/bench.csv, bench_passes.csv, bench.md, bench.svg (%zu rows)\n",
                out.string().c_str(), rows.size());
    return 0;
}

}  // namespace

// Only declaring the options runs outside runTool's handler: an exception there is a bug of the
// tool itself (a flag declared twice), which the tool's --help test finds first.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    CLI::App app{"ssam-bench: run time against error of every transparency technique ([Hathaway 2010])"};
    Options o;
    app.add_option("--scenes", o.scenes, "comma list of scenes: tree, forest, vista, empty")->capture_default_str();
    app.add_option("--techniques", o.techniques,
                   "comma list of techniques (" + allTechniqueNames() +
                       ") or all; with --sweep, the ones measured beside the settings (default there: "
                       "alpha-test,ssam-plus; or none)")
        ->capture_default_str();
    app.add_option(
           "--ssam-preset", o.ssamPreset,
           "techniques ssam's and ssam+taa's knobs: paper ([Hathaway 2010]'s values) or measured (the knob sweep's best "
           "within 1.25x the paper's time; ssam/docs/knobs.md)")
        ->check(CLI::IsMember({ssam::presetName(ssam::Preset::Paper), ssam::presetName(ssam::Preset::Measured)}))
        ->capture_default_str();
    app.add_option(
        "--ssam-setting", o.ssamSettings,
        "NAME=VALUE, repeatable: one of techniques ssam's and ssam+taa's knobs over the preset's (maskLerp, "
        "colorAlphaReference, colorFade in [0,1], squareMask, colorBlur on/off; ssam/docs/steady_in_motion.md)");
    racer::addOnOffOption(
        app, "--ssam-plus-blur", o.ssamPlusBlur,
        "technique ssam-plus's composite averages the foliage colour over 3x3 (on) or takes the pixel's "
        "own (off; ssam/docs/ssam_plus.md)");
    racer::addOnOffOption(
        app, "--ssam-plus-front-layers", o.ssamPlusFrontLayers,
        "technique ssam-plus mixes in the colours of the layers in front of the colour pass's leaf, "
        "from a third geometry pass (on), or not (off; ssam/docs/ssam_plus.md, \"The front layers\")");
    app.add_option(
           "--backend", o.backends,
           "comma list of backends: soft, gl (EGL; Mesa llvmpipe without a GPU), vk (Vulkan; lavapipe without a GPU)")
        ->capture_default_str();
    app.add_option("--size", o.size, "frame size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--reps", o.reps, "timed repetitions per technique")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--warmup", o.warmup, "untimed frames before the repetitions")
        ->check(CLI::Range(0, 10000))
        ->capture_default_str();
    app.add_option("--pan-frames", o.panFrames, "frames of the sideways pan for the flicker measure")
        ->check(CLI::Range(2, 1000))
        ->capture_default_str();
    app.add_option("--temporal-frames", o.temporalFrames,
                   "frames of the pan on which every technique's error is measured frame by frame against that "
                   "frame's reference (converged: median of the last half; worst frame); 0: none")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    app.add_option("--threads", o.threads, "soft backend threads and LP_NUM_THREADS for gl (0: all)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    racer::addSimdOption(app, o.simd);
    app.add_flag("--quick", o.quick,
                 "CI mode: 160x90, 1 rep, no warm-up, 3 pan frames, 4 temporal frames (explicit flags win)");
    app.add_flag("--images", o.images,
                 "also write each still frame, and its per-pixel FLIP error (_flip), as a PNG into OUT/images");
    CLI::Option* sweep = app.add_flag("--sweep", o.sweep,
                                      "instead of comparing techniques: SSAM under a grid of its knobs "
                                      "(ssam::Settings), each against the exact reference; writes sweep.csv, sweep.md");
    app.add_flag("--sweep-full", o.sweepFull,
                 "every combination of the sweep values (default: every maskLerp x squareMask, then each "
                 "other knob alone, the rest at the paper's defaults)")
        ->needs(sweep);
    app.add_option("--sweep-lerp", o.sweepLerp, "maskLerp values (§3.5.4), each in [0,1]")
        ->capture_default_str()
        ->needs(sweep);
    app.add_option("--sweep-square", o.sweepSquare, "squareMask values (§3.6.2): on, off")
        ->capture_default_str()
        ->needs(sweep);
    app.add_option("--sweep-blur", o.sweepBlur, "colorBlur values (the composite's 3x3 colour mean): on, off")
        ->capture_default_str()
        ->needs(sweep);
    app.add_option("--sweep-reference", o.sweepReference,
                   "colorAlphaReference values in 255ths (§3.5.3; Pure shipped 64), each in [0,255]")
        ->capture_default_str()
        ->needs(sweep);
    app.add_option("--sweep-precision", o.sweepPrecision, "maskPrecision values (§3.5.2): rgba8, rgba16f, rg16f")
        ->capture_default_str()
        ->needs(sweep);
    CLI::Option* figures = app.add_option(
        "--figures", o.figures,
        "also write FIGURES.md (the figures the READMEs quote: the goals still, in motion and along the dolly, from "
        "further runs of their techniques on the soft backend, and what limits those not met; ssam beside what "
        "engines ship) from this run to this file, and the rows they come from (every scene's techniques, every "
        "technique in motion) to the file beside it named with _ROWS (FIGURES_ROWS.md); make bench writes "
        "game/bench/FIGURES.md");
    app.add_option("--speed-table", o.speedTable,
                   "game/bench/speed_table.sh's table (its speed_table.md), copied into --figures' file")
        ->check(CLI::ExistingFile)
        ->needs(figures);
    app.add_flag("--with-paper-ssam", o.withPaperSsam,
                 "also run technique ssam with the paper's knobs, as row ssam-paper (the time goal against the "
                 "paper preset, bench.md)");
    CLI::Option* scaling =
        app.add_flag("--scaling", o.scaling,
                     "instead of comparing techniques: each backend's SSAM and alpha-test frame time against "
                     "resolution (forest, 360p..2160p) and foliage depth complexity (1..64 full-view leaf layers "
                     "at 720p); --quick: 160x90..320x180 and 1..4 layers; writes scaling.csv, scaling.svg");
    scaling->excludes(sweep);
    figures->excludes(sweep)->excludes(scaling);
    for (const char* flag : {"--scenes", "--techniques", "--size", "--pan-frames", "--temporal-frames", "--images"})
        scaling->excludes(app.get_option(flag));
    app.add_option("--out", o.out, "output directory (created if missing; checked before the first frame)")
        ->capture_default_str();
    app.add_option("--content", o.contentDir, "content directory")->capture_default_str();
    racer::addOnOffOption(
        app, "--lod", o.lod,
        "levels of detail for the scenes' trees and bushes, chosen for --size: on, or off (every plant "
        "at full detail)");
    racer::addOnOffOption(app, "--crossfade", o.crossfade,
                          "with --lod on, crossfade each level change over 10 % of its threshold (both levels drawn, "
                          "their weights in the instance alpha): on, or off (each level switches in one frame)");
    CLI::Option* dolly = app.add_flag(
        "--dolly", o.dolly,
        "instead of comparing techniques: popping along the forest's dolly (the camera moving toward the trees "
        "1 m a frame), each technique with levels of detail against full detail; default 320x180; writes dolly.csv and, frame by frame, dolly_frames.csv");
    app.add_option("--dolly-frames", o.dollyFrames,
                   "frames of the dolly from its start (2..117), for --dolly and --figures' dolly (--quick: 16)")
        ->capture_default_str();
    dolly->excludes(sweep)->excludes(scaling)->excludes(figures);
    CLI::Option* motion = app.add_option(
        "--motion", o.motion,
        "instead of comparing techniques: every technique in motion, a comma list of pan (the sideways pan), dolly "
        "(the forest's dolly toward the trees) and wind (a still camera, the plants in the wind): flicker, ꟻLIP and "
        "RMSE on foliage pixels against each frame's reference (converged, worst) and ghosting (the error on pixels "
        "whose surface moved; game/README.md); default 320x180, the forest; writes motion.csv");
    app.add_option("--motion-frames", o.motionFrames, "frames measured per motion (2..117)")
        ->capture_default_str()
        ->needs(motion);
    racer::addOnOffOption(
        app, "--motion-vectors", o.motionVectors,
        "with --motion, the temporal techniques reproject by the draws' motion vectors (on) or by the "
        "camera alone (off)")
        ->needs(motion);
    motion->excludes(sweep)->excludes(scaling)->excludes(figures)->excludes(dolly);
    app.footer(engine::cli::contractHelpFooter());
    return engine::cli::runTool("ssam-bench", app, argc, argv, [&] { return run(app, o, argc, argv); });
}
