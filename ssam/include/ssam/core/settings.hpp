// SPDX-License-Identifier: MIT
#pragma once
// Every knob of the paper ([Hathaway 2010] §3.5-§3.7), with Pure's values as defaults, and the
// named presets. One struct for every SSAM: the engine-hosted ssam::ScreenSpaceAlphaMask,
// ssam::gl and ssam::vk take it as it is. Host-neutral core: standard C++17 only.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ssam {

// Storage of the mask (§3.5.2). Rgba8 is Pure's: the ADD mask saturates at 1 after 255/alpha
// layers of one alpha. Rgba16f keeps both masks in one target unclamped. Rg16f stores MAX and
// ADD in two single-channel R16F targets: one RG target has a single blend equation for both
// channels, so Table 3.1's RGB = MAX / A = ADD needs an alpha channel or two targets (two R16F
// targets are the same memory as one RG16F; the host needs per-target blend equations).
enum class MaskPrecision : std::uint8_t { Rgba8, Rgba16f, Rg16f };
const char* maskPrecisionName(MaskPrecision precision) noexcept;  // "rgba8", "rgba16f", "rg16f"

// The scene's depth convention: Less / LessEqual conventional, Greater / GreaterEqual reverse-Z.
// Both SSAM passes test with it; the colour pass writes with it (§3.5.3).
enum class DepthTest : std::uint8_t { Less, LessEqual, Greater, GreaterEqual };
const char* depthTestName(DepthTest test) noexcept;  // "less", "less-equal", "greater", "greater-equal"
inline bool isReverseZ(DepthTest test) { return test == DepthTest::Greater || test == DepthTest::GreaterEqual; }

struct Settings {
    // mask = lerp(MAX mask, ADD mask, maskLerp): 0.85 = 85% additive, 15% max (§3.5.4, Listing 3.2).
    float maskLerp = 0.85f;
    // Colour-pass alpha reference (§3.5.3): Pure shipped ~64 of 255, between 64 and 128.
    float colorAlphaReference = 64.0f / 255.0f;
    // Colour-pass clear colour (§3.6.1, the clear-screen colour fix): shows through where the mask
    // is non-zero but the alpha-tested colour pass wrote nothing. A mid foliage green.
    float foliageClearColor[4] = {0.16f, 0.22f, 0.08f, 0.0f};
    // Square the final mask (§3.6.2, the squared alpha trick).
    bool squareMask = true;
    MaskPrecision maskPrecision = MaskPrecision::Rgba8;
    DepthTest depthTest = DepthTest::Less;
    // The depth SSAM leaves for later transparent passes (§3.7) keeps the foliage depth only where
    // the composited mask reaches this value; elsewhere the opaque depth is put back. 0 (the
    // paper's): foliage depth wherever the colour pass wrote, so a later pass behind a leaf edge
    // is cut where the leaf is only partly opaque and a rim of the unfogged background shows
    // round it. Above 0: those edges take the later pass, for a copy of the depth and one
    // full-screen depth pass (ssam/README.md, "Later transparent passes").
    float depthMaskThreshold = 0.0f;
    // The composite fades the colour pass's colour in from foliageClearColor as the MAX mask goes
    // from colorAlphaReference to colorAlphaReference + colorFade (smoothstep), so a leaf whose
    // alpha crosses the reference (§3.5.3) changes the picture continuously instead of by its
    // alpha times |leaf - clear colour| in one frame (ssam/docs/steady_in_motion.md). 0 (the
    // paper's): the step. In [0, 1].
    float colorFade = 0.0f;
    // The composite takes the 1-2-1 3x3 average of the colours the colour pass wrote (alpha > 0)
    // around the pixel instead of the pixel's own, each weighted too by its alpha^1.5, as
    // SSAM+ does: the colour pass keeps one alpha-tested layer per pixel, a different leaf from
    // pixel to pixel and frame to frame, and the average stands in for the blend of the layers
    // (ssam/docs/steady_in_motion.md). False (the paper's): the pixel's own.
    bool colorBlur = false;
};

// "" when every knob is usable, else what is wrong, naming the knob and its value
// ("ssam settings: maskLerp = 1.5 is outside [0, 1]"). Each SSAM refuses such settings.
std::string settingsError(const Settings& settings);

// Named sets of knobs. Paper is Settings{} ([Hathaway 2010] §3.5-§3.6, Pure's values); Measured is
// what ssam-bench's knob sweep found best against the exact reference within 1.25x the paper's
// frame time (ssam/docs/knobs.md "Presets").
enum class Preset : std::uint8_t { Paper, Measured };
inline constexpr Preset kRecommendedPreset = Preset::Measured;  // the demo's and the benchmark's
const char* presetName(Preset preset) noexcept;                 // "paper", "measured"
std::optional<Preset> parsePreset(std::string_view name);       // none for an unknown name
// The knobs of `preset`; depthTest, foliageClearColor and depthMaskThreshold are Settings{}'s (the
// host's, the look's and the later passes' choices, not a trade of error against time).
Settings presetSettings(Preset preset);

}  // namespace ssam
