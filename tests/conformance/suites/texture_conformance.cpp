// SPDX-License-Identifier: MIT
// Texture sampling through the surface programs: nearest and bilinear values at known UVs,
// wrap / clamp-to-edge / mirrored-repeat addressing, trilinear mip selection at known
// derivatives, generated mips, straight vs premultiplied declared alpha, sRGB decode before
// filtering. The references follow GL 4.5 §8.14 (texture minification: rho, lambda, the
// LINEAR_MIPMAP_LINEAR blend) and §8.14.2 (wrap modes), written here independently.
//
// The MaskedLit program with ambient 1 and no directional light outputs the (straight)
// texel itself, alpha included, so a textured quad into an RGBA32F target reads the filter
// result back unchanged.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "../backend_fixture.hpp"
#include "../reference_blend.hpp"

namespace ssam::test {
namespace {

using render::AddressMode;
using render::AlphaMode;
using render::Filter;
using render::ProgramKind;
using render::SamplerState;

template <typename T>
std::vector<std::byte> toBytes(const std::vector<T>& v) {
    std::vector<std::byte> out(v.size() * sizeof(T));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
}

// GL 4.5 §8.14.2, eq. 8.10 and table 8.20, for integer texel coordinate i.
int wrapTexel(AddressMode mode, int i, int size) {
    auto mod = [](int a, int b) { return ((a % b) + b) % b; };
    auto mirror = [](int a) { return a >= 0 ? a : -(1 + a); };
    switch (mode) {
        case AddressMode::Wrap: return mod(i, size);
        case AddressMode::Clamp: return std::clamp(i, 0, size - 1);
        case AddressMode::Mirror: return (size - 1) - mirror(mod(i, 2 * size) - size);
    }
    return 0;
}

struct Image {
    int width = 0, height = 0;
    std::vector<glm::dvec4> texels;  // linear values, row 0 first
    glm::dvec4 at(int x, int y) const { return texels[std::size_t(y) * width + x]; }
};

glm::dvec4 referenceNearest(const Image& img, const SamplerState& s, double u, double v) {
    const int x = wrapTexel(s.addressU, int(std::floor(u * img.width)), img.width);
    const int y = wrapTexel(s.addressV, int(std::floor(v * img.height)), img.height);
    return img.at(x, y);
}

glm::dvec4 referenceBilinear(const Image& img, const SamplerState& s, double u, double v) {
    const double fx = u * img.width - 0.5, fy = v * img.height - 0.5;
    const int i0 = int(std::floor(fx)), j0 = int(std::floor(fy));
    const double a = fx - i0, b = fy - j0;
    const int xa = wrapTexel(s.addressU, i0, img.width), xb = wrapTexel(s.addressU, i0 + 1, img.width);
    const int ya = wrapTexel(s.addressV, j0, img.height), yb = wrapTexel(s.addressV, j0 + 1, img.height);
    return (1 - a) * (1 - b) * img.at(xa, ya) + a * (1 - b) * img.at(xb, ya) + (1 - a) * b * img.at(xa, yb) +
           a * b * img.at(xb, yb);
}

class TextureRig {
public:
    explicit TextureRig(render::Backend& gfx) : gfx_(gfx) {}

    render::TextureHandle texture(Format format, int width, int height,
                                  const std::vector<std::vector<std::byte>>& levels, int mipLevels = 1,
                                  AlphaMode alpha = AlphaMode::Straight) {
        render::TextureDesc desc;
        desc.name = "texture";
        desc.width = width;
        desc.height = height;
        desc.format = format;
        desc.mipLevels = mipLevels;
        desc.usage = render::UsageSampled;
        desc.alpha = alpha;
        render::TextureData data;
        for (const auto& l : levels) data.levels.emplace_back(l);
        return gfx_.createTexture(desc, &data);
    }

