// SPDX-License-Identifier: MIT
#pragma once
// The program both Vulkan examples share: a plain Vulkan host (vk_host.hpp) drawing the GL
// examples' scene (vk_scene.hpp), SSAM created from its device, frames in flight, PNGs. What differs
// between the examples is how its foliage reaches SSAM (a FoliageRecorder):
//   vk_embedding     SSAM's built-in foliage programs draw the host's vertex buffer (way a)
//   vk_host_shaders  the host's own pipelines, with a wind bend, inside SSAM's passes (way b)
// Exit codes: 0 ok, 1 error (or a validation message), 2 usage error, 77 no Vulkan device (or no
// validation layer with --validation, or no dynamic rendering with --dynamic-rendering) -- 1
// instead under CI=true, so CI cannot skip them.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include <ssam/vk/ssam_vk.hpp>

#include "vk_scene.hpp"

namespace vk_example {

struct Tool {
    const char* name;
    bool bendsInTheWind = false;  // takes --wind
};

struct Arguments {
    std::string out;   // default <tool>.png
    std::string mask;  // "" = not written
    int frames = 1;    // two in flight; the last is written
    bool validation = false;
    bool dynamicRendering = false;
    bool present = false;  // --present: each frame shown in a window (vk_present.hpp)
    float wind = 0.0f;     // --wind (tools that bend in the wind; their default kDefaultWind)
    // The host's transparent pass (--mist after|before SSAM), as the GL examples'.
    enum class Mist { None, After, Before } mist = Mist::None;
    float depthMaskThreshold = 0.0f;                                     // --depth-threshold
    ssam::vk::MaskPrecision precision = ssam::vk::MaskPrecision::Rgba8;  // --precision
};

// How the host's foliage reaches SSAM: made once SSAM is initialised, destroyed before it goes.
class FoliageRecorder {
public:
    virtual ~FoliageRecorder() = default;
    // Records SSAM's passes over the cards into frame.commandBuffer; throws std::runtime_error
    // with SSAM's message when a call does not return Ok.
    virtual void record(ssam::vk::ScreenSpaceAlphaMaskVk& ssam, const ssam::vk::FrameDesc& frame) = 0;
};
using MakeRecorder =
    std::function<std::unique_ptr<FoliageRecorder>(HostScene&, ssam::vk::ScreenSpaceAlphaMaskVk&, const Arguments&)>;

// Throws std::runtime_error naming the call and SSAM's message unless `status` is Ok.
void checkSsam(const ssam::vk::ScreenSpaceAlphaMaskVk& ssam, ssam::vk::Status status, const char* call);

// Arguments, the host, SSAM (its settings: the paper's knobs, the cards' vertex layout), frames,
// PNGs. Returns the exit status.
int runExample(const Tool& tool, int argc, char** argv, const MakeRecorder& makeRecorder);

}  // namespace vk_example
