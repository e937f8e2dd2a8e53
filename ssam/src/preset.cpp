// SPDX-License-Identifier: MIT
#include "ssam/preset.hpp"

namespace ssam {

const char* presetName(Preset preset) {
    switch (preset) {
        case Preset::Paper: return "paper";
        case Preset::Measured: return "measured";
    }
    return "?";
}

std::optional<Preset> parsePreset(std::string_view name) {
    for (Preset p : {Preset::Paper, Preset::Measured})
        if (name == presetName(p)) return p;
    return std::nullopt;
}

Config presetConfig(Preset preset) {
    Config config;
    if (preset == Preset::Measured) {
        // ssam-bench's sweep (ssam/docs/knobs.md "Presets"): the lowest mean ꟻLIP over tree, forest
        // and vista among the settings that cost no more than the paper's. Not squaring (§3.6.2)
        // removes the see-through veil in partly covered pixels; more ADD (§3.5.4) thickens deep
        // canopies; a colour reference of 96 (§3.5.3: Pure's lay between 64 and 128) fills more
        // of the mask with leaf colour. The RGBA8 mask stays: a float one costs +46% on soft.
        config.maskLerp = 0.9f;
        config.squareMask = false;
        config.colorAlphaReference = 96.0f / 255.0f;
    }
    return config;
}

}  // namespace ssam
