// SPDX-License-Identifier: MIT
#pragma once
// The order of a frame's calls when a host draws pass by pass (ssam::gl's and ssam::vk's way b;
// way a runs through it): beginFrame, beginMaskPass, endMaskPass, beginColorPass, endColorPass,
// composite, in this order only. A call out of order is refused (InvalidCall) with where the frame
// is and what comes next.
#include <string>

#include "failure.hpp"

namespace ssam::core {

enum class Phase { Idle, FrameBegun, InMaskPass, MaskDone, InColorPass, ColorDone };

inline const char* describePhase(Phase phase) {
    switch (phase) {
        case Phase::Idle: return "no frame is open";
        case Phase::FrameBegun: return "the frame is begun (beginMaskPass comes next)";
        case Phase::InMaskPass: return "the mask pass is open (endMaskPass comes next)";
        case Phase::MaskDone: return "the mask pass is done (beginColorPass comes next)";
        case Phase::InColorPass: return "the colour pass is open (endColorPass comes next)";
        case Phase::ColorDone: return "the colour pass is done (composite comes next)";
    }
    return "?";
}

// Throws InvalidCall unless the API is initialised and the frame is at `expected`.
inline void expectPhase(const char* api, bool initialized, Phase current, Phase expected, const char* call) {
    if (!initialized) throw Failure(Status::InvalidCall, std::string(api) + ": " + call + " before initialize()");
    if (current != expected)
        throw Failure(Status::InvalidCall, std::string(api) + ": " + call + " called when " + describePhase(current));
}

// Throws InvalidCall when a frame is open: `call` changes what every pass of a frame is drawn with.
inline void expectNoFrame(const char* api, Phase current, const char* call) {
    if (current != Phase::Idle)
        throw Failure(Status::InvalidCall, std::string(api) + ": " + call + "() inside a frame");
}

}  // namespace ssam::core
