// SPDX-License-Identifier: MIT
#include "bench_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "report_text.hpp"

namespace bench {

namespace {

constexpr double kPanelWidth = 480, kPanelHeight = 360, kMargin = 20, kMarkerRadius = 5;
constexpr double kLabelHeight = 14;                        // 12 px text: ascent + descent, with a pixel of air
constexpr double kLabelBaseline = 11;                      // from the label box's top
constexpr double kBoldFactor = 1.12;                       // bold glyphs are wider than regular ones
constexpr double kTitleFontSize = 15, kHeaderHeight = 56;  // the title line and the legend line

// DejaVu Sans advance widths of printable ASCII (32..126), in 1/2048 em.
constexpr std::array<int, 95> kAdvance{
    651,  821,  942,  1716, 1303, 1946, 1597, 563,  799,  799,  1024, 1716, 651,  739,  651,  690,   // ' '../
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690,  690,  1716, 1716, 1716, 1087,  // 0..?
    2048, 1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604,  604,  1343, 1141, 1767, 1532, 1612,  // @..O
    1235, 1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799,  690,  799,  1716, 1024,  // P.._
    1024, 1255, 1300, 1126, 1300, 1260, 721,  1300, 1298, 569,  569,  1186, 569,  1995, 1298, 1253,  // `..o
    1300, 1300, 842,  1067, 803,  1298, 1212, 1675, 1212, 1212, 1075, 1303, 690,  1303, 1716};       // p..~
constexpr int kWideAdvance = 1843;  // any other character (e.g. ꟻ): 0.9 em

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

std::vector<std::string> distinct(const std::vector<BenchRow>& rows, std::string BenchRow::*field) {
    std::vector<std::string> out;
    for (const BenchRow& r : rows)
        if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
    return out;
}

double BenchRow::*measureField(ChartMeasure m) {
    return m == ChartMeasure::Flip ? &BenchRow::flipMean : &BenchRow::flicker;
}

const char* measureName(ChartMeasure m) { return m == ChartMeasure::Flip ? "ꟻLIP" : "flicker"; }

bool charted(const BenchRow& r, ChartMeasure m = ChartMeasure::Flip) {
    return r.technique != kOpaqueOnly && has(r.timeMedianMs) && r.timeMedianMs > 0.0 && has(r.*measureField(m));
}

// Decade ticks of the log time axis; 2 and 5 between them when the axis spans one decade.
std::vector<double> timeTicks(double log0, double log1) {
    std::vector<double> ticks;
    for (double l = log0; l <= log1 + 1e-9; l += 1.0) {
        const double decade = std::pow(10.0, l);
        ticks.push_back(decade);
        if (log1 - log0 <= 1.0 + 1e-9 && l < log1 - 1e-9) {
            ticks.push_back(2.0 * decade);
            ticks.push_back(5.0 * decade);
        }
    }
    return ticks;
}

// A 1-2-5 step giving about four intervals over [min(0, minValue), maxValue], and the axis
// ends it implies (flicker can be negative: less than the reference's).
struct ErrorAxis {
    double step = 0.25, bottom = 0.0, top = 1.0;
    int decimals = 2;
};
ErrorAxis errorAxis(double minValue, double maxValue) {
    const double low = std::min(0.0, minValue), span = std::max(maxValue, 0.0) - low;
    if (!(span > 0.0)) return {};
    const double raw = span * 1.05 / 4.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10.0 * magnitude;
    for (double m : {1.0, 2.0, 5.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    ErrorAxis axis;
    axis.step = step;
    axis.bottom = low < 0.0 ? std::floor(low * 1.05 / step + 1e-9) * step : 0.0;
    axis.top = std::max(step, std::ceil(std::max(maxValue, 0.0) * 1.05 / step - 1e-9) * step);
    axis.decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
    return axis;
}

std::string fixed(double v, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

// The label box for `text` with its left edge at x and its vertical centre at y.
ChartBox labelBox(const std::string& text, double x, double centreY) {
    return {x, centreY - kLabelHeight / 2, x + chartTextWidth(text, kLabelFontSize), centreY + kLabelHeight / 2};
}

// Distance from a marker's centre to the nearest point of a box.
double distanceTo(const ChartBox& b, double x, double y) {
    const double dx = std::max({b.x0 - x, 0.0, x - b.x1}), dy = std::max({b.y0 - y, 0.0, y - b.y1});
    return std::hypot(dx, dy);
}

// Places each technique's label (at its first backend's marker): beside the marker where that
// is free, else at the free place nearest to it inside the plot (joined by a leader line),
// else under the panel. Free: inside the plot, clear of every marker and every placed label.
void placeLabels(ChartPanel& p) {
    std::vector<ChartBox> taken;
    for (const ChartMarker& m : p.markers) taken.push_back(m.box());
    auto fits = [&](const ChartBox& b) {
        return b.inside(p.plot) &&
               std::none_of(taken.begin(), taken.end(), [&](const ChartBox& t) { return b.overlaps(t); });
    };
    std::vector<std::string> named;
    double overflowBaseline = p.frame.y1 + kLabelHeight;
    for (std::size_t i = 0; i < p.markers.size(); ++i) {
        const ChartMarker& m = p.markers[i];
        if (std::find(named.begin(), named.end(), m.technique) != named.end()) continue;
        named.push_back(m.technique);
        const std::string& text = m.technique;
        const double w = chartTextWidth(text, kLabelFontSize), gap = kMarkerRadius + 3;
        const std::array<ChartBox, 8> beside{
            labelBox(text, m.x + gap, m.y),                                   // right
            labelBox(text, m.x - gap - w, m.y),                               // left
            labelBox(text, m.x - w / 2, m.y - gap - kLabelHeight / 2),        // above
            labelBox(text, m.x - w / 2, m.y + gap + kLabelHeight / 2),        // below
            labelBox(text, m.x + gap - 2, m.y - gap - kLabelHeight / 2 + 2),  // above right
            labelBox(text, m.x + gap - 2, m.y + gap + kLabelHeight / 2 - 2),  // below right
            labelBox(text, m.x - gap + 2 - w, m.y - gap - kLabelHeight / 2 + 2),
            labelBox(text, m.x - gap + 2 - w, m.y + gap + kLabelHeight / 2 - 2)};
        std::optional<ChartLabel> placed;
        for (const ChartBox& b : beside)
            if (fits(b)) {
                placed = ChartLabel{text, b, i, false};
                break;
            }
        if (!placed) {  // the nearest free place on a 2 px grid over the plot
            double best = 1e300;
            for (double y = p.plot.y0 + kLabelHeight / 2; y <= p.plot.y1 - kLabelHeight / 2; y += 2.0)
                for (double x = p.plot.x0; x + w <= p.plot.x1; x += 2.0) {
                    const ChartBox b = labelBox(text, x, y);
                    const double d = distanceTo(b, m.x, m.y);
                    if (d < best && fits(b)) {
                        best = d;
                        placed = ChartLabel{text, b, i, true};
                    }
                }
        }
        if (placed) {
            taken.push_back(placed->box);
            p.labels.push_back(*placed);
        } else {
            p.overflow.push_back({text + ": " + num(m.timeMs, "%.2f") + " ms, " + measureName(p.measure) + " " +
                                      num(m.error, p.measure == ChartMeasure::Flip ? "%.4f" : "%.5f"),
                                  p.frame.x0 + 8, overflowBaseline});
            overflowBaseline += kLabelHeight;
        }
    }
    if (!p.overflow.empty()) p.frame.y1 = overflowBaseline;
}

ChartPanel layoutPanel(const std::string& scene, ChartMeasure measure, const std::vector<BenchRow>& rows,
                       const std::vector<std::string>& backends) {
    ChartPanel p;
    p.scene = scene;
    p.measure = measure;
    for (const std::string& backend : backends)
        for (const BenchRow& r : rows)
            if (r.scene == scene && r.backend == backend && charted(r, measure))
                p.markers.push_back({r.technique, r.backend, r.timeMedianMs, r.*measureField(measure), 0, 0, false});
    for (ChartMarker& a : p.markers)  // Pareto front per backend: nothing as fast and as accurate, and better in one
        a.onFront = std::none_of(p.markers.begin(), p.markers.end(), [&](const ChartMarker& b) {
            const double ea = std::abs(a.error), eb = std::abs(b.error);
            return b.backend == a.backend && b.timeMs <= a.timeMs && eb <= ea && (b.timeMs < a.timeMs || eb < ea);
        });

    double tMin = 1e300, tMax = 0.0, eMin = 0.0, eMax = 0.0;
    for (const ChartMarker& m : p.markers) {
        tMin = std::min(tMin, m.timeMs);
        tMax = std::max(tMax, m.timeMs);
        eMin = std::min(eMin, m.error);
        eMax = std::max(eMax, m.error);
    }
    const double log0 = std::floor(std::log10(tMin)), log1 = std::max(log0 + 1.0, std::ceil(std::log10(tMax)));
    const ErrorAxis axis = errorAxis(eMin, eMax);
    double tickWidth = 0.0;
    for (int k = 0; axis.bottom + k * axis.step <= axis.top + axis.step / 2; ++k) {
        const double v = std::abs(axis.bottom + k * axis.step) < axis.step / 2 ? 0.0 : axis.bottom + k * axis.step;
        p.yTicks.push_back({v, fixed(v, axis.decimals)});
        tickWidth = std::max(tickWidth, chartTextWidth(p.yTicks.back().text, kLabelFontSize));
    }
    p.frame = {0, 0, kPanelWidth, kPanelHeight};
    // Left: the rotated axis title (a text line), the tick texts, the tick marks.
    p.plot = {kLabelHeight + 12 + tickWidth + 8, 28, kPanelWidth - 24, kPanelHeight - 52};
    auto X = [&](double t) { return p.plot.x0 + (std::log10(t) - log0) / (log1 - log0) * (p.plot.x1 - p.plot.x0); };
    auto Y = [&](double e) {
        return p.plot.y1 - (e - axis.bottom) / (axis.top - axis.bottom) * (p.plot.y1 - p.plot.y0);
    };
    for (ChartTick& t : p.yTicks) t.at = Y(t.at);
    for (double t : timeTicks(log0, log1)) p.xTicks.push_back({X(t), num(t, "%g")});
    for (ChartMarker& m : p.markers) {
        m.x = X(m.timeMs);
        m.y = Y(m.error);
    }
    placeLabels(p);
    return p;
}

// A legend entry: the backend's marker, its name, space before the next.
double legendEntryWidth(const std::string& backend) {
    return 2 * kMarkerRadius + 4 + chartTextWidth(backend, kLabelFontSize) + 16;
}

std::string backendColor(std::size_t index) {
    static const char* colors[] = {"#c0392b", "#1f618d", "#1e8449", "#7d3c98"};
    return colors[index % 4];
}

// A marker's shape: a circle for the first backend, a square for the second, a diamond after.
void drawMarker(std::ostringstream& s, std::size_t backend, double x, double y, bool filled, const std::string& title) {
    const std::string color = backendColor(backend), fill = filled ? color : "white";
    const double r = kMarkerRadius;
    if (backend == 0) s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"" << r << "\"";
    else if (backend == 1)
        s << "<rect x=\"" << x - r << "\" y=\"" << y - r << "\" width=\"" << 2 * r << "\" height=\"" << 2 * r << "\"";
    else
        s << "<polygon points=\"" << x << ',' << y - r << ' ' << x + r << ',' << y << ' ' << x << ',' << y + r << ' '
          << x - r << ',' << y << "\"";
    s << " fill=\"" << fill << "\" stroke=\"" << color << "\" stroke-width=\"1.5\">";
    if (!title.empty()) s << "<title>" << xmlEscape(title) << "</title>";
    s << "</" << (backend == 0 ? "circle" : backend == 1 ? "rect" : "polygon") << ">\n";
}

void drawPanel(std::ostringstream& s, const Chart& chart, const ChartPanel& p) {
    const ChartBox& q = p.plot;
    s << "<g transform=\"translate(" << p.originX << ' ' << p.originY << ")\">\n";
    s << "<text x=\"" << (q.x0 + q.x1) / 2 << "\" y=\"16\" text-anchor=\"middle\" font-weight=\"bold\">scene "
      << xmlEscape(p.scene) << ": " << measureName(p.measure) << "</text>\n";
    s << "<rect x=\"" << q.x0 << "\" y=\"" << q.y0 << "\" width=\"" << q.x1 - q.x0 << "\" height=\"" << q.y1 - q.y0
      << "\" fill=\"none\" stroke=\"#444\"/>\n";
    for (const ChartTick& t : p.xTicks)
        s << "<line x1=\"" << t.at << "\" y1=\"" << q.y1 << "\" x2=\"" << t.at << "\" y2=\"" << q.y1 + 5
          << "\" stroke=\"#444\"/><text x=\"" << t.at << "\" y=\"" << q.y1 + 18 << "\" text-anchor=\"middle\">"
          << t.text << "</text>\n";
    for (const ChartTick& t : p.yTicks)
        s << "<line x1=\"" << q.x0 - 5 << "\" y1=\"" << t.at << "\" x2=\"" << q.x0 << "\" y2=\"" << t.at
          << "\" stroke=\"#444\"/><text x=\"" << q.x0 - 8 << "\" y=\"" << t.at + 4 << "\" text-anchor=\"end\">"
          << t.text << "</text>\n";
    s << "<text x=\"" << (q.x0 + q.x1) / 2 << "\" y=\"" << q.y1 + 36
      << "\" text-anchor=\"middle\">median frame time, ms (log scale)</text>\n";
    s << "<text transform=\"translate(" << kLabelHeight << ' ' << (q.y0 + q.y1) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">"
      << (p.measure == ChartMeasure::Flip ? "mean ꟻLIP vs reference" : "flicker of a pan, minus the reference's")
      << "</text>\n";

    for (std::size_t b = 0; b < chart.backends.size(); ++b) {
        std::vector<const ChartMarker*> front;
        for (const ChartMarker& m : p.markers)
            if (m.backend == chart.backends[b] && m.onFront) front.push_back(&m);
        std::sort(front.begin(), front.end(), [](const ChartMarker* a, const ChartMarker* c) { return a->x < c->x; });
        if (front.size() < 2) continue;
        s << "<polyline fill=\"none\" stroke=\"" << backendColor(b) << "\" stroke-dasharray=\"4 3\" points=\"";
        for (std::size_t k = 0; k < front.size(); ++k) {
            if (k) s << front[k]->x << ',' << front[k - 1]->y << ' ';
            s << front[k]->x << ',' << front[k]->y << ' ';
        }
        s << "\"/>\n";
    }
    // One technique on several backends: a grey line through its markers.
    for (std::size_t i = 0; i < p.markers.size(); ++i)
        for (std::size_t j = i + 1; j < p.markers.size(); ++j)
            if (p.markers[j].technique == p.markers[i].technique)
                s << "<line x1=\"" << p.markers[i].x << "\" y1=\"" << p.markers[i].y << "\" x2=\"" << p.markers[j].x
                  << "\" y2=\"" << p.markers[j].y << "\" stroke=\"#bbb\"/>\n";
    for (const ChartLabel& l : p.labels) {
        if (!l.leader) continue;
        const ChartMarker& m = p.markers[l.marker];
        const double x = std::clamp(m.x, l.box.x0, l.box.x1), y = std::clamp(m.y, l.box.y0, l.box.y1);
        s << "<line x1=\"" << m.x << "\" y1=\"" << m.y << "\" x2=\"" << x << "\" y2=\"" << y
          << "\" stroke=\"#333\" stroke-width=\"0.75\" stroke-dasharray=\"1 2\"/>\n";
    }
    for (const ChartMarker& m : p.markers) {
        const auto b =
            std::size_t(std::find(chart.backends.begin(), chart.backends.end(), m.backend) - chart.backends.begin());
        drawMarker(s, b, m.x, m.y, m.onFront,
                   m.technique + " (" + m.backend + "): " + num(m.timeMs, "%.2f") + " ms, " + measureName(p.measure) +
                       " " + num(m.error, p.measure == ChartMeasure::Flip ? "%.4f" : "%.5f"));
    }
    for (const ChartLabel& l : p.labels)
        s << "<text x=\"" << l.box.x0 << "\" y=\"" << l.box.y0 + kLabelBaseline << "\">" << xmlEscape(l.text)
          << "</text>\n";
    for (const ChartOverflow& o : p.overflow)
        s << "<text x=\"" << o.x << "\" y=\"" << o.baseline << "\">" << xmlEscape(o.text) << "</text>\n";
    s << "</g>\n";
}

}  // namespace

bool ChartBox::overlaps(const ChartBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
bool ChartBox::inside(const ChartBox& o) const { return x0 >= o.x0 && x1 <= o.x1 && y0 >= o.y0 && y1 <= o.y1; }

ChartBox ChartMarker::box() const {
    const double r = kMarkerRadius + 1;  // half the 1.5 px stroke, rounded up
    return {x - r, y - r, x + r, y + r};
}

double chartTextWidth(const std::string& text, double fontSize) {
    int units = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 32 && c < 127) units += kAdvance[c - 32];
        else if ((c & 0xC0) != 0x80) units += kWideAdvance;  // the first byte of any other UTF-8 character
    }
    return units * fontSize / 2048.0 * 1.03;  // a little air for hinting and other fonts' kerning
}

Chart layoutChart(const std::vector<BenchRow>& rows) {
    Chart chart;
    for (const BenchRow& r : rows)
        if (charted(r) && std::find(chart.backends.begin(), chart.backends.end(), r.backend) == chart.backends.end())
            chart.backends.push_back(r.backend);
    // One row per scene: its ꟻLIP panel, then its flicker panel where it has one.
    std::vector<std::size_t> rowStarts;
    for (const std::string& scene : distinct(rows, &BenchRow::scene))
        for (ChartMeasure measure : {ChartMeasure::Flip, ChartMeasure::Flicker}) {
            const bool any = std::any_of(rows.begin(), rows.end(),
                                         [&](const BenchRow& r) { return r.scene == scene && charted(r, measure); });
            if (!any) continue;
            if (measure == ChartMeasure::Flip || chart.panels.empty() || chart.panels.back().scene != scene)
                rowStarts.push_back(chart.panels.size());
            chart.panels.push_back(layoutPanel(scene, measure, rows, chart.backends));
        }

    std::string backends;
    for (std::size_t b = 0; b < chart.backends.size(); ++b)
        backends += (b ? (b + 1 == chart.backends.size() ? " and " : ", ") : "") + chart.backends[b];
    const bool flicker = std::any_of(chart.panels.begin(), chart.panels.end(),
                                     [](const ChartPanel& p) { return p.measure == ChartMeasure::Flicker; });
    chart.header.push_back(std::string("ssam-bench: frame time against ꟻLIP error") + (flicker ? " and flicker" : "") +
                           ", " + (backends.empty() ? std::string("no backend") : backends) + " backend" +
                           (chart.backends.size() > 1 ? "s" : ""));
    chart.header.push_back(chart.panels.empty()
                               ? "no error data: the exact reference was not available in this run"
                               : "filled: on that backend's Pareto front (dashed); grey lines join one technique");

    int cols = 1;
    double y = kMargin + kHeaderHeight;
    for (std::size_t i = 0; i < rowStarts.size(); ++i) {
        const std::size_t end = i + 1 < rowStarts.size() ? rowStarts[i + 1] : chart.panels.size();
        cols = std::max(cols, int(end - rowStarts[i]));
        double rowHeight = 0;
        for (std::size_t k = rowStarts[i]; k < end; ++k) {
            chart.panels[k].originX = kMargin + double(k - rowStarts[i]) * kPanelWidth;
            chart.panels[k].originY = y;
            rowHeight = std::max(rowHeight, chart.panels[k].frame.y1);
        }
        y += rowHeight;
    }
    double legendWidth = chartTextWidth(chart.header[1], kLabelFontSize);
    for (const std::string& b : chart.backends) legendWidth += legendEntryWidth(b);
    const double headerWidth = std::max(chartTextWidth(chart.header[0], kTitleFontSize) * kBoldFactor, legendWidth);
    chart.width = std::max(cols * kPanelWidth, headerWidth) + 2 * kMargin;
    chart.height = y + kMargin;
    return chart;
}

std::string chartSvg(const Chart& chart) {
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << chart.width << "\" height=\"" << chart.height
      << "\" viewBox=\"0 0 " << chart.width << ' ' << chart.height
      << "\" font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"12\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << kMargin << "\" y=\"" << kMargin + 14 << "\" font-size=\"" << kTitleFontSize
      << "\" font-weight=\"bold\">" << xmlEscape(chart.header[0]) << "</text>\n";
    // Legend: one marker per backend, then the second header line.
    double x = kMargin;
    const double legendY = kMargin + 36;
    for (std::size_t b = 0; b < chart.backends.size(); ++b) {
        drawMarker(s, b, x + kMarkerRadius, legendY - 4, true, "");
        s << "<text x=\"" << x + 2 * kMarkerRadius + 4 << "\" y=\"" << legendY << "\">" << xmlEscape(chart.backends[b])
          << "</text>\n";
        x += legendEntryWidth(chart.backends[b]);
    }
    s << "<text x=\"" << x << "\" y=\"" << legendY << "\">" << xmlEscape(chart.header[1]) << "</text>\n";
    for (const ChartPanel& p : chart.panels) drawPanel(s, chart, p);
    s << "</svg>\n";
    return s.str();
}

void writeSvg(std::ostream& out, const std::vector<BenchRow>& rows) { out << chartSvg(layoutChart(rows)); }

}  // namespace bench
