#include "bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "engine/core/error.hpp"
#include "report_text.hpp"

namespace bench {

namespace {

std::string xmlEscape(const std::string& s) {
    std::string r;
    for (char c : s) {
        if (c == '<') r += "&lt;";
        else if (c == '>') r += "&gt;";
        else if (c == '&') r += "&amp;";
        else if (c == '"') r += "&quot;";
        else r += c;
    }
    return r;
}

const BenchRow* find(const std::vector<BenchRow>& rows, const std::string& scene, const std::string& technique,
                     const std::string& backend) {
    for (const BenchRow& r : rows)
        if (r.scene == scene && r.technique == technique && r.backend == backend) return &r;
    return nullptr;
}

std::vector<std::string> distinct(const std::vector<BenchRow>& rows, std::string BenchRow::*field) {
    std::vector<std::string> out;
    for (const BenchRow& r : rows)
        if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
    return out;
}

// The backend goals and the chart are computed on: soft when it ran (deterministic errors).
std::string primaryBackend(const std::vector<BenchRow>& rows) {
    const auto backends = distinct(rows, &BenchRow::backend);
    if (std::find(backends.begin(), backends.end(), "soft") != backends.end()) return "soft";
    return backends.empty() ? "" : backends.front();
}

}  // namespace

const std::vector<std::string>& csvColumns() {
    static const std::vector<std::string> columns{
        "scene",       "technique",   "backend",    "width",     "height",    "time_ms_median", "time_ms_min",
        "time_ms_max", "cpu_ms_median", "rmse_linear", "psnr_linear", "rmse_srgb", "psnr_srgb", "ssim",           "flip_mean",
        "flicker",     "flicker_raw", "peak_mem_mb", "peak_rss_mb", "note"};
    return columns;
}

void writeCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows) {
    std::ofstream out = openOut(path);
    const auto& columns = csvColumns();
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << "\n";
    for (const BenchRow& r : rows) {
        out << csvField(r.scene) << ',' << csvField(r.technique) << ',' << r.backend << ',' << r.width << ','
            << r.height << ',' << num(r.timeMedianMs, "%.3f") << ',' << num(r.timeMinMs, "%.3f") << ','
            << num(r.timeMaxMs, "%.3f") << ',' << num(r.cpuMedianMs, "%.3f") << ',' << num(r.rmseLinear) << ',' << num(r.psnrLinear) << ','
            << num(r.rmseSrgb) << ',' << num(r.psnrSrgb) << ',' << num(r.ssim) << ',' << num(r.flipMean) << ','
            << num(r.flicker) << ',' << num(r.flickerRaw) << ',' << num(r.peakMemMb, "%.3f") << ','
            << num(r.peakRssMb, "%.1f") << ',' << csvField(r.note) << "\n";
    }
}

void writePassesCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows) {
    std::ofstream out = openOut(path);
    out << "scene,technique,backend,pass,time_ms_median\n";
    for (const BenchRow& r : rows)
        for (const PassTime& p : r.passes)
            out << csvField(r.scene) << ',' << csvField(r.technique) << ',' << r.backend << ',' << csvField(p.pass)
                << ',' << num(p.medianMs, "%.3f") << "\n";
}

