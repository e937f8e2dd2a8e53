// SPDX-License-Identifier: MIT
#include "bench_goals.hpp"

#include <algorithm>

#include "report_text.hpp"

namespace bench {

const BenchRow* findRow(const std::vector<BenchRow>& rows, const std::string& scene, const std::string& technique,
                        const std::string& backend) {
    for (const BenchRow& r : rows)
        if (r.scene == scene && r.technique == technique && r.backend == backend) return &r;
    return nullptr;
}

std::string primaryBackend(const std::vector<BenchRow>& rows) {
    for (const BenchRow& r : rows)
        if (r.backend == "soft") return "soft";
    return rows.empty() ? "" : rows.front().backend;
}

std::vector<Goal> rivalGoals(const std::vector<BenchRow>& rows) {
    const std::string backend = primaryBackend(rows);
    auto ratio = [&](const std::string& what, const std::string& scene, const std::string& a, const std::string& b,
                     double BenchRow::*field, double target) {
        Goal g{scene + ": " + what, std::nullopt, target, ""};
        const BenchRow* ra = findRow(rows, scene, a, backend);
        const BenchRow* rb = findRow(rows, scene, b, backend);
        if (!ra || !rb) g.missing = "no " + std::string(!ra ? a : b) + " row in this run";
        else if (!has(ra->*field) || !has(rb->*field)) g.missing = "not measured in this run";
        else if (rb->*field == 0.0) g.missing = "undefined (division by zero)";
        else g.ratio = ra->*field / rb->*field;
        return g;
    };
    std::vector<Goal> goals;
    for (const char* scene : {"tree", "forest", "vista"}) {
        goals.push_back(ratio("ꟻLIP ssam / alpha-test", scene, "ssam", "alpha-test", &BenchRow::flipMean, 1.0));
        goals.push_back(ratio("time ssam / ssam-paper, frames alternated", scene, "ssam", kSsamPaperRow,
                              &BenchRow::timeAlternatedMs, 1.25));
        if (!findRow(rows, scene, kSsamPaperRow, backend) && goals.back().missing.rfind("no ", 0) == 0)
            goals.back().missing = "no paper-preset row (run with --with-paper-ssam)";
    }
    for (const char* scene : {"tree", "forest", "vista"})
        goals.push_back(
            ratio("ꟻLIP ssam-plus / alpha-test", scene, "ssam-plus", "alpha-test", &BenchRow::flipMean, 0.6));
    goals.push_back(ratio("flicker ssam / alpha-test", "forest", "ssam", "alpha-test", &BenchRow::flicker, 0.3));
    // Only scenes the run measured: a --scenes subset drops the others' goals.
    goals.erase(std::remove_if(goals.begin(), goals.end(),
                               [&](const Goal& g) {
                                   const std::string scene = g.what.substr(0, g.what.find(':'));
                                   return std::none_of(rows.begin(), rows.end(),
                                                       [&](const BenchRow& r) { return r.scene == scene; });
                               }),
                goals.end());
    return goals;
}

void writeGoalTable(std::ostream& out, const std::vector<Goal>& goals) {
    out << "| goal | measured | target | met? |\n|---|---:|---|---|\n";
    for (const Goal& g : goals)
        out << "| " << g.what << " | " << (g.ratio ? num(*g.ratio, "%.3f") + "x" : std::string("n/a"))
            << " | <= " << num(g.target, "%.2f") << "x | " << (g.ratio ? (g.met() ? "met" : "not met") : g.missing)
            << " |\n";
}

}  // namespace bench
