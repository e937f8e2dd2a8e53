// SPDX-License-Identifier: MIT
// Set-up kept from one pass for the next (SoftOptions::reuseGeometry, src/geometry_key.hpp):
// a draw whose geometry input equals one of the last pass's draws takes that draw's set-up
// triangles and bins. Each test renders the same passes with reuse on and off and wants the
// same bits, and checks from SoftStats::trianglesReused that reuse did (or did not) happen,
// so that neither a stale reuse nor a reuse that never runs can pass.
#include <cstring>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "soft_test_util.hpp"

namespace ssam::test::soft {
namespace {

constexpr int kWidth = 96, kHeight = 64;
constexpr std::uint32_t kTriangles = 2500;  // more than one 2048-triangle chunk

std::vector<render::Vertex> randomTriangles(std::uint32_t seed) {
    return soft::randomTriangles(kTriangles, seed, 0.15f);
}

// What the passes draw; each test changes one thing between the first pass and the second.
struct Scene {
    render::Backend& gfx;
    render::TextureHandle first, second, depth, depthSecond;
    render::BufferHandle vertices, indices, instances;
    render::PipelineHandle flat, flatCulled;
    glm::mat4 viewProj = glm::perspective(1.0f, float(kWidth) / kHeight, 0.5f, 20.0f);

    explicit Scene(render::Backend& backend) : gfx(backend) {
        first = makeTarget(gfx, kWidth, kHeight, Format::RGBA32F, 1, "first");
        second = makeTarget(gfx, kWidth, kHeight, Format::RGBA32F, 1, "second");
        depth = makeTarget(gfx, kWidth, kHeight, Format::D32F, 1, "depth");
        depthSecond = makeTarget(gfx, kWidth, kHeight, Format::D32F, 1, "depth second");
        vertices = makeVertices(gfx, randomTriangles(1));
        std::vector<std::uint32_t> order(kTriangles * 3);
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(order.size()) - 1 - i;
        indices = makeIndices(gfx, order);
        std::vector<render::Instance> two(2);
        two[1].model = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, -0.5f));
        two[1].tint = {0.5f, 1.0f, 0.75f, 1.0f};
        instances = gfx.createBuffer({"instances", render::BufferKind::Instance, two.size() * sizeof(render::Instance)},
                                     bytesOf(two));
        render::PipelineDesc desc = pipelineDesc("flat");
        desc.depth.test = true;
        desc.depth.write = true;
        desc.depth.func = CompareFunc::LessEqual;
        flat = gfx.createPipeline(desc);
        desc.name = "flat culled";
        desc.raster.cull = render::CullMode::Back;
        flatCulled = gfx.createPipeline(desc);
    }

    render::DrawDesc draw(glm::vec4 color = glm::vec4(1.0f)) const {
        render::DrawDesc d = meshDraw(flat, render::FlatParams{viewProj, color}, vertices, kTriangles * 3);
        d.indices = indices;
        d.instances = instances;
        d.instanceCount = 2;
        return d;
    }

    void pass(render::TextureHandle color, render::TextureHandle z, const std::vector<render::DrawDesc>& draws) {
        gfx.beginPass(onePass(color, z));
        for (const render::DrawDesc& d : draws) gfx.draw(d);
        gfx.endPass();
    }
};

struct Result {
    std::vector<float> first, second;  // both passes' targets
    std::uint64_t reused = 0;
    std::uint64_t rasterized = 0;
};

