// SPDX-License-Identifier: MIT
#include "engine/render/pixel_codec.hpp"

#include <algorithm>

namespace engine::render {

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

SrgbEncodeTables::SrgbEncodeTables() {
    auto floatOf = [](std::uint32_t bits) {
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    };
    constexpr std::uint32_t kOne = 0x3F800000;  // 1.0f: encodes to 255
    threshold[0] = 0.0f;
    for (unsigned k = 1; k < 256; ++k) {  // least bit pattern in [0, 1] encoding to >= k
        std::uint32_t lo = 0, hi = kOne;
        while (lo < hi) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            if (encodeSrgb8Exact(floatOf(mid)) >= k) hi = mid;
            else lo = mid + 1;
        }
        threshold[k] = floatOf(lo);
    }
    threshold[256] = INFINITY;
    unsigned code = 0;
    for (std::uint32_t bucket = 0; bucket < kSrgbEncodeBuckets; ++bucket) {
        const float first = floatOf(bucket << 16);
        while (code < 255 && first >= threshold[code + 1]) ++code;
        start[bucket] = static_cast<std::uint8_t>(code);
        // Steps up to the bucket's last pattern (1.0f's bucket holds only 1.0f in [0, 1]).
        const float last = bucket == kSrgbEncodeBuckets - 1 ? first : floatOf(bucket << 16 | 0xFFFFu);
        unsigned lastCode = code;
        while (lastCode < 255 && last >= threshold[lastCode + 1]) ++lastCode;
        maxBucketSteps = std::max(maxBucketSteps, int(lastCode - code));
    }
}

}  // namespace engine::render
