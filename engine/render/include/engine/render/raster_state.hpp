// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>

namespace engine::render {

enum class CullMode : std::uint8_t { None, Back, Front };
enum class Winding : std::uint8_t { CounterClockwise, Clockwise };  // which winding is front-facing

struct RasterState {
    CullMode cull = CullMode::None;
    Winding frontFace = Winding::CounterClockwise;
};

// A pixel rectangle; x/y from the top-left of the target (y down, like the stored image rows).
struct Rect {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

}  // namespace engine::render
