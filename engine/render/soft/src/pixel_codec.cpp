#include "pixel_codec.hpp"

namespace engine::render::soft {

ByteTables::ByteTables() {
    for (int i = 0; i < 256; ++i) {
        unorm[i] = static_cast<float>(i) / 255.0f;
        // Double precision so the table holds the correctly rounded float of the curve.
        const double s = i / 255.0;
        srgb[i] = static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
    }
}

const ByteTables& byteTables() {
    static const ByteTables tables;
    return tables;
}

}  // namespace engine::render::soft
