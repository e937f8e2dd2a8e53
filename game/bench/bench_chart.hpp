// SPDX-License-Identifier: MIT
#pragma once
// bench.svg: median frame time (log axis) against mean ꟻLIP error and, where the scene has a
// pan, against flicker ([Hathaway 2010] §3.4: the change of luma between frames of a pan,
// minus the reference's): one row per scene, the ꟻLIP panel left and the flicker panel right,
// every backend of the run in each panel (soft: circles, gl: squares; a grey line joins one
// technique's markers). Filled markers lie on their backend's Pareto front (for flicker, of
// its magnitude: less flicker than the reference is no better than as much), which a dashed
// staircase joins.
//
// The chart is laid out first (layoutChart: every mark and label as a box in SVG units) and
// drawn from that layout (chartSvg), so what the unit test checks is what is drawn: no label
// overlaps another label or a marker, every label stays inside its plot and its panel, no two
// ticks of an axis read the same. A label that finds no free place near its marker is drawn
// further away with a line to it, or, if the plot has no room left at all, listed under the
// panel.
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "bench_result.hpp"

namespace bench {

// An axis-aligned box in SVG user units (y grows downwards).
struct ChartBox {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    bool overlaps(const ChartBox& other) const;
    bool inside(const ChartBox& outer) const;
};

struct ChartTick {
    double at = 0.0;  // x (time axis) or y (error axis) in the panel
    std::string text;
};

struct ChartMarker {
    std::string technique, backend;
    double timeMs = 0.0, error = 0.0;  // error: the panel's measure (ꟻLIP or flicker)
    double x = 0.0, y = 0.0;           // centre
    bool onFront = false;              // on its backend's Pareto front in this scene
    ChartBox box() const;              // the drawn shape, stroke included
};

struct ChartLabel {
    std::string text;
    ChartBox box;            // the text's extent (chartTextWidth; font size kLabelFontSize)
    std::size_t marker = 0;  // index of the marker it names
    bool leader = false;     // placed away from the marker: a line joins them
};

// A technique named under the panel because the plot had no free place for its label.
struct ChartOverflow {
    std::string text;
    double x = 0.0, baseline = 0.0;
};

// What a panel's vertical axis shows.
enum class ChartMeasure { Flip, Flicker };

struct ChartPanel {
    std::string scene;
    ChartMeasure measure = ChartMeasure::Flip;
    double originX = 0.0, originY = 0.0;  // where the panel sits in the chart; boxes are panel-local
    ChartBox frame, plot;
    std::vector<ChartTick> xTicks, yTicks;
    std::vector<ChartMarker> markers;
    std::vector<ChartLabel> labels;
    std::vector<ChartOverflow> overflow;
};

struct Chart {
    double width = 0.0, height = 0.0;
    std::vector<std::string> backends;  // in the order of the run; each has its own shape
    std::vector<ChartPanel> panels;
    std::vector<std::string> header;  // title and legend lines
};

inline constexpr double kLabelFontSize = 12.0;

// Width in px of `text` set at `fontSize` px in DejaVu Sans, the widest of the common default
// sans-serif fonts, so a box reserved with it holds the text in any of them.
double chartTextWidth(const std::string& text, double fontSize);

// Rows that did not run or have no error are left out; so is the opaque-only frame. A
// scene's flicker panel holds the rows with a flicker value; a scene without any has none.
Chart layoutChart(const std::vector<BenchRow>& rows);
std::string chartSvg(const Chart& chart);
void writeSvg(std::ostream& out, const std::vector<BenchRow>& rows);

}  // namespace bench
