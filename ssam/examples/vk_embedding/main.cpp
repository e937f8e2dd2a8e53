// SPDX-License-Identifier: MIT
// ssam::vk with SSAM's built-in foliage programs (way a): a plain Vulkan program
// (vk_common/vk_example.hpp: its own instance, device, queue, images and buffers) records its
// opaque scene into its own colour + depth images, then ssam::vk::ScreenSpaceAlphaMaskVk::render
// records the mask, colour and composite passes ([Hathaway 2010] §3.5) into the same command
// buffer, calling back into the program to record its foliage cards' draws from its own vertex
// buffer. The scene is the GL examples' (common/scene.hpp), so the picture is theirs.
//
//   ssam_vk_embedding [--out frame.png] [--mask mask.png] [--frames N] [--validation]
//                     [--dynamic-rendering] [--present] [--mist after|before] [--depth-threshold T]
//                     [--precision rgba8|rgba16f|rg16f]
//       headless; --frames records N frames (two in flight; frame N is written); --validation
//       runs under VK_LAYER_KHRONOS_validation with synchronization validation, and any message
//       it reports fails the run; --dynamic-rendering enables Vulkan 1.3's feature and has SSAM
//       record with vkCmdBeginRendering (ssam::vk::RenderingPath::DynamicRendering); --mist,
//       --depth-threshold and --precision as the GL examples' (the host's transparent pass,
//       Settings::depthMaskThreshold, Settings::maskPrecision; --mask with rgba8 only); --present
//       also shows each frame in a window (vk_common/vk_present.hpp: the presents capture tools
//       count frames by; ssam/docs/vk_hosts.md "Capturing a frame")
// Exit codes: vk_common/vk_example.hpp.
#include "vk_example.hpp"

namespace {

using namespace vk_example;

class BuiltInPrograms final : public FoliageRecorder {
public:
    BuiltInPrograms(HostScene& scene, ssam::vk::ScreenSpaceAlphaMaskVk& ssam) : scene_(scene) {
        // The leaf texture, sampled with SSAM's linear clamp-to-edge sampler.
        checkSsam(ssam, ssam.createTexture(scene.leaf.view, VK_NULL_HANDLE, &leaf_), "ssam::vk createTexture");
    }

    void record(ssam::vk::ScreenSpaceAlphaMaskVk& ssam, const ssam::vk::FrameDesc& frame) override {
        // Called twice: mask pass, then colour pass, inside SSAM's render pass with its pipeline
        // bound. The host binds its vertex buffer, sets per-draw values through the program and
        // draws the same cards in the same order both times.
        const ssam::vk::Status status = ssam.render(frame, [&](const ssam::vk::FoliageProgram& program) {
            program.bindBaseColorTexture(leaf_);
            scene_.drawCards(program.commandBuffer, [&](const float tint[4]) {
                program.setBaseColorFactor(tint[0], tint[1], tint[2], tint[3]);
            });
        });
        checkSsam(ssam, status, "ssam::vk render");
    }

private:
    HostScene& scene_;
    ssam::vk::TextureId leaf_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    return runExample({"ssam_vk_embedding", false}, argc, argv,
                      [](HostScene& scene, ssam::vk::ScreenSpaceAlphaMaskVk& ssam, const Arguments&) {
                          return std::make_unique<BuiltInPrograms>(scene, ssam);
                      });
}
