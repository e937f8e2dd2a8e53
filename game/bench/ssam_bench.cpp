// ssam-bench: every transparency technique's run time against its error from the exact
// reference (DESIGN.md "Accuracy and the ground truth", issue #6). Writes bench.csv,
// bench_passes.csv, bench.md and bench.svg into --out.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "bench_report.hpp"
#include "bench_runner.hpp"
#include "engine/core/error.hpp"

namespace {

using namespace bench;

struct Options {
    std::string scenes = "tree,forest,vista,empty";
    std::string techniques = "all";
    std::string backends = "soft";
    std::string size = "1280x720";
    int reps = 5;
    int warmup = 1;
    int panFrames = 8;
    int threads = 0;
    bool quick = false;
    bool images = false;
    std::string out = "out/bench";
    std::string contentDir = SSAM_CONTENT_DIR;
};

std::vector<std::string> splitList(const std::string& list, const char* flag) {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string item = list.substr(start, comma - start);
        if (item.empty()) throw engine::Error(std::string(flag) + " '" + list + "': empty entry in the comma list");
        items.push_back(item);
        start = comma + 1;
    }
    return items;
}

std::string allTechniqueNames() {
    std::string names;
    for (auto k : transparency::allTechniques()) names += std::string(names.empty() ? "" : ", ") + transparency::techniqueName(k);
    return names;
}

BenchOptions parse(const Options& o) {
    BenchOptions b;
    for (const std::string& name : splitList(o.scenes, "--scenes")) {
        SceneKind kind;
        if (!parseScene(name, kind))
            throw engine::Error("--scenes: unknown scene '" + name + "' (known: tree, forest, vista, empty)");
        b.scenes.push_back(kind);
    }
    if (o.techniques == "all") {
        b.techniques.assign(transparency::allTechniques().begin(), transparency::allTechniques().end());
    } else {
        for (const std::string& name : splitList(o.techniques, "--techniques")) {
            const auto kind = transparency::parseTechnique(name);
            if (!kind)
                throw engine::Error("--techniques: unknown technique '" + name + "' (known: " + allTechniqueNames() +
                                    "; or all)");
            b.techniques.push_back(*kind);
        }
    }
    for (const std::string& name : splitList(o.backends, "--backend")) {
        if (name != "soft" && name != "gl")
            throw engine::Error("--backend: unknown backend '" + name + "' (known: soft, gl)");
        b.backends.push_back(name);
    }
    std::smatch m;
    static const std::regex sizePattern(R"((\d{1,5})x(\d{1,5}))");
    if (!std::regex_match(o.size, m, sizePattern))
        throw engine::Error("--size '" + o.size + "': expected WIDTHxHEIGHT, e.g. 1280x720");
    b.width = std::stoi(m[1]);
    b.height = std::stoi(m[2]);
    // SSIM's 11x11 window needs at least 11 pixels each way.
    if (b.width < 11 || b.height < 11 || b.width > 16384 || b.height > 16384)
        throw engine::Error("--size '" + o.size + "': each dimension must be in 11..16384");
    b.reps = o.reps;
    b.warmup = o.warmup;
    b.panFrames = o.panFrames;
    b.threads = o.threads;
    b.contentDir = o.contentDir;
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"ssam-bench: run time against error of every transparency technique (seeds/000, issue #6)"};
    Options o;
    app.add_option("--scenes", o.scenes, "comma list of scenes: tree, forest, vista, empty")->capture_default_str();
    app.add_option("--techniques", o.techniques, "comma list of techniques (" + allTechniqueNames() + ") or all")
        ->capture_default_str();
    app.add_option("--backend", o.backends, "comma list of backends: soft, gl (EGL; Mesa llvmpipe without a GPU)")
        ->capture_default_str();
    app.add_option("--size", o.size, "frame size WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--reps", o.reps, "timed repetitions per technique")->check(CLI::Range(1, 10000))->capture_default_str();
    app.add_option("--warmup", o.warmup, "untimed frames before the repetitions")
        ->check(CLI::Range(0, 10000))
        ->capture_default_str();
    app.add_option("--pan-frames", o.panFrames, "frames of the sideways pan for the flicker measure")
        ->check(CLI::Range(2, 1000))
        ->capture_default_str();
    app.add_option("--threads", o.threads, "soft backend threads and LP_NUM_THREADS for gl (0: all)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    app.add_flag("--quick", o.quick, "CI mode: 160x90, 1 rep, no warm-up, 3 pan frames (explicit flags win)");
    app.add_flag("--images", o.images, "also write each still frame as a PNG into OUT/images");
    app.add_option("--out", o.out, "output directory")->capture_default_str();
    app.add_option("--content", o.contentDir, "content directory")->check(CLI::ExistingDirectory)->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    if (o.quick) {
        if (!app.count("--size")) o.size = "160x90";
        if (!app.count("--reps")) o.reps = 1;
        if (!app.count("--warmup")) o.warmup = 0;
        if (!app.count("--pan-frames")) o.panFrames = 3;
    }
    try {
        const BenchOptions options = parse(o);
        std::string command = "ssam-bench";
        for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
        const std::filesystem::path out(o.out);
        std::filesystem::create_directories(out);
        BenchOptions run = options;
        if (o.images) run.imagesDir = out / "images";
        const std::vector<BenchRow> rows = runBench(run);
        writeCsv(out / "bench.csv", rows);
        writePassesCsv(out / "bench_passes.csv", rows);
        writeMarkdown(out / "bench.md", rows,
                      {command, resolvedThreads(options.threads), options.reps, options.warmup, options.panFrames});
        writeSvg(out / "bench.svg", rows);
        std::printf("ssam-bench: wrote %s/bench.csv, bench_passes.csv, bench.md, bench.svg (%zu rows)\n",
                    out.string().c_str(), rows.size());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssam-bench: error: %s\n", e.what());
        return 1;
    }
}
