// SPDX-License-Identifier: MIT
#pragma once
// ssam-bench --motion: every technique in motion, three ways a racing game's foliage moves
// ([Hathaway 2010] §3.4: motion is where alpha testing sparkles):
//   pan    the scene's sideways pan (bench_scenes.hpp), as the comparison run's flicker;
//   dolly  the last frames of the forest's dolly, the camera moving toward the trees;
//   wind   the still view, the plants bent by the wind (modules/wind), a frame every 1/60 s;
//   car    the still view, the racer's car crossing it in front of the trees (kCarStep a frame),
//          its motion vectors from engine/scene's RigidMotion.
// Each frame of each technique (soft backend) is judged against the exact reference of the same
// frame over the foliage pixels (foliage_errors.hpp). Per technique and motion:
//   flicker        temporalFlicker (engine/capture/metrics.hpp) over the measured frames, minus
//                  the reference's over the same frames: the change the motion does not explain;
//   flip, rmse     converged (the median over the last half of the frames) and worst;
//   ghost          per frame, the mean ꟻLIP against the reference over the moved pixels: the
//                  foliage pixels (of this frame's reference or the previous one's) where the
//                  reference's ꟻLIP between the two frames exceeds kMovedFlip, i.e. whose
//                  surface visibly changed; what a history fetched from the wrong place (or a
//                  trail) costs. In the car motion, every pixel whose reference changed so (the
//                  car's own pixels too: a history without the car's motion smears it). Converged
//                  and worst, as flip.
// A technique with history draws kHistoryFrames frames first (the wind already blowing, the
// camera on the first view), so none is measured on its first frame. `motionVectors` sets
// TemporalOptions::motionVectors for every technique (off: the camera-only TAA). Deterministic:
// the same numbers for any thread count.
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "bench_runner.hpp"

namespace bench {

enum class Motion { Pan, Dolly, Wind, Car };

// "pan,dolly,wind,car" (any non-empty subset, each once) into `motions`; throws engine::UsageError
// naming the bad entry.
std::vector<Motion> parseMotions(std::string_view list);
const char* motionName(Motion motion);
// Every motion this build can run: pan, dolly and car, and wind when modules/wind is in it.
std::vector<Motion> availableMotions();

// A pixel whose reference changed by more ꟻLIP than this between two frames has moved.
inline constexpr double kMovedFlip = 0.1;

// Every subject with a technique of `options`, on each of its scenes that has the motion,
// `frames` (>= 2) frames each. Prints one progress line per frame.
std::vector<MotionRow> runMotion(const BenchOptions& options, const std::vector<Motion>& motions, int frames,
                                 bool motionVectors);

void writeMotionCsv(std::ostream& out, const std::vector<MotionRow>& rows);
// The table printed at the end of a run.
void printMotionTable(const std::vector<MotionRow>& rows);

}  // namespace bench
