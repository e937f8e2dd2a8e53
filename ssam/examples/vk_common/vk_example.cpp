// SPDX-License-Identifier: MIT
#include "vk_example.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <string>
#include <vector>

#include "png_writer.hpp"
#include "ssam_device.hpp"
#include "vk_mist.hpp"
#include "vk_present.hpp"

namespace vk_example {

void checkSsam(const ssam::vk::ScreenSpaceAlphaMaskVk& ssam, ssam::vk::Status status, const char* call) {
    if (status != ssam::vk::Status::Ok)
        throw std::runtime_error(std::string(call) + ": " + ssam::vk::statusName(status) + ": " + ssam.lastMessage());
}

namespace {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

Arguments parse(const Tool& tool, int argc, char** argv) {
    Arguments a;
    a.out = std::string(tool.name) + ".png";
    if (tool.bendsInTheWind) a.wind = kDefaultWind;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--out") a.out = value();
        else if (arg == "--mask") a.mask = value();
        else if (arg == "--validation") a.validation = true;
        else if (arg == "--dynamic-rendering") a.dynamicRendering = true;
        else if (arg == "--present") a.present = true;
        else if (arg == "--mist") {
            const std::string v = value();
            if (v != "after" && v != "before") throw UsageError("--mist '" + v + "': expected after or before");
            a.mist = v == "after" ? Arguments::Mist::After : Arguments::Mist::Before;
        } else if (arg == "--depth-threshold") {
            const std::string v = value();
            char* end = nullptr;
            const float t = std::strtof(v.c_str(), &end);
            if (v.empty() || *end || !(t >= 0.0f && t <= 1.0f))
                throw UsageError("--depth-threshold '" + v + "': expected a mask value in 0..1");
            a.depthMaskThreshold = t;
        } else if (arg == "--precision") {
            const std::string v = value();
            if (v == "rgba8") a.precision = ssam::vk::MaskPrecision::Rgba8;
            else if (v == "rgba16f") a.precision = ssam::vk::MaskPrecision::Rgba16f;
            else if (v == "rg16f") a.precision = ssam::vk::MaskPrecision::Rg16f;
            else throw UsageError("--precision '" + v + "': expected rgba8, rgba16f or rg16f");
        } else if (arg == "--wind" && tool.bendsInTheWind) {
            const std::string v = value();
            char* end = nullptr;
            const float w = std::strtof(v.c_str(), &end);
            if (v.empty() || *end || !(std::fabs(w) <= 1.0f))
                throw UsageError("--wind '" + v + "': expected an amplitude in -1..1");
            a.wind = w;
        } else if (arg == "--frames") {
            const std::string v = value();
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end || n < 1 || n > 1000) throw UsageError("--frames '" + v + "': expected 1 to 1000");
            a.frames = int(n);
        } else if (arg == "--help") {
            std::printf(
                "usage: %s [--out frame.png] [--mask mask.png] [--frames N] [--validation]"
                " [--dynamic-rendering] [--present] [--mist after|before] [--depth-threshold T] [--precision P]%s\n",
                tool.name, tool.bendsInTheWind ? " [--wind AMPLITUDE]" : "");
            std::exit(0);
        } else throw UsageError("unknown argument '" + arg + "'");
    }
    if (!a.mask.empty() && a.precision != ssam::vk::MaskPrecision::Rgba8)
        throw UsageError("--mask writes an RGBA8 mask: only with --precision rgba8");
    for (const std::string& path : {a.out, a.mask})
        if (!path.empty() && (path.size() < 4 || path.compare(path.size() - 4, 4, ".png") != 0))
            throw UsageError("'" + path + "': the name must end in .png");
    return a;
}

void writeOrThrow(const std::string& path, const std::vector<std::uint8_t>& rgba) {
    if (const std::string why = writePng(path, kWidth, kHeight, rgba); !why.empty()) throw std::runtime_error(why);
    std::printf("wrote %s (%dx%d)\n", path.c_str(), kWidth, kHeight);
}

