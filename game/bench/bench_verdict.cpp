// SPDX-License-Identifier: MIT
#include "bench_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "bench_goals.hpp"
#include "report_text.hpp"

namespace bench {

namespace {

// One line of the table: a measure on a scene (or a motion), each technique's value.
struct Line {
    std::string where, measure;
    const char* format;
    bool magnitude;              // signed measures (flicker less the reference's): the lower |value| is better
    std::vector<double> values;  // ssam, then kShippedTechniques; kMissing where not measured
};

std::vector<std::string> columns() {
    std::vector<std::string> names{"ssam"};
    for (const char* t : kShippedTechniques) names.push_back(t);
    return names;
}

// The techniques sharing the lowest value of `line` (empty when fewer than two were measured).
std::vector<std::string> lowest(const Line& line, const std::vector<std::string>& names) {
    double best = kMissing;
    int measuredCount = 0;
    for (double v : line.values)
        if (has(v)) {
            ++measuredCount;
            const double k = line.magnitude ? std::abs(v) : v;
            if (!has(best) || k < best) best = k;
        }
    std::vector<std::string> out;
    if (measuredCount < 2) return out;
    for (std::size_t i = 0; i < line.values.size(); ++i)
        if (has(line.values[i]) && (line.magnitude ? std::abs(line.values[i]) : line.values[i]) == best)
            out.push_back(names[i]);
    return out;
}

template <class Row>
struct Measure {
    const char* name;
    double Row::*field;
    const char* format;
};

// One line per place and measure, with each technique's value where `find(place, technique)`
// gives a row; lines no technique measured are left out.
template <class Row, class Find>
std::vector<Line> linesOf(const std::vector<std::string>& places, const std::vector<Measure<Row>>& measures,
                          const std::vector<std::string>& names, double Row::*signedField, Find find) {
    std::vector<Line> lines;
    for (const std::string& where : places)
        for (const Measure<Row>& m : measures) {
            Line line{where, m.name, m.format, m.field == signedField, {}};
            for (const std::string& t : names) {
                const Row* r = find(where, t);
                line.values.push_back(r ? r->*m.field : kMissing);
            }
            if (std::any_of(line.values.begin(), line.values.end(), has)) lines.push_back(line);
        }
    return lines;
}

// `where(row)` of each row, once each, in the rows' order.
template <class Row, class Where>
std::vector<std::string> placesOf(const std::vector<Row>& rows, Where where) {
    std::vector<std::string> places;
    for (const Row& r : rows)
        if (std::find(places.begin(), places.end(), where(r)) == places.end()) places.push_back(where(r));
    return places;
}

std::vector<Line> stillLines(const std::vector<BenchRow>& rows, const std::vector<std::string>& names) {
    const std::vector<Measure<BenchRow>> measures = {{"time ms", &BenchRow::timeMedianMs, "%.2f"},
                                                     {"ꟻLIP, still frame", &BenchRow::flipMean, "%.4f"},
                                                     {"ꟻLIP, pan converged", &BenchRow::temporalFlip, "%.4f"},
                                                     {"ꟻLIP, pan worst frame", &BenchRow::temporalFlipWorst, "%.4f"},
                                                     {"RMSE, pan converged", &BenchRow::temporalRmse, "%.5f"},
                                                     {"flicker, pan", &BenchRow::flicker, "%.5f"},
                                                     {"memory MiB", &BenchRow::peakMemMb, "%.1f"}};
    const std::string backend = primaryBackend(rows);
    return linesOf(placesOf(rows, [](const BenchRow& r) { return r.scene; }), measures, names, &BenchRow::flicker,
                   [&](const std::string& scene, const std::string& t) { return findRow(rows, scene, t, backend); });
}

std::vector<Line> motionLines(const std::vector<MotionRow>& motion, const std::vector<std::string>& names) {
    const std::vector<Measure<MotionRow>> measures = {{"ꟻLIP converged", &MotionRow::flip, "%.4f"},
                                                      {"ꟻLIP worst frame", &MotionRow::flipWorst, "%.4f"},
                                                      {"ghosting converged", &MotionRow::ghost, "%.4f"},
                                                      {"flicker", &MotionRow::flicker, "%.5f"}};
    auto where = [](const MotionRow& r) { return r.scene + " " + r.motion; };
    return linesOf(placesOf(motion, where), measures, names, &MotionRow::flicker,
                   [&](const std::string& place, const std::string& t) -> const MotionRow* {
                       for (const MotionRow& r : motion)
                           if (where(r) == place && r.technique == t) return &r;
                       return nullptr;
                   });
}

}  // namespace

void writeWhatEnginesShip(std::ostream& out, const std::vector<BenchRow>& rows, const std::vector<MotionRow>& motion,
                          const std::string& rowsPage) {
    const std::vector<std::string> names = columns();
    out << "## SSAM and what engines ship\n\n"
           "Technique `ssam` (its preset above) beside what engines ship for alpha-tested foliage at full "
           "strength: `hashed+taa` (hashed alpha testing [Wyman & McGuire 2017] resolved by the temporal pass "
           "with motion vectors [Karis 2014]), `alpha-test+taa` (alpha testing resolved by the same pass) and "
           "`a2c-sharp` (4x alpha to coverage with the alpha sharpened by its screen-space derivative "
           "[Golus 2017]), on the "
        << primaryBackend(rows)
        << " backend. The still frame, the pan, time and memory come from the comparison ([SSAM against its "
           "rivals]("
        << rowsPage << "#ssam-against-its-rivals)); each motion of the forest from the run in [In motion](" << rowsPage
        << "#in-motion). The last column names the lowest (better); "
           "flicker compares magnitudes (below the reference's is smoothing, not steadiness). Memory counts the "
           "temporal pass's history and the multisampled targets.\n\n"
           "| where | measure |";
    for (const std::string& t : names) out << " " << t << " |";
    out << " lowest |\n|---|---|";
    for (std::size_t i = 0; i < names.size(); ++i) out << "---:|";
    out << "---|\n";
    std::vector<Line> lines = stillLines(rows, names);
    for (Line& l : motionLines(motion, names)) lines.push_back(std::move(l));
    // technique -> measure -> the places it is lowest at
    std::map<std::string, std::map<std::string, std::vector<std::string>>> wins;
    for (const Line& line : lines) {
        out << "| " << line.where << " | " << line.measure << " |";
        for (double v : line.values) out << " " << num(v, line.format) << " |";
        const std::vector<std::string> best = lowest(line, names);
        std::string bestText;
        for (const std::string& t : best) bestText += (bestText.empty() ? "" : " = ") + t;
        out << " " << bestText << " |\n";
        for (const std::string& t : best) wins[t][line.measure].push_back(line.where);
    }
    if (lines.empty()) {
        out << "| | not measured: the run lacked `ssam` and the shipped techniques |";
        for (std::size_t i = 0; i <= names.size(); ++i) out << " |";
        out << "\n";
    }
    out << "\nWhich is better at what, from the lines above:\n\n";
    for (const std::string& t : names) {
        out << "- `" << t << "` is lowest at ";
        const auto at = wins.find(t);
        if (at == wins.end()) {
            out << "nothing measured here.\n";
            continue;
        }
        bool first = true;
        for (const auto& [measure, places] : at->second) {
            out << (first ? "" : "; ") << measure << " (";
            for (std::size_t i = 0; i < places.size(); ++i) out << (i ? ", " : "") << places[i];
            out << ")";
            first = false;
        }
        out << ".\n";
    }
    out << "\n";
}

}  // namespace bench
