// SPDX-License-Identifier: MIT
// The Vulkan backend's errors at its limits: an image or buffer more than the device's memory
// can hold (the memory probe, memory_budget.hpp) is refused by name and size before anything
// is allocated, and the backend goes on rendering; the words for a lost device and for
// out-of-memory results (a lost device cannot be provoked on lavapipe: the mapping is tested
// as a function); timestamps masked to their valid bits. Under validation.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "engine/core/error.hpp"
#include "engine/render/vk/vk_results.hpp"
#include "vk_validation.hpp"

namespace {

using namespace engine::render;
using ssam::testing::validatedVulkanBackend;
using ssam::testing::validatedVulkanOptions;

constexpr std::uint64_t kMiB = 1ull << 20;
// VkResult values (the Vulkan specification's): the test needs no Vulkan headers.
constexpr int kDeviceLost = -4, kOutOfDeviceMemory = -2, kFormatNotSupported = -11;

vk::VulkanOptions withMemory(std::uint64_t bytes) {
    vk::VulkanOptions options = validatedVulkanOptions();
    options.memory = [bytes]() -> std::optional<AvailableMemory> { return AvailableMemory{bytes, "the test's probe"}; };
    return options;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const engine::Error& e) {
        return e.what();
    }
    return {};
}

// Still usable: a target cleared and read back.
void expectUsable(Backend& gfx) {
    const TextureHandle t = gfx.createTexture(renderTargetDesc("after", 4, 4, Format::RGBA8_UNORM));
    PassDesc pass;
    pass.name = "after";
    pass.color[0] = {t, LoadOp::Clear, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f)};
    gfx.beginPass(pass);
    gfx.endPass();
    gfx.endFrame();
    const Readback r = gfx.readback(t);
    EXPECT_EQ(r.at(3, 3, 0), 1.0f);
    EXPECT_EQ(r.at(3, 3, 1), 0.0f);
    gfx.destroy(t);
}

TEST(VkErrors, TextureBeyondTheDevicesMemoryIsRefusedByNameAndTheBackendGoesOn) {
    auto gfx = validatedVulkanBackend(withMemory(64 * kMiB));
    // 2048x2048 RGBA32F: 64 MiB, of which twice must be free.
    const std::string message =
        errorOf([&] { gfx->createTexture(renderTargetDesc("huge target", 2048, 2048, Format::RGBA32F)); });
    EXPECT_NE(message.find("texture 'huge target'"), std::string::npos) << message;
    EXPECT_NE(message.find("2048x2048 RGBA32F"), std::string::npos) << message;
    EXPECT_NE(message.find("the test's probe"), std::string::npos) << message;
    EXPECT_EQ(engine::render::vk::vulkanDriver(*gfx).counters().imagesCreated, 0u) << "counted as made";
    expectUsable(*gfx);
}

TEST(VkErrors, BufferBeyondTheDevicesMemoryIsRefusedByNameAndTheBackendGoesOn) {
    auto gfx = validatedVulkanBackend(withMemory(4 * kMiB));
    const std::string message = errorOf([&] {
        gfx->createBuffer({"huge vertices", BufferKind::Vertex, 48 * 180000}, {});
    });
    EXPECT_NE(message.find("buffer 'huge vertices'"), std::string::npos) << message;
    EXPECT_NE(message.find("8640000 bytes"), std::string::npos) << message;
    expectUsable(*gfx);
}

TEST(VkErrors, ALostDeviceIsNamedAsSuch) {
    const std::string lost = vk::vulkanResultMessage(kDeviceLost, "Vulkan backend: vkQueueSubmit");
    EXPECT_EQ(lost.rfind("Vulkan backend: vkQueueSubmit: VK_ERROR_DEVICE_LOST (-4): the Vulkan device was lost", 0), 0u)
        << lost;
    EXPECT_NE(lost.find("make a new backend"), std::string::npos) << lost;
    const std::string memory = vk::vulkanResultMessage(kOutOfDeviceMemory, "texture 'x': allocating");
    EXPECT_NE(memory.find("VK_ERROR_OUT_OF_DEVICE_MEMORY (-2): out of device memory"), std::string::npos) << memory;
    const std::string other = vk::vulkanResultMessage(kFormatNotSupported, "x");
    EXPECT_EQ(other, "x: VK_ERROR_FORMAT_NOT_SUPPORTED (-11)");
}

TEST(VkTimestamps, DifferencesUseTheValidBitsAndThePeriod) {
    // 64 valid bits, 1 ns ticks (lavapipe): 2.5 ms.
    EXPECT_DOUBLE_EQ(vk::timestampMilliseconds(1'000'000, 3'500'000, 64, 1.0), 2.5);
    // 32 valid bits: the undefined high bits are masked, a wrap counts forward.
    EXPECT_DOUBLE_EQ(vk::timestampMilliseconds(0xABCD'0000'FFFF'FFF0ull, 0x1234'0000'0000'0010ull, 32, 1.0),
                     32.0 / 1.0e6);
    // A 52.08 ns period (some GPUs): ticks scale by it.
    EXPECT_DOUBLE_EQ(vk::timestampMilliseconds(0, 1'000'000, 64, 52.08), 52.08);
}

}  // namespace
