// SPDX-License-Identifier: MIT
#pragma once
// ssam-bench --dolly: popping at the levels of detail's changes, per technique. The forest's
// dolly (bench_scenes.hpp: the camera moving toward the trees a fixed step a frame) is drawn
// twice per technique on the soft backend, with the levels of detail and at full detail, and
// judged with ꟻLIP ([Andersson et al. 2020]) over the plant pixels (those where either frame
// differs from the opaque-only frame of the full scene):
//   pop       the largest ꟻLIP between consecutive LOD frames: what the eye sees change;
//   pop_lod   the largest mean, over the plant pixels, of each pixel's excess of that ꟻLIP
//             over the same pair's at full detail (0 where full detail changed as much): the
//             change the levels add to the motion's own (a level switching in one frame);
//   pop_lod_median  the same excess in the median frame: the floor a switch rises above,
//             which the per-pixel difference between the LOD and full-detail frames leaves in
//             every frame of a moving camera;
//   lod_flip  the LOD frame against the full-detail frame over the plant pixels, mean and
//             worst over the dolly; lod_frame_flip the same over the whole frame.
// A technique with history draws kHistoryFrames of the first view first, in both runs.
#include <ostream>
#include <string>
#include <vector>

#include "bench_runner.hpp"

namespace bench {

// Every subject with a technique of `options`, on each scene that has a dolly, through its
// first `frames` frames (2 .. kDollyFrames). Prints one progress line per frame.
std::vector<DollyRow> runDolly(const BenchOptions& options, int frames, float crossfade);

void writeDollyCsv(std::ostream& out, const std::vector<DollyRow>& rows);
// dolly_frames.csv: each technique's measures frame by frame (the change and the excess from
// the frame before, empty on the first; the LOD frame's ꟻLIP against full detail), to tell a
// level switching in one frame (a peak) from the difference every frame shows (a floor).
void writeDollyFramesCsv(std::ostream& out, const std::vector<DollyRow>& rows);
// The table printed at the end of a run.
void printDollyTable(const std::vector<DollyRow>& rows);

}  // namespace bench
