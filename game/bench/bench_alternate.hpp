// SPDX-License-Identifier: MIT
#pragma once
// Two subjects' frames timed alternately, A B A B ..., on one backend and view. Timed one after
// the other, a change in the machine's speed during the run (other work on the cores, the clock)
// lands on one subject only: two 1280x720 runs of the whole bench gave the forest's ssam /
// ssam-paper time as 1.12 and 1.45, with the opaque pass, the same work in both, itself 1.42x
// slower in the second. Alternated, such a change falls on both; the time goal compares these.
#include <string>

#include "bench_frame.hpp"
#include "bench_runner.hpp"

namespace bench {

struct AlternatedTimes {
    double aMedianMs = 0.0, bMedianMs = 0.0;
};

// `warmup` frames of each, then `reps` pairs timed; the medians of each subject's frames. Throws
// engine::Error where a subject cannot be created (a technique the backend refuses).
AlternatedTimes timeAlternately(engine::render::Backend& backend, BenchScene& scene, const ViewUpload& view,
                                const BenchSubject& a, const BenchSubject& b, int warmup, int reps, int width,
                                int height);

}  // namespace bench
