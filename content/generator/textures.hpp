// SPDX-License-Identifier: MIT
#pragma once
// Procedural textures of the committed content: straight-alpha RGBA8 with sRGB colour codes,
// as glTF base colour textures are stored. Every function is a pure function of its seed.
#include <cstdint>
#include <vector>

#include "engine/assets/image.hpp"

namespace content {

using engine::assets::RgbaImage;

// 256x256 foliage: a cluster of twigs carrying leaves with soft (about 3 texel) alpha ramps at
// their edges, transparent elsewhere. Transparent texels hold the mean leaf colour, so even
// straight-alpha bilinear filtering never pulls in a dark fringe. Nothing touches the border.
RgbaImage makeLeafCluster(std::uint32_t seed);
// 256x256 foliage: a fern frond, a curved stem with tapering leaflets on both sides.
RgbaImage makeFrond(std::uint32_t seed);
// 128x128 opaque bark, tileable in both directions (u around the trunk, v up it).
RgbaImage makeBark(std::uint32_t seed);
// 256x256 opaque grass and dirt, tileable.
RgbaImage makeGround(std::uint32_t seed);
// 256x256 opaque asphalt across the road (u) with white edge lines and a dashed centre line,
// tileable along it (v).
RgbaImage makeTrack(std::uint32_t seed);
// 128x128 opaque car atlas: paint with a stripe and a number disc (v 0..0.5), glass
// (v 0.5..0.75), tyre rubber (v 0.75..1).
RgbaImage makeCarAtlas(std::uint32_t seed);

// PNG bytes of an image (straight alpha stored as is), encoded by OpenImageIO at a fixed
// compression level and with no metadata, so equal images give equal bytes.
std::vector<std::uint8_t> encodePng(const RgbaImage& image);

}  // namespace content
