// SPDX-License-Identifier: MIT
#pragma once
// Inside ssam::vk errors travel as a Failure (a Status and its message); the public calls turn
// them into their return value and the message callback (ssam_vk.cpp), so nothing throws into
// host code.
#include <string>

#include "../core/failure.hpp"
#include "ssam/vk/ssam_vk.hpp"

namespace ssam::vk::detail {

using core::Failure;

const char* resultName(VkResult result) noexcept;
// "VK_FORMAT_R8G8B8A8_SRGB", or "VkFormat <n>" for a value Vulkan's headers do not name (messages
// name what the host passed, not its number).
std::string formatName(VkFormat format);

// Throws DeviceError (OutOfMemory for the VK_ERROR_OUT_OF_*_MEMORY results) naming `what`.
void check(VkResult result, const char* what);
// The same, naming "`call`, `what`": the call that failed and the object it was making for.
void check(VkResult result, const char* call, const char* what);

}  // namespace ssam::vk::detail
