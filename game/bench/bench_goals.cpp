// SPDX-License-Identifier: MIT
#include "bench_goals.hpp"

#include <algorithm>
#include <utility>

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

namespace {

// `what`: a's `field` over b's, or what the run lacked to compute it.
template <class Row>
Goal ratioGoal(std::string what, const Row* ra, const std::string& a, const Row* rb, const std::string& b,
               double Row::*field, double target) {
    Goal g{std::move(what), std::nullopt, target, ""};
    if (!ra || !rb) g.missing = "no " + std::string(!ra ? a : b) + " row in this run";
    else if (!has(ra->*field) || !has(rb->*field)) g.missing = "not measured in this run";
    else if (rb->*field == 0.0) g.missing = "undefined (division by zero)";
    else g.ratio = ra->*field / rb->*field;
    return g;
}

// The goals of the forest only: the scene the motions and the dolly run in.
constexpr const char* kMotionScene = "forest";

const MotionRow* findMotionRow(const std::vector<MotionRow>& rows, const std::string& motion,
                               const std::string& technique) {
    for (const MotionRow& r : rows)
        if (r.scene == kMotionScene && r.motion == motion && r.technique == technique) return &r;
    return nullptr;
}

const DollyRow* findDollyRow(const std::vector<DollyRow>& rows, const std::string& technique) {
    for (const DollyRow& r : rows)
        if (r.scene == kMotionScene && r.technique == technique) return &r;
    return nullptr;
}

// Where each kind of goal's limit is worked out.
constexpr const char* kSsamFlipLimits =
    "ssam/docs/knobs.md, \"Why SSAM's ꟻLIP exceeds alpha testing's in the dense forest\"";
constexpr const char* kTimeLimits = "ssam/docs/knobs.md, \"Presets\"";
constexpr const char* kSsamPlusLimits = "ssam/docs/ssam_plus.md, \"Where the goal stands\"";
constexpr const char* kFlickerLimits = "ssam/docs/steady_in_motion.md, \"Figures\"";
constexpr const char* kDollyLimits = "game/docs/levels_of_detail.md, \"Popping along the dolly\"";

Goal limitedBy(Goal goal, const char* where) {
    goal.limitedBy = where;
    return goal;
}

}  // namespace

