// SPDX-License-Identifier: MIT
#pragma once
// Named sets of SSAM's knobs. `Config{}` stays the paper's ([Hathaway 2010] §3.5–§3.6, Pure's
// values); `measured` is the setting ssam-bench's knob sweep found best against the exact
// reference within 1.25x the paper's frame time (ssam/docs/knobs.md "Presets" has the sweep).
#include <cstdint>
#include <optional>
#include <string_view>

#include "ssam/config.hpp"

namespace ssam {

enum class Preset : std::uint8_t { Paper, Measured };

// The preset the demo and the benchmark use unless told otherwise.
inline constexpr Preset kRecommendedPreset = Preset::Measured;

const char* presetName(Preset preset);                     // "paper", "measured"
std::optional<Preset> parsePreset(std::string_view name);  // none for an unknown name

// The knobs of `preset`; depthFunc and foliageClearColor are Config{}'s (the host's and the
// look's, not a trade of error against time).
Config presetConfig(Preset preset);

}  // namespace ssam
