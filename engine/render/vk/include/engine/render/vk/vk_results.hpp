// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan backend's rules for what a device reports, as plain functions so that they are
// tested without a device (a lost device cannot be provoked on lavapipe).
#include <cstdint>
#include <string>

namespace engine::render::vk {

// The engine::Error message for a Vulkan call `what` that returned `result` (a VkResult):
// "<what>: VK_ERROR_OUT_OF_DEVICE_MEMORY (-2): ...". A lost device (VK_ERROR_DEVICE_LOST, from
// any submit, wait or present) says that the device was lost and that nothing made on it can be
// used again; out-of-memory results say which memory ran out.
std::string vulkanResultMessage(int result, const std::string& what);

// Milliseconds between two timestamps written `validBits` bits wide (the bits above are not
// defined: masked off; a counter that wrapped between them counts modulo 2^validBits), in ticks
// of `periodNs` nanoseconds (VkPhysicalDeviceLimits::timestampPeriod).
double timestampMilliseconds(std::uint64_t begin, std::uint64_t end, std::uint32_t validBits, double periodNs);

}  // namespace engine::render::vk