    // A quad over the whole width x height RGBA32F target, uv (u0, v0) at the top-left corner
    // and (u1, v1) at the bottom-right, drawn with `program` sampling `texture`.
    render::Readback draw(int width, int height, render::TextureHandle texture, SamplerState sampler, glm::vec2 uv0,
                          glm::vec2 uv1, ProgramKind program = ProgramKind::MaskedLit) {
        std::vector<render::Vertex> quad = pixelRect(width, height, 0, 0, float(width), float(height));
        for (render::Vertex& v : quad) v.uv = uv0 + (uv1 - uv0) * v.uv;
        const render::TextureHandle target = outputTarget(width, height);
        const render::BufferHandle vb = gfx_.createBuffer(
            {"quad", render::BufferKind::Vertex, quad.size() * sizeof(render::Vertex)}, bytesOf(quad));
        render::PipelineDesc desc;
        desc.name = "textured";
        desc.program = program;
        const render::PipelineHandle pipeline = gfx_.createPipeline(desc);
        render::SurfaceParams params;
        params.baseColor = {texture, sampler};
        params.light.ambient = glm::vec3(1.0f);
        params.light.color = glm::vec3(0.0f);
        render::PassDesc pass;
        pass.name = "textured";
        pass.color[0] = {target, render::LoadOp::Clear, glm::vec4(-1.0f)};
        gfx_.beginPass(pass);
        gfx_.draw(meshDraw(pipeline, params, vb, 6));
        gfx_.endPass();
        render::Readback r = gfx_.readback(target);
        gfx_.destroy(target);
        gfx_.destroy(vb);
        gfx_.destroy(pipeline);
        return r;
    }

private:
    render::TextureHandle outputTarget(int width, int height) {
        render::TextureDesc desc;
        desc.name = "sampled_out";
        desc.width = width;
        desc.height = height;
        desc.format = Format::RGBA32F;
        desc.usage = render::UsageRenderTarget;
        return gfx_.createTexture(desc);
    }

