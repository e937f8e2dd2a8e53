// SPDX-License-Identifier: MIT
#include "bench_scaling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>

#include "bench_frame.hpp"
#include "frame_timing.hpp"
#include "bench_runner.hpp"
#include "engine/render/devices/create_device.hpp"
#include "report_text.hpp"

namespace bench {

using namespace engine::render;
using transparency::TechniqueKind;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr TechniqueKind kTechniques[] = {TechniqueKind::Ssam, TechniqueKind::AlphaTest};

// Times one technique's frame of `view` at one size: warm-up frames, then the median of the
// timed ones (wall and process CPU time, as ssam-bench's rows).
void timeFrames(Backend& backend, BenchScene& scene, const ViewUpload& view, TechniqueKind kind, ScalingSize size,
                const ScalingOptions& o, ScalingRow& row) {
    transparency::TechniqueOptions options;
    options.depthFunc = kDepthFunc;
    auto technique = transparency::createTechnique(kind, backend, options);
    FrameTargets targets(backend,
                         {size.width, size.height, technique->opaqueSamples(), Format::RGBA8_SRGB, kDepthFunc});
    FrameDrawer drawer(backend, scene.library());
    backend.takeTimings();
    std::vector<double> wall, cpu;
    for (int i = 0; i < o.warmup + o.reps; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const double cpuStart = processCpuMs();
        drawer.draw(targets, technique.get(), view);
        backend.takeTimings();  // GL: waits for the frame
        if (i < o.warmup) continue;
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        cpu.push_back(processCpuMs() - cpuStart);
    }
    row.medianMs = median(wall);
    row.cpuMedianMs = median(cpu);
}

void measurePoint(Backend& backend, const std::string& backendName, BenchScene& scene, const ViewUpload& view,
                  const std::string& axis, ScalingSize size, int layers, const ScalingOptions& o,
                  std::vector<ScalingRow>& rows) {
    for (TechniqueKind kind : kTechniques) {
        ScalingRow row{axis, backendName, transparency::techniqueName(kind), size.width, size.height, layers, kNaN,
                       kNaN, {}};
        try {
            timeFrames(backend, scene, view, kind, size, o, row);
        } catch (const std::exception& e) {
            row.note = std::string("skipped: ") + e.what();
        }
        std::printf("[ssam-bench --scaling] %-6s %-4s %-10s %5dx%-5d layers %2d (%4zu foliage instances) %9.2f ms %s\n",
                    axis.c_str(), backendName.c_str(), row.technique.c_str(), size.width, size.height, layers,
                    view.foliageInstances(), row.medianMs, row.note.c_str());
        std::fflush(stdout);
        rows.push_back(row);
    }
}

}  // namespace

ScalingOptions defaultScaling(bool quick) {
    ScalingOptions o;
    if (quick) {
        o.sizes = {{160, 90}, {320, 180}};
        o.layers = {1, 2, 4};
        o.layersSize = {160, 90};
        o.reps = 1;
        o.warmup = 0;
    } else {
        o.sizes = {{640, 360}, {1280, 720}, {1920, 1080}, {2560, 1440}, {3840, 2160}};
        o.layers = {1, 2, 4, 8, 16, 32, 64};
        o.layersSize = {1280, 720};
    }
    return o;
}

std::vector<ScalingRow> runScaling(const ScalingOptions& o) {
    const int threads = resolvedThreads(o.threads);
    std::vector<ScalingRow> pixelRows, layerRows;
    for (const std::string& backendName : o.backends) {
        std::unique_ptr<Backend> backend;
        std::string unavailable;
        engine::render::DeviceOptions deviceOptions;  // the same threads for every driver (create_device.hpp)
        deviceOptions.threads = threads;
        deviceOptions.soft = {.threads = threads, .tileSize = 64, .simd = o.simd};
        try {
            backend = engine::render::createDevice(*engine::render::parseDeviceKind(backendName), deviceOptions);
        } catch (const std::exception& e) {
            unavailable = backendName + " backend unavailable: " + e.what();
        }
        if (!backend) {
            std::printf("[ssam-bench --scaling] %s\n", unavailable.c_str());
            for (TechniqueKind kind : kTechniques) {
                for (ScalingSize s : o.sizes)
                    pixelRows.push_back({"pixels", backendName, transparency::techniqueName(kind), s.width, s.height, 0,
                                         kNaN, kNaN, unavailable});
                for (int n : o.layers)
                    layerRows.push_back({"layers", backendName, transparency::techniqueName(kind), o.layersSize.width,
                                         o.layersSize.height, n, kNaN, kNaN, unavailable});
            }
            continue;
        }
        // Each size's view uploaded on its own, for its aspect (the default sizes are all 16:9).
        {
            BenchScene forest(*backend, SceneKind::Forest, o.contentDir);
            for (ScalingSize s : o.sizes) {
                const ViewUpload view(*backend, forest, forest.camera(float(s.width) / float(s.height)));
                measurePoint(*backend, backendName, forest, view, "pixels", s, 0, o, pixelRows);
            }
        }
        for (int n : o.layers) {
            BenchScene cards(*backend, n, o.contentDir);
            const ViewUpload view(*backend, cards,
                                  cards.camera(float(o.layersSize.width) / float(o.layersSize.height)));
            measurePoint(*backend, backendName, cards, view, "layers", o.layersSize, n, o, layerRows);
        }
    }
    // Grouped as the header promises: axis, backend, technique, then the points in order.
    std::vector<ScalingRow> rows;
    for (std::vector<ScalingRow>* axis : {&pixelRows, &layerRows}) {
        std::stable_sort(axis->begin(), axis->end(), [&](const ScalingRow& a, const ScalingRow& b) {
            auto rank = [&](const ScalingRow& r) {
                return std::distance(o.backends.begin(), std::find(o.backends.begin(), o.backends.end(), r.backend));
            };
            if (rank(a) != rank(b)) return rank(a) < rank(b);
            return a.technique < b.technique;
        });
        rows.insert(rows.end(), axis->begin(), axis->end());
    }
    return rows;
}

