// SPDX-License-Identifier: MIT
#include "engine/render/kernel/sampler.hpp"

#include <algorithm>
#include <cmath>

#include "engine/render/pixel_codec.hpp"
#include "engine/render/kernel/detail/texture_lod.hpp"
#include "engine/render/kernel/detail/texel_addressing.hpp"

namespace engine::render::soft {
namespace {

// The per-texel helpers are forced inline: a glm::vec4 returned from a call comes back in
// two registers and is reassembled through memory, a store-forwarding stall per texel.
[[gnu::noinline]] glm::vec4 loadOther(const std::byte* p, Format format) { return loadTexel(p, format); }

template <SampledChannels Channels>
[[gnu::always_inline]] inline glm::vec4 load(const SoftTexture& t, const ByteTables& tables, int level, int x, int y) {
    const std::byte* p = t.texel(level, x, y);
    const Format f = t.desc.format;
    auto u8 = [p](int i) { return std::to_integer<std::uint8_t>(p[i]); };
    if constexpr (Channels == SampledChannels::AlphaOnly) {
        // The mask program's dead-code stripping ([Hathaway 2010] §3.5.2): only alpha is decoded.
        if (f == Format::RGBA8_UNORM || f == Format::RGBA8_SRGB) return {0.0f, 0.0f, 0.0f, tables.unorm[u8(3)]};
    }
    // The 8-bit formats inline (as loadTexel decodes them); the rest through loadTexel.
    if (f == Format::RGBA8_UNORM)
        return {tables.unorm[u8(0)], tables.unorm[u8(1)], tables.unorm[u8(2)], tables.unorm[u8(3)]};
    if (f == Format::RGBA8_SRGB)
        return {tables.srgb[u8(0)], tables.srgb[u8(1)], tables.srgb[u8(2)], tables.unorm[u8(3)]};
    return loadOther(p, f);
}

template <SampledChannels Channels>
glm::vec4 nearest(const SoftTexture& t, const SamplerState& s, int level, glm::vec2 uv) {
    const MipLevel& l = t.levels[level];
    const int x = applyAddress(s.addressU, static_cast<int>(std::floor(safeCoord(uv.x) * l.width)), l.width);
    const int y = applyAddress(s.addressV, static_cast<int>(std::floor(safeCoord(uv.y) * l.height)), l.height);
    return load<Channels>(t, byteTables(), level, x, y);
}

template <SampledChannels Channels>
[[gnu::always_inline]] inline glm::vec4 bilinear(const SoftTexture& t, const SamplerState& s, int level, glm::vec2 uv) {
    const MipLevel& l = t.levels[level];
    const BilinearTaps b = bilinearTaps(s, l.width, l.height, uv);
    const ByteTables& tables = byteTables();
    const glm::vec4 top =
        glm::mix(load<Channels>(t, tables, level, b.xa, b.ya), load<Channels>(t, tables, level, b.xb, b.ya), b.ax);
    const glm::vec4 bottom =
        glm::mix(load<Channels>(t, tables, level, b.xa, b.yb), load<Channels>(t, tables, level, b.xb, b.yb), b.ax);
    return glm::mix(top, bottom, b.ay);
}

}  // namespace

template <SampledChannels Channels>
glm::vec4 sampleTexture(const SoftTexture& t, const SamplerState& s, glm::vec2 uv, const UvDerivatives& d) {
    switch (s.filter) {
        case Filter::Nearest: return nearest<Channels>(t, s, 0, uv);
        case Filter::Bilinear: return bilinear<Channels>(t, s, 0, uv);
        case Filter::Trilinear: break;
    }
    const glm::vec2 size(t.levels[0].width, t.levels[0].height);
    const glm::vec2 sx = d.dx * size, sy = d.dy * size;
    const float rhoSquared = std::max(glm::dot(sx, sx), glm::dot(sy, sy));
    const int last = static_cast<int>(t.levels.size()) - 1;
    // Magnification without the log (textureLambda takes rho^2 > 1 only), NaN included (both
    // tests false).
    if (!(rhoSquared > 1.0f) || last == 0) return bilinear<Channels>(t, s, 0, uv);
    const float lambda = textureLambda(rhoSquared);
    if (lambda >= static_cast<float>(last)) return bilinear<Channels>(t, s, last, uv);
    const int lo = static_cast<int>(lambda);
    return glm::mix(bilinear<Channels>(t, s, lo, uv), bilinear<Channels>(t, s, lo + 1, uv), lambda - lo);
}

template glm::vec4 sampleTexture<SampledChannels::All>(const SoftTexture&, const SamplerState&, glm::vec2,
                                                       const UvDerivatives&);
template glm::vec4 sampleTexture<SampledChannels::AlphaOnly>(const SoftTexture&, const SamplerState&, glm::vec2,
                                                             const UvDerivatives&);

void generateMipLevel(SoftTexture& t, int level) {
    const MipLevel& src = t.levels[level - 1];
    MipLevel& dst = t.levels[level];
    for (int y = 0; y < dst.height; ++y) {
        for (int x = 0; x < dst.width; ++x) {
            // Odd sizes: the last row/column repeats (clamped), as a 2x2 box needs 4 texels.
            const int x0 = std::min(2 * x, src.width - 1), x1 = std::min(2 * x + 1, src.width - 1);
            const int y0 = std::min(2 * y, src.height - 1), y1 = std::min(2 * y + 1, src.height - 1);
            const glm::vec4 sum = loadTexel(t.texel(level - 1, x0, y0), t.desc.format) +
                                  loadTexel(t.texel(level - 1, x1, y0), t.desc.format) +
                                  loadTexel(t.texel(level - 1, x0, y1), t.desc.format) +
                                  loadTexel(t.texel(level - 1, x1, y1), t.desc.format);
            storeTexel(dst.texels.data() + (std::size_t(y) * dst.width + x) * t.bytesPerSample, t.desc.format,
                       sum * 0.25f, 0xF);
        }
    }
}

}  // namespace engine::render::soft