// The first pass draws what `before` gives, `between` changes the scene, and the second pass
// draws what `after` gives, into its own targets.
using Draws = std::function<std::vector<render::DrawDesc>(Scene&)>;
Result render(bool reuse, const Draws& before, const std::function<void(Scene&)>& between, const Draws& after) {
    auto gfx = createSoftBackend({.threads = 2, .reuseGeometry = reuse});
    Scene scene(*gfx);
    scene.pass(scene.first, scene.depth, before(scene));
    between(scene);
    scene.pass(scene.second, scene.depthSecond, after(scene));
    const auto stats = softDriver(*gfx).stats();
    return {gfx->readback(scene.first).values, gfx->readback(scene.second).values, stats.trianglesReused,
            stats.trianglesRasterized};
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Renders with reuse on and off: the same bits in both targets, and `reused` triangles taken.
void expectReuse(std::uint64_t reused, const Draws& before, const std::function<void(Scene&)>& between,
                 const Draws& after) {
    const Result on = render(true, before, between, after), off = render(false, before, between, after);
    EXPECT_EQ(on.reused, reused);
    EXPECT_EQ(off.reused, 0u);
    EXPECT_EQ(on.rasterized, off.rasterized);
    EXPECT_TRUE(sameBits(on.first, off.first));
    EXPECT_TRUE(sameBits(on.second, off.second)) << "the second pass differs with reuse";
    // Something was drawn: an empty target would make the comparison mean nothing.
    EXPECT_NE(std::count(on.second.begin(), on.second.end(), 0.0f), std::ptrdiff_t(on.second.size()));
}

const Draws kOneDraw = [](Scene& s) { return std::vector<render::DrawDesc>{s.draw()}; };
const auto kNothing = [](Scene&) {};
constexpr std::uint64_t kDrawTriangles = 2ull * kTriangles;  // two instances

TEST(GeometryReuse, TheSameDrawInTheNextPassTakesItsSetUp) {
    // Another colour (params the set-up does not read) and other targets of the same size.
    expectReuse(kDrawTriangles, kOneDraw, kNothing, [](Scene& s) {
        return std::vector<render::DrawDesc>{s.draw({0.5f, 0.25f, 1.0f, 1.0f})};
    });
}

TEST(GeometryReuse, ADrawAtAnotherIndexIsShadedAsThatDraw) {
    // The kept triangles were the first pass's draw 0; here they are draw 1, behind a draw of
    // other geometry (one instance) in another colour, which they must not be shaded as.
    expectReuse(kDrawTriangles, kOneDraw, kNothing, [](Scene& s) {
        render::DrawDesc other = s.draw({1.0f, 0.0f, 0.0f, 1.0f});
        other.instanceCount = 1;
        return std::vector<render::DrawDesc>{other, s.draw({0.0f, 0.5f, 1.0f, 1.0f})};
    });
}

TEST(GeometryReuse, EachKeptDrawIsTakenOnce) {
    const Draws twice = [](Scene& s) { return std::vector<render::DrawDesc>{s.draw(), s.draw()}; };
    const Draws thrice = [](Scene& s) { return std::vector<render::DrawDesc>{s.draw(), s.draw(), s.draw()}; };
    expectReuse(2 * kDrawTriangles, twice, kNothing, thrice);
}

TEST(GeometryReuse, OnlyTheLastPassIsKept) {
    // first pass: the draw; a pass between of other geometry; second pass: the draw again.
    expectReuse(
        0, kOneDraw,
        [](Scene& s) {
            render::DrawDesc other = s.draw();
            other.instanceCount = 1;
            s.pass(s.second, s.depthSecond, {other});
        },
        kOneDraw);
}

// What the set-up reads, changed between the passes: nothing may be reused.
struct Change {
    const char* name;
    std::function<void(Scene&)> between;
    std::function<void(render::DrawDesc&, Scene&)> draw;
};

void PrintTo(const Change& change, std::ostream* out) { *out << change.name; }

void noDrawChange(render::DrawDesc&, Scene&) {}

class GeometryReuseChange : public ::testing::TestWithParam<Change> {};

TEST_P(GeometryReuseChange, IsSetUpAgain) {
    const Change& change = GetParam();
    expectReuse(0, kOneDraw, change.between, [&](Scene& s) {
        render::DrawDesc d = s.draw();
        change.draw(d, s);
        return std::vector<render::DrawDesc>{d};
    });
}

render::Instance movedInstance() {
    render::Instance moved;
    moved.model = glm::translate(glm::mat4(1.0f), glm::vec3(-0.25f, 0.0f, 0.0f));
    return moved;
}

const Change kChanges[] = {
    {"vertex_written",
     [](Scene& s) {
         // One vertex's colour: only an attribute plane changes.
         render::Vertex v = randomTriangles(1)[7];
         v.color = {0.0f, 1.0f, 0.0f, 1.0f};
         s.gfx.updateBuffer(s.vertices, 7 * sizeof(render::Vertex), std::as_bytes(std::span(&v, 1)));
     },
     noDrawChange},
    {"index_written",
     [](Scene& s) {
         const std::uint32_t swapped[3] = {0, 2, 1};  // triangle 0's winding
         s.gfx.updateBuffer(s.indices, 0, std::as_bytes(std::span(swapped)));
     },
     noDrawChange},
    {"instance_written",
     [](Scene& s) {
         const render::Instance moved = movedInstance();
         s.gfx.updateBuffer(s.instances, sizeof(render::Instance), std::as_bytes(std::span(&moved, 1)));
     },
     noDrawChange},
    {"vertex_buffer_replaced",
     [](Scene& s) {
         s.gfx.destroy(s.vertices);
         s.vertices = makeVertices(s.gfx, randomTriangles(2));
     },
     [](render::DrawDesc& d, Scene& s) { d.vertices = s.vertices; }},
    {"camera", kNothing,
     [](render::DrawDesc& d, Scene& s) {
         d.params = render::FlatParams{glm::translate(s.viewProj, glm::vec3(0.0f, 0.0f, -0.01f)), glm::vec4(1.0f)};
     }},
    {"first_index", kNothing, [](render::DrawDesc& d, Scene&) { d.first = 3, d.count -= 3; }},
    {"instance_count", kNothing, [](render::DrawDesc& d, Scene&) { d.instanceCount = 1; }},
    {"scissor", kNothing,
     [](render::DrawDesc& d, Scene&) {
         d.scissor = render::Rect{8, 8, 40, 40};
     }},
    {"culling", kNothing, [](render::DrawDesc& d, Scene& s) { d.pipeline = s.flatCulled; }},
};

INSTANTIATE_TEST_SUITE_P(EachInput, GeometryReuseChange, ::testing::ValuesIn(kChanges),
                         [](const ::testing::TestParamInfo<Change>& info) { return std::string(info.param.name); });

// Passes onto targets without depth: the same draw with a pipeline that tests none.
render::DrawDesc depthlessDraw(Scene& s) {
    render::DrawDesc d = s.draw();
    d.pipeline = s.gfx.createPipeline(pipelineDesc("flat without depth"));
    return d;
}

TEST(GeometryReuse, AnotherTargetSizeIsSetUpAgain) {
    auto gfx = createSoftBackend({.threads = 2});
    Scene scene(*gfx);
    const render::TextureHandle narrow = makeTarget(*gfx, kWidth / 2, kHeight, Format::RGBA32F, 1, "narrow");
    const render::DrawDesc d = depthlessDraw(scene);
    scene.pass(scene.first, {}, {d});
    scene.pass(narrow, {}, {d});
    EXPECT_EQ(softDriver(*gfx).stats().trianglesReused, 0u);
    scene.pass(narrow, {}, {d});  // the same size again: taken
    EXPECT_EQ(softDriver(*gfx).stats().trianglesReused, kDrawTriangles);
}

TEST(GeometryReuse, AnotherSamplePatternIsSetUpAgain) {
    auto gfx = createSoftBackend({.threads = 2});
    Scene scene(*gfx);
    const render::TextureHandle msaa = makeTarget(*gfx, kWidth, kHeight, Format::RGBA8_UNORM, 4, "msaa");
    const render::DrawDesc d = depthlessDraw(scene);
    scene.pass(scene.first, {}, {d});
    scene.pass(msaa, {}, {d});
    EXPECT_EQ(softDriver(*gfx).stats().trianglesReused, 0u);
}

}  // namespace
}  // namespace ssam::test::soft
