// SPDX-License-Identifier: MIT
#pragma once
// Image error metrics for the transparency benchmark: how far a technique's frame is from
// the exact reference frame, and how much a sequence of frames flickers.
//
// Common rules for every two-image metric here:
//   - `reference` and `test` are RGB(A) images of the same width, height and channel count,
//     colour in linear light. Anything else throws engine::Error.
//   - The colour channels are the ones named R, G and B when all three exist, otherwise the
//     first three channels that are not alpha; an image without three such channels throws.
//     Alpha and any further channels are ignored.
//   - Values are used as stored for the linear metrics; every other metric first clamps
//     colour to [0,1] (an LDR display). Inputs are expected finite: a NaN makes the result NaN.
//   - Results are deterministic: the same numbers on every run and for any oneTBB thread
//     count (per-pixel work is independent; sums are per-row partial sums in double, added
//     in row order).
#include <vector>

#include "engine/capture/image.hpp"

namespace engine::capture {

// ---- RMSE / PSNR ---------------------------------------------------------------------
// RMSE over all width*height*3 colour values. PSNR = 20 log10(peak / RMSE) with peak 1.0;
// identical images give RMSE 0 and PSNR +infinity.
double rmseLinear(const Image& reference, const Image& test);
double psnrLinear(const Image& reference, const Image& test);
// The same after clamping colour to [0,1] and encoding it with the exact sRGB curve
// (IEC 61966-2-1, linear toe included; evaluated in float, within a few ulp of linearToSrgb).
double rmseSrgb(const Image& reference, const Image& test);
double psnrSrgb(const Image& reference, const Image& test);

// ---- SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) -------------------------------------
// On luma: Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' (Rec.709 weights) of the clamped,
// sRGB-encoded colour, so it sees luminance structure only (a pure chroma change leaves it
// at 1; ꟻLIP covers colour). Gaussian window 11x11, sigma 1.5, normalised to sum 1;
// K1 = 0.01, K2 = 0.03, L = 1. The result is the mean of the SSIM map over the valid window
// positions only ((width-10) x (height-10), as Wang et al.'s reference code with 'valid'):
// no border padding. 1 for identical images, lower (down to -1) as structure departs.
// Throws engine::Error for images smaller than 11x11.
double ssim(const Image& reference, const Image& test);

// ---- ꟻLIP (Andersson et al., HPG 2020), LDR variant ----------------------------------
// Pixels per degree of visual angle for a monitor `monitorWidth` metres wide with
// `resolutionX` pixels across, seen from `distance` metres.
double flipPixelsPerDegree(double distance, double resolutionX, double monitorWidth);

struct FlipOptions {
    // The paper's default: 0.7 m from a 0.7 m wide, 3840-pixel monitor (about 67.02).
    double pixelsPerDegree = flipPixelsPerDegree(0.7, 3840.0, 0.7);
};

// Mean per-pixel ꟻLIP error, in [0,1]; 0 for identical images. Colour is clamped to [0,1]
// first (LDR-ꟻLIP). Symmetric: flip(a, b) == flip(b, a) exactly (see metrics_flip.cpp for
// the pipeline, its constants and where it departs from the reference implementation).
// When `errorMap` is given it receives the per-pixel error as a one-channel ("Y") image.
double flip(const Image& reference, const Image& test, const FlipOptions& options = {}, Image* errorMap = nullptr);

// ---- Temporal flicker ------------------------------------------------------------------
// Mean over all pixels and all consecutive frame pairs of |Y'(t+1) - Y'(t)|, Y' being the
// same Rec.709 luma of clamped, sRGB-encoded colour as SSIM uses. In [0,1]: 0 for a static
// sequence, 1 for a sequence alternating between black and white. The benchmark reports a
// technique's flicker minus the reference's over the same camera path. Needs at least two
// frames, all of the same size and channel count (engine::Error otherwise).
double temporalFlicker(const std::vector<Image>& frames);

}  // namespace engine::capture