    render::Backend& gfx_;
};

// A 4x4 RGBA32F image whose texels all differ, alpha 1 (so straight and premultiplied agree).
Image distinctImage(int width, int height) {
    Image img{width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            img.texels.push_back({(x + 0.25) / width, (y + 0.5) / height, double((x * 7 + y * 3) % 11) / 10.0, 1.0});
    return img;
}

std::vector<std::byte> floatBytes(const Image& img) {
    std::vector<float> f;
    for (const glm::dvec4& t : img.texels)
        for (int c = 0; c < 4; ++c) f.push_back(float(t[c]));
    return toBytes(f);
}

void expectNear(const render::Readback& r, int x, int y, glm::dvec4 expected, double tolerance,
                const std::string& what) {
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(r.at(x, y, c), expected[c], tolerance) << what << " at pixel " << x << "," << y << " channel " << c;
}

TEST_P(TextureConformance, NearestAndBilinearAtKnownUvs) {
    TextureRig rig(gfx());
    const Image img = distinctImage(4, 4);
    const render::TextureHandle tex = rig.texture(Format::RGBA32F, 4, 4, {floatBytes(img)});
    for (Filter filter : {Filter::Nearest, Filter::Bilinear}) {
        const SamplerState s{filter, AddressMode::Wrap, AddressMode::Wrap};
        // 8x8 pixels over the texture: pixel centres at texel quarter points.
        const render::Readback r = rig.draw(8, 8, tex, s, {0, 0}, {1, 1});
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                const double u = (x + 0.5) / 8, v = (y + 0.5) / 8;
                const glm::dvec4 expected =
                    filter == Filter::Nearest ? referenceNearest(img, s, u, v) : referenceBilinear(img, s, u, v);
                expectNear(r, x, y, expected, 1e-5, filter == Filter::Nearest ? "nearest" : "bilinear");
            }
    }
}

TEST_P(TextureConformance, AddressModes) {
    TextureRig rig(gfx());
    const Image img = distinctImage(4, 4);
    const render::TextureHandle tex = rig.texture(Format::RGBA32F, 4, 4, {floatBytes(img)});
    const AddressMode modes[] = {AddressMode::Wrap, AddressMode::Clamp, AddressMode::Mirror};
    for (Filter filter : {Filter::Nearest, Filter::Bilinear}) {
        for (AddressMode mu : modes) {
            for (AddressMode mv : modes) {
                const SamplerState s{filter, mu, mv};
                // uv from -1 to 2: three periods across 24 pixels.
                const render::Readback r = rig.draw(24, 24, tex, s, {-1, -1}, {2, 2});
                for (int y = 0; y < 24; ++y)
                    for (int x = 0; x < 24; ++x) {
                        const double u = -1.0 + 3.0 * (x + 0.5) / 24, v = -1.0 + 3.0 * (y + 0.5) / 24;
                        const glm::dvec4 expected = filter == Filter::Nearest ? referenceNearest(img, s, u, v)
                                                                              : referenceBilinear(img, s, u, v);
                        expectNear(r, x, y, expected, 1e-4,
                                   std::string(filter == Filter::Nearest ? "nearest" : "bilinear") + " modes " +
                                       std::to_string(int(mu)) + "/" + std::to_string(int(mv)));
                        if (HasFailure()) return;
                    }
            }
        }
    }
}

// A 16x16 mip chain with a distinct solid colour per level. A quad of n pixels over the whole
// texture has rho = 16 / n texels per pixel, lambda = log2(rho): 16 px picks level 0, 8 px
// level 1, 4 px level 2, lambda beyond the last level clamps to it, and a fractional lambda
// blends the two levels around it (LINEAR_MIPMAP_LINEAR). rho is the larger of the x and y
// scale factors.
TEST_P(TextureConformance, TrilinearSelectsTheMipLevel) {
    TextureRig rig(gfx());
    const glm::dvec4 colours[5] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 0, 1}, {0, 1, 1, 1}};
    std::vector<std::vector<std::byte>> levels;
    for (int level = 0; level < 5; ++level) {
        const int size = 16 >> level;
        std::vector<float> f;
        for (int i = 0; i < size * size; ++i)
            for (int c = 0; c < 4; ++c) f.push_back(float(colours[level][c]));
        levels.push_back(toBytes(f));
    }
    const render::TextureHandle tex = rig.texture(Format::RGBA32F, 16, 16, levels, 5);
    const SamplerState s{Filter::Trilinear, AddressMode::Wrap, AddressMode::Wrap};
    auto expectedFor = [&](double lambda) {
        if (lambda <= 0.0) return colours[0];
        if (lambda >= 4.0) return colours[4];
        const int lo = int(std::floor(lambda));
        const double t = lambda - lo;
        return (1 - t) * colours[lo] + t * colours[lo + 1];
    };
    struct Case {
        int width, height;
        glm::vec2 uvMax;
    };
    const Case cases[] = {
        {32, 32, {1, 1}},    // magnified: lambda -1
        {16, 16, {1, 1}},    // lambda 0
        {8, 8, {1, 1}},      // minified 2x: level 1
        {4, 4, {1, 1}},      // level 2
        {2, 2, {1, 1}},      // level 3
        {8, 8, {1.5, 1.5}},  // lambda log2(3): between 1 and 2
        {8, 4, {1, 1}},      // anisotropic: rho = max(2, 4), level 2
        {6, 6, {1, 1}},      // lambda log2(16/6)
        {1, 1, {64, 64}},    // lambda 10: clamps to the last level
    };
    for (const Case& k : cases) {
        const double rho = std::max(16.0 * k.uvMax.x / k.width, 16.0 * k.uvMax.y / k.height);
        const glm::dvec4 expected = expectedFor(std::log2(rho));
        const render::Readback r = rig.draw(k.width, k.height, tex, s, {0, 0}, k.uvMax);
        for (int y = 0; y < k.height; ++y)
            for (int x = 0; x < k.width; ++x)
                expectNear(r, x, y, expected, 1e-4,
                           std::to_string(k.width) + "x" + std::to_string(k.height) + " lambda " +
                               std::to_string(std::log2(rho)));
    }
}