const std::vector<std::string>& scalingCsvColumns() {
    static const std::vector<std::string> columns{"axis",          "backend",       "technique",    "width",
                                                  "height",        "megapixels",    "layers",       "median_ms",
                                                  "cpu_median_ms", "ms_per_mpixel", "ms_per_layer", "note"};
    return columns;
}

void writeScalingCsv(std::ostream& out, const std::vector<ScalingRow>& rows) {
    writeCsvHeader(out, scalingCsvColumns());
    for (const ScalingRow& r : rows) {
        const double mpix = double(r.width) * double(r.height) * 1e-6;
        out << r.axis << ',' << r.backend << ',' << r.technique << ',' << r.width << ',' << r.height << ','
            << num(mpix, "%.4f") << ',' << r.layers << ',' << num(r.medianMs, "%.3f") << ','
            << num(r.cpuMedianMs, "%.3f") << ',' << num(r.medianMs / mpix, "%.3f") << ','
            << (r.layers > 0 ? num(r.medianMs / r.layers, "%.3f") : "") << ',' << csvField(r.note) << "\n";
    }
}

void writeScalingSvg(std::ostream& out, const std::vector<ScalingRow>& rows) {
    // Two panels side by side; each plots time (ms) against the axis's measure on linear scales,
    // so a straight line through the points is linear cost.
    constexpr double kPanelW = 460, kPanelH = 320, kLeft = 70, kTop = 40, kPlotW = 370, kPlotH = 230;
    const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"};
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 2 * kPanelW << "\" height=\"" << kPanelH + 40
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const char* axes[] = {"pixels", "layers"};
    for (int p = 0; p < 2; ++p) {
        const std::string axis = axes[p];
        const double ox = p * kPanelW;
        auto xOf = [&](const ScalingRow& r) {
            return axis == "pixels" ? double(r.width) * r.height * 1e-6 : double(r.layers);
        };
        double xMax = 0.0, yMax = 0.0;
        std::map<std::string, std::vector<const ScalingRow*>> lines;  // backend/technique -> points
        for (const ScalingRow& r : rows) {
            if (r.axis != axis || !std::isfinite(r.medianMs)) continue;
            xMax = std::max(xMax, xOf(r));
            yMax = std::max(yMax, r.medianMs);
            lines[r.backend + " " + r.technique].push_back(&r);
        }
        if (xMax <= 0.0) xMax = 1.0;
        if (yMax <= 0.0) yMax = 1.0;
        const double x0 = ox + kLeft, y0 = kTop + kPlotH;
        auto sx = [&](double x) { return x0 + x / xMax * kPlotW; };
        auto sy = [&](double y) { return y0 - y / yMax * kPlotH; };
        out << "<text x=\"" << ox + kLeft << "\" y=\"24\" font-weight=\"bold\">"
            << (axis == "pixels" ? "forest: frame time against megapixels (360p..2160p)"
                                 : "leaf cards: frame time against layers")
            << "</text>\n";
        out << "<line x1=\"" << x0 << "\" y1=\"" << y0 << "\" x2=\"" << x0 + kPlotW << "\" y2=\"" << y0
            << "\" stroke=\"black\"/>\n<line x1=\"" << x0 << "\" y1=\"" << y0 << "\" x2=\"" << x0 << "\" y2=\"" << kTop
            << "\" stroke=\"black\"/>\n";
        for (int t = 0; t <= 4; ++t) {
            const double xv = xMax * t / 4, yv = yMax * t / 4;
            out << "<text x=\"" << sx(xv) << "\" y=\"" << y0 + 16 << "\" text-anchor=\"middle\">" << num(xv, "%.3g")
                << "</text>\n<text x=\"" << x0 - 6 << "\" y=\"" << sy(yv) + 4 << "\" text-anchor=\"end\">"
                << num(yv, yv >= 1000.0 ? "%.0f" : "%.4g") << "</text>\n";
        }
        out << "<text x=\"" << x0 + kPlotW / 2 << "\" y=\"" << y0 + 34 << "\" text-anchor=\"middle\">"
            << (axis == "pixels" ? "megapixels" : "full-view leaf layers") << "</text>\n<text x=\"" << ox + 14
            << "\" y=\"" << kTop + kPlotH / 2 << "\" transform=\"rotate(-90 " << ox + 14 << ' ' << kTop + kPlotH / 2
            << ")\" text-anchor=\"middle\">median frame ms</text>\n";
        int c = 0;
        for (const auto& [name, points] : lines) {
            const char* colour = colours[c % 6];
            const bool dashed = name.find("alpha-test") != std::string::npos;
            out << "<polyline fill=\"none\" stroke=\"" << colour << "\"" << (dashed ? " stroke-dasharray=\"5,3\"" : "")
                << " points=\"";
            for (const ScalingRow* r : points) out << sx(xOf(*r)) << ',' << sy(r->medianMs) << ' ';
            out << "\"/>\n";
            for (const ScalingRow* r : points)
                out << "<circle cx=\"" << sx(xOf(*r)) << "\" cy=\"" << sy(r->medianMs) << "\" r=\"3\" fill=\"" << colour
                    << "\"/>\n";
            out << "<text x=\"" << x0 + 10 << "\" y=\"" << kTop + 14 + 15 * c << "\" fill=\"" << colour << "\">" << name
                << "</text>\n";
            ++c;
        }
    }
    out << "</svg>\n";
}

}  // namespace bench
