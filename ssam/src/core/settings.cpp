// SPDX-License-Identifier: MIT
#include "ssam/core/settings.hpp"

#include <cmath>

#include "enum_names.hpp"
#include "number_text.hpp"

namespace ssam {

const char* maskPrecisionName(MaskPrecision precision) noexcept {
    static constexpr const char* kNames[] = {"rgba8", "rgba16f", "rg16f"};
    return core::enumName<MaskPrecision::Rg16f>(precision, kNames, "?");
}

const char* depthTestName(DepthTest test) noexcept {
    static constexpr const char* kNames[] = {"less", "less-equal", "greater", "greater-equal"};
    return core::enumName<DepthTest::GreaterEqual>(test, kNames, "?");
}

namespace {

bool inUnitRange(float value) { return std::isfinite(value) && value >= 0.0f && value <= 1.0f; }

}  // namespace

std::string settingsError(const Settings& s) {
    const auto outside = [](const char* knob, float value) {
        return std::string("ssam settings: ") + knob + " = " + core::numberText(value) + " is outside [0, 1]";
    };
    // §3.5.4: a lerp weight; §3.5.3: an alpha reference; a mask value. Each in [0, 1] and finite.
    if (!inUnitRange(s.maskLerp)) return outside("maskLerp", s.maskLerp);
    if (!inUnitRange(s.colorAlphaReference)) return outside("colorAlphaReference", s.colorAlphaReference);
    if (!inUnitRange(s.depthMaskThreshold)) return outside("depthMaskThreshold", s.depthMaskThreshold);
    if (!inUnitRange(s.colorFade)) return outside("colorFade", s.colorFade);
    for (int c = 0; c < 4; ++c)
        if (!std::isfinite(s.foliageClearColor[c]))
            return "ssam settings: foliageClearColor[" + std::to_string(c) +
                   "] = " + core::numberText(s.foliageClearColor[c]) + " is not finite";
    // Enums from a cast or a corrupted struct: a value no SSAM knows how to draw.
    if (static_cast<unsigned>(s.maskPrecision) > static_cast<unsigned>(MaskPrecision::Rg16f))
        return "ssam settings: maskPrecision = " + std::to_string(static_cast<unsigned>(s.maskPrecision)) +
               " is not a MaskPrecision (rgba8, rgba16f, rg16f)";
    if (static_cast<unsigned>(s.depthTest) > static_cast<unsigned>(DepthTest::GreaterEqual))
        return "ssam settings: depthTest = " + std::to_string(static_cast<unsigned>(s.depthTest)) +
               " is not a DepthTest (less, less-equal, greater, greater-equal: SSAM needs a test that orders surfaces)";
    return {};
}

const char* presetName(Preset preset) noexcept {
    static constexpr const char* kNames[] = {"paper", "measured"};
    return core::enumName<Preset::Measured>(preset, kNames, "?");
}

std::optional<Preset> parsePreset(std::string_view name) {
    for (Preset p : {Preset::Paper, Preset::Measured})
        if (name == presetName(p)) return p;
    return std::nullopt;
}

Settings presetSettings(Preset preset) {
    Settings settings;
    if (preset == Preset::Measured) {
        // ssam-bench's sweep (ssam/docs/knobs.md "Presets"): the lowest mean ꟻLIP over tree, forest
        // and vista among the settings that cost no more than the paper's. Not squaring (§3.6.2)
        // removes the see-through veil in partly covered pixels; more ADD (§3.5.4) thickens deep
        // canopies; a colour reference of 96 (§3.5.3: Pure's lay between 64 and 128) fills more of
        // the mask with leaf colour. The RGBA8 mask stays: a float one costs +46% on soft. The
        // colour averaged over 3x3 (ssam/docs/steady_in_motion.md) lowers the still error and
        // steadies the foliage in motion, at 1.04-1.11x the paper's time.
        settings.maskLerp = 0.9f;
        settings.squareMask = false;
        settings.colorAlphaReference = 96.0f / 255.0f;
        settings.colorBlur = true;
    }
    return settings;
}

}  // namespace ssam