// Levels not given are box-filtered from the one above, in linear light: a black/white
// checkerboard's level 1 is grey 0.5 in linear terms, for UNORM and for sRGB alike.
TEST_P(TextureConformance, GeneratedMipsAverageInLinearLight) {
    TextureRig rig(gfx());
    for (Format format : {Format::RGBA8_UNORM, Format::RGBA8_SRGB}) {
        std::vector<std::uint8_t> texels;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const std::uint8_t v = (x + y) % 2 ? 255 : 0;
                texels.insert(texels.end(), {v, v, v, 255});
            }
        const render::TextureHandle tex = rig.texture(format, 16, 16, {toBytes(texels)}, 5);
        const render::Readback r =
            rig.draw(8, 8, tex, {Filter::Trilinear, AddressMode::Wrap, AddressMode::Wrap}, {0, 0}, {1, 1});
        // The stored level-1 texel is the 8-bit code nearest to linear 0.5 (sRGB: encoded).
        const double stored = format == Format::RGBA8_SRGB
                                  ? reference::srgbDecode(reference::unormCode(reference::srgbEncode(0.5)) / 255.0)
                                  : reference::unormCode(0.5) / 255.0;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(r.at(3, 3, c), stored, 1.0 / 255.0) << formatName(format) << " channel " << c;
        EXPECT_NEAR(r.at(3, 3, 3), 1.0, 1e-6);
    }
}

// A premultiplied texture is un-premultiplied by the program; a straight one is used as is.
TEST_P(TextureConformance, PremultipliedAndStraightDeclaredAlpha) {
    TextureRig rig(gfx());
    const SamplerState nearest{Filter::Nearest, AddressMode::Clamp, AddressMode::Clamp};
    const std::vector<float> premultiplied = {0.4f, 0.2f, 0.1f, 0.5f};
    const std::vector<float> straight = {0.8f, 0.4f, 0.2f, 0.5f};
    const render::TextureHandle p =
        rig.texture(Format::RGBA32F, 1, 1, {toBytes(premultiplied)}, 1, AlphaMode::Premultiplied);
    const render::TextureHandle s = rig.texture(Format::RGBA32F, 1, 1, {toBytes(straight)}, 1, AlphaMode::Straight);
    for (render::TextureHandle tex : {p, s}) {
        const render::Readback r = rig.draw(2, 2, tex, nearest, {0, 0}, {1, 1});
        expectNear(r, 1, 1, {0.8, 0.4, 0.2, 0.5}, 1e-6, tex == p ? "premultiplied" : "straight");
    }
    // Fully transparent premultiplied texels give finite colour.
    const std::vector<float> clear = {0.0f, 0.0f, 0.0f, 0.0f};
    const render::TextureHandle z = rig.texture(Format::RGBA32F, 1, 1, {toBytes(clear)}, 1, AlphaMode::Premultiplied);
    const render::Readback r = rig.draw(2, 2, z, nearest, {0, 0}, {1, 1});
    for (float v : r.values) EXPECT_TRUE(std::isfinite(v));
    EXPECT_EQ(r.at(0, 0, 3), 0.0f);
}