void writeMarkdown(const std::filesystem::path& path, const std::vector<BenchRow>& rows, const RunInfo& info) {
    std::ofstream out = openOut(path);
    out << "# ssam-bench\n\n`" << info.command << "`\n\n";
    if (!rows.empty())
        out << rows.front().width << "x" << rows.front().height << ", " << info.reps << " timed repetition(s) after "
            << info.warmup << " warm-up, flicker over " << info.panFrames << " pan frames, " << info.threads
            << " thread(s) (soft backend; LP_NUM_THREADS for gl).\n\n";
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
                << " | " << num(r.rmseLinear, "%.5f")
                << " | " << num(r.psnrSrgb, "%.2f") << " | " << num(r.ssim, "%.4f") << " | "
                << num(r.flipMean, "%.4f") << " | " << num(r.flicker, "%.5f") << " | " << num(r.peakMemMb, "%.2f")
                << " | " << num(r.peakRssMb, "%.1f") << " | " << mdCell(r.note) << " |\n";
        }
        out << "\n";
    }

    // Goal ratios (issue #6), from this run.
    const std::string primary = primaryBackend(rows);
    auto value = [&](const std::string& scene, const std::string& technique, double BenchRow::*field,
                     const std::string& backend) -> std::optional<double> {
        const BenchRow* r = find(rows, scene, technique, backend);
        if (!r || !has(r->*field)) return std::nullopt;
        return r->*field;
    };
    out << "## goals (" << primary << " backend)\n\nStatus from the ratio (wall time for time goals); for time goals "
           "the ratio of median CPU times is shown too, which other processes on the machine disturb less.\n\n"
           "| goal | ratio | CPU-time ratio | target | status |\n|---|---:|---:|---|---|\n";
    auto goal = [&](const std::string& what, std::optional<double> a, std::optional<double> b, bool atMost,
                    double target, std::optional<double> cpuA = std::nullopt, std::optional<double> cpuB = std::nullopt) {
        const std::string cpuRatio = cpuA && cpuB && *cpuB > 0.0 ? num(*cpuA / *cpuB, "%.3f") : "";
        std::string ratio = "n/a", status = "not measured";
        if (a && b && *b != 0.0) {
            const double q = *a / *b;
            ratio = num(q, "%.3f");
            status = (atMost ? q <= target : q >= target) ? "met" : "not met";
        } else if (a && b) {
            status = "undefined (division by zero)";
        }
        out << "| " << what << " | " << ratio << " | " << cpuRatio << " | " << (atMost ? "<= " : ">= ") << num(target, "%.2f") << " | "
            << status << " |\n";
    };
    auto v = [&](const char* scene, const char* technique, double BenchRow::*field) {
        return value(scene, technique, field, primary);
    };
    goal("forest: ꟻLIP ssam / alpha-test", v("forest", "ssam", &BenchRow::flipMean),
         v("forest", "alpha-test", &BenchRow::flipMean), true, 0.5);
    goal("forest: RMSE ssam / alpha-test", v("forest", "ssam", &BenchRow::rmseLinear),
         v("forest", "alpha-test", &BenchRow::rmseLinear), true, 0.5);
    goal("forest: ꟻLIP ssam / wboit", v("forest", "ssam", &BenchRow::flipMean), v("forest", "wboit", &BenchRow::flipMean),
         true, 1.0);
    goal("forest: RMSE ssam / wboit", v("forest", "ssam", &BenchRow::rmseLinear),
         v("forest", "wboit", &BenchRow::rmseLinear), true, 1.0);
    goal("forest: flicker ssam / alpha-test", v("forest", "ssam", &BenchRow::flicker),
         v("forest", "alpha-test", &BenchRow::flicker), true, 0.3);
    goal("forest: time ssam / alpha-test", v("forest", "ssam", &BenchRow::timeMedianMs),
         v("forest", "alpha-test", &BenchRow::timeMedianMs), true, 1.5, v("forest", "ssam", &BenchRow::cpuMedianMs),
         v("forest", "alpha-test", &BenchRow::cpuMedianMs));
    goal("forest: time reference / ssam", v("forest", "reference", &BenchRow::timeMedianMs),
         v("forest", "ssam", &BenchRow::timeMedianMs), false, 10.0, v("forest", "reference", &BenchRow::cpuMedianMs),
         v("forest", "ssam", &BenchRow::cpuMedianMs));
    goal("forest: ꟻLIP ssam-plus / ssam (30% lower)", v("forest", "ssam-plus", &BenchRow::flipMean),
         v("forest", "ssam", &BenchRow::flipMean), true, 0.7);
    goal("forest: RMSE ssam-plus / ssam (30% lower)", v("forest", "ssam-plus", &BenchRow::rmseLinear),
         v("forest", "ssam", &BenchRow::rmseLinear), true, 0.7);
    goal("forest: time ssam-plus / ssam", v("forest", "ssam-plus", &BenchRow::timeMedianMs),
         v("forest", "ssam", &BenchRow::timeMedianMs), true, 1.2, v("forest", "ssam-plus", &BenchRow::cpuMedianMs),
         v("forest", "ssam", &BenchRow::cpuMedianMs));
    goal("empty: time ssam / opaque-only", v("empty", "ssam", &BenchRow::timeMedianMs),
         v("empty", kOpaqueOnly, &BenchRow::timeMedianMs), true, 1.05, v("empty", "ssam", &BenchRow::cpuMedianMs),
         v("empty", kOpaqueOnly, &BenchRow::cpuMedianMs));
    const auto backends = distinct(rows, &BenchRow::backend);
    const bool both = std::find(backends.begin(), backends.end(), "soft") != backends.end() &&
                      std::find(backends.begin(), backends.end(), "gl") != backends.end();
    if (both)
        for (const std::string& scene : distinct(rows, &BenchRow::scene))
            goal(scene + ": time ssam soft / gl", value(scene, "ssam", &BenchRow::timeMedianMs, "soft"),
                 value(scene, "ssam", &BenchRow::timeMedianMs, "gl"), true, 0.5,
                 value(scene, "ssam", &BenchRow::cpuMedianMs, "soft"), value(scene, "ssam", &BenchRow::cpuMedianMs, "gl"));
    else
        out << "| time ssam soft / gl | n/a |  | <= 0.50 | not measured (run with --backend soft,gl) |\n";
    out << "\n";

    if (both) {
        out << "## soft / gl time per technique\n\n| scene | technique | soft ms | gl ms | soft / gl |\n"
               "|---|---|---:|---:|---:|\n";
        for (const BenchRow& r : rows) {
            if (r.backend != "soft") continue;
            const BenchRow* g = find(rows, r.scene, r.technique, "gl");
            const double s = r.timeMedianMs, gms = g ? g->timeMedianMs : kMissing;
            out << "| " << r.scene << " | " << r.technique << " | " << num(s, "%.2f") << " | " << num(gms, "%.2f")
                << " | " << (has(s) && has(gms) && gms > 0 ? num(s / gms, "%.3f") : "") << " |\n";
        }
        out << "\n";
    }
    out << "Chart: [bench.svg](bench.svg). Per-pass medians: bench_passes.csv.\n";
}