std::vector<Goal> rivalGoals(const std::vector<BenchRow>& rows) {
    const std::string backend = primaryBackend(rows);
    auto ratio = [&](const std::string& what, const std::string& scene, const std::string& a, const std::string& b,
                     double BenchRow::*field, double target) {
        return ratioGoal(scene + ": " + what, findRow(rows, scene, a, backend), a, findRow(rows, scene, b, backend), b,
                         field, target);
    };
    std::vector<Goal> goals;
    for (const char* scene : {"tree", "forest", "vista"}) {
        goals.push_back(limitedBy(
            ratio("ꟻLIP ssam / alpha-test", scene, "ssam", "alpha-test", &BenchRow::flipMean, 1.0), kSsamFlipLimits));
        goals.push_back(limitedBy(ratio("time ssam / ssam-paper, frames alternated", scene, "ssam", kSsamPaperRow,
                                        &BenchRow::timeAlternatedMs, 1.25),
                                  kTimeLimits));
        if (!findRow(rows, scene, kSsamPaperRow, backend) && goals.back().missing.rfind("no ", 0) == 0)
            goals.back().missing = "no paper-preset row (run with --with-paper-ssam)";
    }
    for (const char* scene : {"tree", "forest", "vista"})
        goals.push_back(
            limitedBy(ratio("ꟻLIP ssam-plus / alpha-test", scene, "ssam-plus", "alpha-test", &BenchRow::flipMean, 0.6),
                      kSsamPlusLimits));
    goals.push_back(limitedBy(
        ratio("flicker ssam / alpha-test", "forest", "ssam", "alpha-test", &BenchRow::flicker, 0.3), kFlickerLimits));
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

std::vector<Goal> motionGoals(const std::vector<MotionRow>& rows) {
    std::vector<Goal> goals;
    for (const char* motion : {"pan", "dolly", "wind"}) {
        if (std::none_of(rows.begin(), rows.end(), [&](const MotionRow& r) { return r.motion == motion; })) continue;
        auto ratio = [&](const char* what, const char* a, const char* b, double MotionRow::*field, double target) {
            return ratioGoal(std::string(kMotionScene) + " " + motion + ": " + what, findMotionRow(rows, motion, a), a,
                             findMotionRow(rows, motion, b), b, field, target);
        };
        goals.push_back(limitedBy(ratio("flicker ssam / alpha-test", "ssam", "alpha-test", &MotionRow::flicker, 0.3),
                                  kFlickerLimits));
        goals.push_back(
            limitedBy(ratio("ꟻLIP converged ssam-plus / alpha-test", "ssam-plus", "alpha-test", &MotionRow::flip, 0.6),
                      kSsamPlusLimits));
    }
    return goals;
}

std::vector<Goal> dollyGoals(const std::vector<DollyRow>& rows) {
    if (rows.empty()) return {};
    const std::string at = std::string(kMotionScene) + " dolly: ";
    std::vector<Goal> goals;
    for (const char* rival : {"alpha-test", "hashed"}) {
        goals.push_back(ratioGoal(at + "popping (pop_lod) ssam / " + rival, findDollyRow(rows, "ssam"), "ssam",
                                  findDollyRow(rows, rival), rival, &DollyRow::popLod, 1.0));
        goals.back().below = true;
        goals.back().limitedBy = kDollyLimits;
    }
    Goal flip{at + "LOD frame ꟻLIP against full detail, ssam", std::nullopt, 0.02, ""};
    flip.isRatio = false;
    if (const DollyRow* s = findDollyRow(rows, "ssam")) flip.ratio = s->lodFlipMean;
    else flip.missing = "no ssam row in this run";
    goals.push_back(limitedBy(flip, kDollyLimits));
    return goals;
}

namespace {

std::string measured(const Goal& g) {
    if (!g.ratio) return "n/a";
    return g.isRatio ? num(*g.ratio, "%.3f") + "x" : num(*g.ratio, "%.4f");
}

std::string verdict(const Goal& g) { return g.ratio ? (g.met() ? "met" : "not met") : g.missing; }

}  // namespace

void writeGoalLimits(std::ostream& out, const std::vector<Goal>& goals) {
    std::vector<const Goal*> notMet;
    for (const Goal& g : goals)
        if (g.ratio && !g.met()) notMet.push_back(&g);
    if (notMet.empty()) {
        out << "Every goal measured in this run is met.\n";
        return;
    }
    out << "What limits each goal not met in this run is worked out in:\n\n";
    for (const Goal* g : notMet) out << "- " << g->what << " (" << measured(*g) << "): " << g->limitedBy << ".\n";
}

void writeGoalTable(std::ostream& out, const std::vector<Goal>& goals, const std::vector<Goal>* beside,
                    const std::string& besideName) {
    out << "| goal | measured | target | met? |" << (beside ? " " + besideName + " | met? |" : "") << "\n"
        << "|---|---:|---|---|" << (beside ? "---:|---|" : "") << "\n";
    for (const Goal& g : goals) {
        const std::string target = std::string(g.below ? "< " : "<= ") + num(g.target, "%.2f") + (g.isRatio ? "x" : "");
        out << "| " << g.what << " | " << measured(g) << " | " << target << " | " << verdict(g) << " |";
        if (beside) {
            const auto other =
                std::find_if(beside->begin(), beside->end(), [&](const Goal& b) { return b.what == g.what; });
            if (other == beside->end()) out << " n/a | not in that run |";
            else out << " " << measured(*other) << " | " << verdict(*other) << " |";
        }
        out << "\n";
    }
}

}  // namespace bench