// Filtering between a transparent texel and opaque red: premultiplied texels filter to
// (0.5, 0, 0, 0.5) premultiplied, i.e. straight red at half alpha (no dark fringe); the same
// straight texels filter to dark red at half alpha.
TEST_P(TextureConformance, PremultipliedFilteringHasNoDarkFringe) {
    TextureRig rig(gfx());
    const std::vector<float> texels = {0, 0, 0, 0, 1, 0, 0, 1};  // 2x1: transparent, red
    const SamplerState bilinear{Filter::Bilinear, AddressMode::Clamp, AddressMode::Clamp};
    const render::TextureHandle p = rig.texture(Format::RGBA32F, 2, 1, {toBytes(texels)}, 1, AlphaMode::Premultiplied);
    const render::TextureHandle s = rig.texture(Format::RGBA32F, 2, 1, {toBytes(texels)}, 1, AlphaMode::Straight);
    // A 1x1 target: its pixel centre samples u = 0.5, half way between the texel centres.
    expectNear(rig.draw(1, 1, p, bilinear, {0, 0}, {1, 1}), 0, 0, {1.0, 0.0, 0.0, 0.5}, 1e-6, "premultiplied");
    expectNear(rig.draw(1, 1, s, bilinear, {0, 0}, {1, 1}), 0, 0, {0.5, 0.0, 0.0, 0.5}, 1e-6, "straight");
}

// sRGB texels are decoded to linear before filtering; alpha is never decoded.
TEST_P(TextureConformance, SrgbDecodedBeforeFiltering) {
    TextureRig rig(gfx());
    const std::vector<std::uint8_t> texels = {0, 0, 0, 255, 255, 255, 255, 128};
    const render::TextureHandle tex = rig.texture(Format::RGBA8_SRGB, 2, 1, {toBytes(texels)});
    // Half way: linear (0 + 1) / 2, not decode(127.5 / 255) = 0.212.
    const render::Readback mid =
        rig.draw(1, 1, tex, {Filter::Bilinear, AddressMode::Clamp, AddressMode::Clamp}, {0, 0}, {1, 1});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mid.at(0, 0, c), 0.5, 1e-5);
    EXPECT_NEAR(mid.at(0, 0, 3), (1.0 + 128.0 / 255.0) / 2.0, 1e-5);

    const std::vector<std::uint8_t> one = {188, 64, 10, 77};
    const render::TextureHandle single = rig.texture(Format::RGBA8_SRGB, 1, 1, {toBytes(one)});
    const render::Readback r =
        rig.draw(1, 1, single, {Filter::Nearest, AddressMode::Wrap, AddressMode::Wrap}, {0, 0}, {1, 1});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.at(0, 0, c), reference::srgbDecode(one[c] / 255.0), 1e-6) << c;
    EXPECT_NEAR(r.at(0, 0, 3), 77.0 / 255.0, 1e-6);
}

// RGBA16F textures take 32-bit floats and store them rounded to half.
TEST_P(TextureConformance, HalfFloatTexturesRoundToHalf) {
    TextureRig rig(gfx());
    const std::vector<float> texel = {0.1f, 1.0f / 3.0f, 1000.7f, -2.2f};
    const render::TextureHandle tex = rig.texture(Format::RGBA16F, 1, 1, {toBytes(texel)});
    const render::Readback r =
        rig.draw(1, 1, tex, {Filter::Nearest, AddressMode::Wrap, AddressMode::Wrap}, {0, 0}, {1, 1});
    for (int c = 0; c < 4; ++c) EXPECT_EQ(r.at(0, 0, c), float(reference::roundToHalf(texel[c]))) << c;
}

// OpaqueLit forces alpha to 1 whatever the texture says.
TEST_P(TextureConformance, OpaqueLitForcesAlphaOne) {
    TextureRig rig(gfx());
    const std::vector<float> texel = {0.25f, 0.5f, 0.75f, 0.3f};
    const render::TextureHandle tex = rig.texture(Format::RGBA32F, 1, 1, {toBytes(texel)});
    const render::Readback r = rig.draw(2, 2, tex, {Filter::Nearest, AddressMode::Wrap, AddressMode::Wrap}, {0, 0},
                                        {1, 1}, ProgramKind::OpaqueLit);
    expectNear(r, 0, 0, {0.25, 0.5, 0.75, 1.0}, 1e-6, "opaque lit");
}

}  // namespace
}  // namespace ssam::test