int run(const Tool& tool, const Arguments& args, const MakeRecorder& makeRecorder) {
    std::unique_ptr<PresentWindow> window;  // --present: made first, the instance needs its extensions
    if (args.present)
        window = std::make_unique<PresentWindow>(std::uint32_t(kWidth), std::uint32_t(kHeight), tool.name);
    vk_example::VulkanHost host(args.validation, args.dynamicRendering,
                                window ? window->instanceExtensions() : std::vector<const char*>{});
    std::printf("Vulkan: %s (API %u.%u)%s\n", host.deviceName.c_str(), VK_API_VERSION_MAJOR(host.apiVersion),
                VK_API_VERSION_MINOR(host.apiVersion),
                args.validation ? ", validation with synchronization validation" : "");
    if (args.dynamicRendering) std::printf("SSAM records with dynamic rendering\n");
    {
        HostScene scene(host, args.wind);
        ssam::vk::ScreenSpaceAlphaMaskVk ssam;
        ssam.setMessageCallback(
            [](void*, ssam::vk::Severity severity, const char* message) {
                if (severity == ssam::vk::Severity::Info) std::printf("%s\n", message);
            },
            nullptr);
        // SSAM is created from the host's Vulkan objects and its loader's vkGetInstanceProcAddr.
        ssam::vk::DeviceDesc device = ssamDevice(host);
        device.getDeviceProcAddr = vkGetDeviceProcAddr;
        device.dynamicRendering = host.dynamicRendering;
        if (args.dynamicRendering) device.renderingPath = ssam::vk::RenderingPath::DynamicRendering;
        device.independentBlend = host.independentBlend;  // MaskPrecision::Rg16f needs it
        ssam::vk::Settings settings;  // the paper's knobs, but for --depth-threshold and --precision
        settings.depthMaskThreshold = args.depthMaskThreshold;
        settings.maskPrecision = args.precision;
        ssam::vk::VertexLayout layout;  // what the built-in programs read of the scene's vertex buffer
        layout.bindings[0] = {0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        layout.position = {0, VK_FORMAT_R32G32B32_SFLOAT, 0};
        layout.uv = {0, VK_FORMAT_R32G32_SFLOAT, 3 * sizeof(float)};
        checkSsam(ssam, ssam.initialize(device, settings, layout), "ssam::vk initialize");
        const std::unique_ptr<FoliageRecorder> foliage = makeRecorder(scene, ssam, args);
        std::unique_ptr<MistPass> mist;
        if (args.mist != Arguments::Mist::None) mist = std::make_unique<MistPass>(scene);
        std::unique_ptr<Presenter> presenter;  // --present: each frame shown in the window
        if (window) presenter = std::make_unique<Presenter>(host, *window);

        // Two frames in flight: frame i waits for frame i - 2's fence before it records.
        std::deque<VkFence> inFlight;
        std::uint64_t framesCompleted = 0;
        for (int i = 0; i < args.frames; ++i) {
            if (inFlight.size() == 2) {
                host.wait(inFlight.front());
                inFlight.pop_front();
                ++framesCompleted;
            }
            const VkCommandBuffer cb = host.begin();
            scene.recordOpaque(cb);
            if (args.mist == Arguments::Mist::Before) mist->record(cb);
            ssam::vk::FrameDesc frame;
            frame.commandBuffer = cb;
            frame.colorView = scene.color.view;
            frame.colorFormat = scene.color.format;
            frame.colorImageExtent = {kWidth, kHeight};  // as the images were created: SSAM renders no further
            frame.depthView = scene.depth.view;
            frame.depthFormat = scene.depth.format;
            frame.depthImageExtent = {kWidth, kHeight};
            frame.depthImage = scene.depth.image;  // Settings::depthMaskThreshold copies its depth
            frame.width = kWidth;
            frame.height = kHeight;
            std::copy(std::begin(kViewProj), std::end(kViewProj), frame.viewProj);
            frame.foliageBounds = scene.cardBounds.data();
            frame.foliageBoundsCount = scene.cardBounds.size();
            frame.frameIndex = std::uint64_t(i);
            frame.framesCompleted = framesCompleted;
            foliage->record(ssam, frame);
            // Later transparent passes after SSAM: they see the foliage depth.
            if (args.mist == Arguments::Mist::After) mist->record(cb);
            if (presenter) presenter->record(cb, scene.color.image);
            inFlight.push_back(host.submit(cb, presenter ? presenter->rendered() : VK_NULL_HANDLE));
            if (presenter) presenter->present();
        }
        for (VkFence f : inFlight) host.wait(f);
        writeOrThrow(args.out, scene.read(scene.color.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL));
        if (!args.mask.empty())
            writeOrThrow(args.mask, scene.read(ssam.intermediates().mask, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
        vkDeviceWaitIdle(host.device);  // SSAM's objects go with the device idle (ssam_vk.hpp, Lifetime)
        mist.reset();
        presenter.reset();
        ssam.release();
    }
    if (!host.validationMessages.empty()) {
        for (const std::string& m : host.validationMessages)
            std::fprintf(stderr, "%s: validation: %s\n", tool.name, m.c_str());
        throw std::runtime_error(std::to_string(host.validationMessages.size()) + " validation message(s)");
    }
    return 0;
}

}  // namespace

int runExample(const Tool& tool, int argc, char** argv, const MakeRecorder& makeRecorder) {
    Arguments args;
    try {
        args = parse(tool, argc, argv);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "%s: error: %s (see --help)\n", tool.name, e.what());
        return 2;
    }
    if (const std::string why = checkWritable({args.out, args.mask}); !why.empty()) {
        std::fprintf(stderr, "%s: error: %s\n", tool.name, why.c_str());
        return 1;
    }
    try {
        return run(tool, args, makeRecorder);
    } catch (const vk_example::NoVulkan& e) {
        const char* ci = std::getenv("CI");
        if (ci && std::strcmp(ci, "true") == 0) {
            std::fprintf(stderr, "%s: error: CI=true and no Vulkan here: %s\n", tool.name, e.what());
            return 1;
        }
        std::printf("SKIPPED: %s\n", e.what());
        return 77;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: error: %s\n", tool.name, e.what());
        return 1;
    }
}

}  // namespace vk_example