void writeSvg(const std::filesystem::path& path, const std::vector<BenchRow>& rows) {
    const std::string backend = primaryBackend(rows);
    struct Point {
        std::string label;
        double time, error;
        bool front = false;
    };
    struct Panel {
        std::string scene;
        std::vector<Point> points;
    };
    std::vector<Panel> panels;
    for (const std::string& scene : distinct(rows, &BenchRow::scene)) {
        Panel p{scene, {}};
        for (const BenchRow& r : rows)
            if (r.scene == scene && r.backend == backend && r.technique != kOpaqueOnly && has(r.timeMedianMs) &&
                r.timeMedianMs > 0.0 && has(r.flipMean))
                p.points.push_back({r.technique, r.timeMedianMs, r.flipMean});
        // Pareto front: no other point is at least as fast and at least as accurate, and better in one.
        for (Point& a : p.points) {
            a.front = std::none_of(p.points.begin(), p.points.end(), [&](const Point& b) {
                return b.time <= a.time && b.error <= a.error && (b.time < a.time || b.error < a.error);
            });
        }
        if (!p.points.empty()) panels.push_back(std::move(p));
    }

    const int panelW = 460, panelH = 340, margin = 20;
    const int cols = std::max<int>(1, std::min<int>(2, int(panels.size())));
    const int rowsN = std::max<int>(1, (int(panels.size()) + cols - 1) / cols);
    const int width = cols * panelW + margin * 2, height = rowsN * panelH + margin * 2 + 40;
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << margin << "\" y=\"" << margin + 12 << "\" font-size=\"15\" font-weight=\"bold\">"
      << "ssam-bench: frame time against ꟻLIP error (" << xmlEscape(backend)
      << " backend); filled = Pareto front</text>\n";
    if (panels.empty())
        s << "<text x=\"" << margin << "\" y=\"" << margin + 50
          << "\">no error data: the exact reference was not available in this run</text>\n";

    for (std::size_t i = 0; i < panels.size(); ++i) {
        const Panel& p = panels[i];
        const double ox = margin + double(i % cols) * panelW, oy = margin + 40 + double(i / cols) * panelH;
        const double left = ox + 60, right = ox + panelW - 20, top = oy + 24, bottom = oy + panelH - 50;
        double tMin = 1e300, tMax = 0, eMax = 0;
        for (const Point& pt : p.points) {
            tMin = std::min(tMin, pt.time);
            tMax = std::max(tMax, pt.time);
            eMax = std::max(eMax, pt.error);
        }
        // Time on a log axis (techniques span orders of magnitude), error linear from 0.
        const double l0 = std::floor(std::log10(tMin)), l1 = std::max(l0 + 1.0, std::ceil(std::log10(tMax)));
        const double eTop = eMax > 0 ? eMax * 1.15 : 1.0;
        auto X = [&](double t) { return left + (std::log10(t) - l0) / (l1 - l0) * (right - left); };
        auto Y = [&](double e) { return bottom - e / eTop * (bottom - top); };
        s << "<g>\n<text x=\"" << (left + right) / 2 << "\" y=\"" << oy + 14
          << "\" text-anchor=\"middle\" font-weight=\"bold\">scene " << xmlEscape(p.scene) << "</text>\n";
        s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\""
          << bottom - top << "\" fill=\"none\" stroke=\"#444\"/>\n";
        for (double l = l0; l <= l1 + 1e-9; l += 1.0) {
            const double x = X(std::pow(10.0, l));
            s << "<line x1=\"" << x << "\" y1=\"" << bottom << "\" x2=\"" << x << "\" y2=\"" << bottom + 5
              << "\" stroke=\"#444\"/><text x=\"" << x << "\" y=\"" << bottom + 18 << "\" text-anchor=\"middle\">"
              << num(std::pow(10.0, l), "%g") << "</text>\n";
        }
        for (int k = 0; k <= 4; ++k) {
            const double e = eTop * k / 4.0, y = Y(e);
            s << "<line x1=\"" << left - 5 << "\" y1=\"" << y << "\" x2=\"" << left << "\" y2=\"" << y
              << "\" stroke=\"#444\"/><text x=\"" << left - 8 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
              << num(e, "%.3f") << "</text>\n";
        }
        s << "<text x=\"" << (left + right) / 2 << "\" y=\"" << bottom + 36
          << "\" text-anchor=\"middle\">median frame time, ms (log scale)</text>\n";
        s << "<text transform=\"translate(" << ox + 16 << ' ' << (top + bottom) / 2
          << ") rotate(-90)\" text-anchor=\"middle\">mean ꟻLIP vs reference</text>\n";
        // The front as a staircase from the fastest to the most accurate point.
        std::vector<Point> front;
        for (const Point& pt : p.points)
            if (pt.front) front.push_back(pt);
        std::sort(front.begin(), front.end(), [](const Point& a, const Point& b) { return a.time < b.time; });
        if (front.size() > 1) {
            s << "<polyline fill=\"none\" stroke=\"#c0392b\" stroke-dasharray=\"4 3\" points=\"";
            for (std::size_t k = 0; k < front.size(); ++k) {
                if (k) s << X(front[k].time) << ',' << Y(front[k - 1].error) << ' ';
                s << X(front[k].time) << ',' << Y(front[k].error) << ' ';
            }
            s << "\"/>\n";
        }
        std::vector<std::pair<double, double>> labels;  // placed label anchors, to keep labels apart
        for (const Point& pt : p.points) {
            const double x = X(pt.time), y = Y(pt.error);
            double labelY = y - 6;
            auto clashes = [&](double ly) {
                return std::any_of(labels.begin(), labels.end(), [&](const auto& l) {
                    return std::abs(l.first - x) < 90 && std::abs(l.second - ly) < 12;
                });
            };
            for (int tries = 0; tries < 12 && clashes(labelY); ++tries) labelY += 13;
            labels.push_back({x, labelY});
            s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" fill=\"" << (pt.front ? "#c0392b" : "white")
              << "\" stroke=\"#c0392b\" stroke-width=\"1.5\"><title>" << xmlEscape(pt.label) << ": "
              << num(pt.time, "%.2f") << " ms, ꟻLIP " << num(pt.error, "%.4f") << "</title></circle>\n";
            s << "<text x=\"" << x + 7 << "\" y=\"" << labelY << "\">" << xmlEscape(pt.label) << "</text>\n";
        }
        s << "</g>\n";
    }
    s << "</svg>\n";
    std::ofstream out = openOut(path);
    out << s.str();
}

}  // namespace bench
