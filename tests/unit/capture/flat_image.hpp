// SPDX-License-Identifier: MIT
#pragma once
// A test image of one colour, for the capture tests.
#include <initializer_list>

#include "engine/capture/image.hpp"

namespace capture_test {

// width x height pixels of `value`, as many channels as it has components.
inline engine::capture::Image flat(int width, int height, std::initializer_list<float> value) {
    engine::capture::Image image = engine::capture::Image::make(width, height, static_cast<int>(value.size()));
    image.fill(value);
    return image;
}

}  // namespace capture_test
