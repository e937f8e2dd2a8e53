// SPDX-License-Identifier: MIT
// bench.svg's layout (bench_chart.hpp): labels never overlap one another or a marker and stay
// inside their plot and panel, every technique is named once per scene, axis ticks never read
// the same twice, every backend of the run is drawn, and the SVG shows what the layout placed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bench_chart.hpp"
#include "lcg.hpp"

namespace {

using namespace bench;

const std::vector<std::string> kTechniques{"ssam",           "ssam-plus",    "alpha-test", "a2c",
                                           "blend-unsorted", "blend-sorted", "wboit",      "reference"};

BenchRow row(const std::string& scene, const std::string& technique, const std::string& backend, double ms,
             double flip) {
    BenchRow r;
    r.scene = scene;
    r.technique = technique;
    r.backend = backend;
    r.ran = true;
    r.timeMedianMs = ms;
    r.flipMean = flip;
    return r;
}

std::string describe(const ChartBox& b) {
    std::ostringstream text;  // not "[" + std::to_string(...): GCC 12 -O3 warns falsely (-Wrestrict)
    text << '[' << b.x0 << ", " << b.y0 << " .. " << b.x1 << ", " << b.y1 << ']';
    return text.str();
}

// Every property the chart promises, for one layout.
void expectReadable(const Chart& chart, const std::vector<BenchRow>& rows, const std::string& what) {
    SCOPED_TRACE(what);
    // The bold 15 px title, then the legend: a marker and name per backend, then its text.
    EXPECT_LE(2 * 20 + chartTextWidth(chart.header[0], 15) * 1.12, chart.width + 1e-9) << chart.header[0];
    double legend = chartTextWidth(chart.header[1], kLabelFontSize);
    for (const std::string& b : chart.backends) legend += 2 * 5 + 4 + chartTextWidth(b, kLabelFontSize) + 16;
    EXPECT_LE(2 * 20 + legend, chart.width + 1e-9) << chart.header[1];
    for (const ChartPanel& p : chart.panels) {
        SCOPED_TRACE("scene " + p.scene);
        EXPECT_GE(p.originX, 0.0);
        EXPECT_LE(p.originX + p.frame.x1, chart.width);
        EXPECT_LE(p.originY + p.frame.y1, chart.height);
        EXPECT_TRUE(p.plot.inside(p.frame));
        for (std::size_t i = 0; i < p.labels.size(); ++i) {
            const ChartLabel& a = p.labels[i];
            EXPECT_TRUE(a.box.inside(p.plot))
                << a.text << " " << describe(a.box) << " leaves the plot " << describe(p.plot);
            EXPECT_NEAR(a.box.x1 - a.box.x0, chartTextWidth(a.text, kLabelFontSize), 1e-9) << a.text;
            for (std::size_t j = i + 1; j < p.labels.size(); ++j)
                EXPECT_FALSE(a.box.overlaps(p.labels[j].box)) << a.text << " " << describe(a.box) << " overlaps "
                                                              << p.labels[j].text << " " << describe(p.labels[j].box);
            for (const ChartMarker& m : p.markers)
                EXPECT_FALSE(a.box.overlaps(m.box()))
                    << a.text << " covers the marker of " << m.technique << " (" << m.backend << ")";
            ASSERT_LT(a.marker, p.markers.size());
            EXPECT_EQ(p.markers[a.marker].technique, a.text);
        }
        for (const ChartOverflow& o : p.overflow) {
            EXPECT_GE(o.baseline, p.plot.y1 + 36) << "under the axis title";
            EXPECT_LE(o.baseline, p.frame.y1);
            EXPECT_LE(o.x + chartTextWidth(o.text, kLabelFontSize), p.frame.x1) << o.text;
        }
        // Each technique of the scene is named exactly once, by a label or under the panel.
        std::multiset<std::string> named;
        for (const ChartLabel& l : p.labels) named.insert(l.text);
        for (const ChartOverflow& o : p.overflow) named.insert(o.text.substr(0, o.text.find(':')));
        std::set<std::string> techniques;
        for (const ChartMarker& m : p.markers) techniques.insert(m.technique);
        EXPECT_EQ(named.size(), techniques.size());
        for (const std::string& t : techniques) EXPECT_EQ(named.count(t), 1u) << t;
        // Ticks: distinct texts, ordered positions, texts that do not collide, markers on the plot.
        for (const auto* ticks : {&p.xTicks, &p.yTicks}) {
            std::set<std::string> texts;
            for (const ChartTick& t : *ticks)
                EXPECT_TRUE(texts.insert(t.text).second) << "tick '" << t.text << "' twice";
            EXPECT_GE(ticks->size(), 2u);
        }
        for (std::size_t k = 1; k < p.xTicks.size(); ++k) {
            const double gap = p.xTicks[k].at - p.xTicks[k - 1].at;
            EXPECT_GT(gap, (chartTextWidth(p.xTicks[k].text, kLabelFontSize) +
                            chartTextWidth(p.xTicks[k - 1].text, kLabelFontSize)) /
                               2)
                << p.xTicks[k - 1].text << " and " << p.xTicks[k].text << " collide";
        }
        for (std::size_t k = 1; k < p.yTicks.size(); ++k) EXPECT_LT(p.yTicks[k].at, p.yTicks[k - 1].at - 14.0);
        EXPECT_GE(p.xTicks.front().at, p.plot.x0 - 1e-9);
        EXPECT_LE(p.xTicks.back().at + chartTextWidth(p.xTicks.back().text, kLabelFontSize) / 2, p.frame.x1);
        for (const ChartMarker& m : p.markers) {
            EXPECT_GE(m.x, p.plot.x0 - 1e-9);
            EXPECT_LE(m.x, p.plot.x1 + 1e-9);
            EXPECT_GE(m.y, p.plot.y0 - 1e-9);
            EXPECT_LE(m.y, p.plot.y1 + 1e-9);
        }
    }
    // Every charted row is a marker of its scene's panel of each measure it has.
    std::size_t charted = 0, chartedFlicker = 0, markers = 0, flickerMarkers = 0;
    for (const BenchRow& r : rows) {
        charted += r.technique != kOpaqueOnly && has(r.timeMedianMs) && has(r.flipMean);
        chartedFlicker += r.technique != kOpaqueOnly && has(r.timeMedianMs) && has(r.flicker);
    }
    for (const ChartPanel& p : chart.panels)
        (p.measure == ChartMeasure::Flip ? markers : flickerMarkers) += p.markers.size();
    EXPECT_EQ(markers, charted);
    EXPECT_EQ(flickerMarkers, chartedFlicker);
}

TEST(BenchChart, BothBackendsOfARunAreDrawnAndNamed) {
    std::vector<BenchRow> rows;
    for (const std::string backend : {"soft", "gl"})
        for (std::size_t t = 0; t < kTechniques.size(); ++t)
            rows.push_back(row("forest", kTechniques[t], backend,
                               100.0 + 40.0 * double(t) + (backend == "gl" ? -70 : 0), 0.02 + 0.01 * double(t)));
    rows.push_back(row("forest", kOpaqueOnly, "soft", 20.0, 0.4));
    const Chart chart = layoutChart(rows);
    ASSERT_EQ(chart.backends, (std::vector<std::string>{"soft", "gl"}));
    EXPECT_NE(chart.header[0].find("soft and gl backends"), std::string::npos) << chart.header[0];
    ASSERT_EQ(chart.panels.size(), 1u);
    EXPECT_EQ(chart.panels[0].markers.size(), 2 * kTechniques.size());  // opaque-only is not charted
    expectReadable(chart, rows, "two backends");
    const std::string svg = chartSvg(chart);
    EXPECT_NE(svg.find("<circle"), std::string::npos);   // soft
    EXPECT_NE(svg.find("<rect x="), std::string::npos);  // gl's squares
}

// The layout the README's chart had trouble with: techniques at the same error and close times.
TEST(BenchChart, CoincidentAndCrowdedPointsKeepTheirLabelsApart) {
    std::vector<BenchRow> rows;
    for (const std::string backend : {"soft", "gl"})
        for (std::size_t t = 0; t < kTechniques.size(); ++t)
            rows.push_back(row("tree", kTechniques[t], backend, 100.0 + double(t), t == 4 || t == 5 ? 0.1049 : 0.05));
    expectReadable(layoutChart(rows), rows, "crowded");
}

TEST(BenchChart, ExtremeRangesGiveDistinctTicks) {
    const std::vector<std::pair<double, double>> timeRanges{{0.013, 0.019}, {100, 300}, {0.01, 9000}, {5, 5}};
    const std::vector<std::pair<double, double>> errorRanges{
        {0, 0}, {0.0001, 0.0004}, {0.3, 0.31}, {1e-7, 2e-7}, {0.02, 0.9}};
    for (const auto& [t0, t1] : timeRanges)
        for (const auto& [e0, e1] : errorRanges) {
            std::vector<BenchRow> rows;
            for (std::size_t t = 0; t < kTechniques.size(); ++t) {
                const double f = double(t) / double(kTechniques.size() - 1);
                rows.push_back(row("vista", kTechniques[t], "soft", t0 * std::pow(t1 / t0, f), e0 + (e1 - e0) * f));
            }
            expectReadable(layoutChart(rows), rows,
                           "times " + std::to_string(t0) + ".." + std::to_string(t1) + ", errors " +
                               std::to_string(e0) + ".." + std::to_string(e1));
        }
}

TEST(BenchChart, RandomRunsStayReadable) {
    ssam::testing::Lcg lcg{15};
    for (int run = 0; run < 150; ++run) {
        std::vector<BenchRow> rows;
        const int scenes = 1 + int(lcg.next() % 4);
        const double t0 = std::pow(10.0, lcg.range(-2.0f, 3.0f)), spread = std::pow(10.0, lcg.range(0.0f, 3.0f));
        const double eMax = std::pow(10.0, lcg.range(-5.0f, 0.0f));
        for (int s = 0; s < scenes; ++s)
            for (const std::string backend : {"soft", "gl"})
                for (const std::string& technique : kTechniques)
                    if (lcg.unit() < 0.9f) {  // some rows missing, as when a technique did not run
                        rows.push_back(row("scene" + std::to_string(s), technique, backend,
                                           t0 * std::pow(spread, lcg.unit()), eMax * lcg.unit()));
                        if (s % 2 == 0) rows.back().flicker = eMax * (lcg.unit() - 0.3);  // a pan: flicker too
                    }
        expectReadable(layoutChart(rows), rows, "random run " + std::to_string(run));
        if (HasFailure()) return;
    }
}

TEST(BenchChart, AnOverfullPlotListsTheRestUnderThePanel) {
    std::vector<BenchRow> rows;
    for (int t = 0; t < 60; ++t)  // far more labels than the plot holds
        rows.push_back(row("forest", "technique-with-a-long-name-" + std::to_string(t), "soft", 10.0 + t, 0.01 * t));
    const Chart chart = layoutChart(rows);
    ASSERT_EQ(chart.panels.size(), 1u);
    EXPECT_FALSE(chart.panels[0].overflow.empty());
    expectReadable(chart, rows, "overfull");
}

TEST(BenchChart, TheSvgDrawsEachLabelWhereTheLayoutPlacedIt) {
    std::vector<BenchRow> rows;
    for (const std::string backend : {"soft", "gl"})
        for (std::size_t t = 0; t < kTechniques.size(); ++t)
            rows.push_back(row("forest", kTechniques[t], backend, 50.0 * double(t + 1), 0.1 - 0.01 * double(t)));
    const Chart chart = layoutChart(rows);
    const std::string svg = chartSvg(chart);
    for (const ChartLabel& l : chart.panels[0].labels) {
        std::ostringstream text;
        text << "<text x=\"" << l.box.x0 << "\" y=\"" << l.box.y0 + 11 << "\">" << l.text << "</text>";
        EXPECT_NE(svg.find(text.str()), std::string::npos) << text.str();
    }
    for (const ChartTick& t : chart.panels[0].yTicks) EXPECT_NE(svg.find(">" + t.text + "</text>"), std::string::npos);
    EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
}

// A scene with a pan gets a flicker panel right of its ꟻLIP panel; flicker below the
// reference's (negative) stays on the plot, under a tick for zero, and its magnitude decides
// the Pareto front.
TEST(BenchChart, FlickerHasItsOwnPanelBesideTheScenesErrorPanel) {
    std::vector<BenchRow> rows;
    for (const std::string scene : {"forest", "vista"})
        for (std::size_t t = 0; t < kTechniques.size(); ++t) {
            BenchRow r = row(scene, kTechniques[t], "soft", 50.0 * double(t + 1), 0.1 - 0.01 * double(t));
            if (scene == "forest") r.flicker = (t % 2 ? -0.0004 : 0.003) * double(t + 1);
            rows.push_back(r);
        }
    rows[0].flicker = -0.0001;  // ssam: fastest, and the least flicker in magnitude
    const Chart chart = layoutChart(rows);
    ASSERT_EQ(chart.panels.size(), 3u);
    EXPECT_EQ(chart.panels[0].measure, ChartMeasure::Flip);
    EXPECT_EQ(chart.panels[1].measure, ChartMeasure::Flicker);
    EXPECT_EQ(chart.panels[1].scene, "forest");
    EXPECT_EQ(chart.panels[1].originY, chart.panels[0].originY);
    EXPECT_GT(chart.panels[1].originX, chart.panels[0].originX);
    EXPECT_EQ(chart.panels[2].scene, "vista");
    EXPECT_GT(chart.panels[2].originY, chart.panels[0].originY);
    EXPECT_NE(chart.header[0].find("flicker"), std::string::npos);
    const ChartPanel& f = chart.panels[1];
    EXPECT_LT(std::stod(f.yTicks.front().text), 0.0);
    EXPECT_TRUE(
        std::any_of(f.yTicks.begin(), f.yTicks.end(), [](const ChartTick& t) { return std::stod(t.text) == 0.0; }));
    for (const ChartMarker& m : f.markers) EXPECT_EQ(m.onFront, m.technique == "ssam") << m.technique;
    expectReadable(chart, rows, "flicker");
    EXPECT_NE(chartSvg(chart).find("flicker of a pan, minus the reference's"), std::string::npos);
}

TEST(BenchChart, NoErrorDataSaysSo) {
    BenchRow r = row("tree", "ssam", "soft", 10.0, kMissing);
    const Chart chart = layoutChart({r});
    EXPECT_TRUE(chart.panels.empty());
    EXPECT_NE(chartSvg(chart).find("no error data"), std::string::npos);
}

}  // namespace
