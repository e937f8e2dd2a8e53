// SPDX-License-Identifier: MIT
#pragma once
// Where the host's foliage can be on screen (FrameDesc::foliageBounds): std::nullopt when no box
// is in view, else the rectangle the composite is scissored to; the whole frame without bounds.
#include <optional>

#include "ssam/vk/ssam_vk.hpp"

namespace ssam::vk::detail {

std::optional<Rect> compositeRegion(const FrameDesc& frame);

}  // namespace ssam::vk::detail
