// SPDX-License-Identifier: MIT
// ssam::gl's public API: the pass state machine of a frame (way b), the built-in programs on top
// of it (way a), and the boundary where every internal Failure becomes a Status + message.
#include "ssam/gl/ssam_gl.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <new>
#include <optional>
#include <string>

#include "../core/frame_sequence.hpp"
#include "../core/host_channel.hpp"
#include "../core/host_passes_impl.hpp"
#include "ssam/core/passes.hpp"
#include "../core/frame_rules.hpp"
#include "depth_restore.hpp"
#include "failure.hpp"
#include "frame_targets.hpp"
#include "gl_functions.hpp"
#include "gl_objects.hpp"
#include "gl_state_guard.hpp"
#include "shaders.hpp"

namespace ssam::gl {

using detail::Failure;
using detail::GlFunctions;
using detail::GlStateGuard;

void FoliageProgram::setModel(const float columnMajor[16]) const noexcept {
    if (gl) gl->UniformMatrix4fv(modelUniform, 1, GL_FALSE, columnMajor);
}
void FoliageProgram::setBaseColorFactor(float r, float g, float b, float a) const noexcept {
    if (gl) gl->Uniform4f(baseColorFactorUniform, r, g, b, a);
}
void FoliageProgram::bindBaseColorTexture(unsigned int texture) const noexcept {
    if (!gl) return;
    gl->ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(baseColorTextureUnit));
    gl->BindTexture(GL_TEXTURE_2D, texture);
    gl->Uniform1i(hasTextureUniform, texture != 0 ? 1 : 0);
}

namespace {

GLenum toGl(core::BlendFactor factor) {
    switch (factor) {
        case core::BlendFactor::Zero: return GL_ZERO;
        case core::BlendFactor::One: return GL_ONE;
        case core::BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
        case core::BlendFactor::OneMinusSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
    }
    return GL_ONE;
}

GLenum toGl(core::BlendOp op) { return op == core::BlendOp::Max ? GL_MAX : GL_FUNC_ADD; }

// A pass's blend (ssam/core/passes.hpp) as GL state: one blend for every draw buffer, or one per buffer
// (two mask targets, MaskPrecision::Rg16f: needs per-buffer blend equations, checked at settings).
void applyBlend(const GlFunctions& gl, const core::PassDescription& pass) {
    const core::TargetBlend& first = pass.colorTargets[0].blend;
    if (!first.enabled) {
        gl.Disable(GL_BLEND);
        return;
    }
    gl.Enable(GL_BLEND);
    if (pass.colorTargetCount == 1) {
        gl.BlendFuncSeparate(toGl(first.srcColor), toGl(first.dstColor), toGl(first.srcAlpha), toGl(first.dstAlpha));
        gl.BlendEquationSeparate(toGl(first.colorOp), toGl(first.alphaOp));
        return;
    }
    for (int t = 0; t < pass.colorTargetCount; ++t) {
        const core::TargetBlend& b = pass.colorTargets[t].blend;
        const auto buffer = static_cast<GLuint>(t);
        gl.BlendFuncSeparatei(buffer, toGl(b.srcColor), toGl(b.dstColor), toGl(b.srcAlpha), toGl(b.dstAlpha));
        gl.BlendEquationSeparatei(buffer, toGl(b.colorOp), toGl(b.alphaOp));
    }
}

GLenum toGl(DepthTest test) {
    switch (test) {
        case DepthTest::Less: return GL_LESS;
        case DepthTest::LessEqual: return GL_LEQUAL;
        case DepthTest::Greater: return GL_GREATER;
        case DepthTest::GreaterEqual: return GL_GEQUAL;
    }
    return GL_LESS;
}

// The locations the built-in programs read, each attribute's first and how many it takes.
struct AttributeSlot {
    const char* name;
    unsigned int first, count;
};
std::array<AttributeSlot, 6> slotsOf(const AttributeLocations& at) {
    return {{{"position", at.position, 1},
             {"normal", at.normal, 1},
             {"uv", at.uv, 1},
             {"color", at.color, 1},
             {"instanceModel", at.instanceModel, 4},
             {"instanceTint", at.instanceTint, 1}}};
}

// Each location below 16 (GL 3.3's minimum GL_MAX_VERTEX_ATTRIBS, so any context has it) and no
// two overlapping: a shader with aliased attribute locations does not link (GLSL 3.30 §4.3.8.1).
void validateAttributes(const AttributeLocations& at) {
    const auto slots = slotsOf(at);
    for (const AttributeSlot& a : slots) {
        if (a.first > 16 - a.count)
            throw Failure(Status::InvalidArgument,
                          std::string("ssam::gl settings: attributes.") + a.name + " = " + std::to_string(a.first) +
                              (a.count > 1 ? " (it takes " + std::to_string(a.count) + " locations)" : std::string()) +
                              " is past location 15 (GL guarantees 16 vertex attributes)");
        for (const AttributeSlot& b : slots)
            if (&a < &b && a.first < b.first + b.count && b.first < a.first + a.count)
                throw Failure(Status::InvalidArgument, std::string("ssam::gl settings: attributes.") + a.name + " (" +
                                                           std::to_string(a.first) + ") and attributes." + b.name +
                                                           " (" + std::to_string(b.first) + ") overlap");
    }
}

bool sameLocations(const AttributeLocations& a, const AttributeLocations& b) {
    return a.position == b.position && a.normal == b.normal && a.uv == b.uv && a.color == b.color &&
           a.instanceModel == b.instanceModel && a.instanceTint == b.instanceTint;
}

// Settings are checked by the core's rules (ssam::settingsError): every SSAM accepts the same knobs.
void validate(const Settings& settings) {
    if (const std::string error = ssam::settingsError(settings); !error.empty())
        throw Failure(Status::InvalidArgument, "ssam::gl: " + error);
}

// A built-in foliage program and its uniforms.
struct FoliageProgramObject {
    GLuint id = 0;
    GLint viewProj = -1, model = -1, factor = -1, hasTexture = -1, sampler = -1, alphaReference = -1, towardLight = -1,
          lightColor = -1, ambient = -1;
    void locate(const GlFunctions& gl) {
        detail::locateUniforms(gl, id,
                               {{&viewProj, "u_viewProj"},
                                {&model, "u_model"},
                                {&factor, "u_baseColorFactor"},
                                {&hasTexture, "u_hasTexture"},
                                {&sampler, "u_baseColor"},
                                {&alphaReference, "u_alphaReference"},
                                {&towardLight, "u_towardLight"},
                                {&lightColor, "u_lightColor"},
                                {&ambient, "u_ambient"}});
    }
};

}  // namespace

using core::Phase;

struct ScreenSpaceAlphaMaskGl::Impl {
    GlFunctions gl;
    bool initialized = false;
    Settings settings;
    core::PassPlan passes;  // describePasses(settings)
    AttributeLocations attributes;
    core::HostChannel channel{"ssam::gl"};

    FoliageProgramObject mask, color;
    GLuint composite = 0;
    shaders::CompositeInputs compositeInputs;
    GLuint emptyVao = 0;
    detail::FrameTargets targets;
    detail::DepthRestore depthRestore;  // Settings::depthMaskThreshold > 0 only

    // The open frame (way b, and way a through it).
    Phase phase = Phase::Idle;
    FrameDesc frame;
    Rect region;
    std::optional<GlStateGuard> passState;  // the host's state while a pass is open

    void message(Severity severity, const std::string& text) noexcept { channel.message(severity, text); }
    Status fail(Status status, const char* text) noexcept { return channel.fail(status, text); }

    // Ends an open frame early: the host's state back, nothing half-done left for the next one.
    void abandonFrame() noexcept {
        passState.reset();
        phase = Phase::Idle;
    }

    // Runs one public call: Ok, or the Failure's status with its message (the frame abandoned).
    template <class Body>
    Status run(Body&& body) noexcept {
        return channel.run(std::forward<Body>(body), [this]() noexcept { abandonFrame(); });
    }

    void expect(Phase expected, const char* call) const {
        core::expectPhase("ssam::gl", initialized, phase, expected, call);
    }

    void initialize(const detail::Loader& load, const Settings& wanted, const AttributeLocations& wantedAttributes,
                    Api api) {
        core::expectNoFrame("ssam::gl", phase, "initialize");
        deleteObjects();
        validate(wanted);
        validateAttributes(wantedAttributes);
        detail::loadFunctions(gl, load, api);
        const std::string context = detail::checkContext(gl, api);
        checkContextHas(gl, wanted);
        settings = wanted;
        passes = core::describePasses(settings);
        attributes = wantedAttributes;
        initialized = true;  // from here release() deletes what exists if a program does not compile
        try {
            gl.GenVertexArrays(1, &emptyVao);
            targets.createFramebuffers(gl);
            compileFoliagePrograms(wantedAttributes, mask, color);
            composite = detail::compileProgram(gl, "ssam::gl composite", shaders::kFullscreenVertex.c_str(),
                                               shaders::kCompositeFragment.c_str());
        } catch (...) {
            deleteObjects();
            throw;
        }
        compositeInputs.locate(gl, composite);
        message(Severity::Info, "ssam::gl " SSAM_VERSION_STRING " initialised on " + context);
    }

    // The built-in foliage programs reading the host's vertex arrays at `locations`.
    void compileFoliagePrograms(const AttributeLocations& locations, FoliageProgramObject& maskOut,
                                FoliageProgramObject& colorOut) {
        const std::string vertex = shaders::foliageVertex(locations);
        maskOut.id = detail::compileProgram(gl, "ssam::gl mask", vertex.c_str(), shaders::kMaskFragment.c_str());
        maskOut.locate(gl);
        colorOut.id = detail::compileProgram(gl, "ssam::gl colour", vertex.c_str(), shaders::kColorFragment.c_str());
        colorOut.locate(gl);
    }

    // Deletes SSAM's objects; false when no context is current (glGetString answers null then:
    // nothing can be deleted, the objects go with the host's context). Forgotten either way.
    bool deleteObjects() noexcept {
        abandonFrame();
        const bool current = !initialized || gl.GetString(GL_VERSION) != nullptr;
        if (initialized && current) {
            for (GLuint p : {mask.id, color.id, composite})
                if (p) gl.DeleteProgram(p);
            targets.destroy(gl);
            depthRestore.destroy(gl);
            if (emptyVao) gl.DeleteVertexArrays(1, &emptyVao);
        }
        mask = {}, color = {};
        composite = emptyVao = 0;
        targets = {};
        depthRestore = {};
        initialized = false;
        return current;
    }

    Status release() noexcept {
        if (deleteObjects()) return Status::Ok;
        return fail(Status::NoContext,
                    "ssam::gl: release() without a current GL context: SSAM's programs, textures and "
                    "framebuffers were not deleted (they go when the host destroys its context; make it "
                    "current before release() or the destructor to delete them now)");
    }

    // What the settings' mask needs of the context: float targets (ES: an extension) and, for
    // Rg16f's two targets blended differently, per-buffer blend equations.
    static void checkContextHas(const GlFunctions& gl, const Settings& wanted) {
        const MaskPrecision precision = wanted.maskPrecision;
        if (precision != MaskPrecision::Rgba8 && !gl.colorBufferFloat)
            throw Failure(Status::UnsupportedFeature,
                          std::string("ssam::gl settings: maskPrecision ") + maskPrecisionName(precision) +
                              " renders into float targets, which this OpenGL ES context cannot without "
                              "GL_EXT_color_buffer_float; use Rgba8");
        if (precision == MaskPrecision::Rg16f && !gl.perBufferBlend)
            throw Failure(Status::UnsupportedFeature,
                          gl.es ? "ssam::gl settings: maskPrecision Rg16f needs per-buffer blend equations "
                                  "(OpenGL ES 3.2, GL_OES_draw_buffers_indexed or GL_EXT_draw_buffers_indexed), "
                                  "which this context has not; use Rgba16f"
                                : "ssam::gl settings: maskPrecision Rg16f needs per-buffer blend equations (OpenGL "
                                  "4.0 or GL_ARB_draw_buffers_blend), which this context has not; use Rgba16f");
    }

    // ---- The frame, one step at a time --------------------------------------------------

    FrameReport beginFrame(const FrameDesc& desc) {
        expect(Phase::Idle, "beginFrame");
        if (!gl.GetString(GL_VERSION))
            throw Failure(Status::NoContext, "ssam::gl: no OpenGL context is current on this thread");
        if (desc.width <= 0 || desc.height <= 0)
            throw Failure(Status::InvalidArgument, "ssam::gl: frame size (FrameDesc::width x height) " +
                                                       std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                                                       " is not positive");
        if (desc.foliageBoundsCount > 0 && !desc.foliageBounds)
            throw Failure(Status::InvalidArgument, "ssam::gl: FrameDesc::foliageBoundsCount is " +
                                                       std::to_string(desc.foliageBoundsCount) +
                                                       " but foliageBounds is null");
        // The rules ssam::vk keeps too (frame_rules.hpp): finite matrices, boxes that can hold a card.
        if (const std::string error = ssam::detail::matrixError(desc.viewProj, "FrameDesc::viewProj"); !error.empty())
            throw Failure(Status::InvalidArgument, "ssam::gl: " + error);
        for (std::size_t i = 0; i < desc.foliageBoundsCount; ++i)
            if (const std::string error = ssam::detail::boxError(desc.foliageBounds[i].min, desc.foliageBounds[i].max,
                                                                 "FrameDesc::foliageBounds[" + std::to_string(i) + "]");
                !error.empty())
                throw Failure(Status::InvalidArgument, "ssam::gl: " + error);
        if (const GLenum pending = gl.GetError(); pending != GL_NO_ERROR) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "ssam::gl: a GL error (0x%04X) was pending when the frame began; it is the host's, "
                          "cleared so it is not taken for SSAM's",
                          pending);
            message(Severity::Warning, text);
        }
        FrameReport report;
        const std::optional<Rect> visible = detail::compositeRegion(gl, desc);
        if (!visible) return report;  // no foliage in view: SSAM costs nothing (not even its targets)
        {
            const GlStateGuard hostState(gl);
            targets.prepare(gl, desc, settings.maskPrecision);
        }
        frame = desc;
        region = *visible;
        phase = Phase::FrameBegun;
        report.foliageInView = true;
        report.passesRun = 3;
        report.compositeRegion = region;
        return report;
    }

    // State shared by the foliage passes: full viewport, no scissor, both faces (§3.5.2-3), no
    // stencil / polygon offset / alpha-to-coverage / logic op, sRGB targets blended in linear.
    // Left as the host set them: clip control (its depth convention), polygon mode, depth clamp,
    // sampler objects (they apply to the host's textures).
    void setFoliagePassState() {
        gl.Viewport(0, 0, frame.width, frame.height);
        gl.Disable(GL_SCISSOR_TEST);
        gl.Disable(GL_CULL_FACE);
        gl.Disable(GL_STENCIL_TEST);
        gl.Disable(GL_POLYGON_OFFSET_FILL);
        gl.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        detail::setDesktopOnly(gl, GL_COLOR_LOGIC_OP, false);  // a logic op would replace blending
        gl.Disable(GL_RASTERIZER_DISCARD);
        detail::disableFixedFunction(gl);  // compatibility contexts: a host's alpha test would cut the edges
        detail::setDesktopOnly(gl, GL_FRAMEBUFFER_SRGB, true);
        gl.colorMaskAt(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl.colorMaskAt(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }

    // The core's pass (ssam/core/passes.hpp) as GL state: culling, depth test and write, blend, and the
    // targets' clears.
    void applyPass(const core::PassDescription& pass) {
        // No SSAM pass culls today (cards are seen from both sides); a culling pass would cull the
        // faces the host's glCullFace names.
        if (pass.cullBackFaces) gl.Enable(GL_CULL_FACE);
        else gl.Disable(GL_CULL_FACE);
        if (pass.depthTest) {
            gl.Enable(GL_DEPTH_TEST);
            gl.DepthFunc(toGl(pass.depthCompare));
        } else {
            gl.Disable(GL_DEPTH_TEST);
        }
        gl.DepthMask(pass.depthWrite ? GL_TRUE : GL_FALSE);
        applyBlend(gl, pass);
    }
    void clearTargets(const core::PassDescription& pass) {
        for (int t = 0; t < pass.colorTargetCount; ++t)
            if (pass.colorTargets[t].clear) gl.ClearBufferfv(GL_COLOR, t, pass.colorTargets[t].clearColor);
    }

    // 1. Mask pass (§3.5.2, Table 3.1): cleared to black; RGB = MAX, A = ADD, all ONE (Rg16f:
    //    MAX into target 0, ADD into target 1); depth test without write; nothing rejected.
    PassInfo beginMaskPass() {
        expect(Phase::FrameBegun, "beginMaskPass");
        passState.emplace(gl);
        phase = Phase::InMaskPass;
        setFoliagePassState();
        const core::PassDescription& pass = passes.mask;
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.maskFramebuffer());
        clearTargets(pass);
        applyPass(pass);
        return {FoliagePass::Mask, pass.colorTargetCount, pass.alphaReference};
    }

    void endPass(Phase open, const char* call) {
        expect(open, call);
        passState.reset();  // the host's state back
        phase = open == Phase::InMaskPass ? Phase::MaskDone : Phase::ColorDone;
    }

    // 2. Colour pass (§3.5.3): cleared to the clear colour (§3.6.1); alpha test at the colour
    //    reference (the program's); depth test and write into the host's depth (§3.7); no blending.
    PassInfo beginColorPass() {
        expect(Phase::MaskDone, "beginColorPass");
        passState.emplace(gl);
        phase = Phase::InColorPass;
        setFoliagePassState();
        if (passes.restoresDepth)  // the opaque depth, before the colour pass writes the foliage's
            depthRestore.saveOpaqueDepth(gl, targets.maskFramebuffer(), targets.depthFormat(), frame.width,
                                         frame.height, region);
        const core::PassDescription& pass = passes.color;
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.foliageFramebuffer());
        clearTargets(pass);
        applyPass(pass);
        return {FoliagePass::Color, pass.colorTargetCount, pass.alphaReference};
    }

    // 3. Composite (§3.5.4, Listing 3.2): (foliage, mask') blended SRC_ALPHA / INV_SRC_ALPHA onto
    //    the host's colour = lerp(opaque, foliage, mask'); its alpha kept; scissored.
    void compositeFrame() {
        expect(Phase::ColorDone, "composite");
        const GlStateGuard hostState(gl);
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.compositeFramebuffer());
        gl.Viewport(0, 0, frame.width, frame.height);
        applyPass(passes.composite);
        gl.Disable(GL_STENCIL_TEST);
        detail::setDesktopOnly(gl, GL_COLOR_LOGIC_OP, false);
        gl.Disable(GL_RASTERIZER_DISCARD);
        gl.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        detail::disableFixedFunction(gl);
        detail::setDesktopOnly(gl, GL_FRAMEBUFFER_SRGB, true);
        gl.colorMaskAt(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl.Enable(GL_SCISSOR_TEST);
        gl.Scissor(region.x, region.y, region.width, region.height);
        gl.UseProgram(composite);
        const GLuint inputs[3] = {targets.foliage(), targets.mask(), targets.maskAdd()};
        for (GLuint unit = 0; unit < 3; ++unit) {
            gl.ActiveTexture(GL_TEXTURE0 + unit);
            gl.BindTexture(GL_TEXTURE_2D, inputs[unit] ? inputs[unit] : targets.mask());
        }
        compositeInputs.set(gl, 0, targets.maskAdd() != 0, settings);
        gl.BindVertexArray(emptyVao);
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
        if (passes.restoresDepth)
            depthRestore.restoreWhereMaskIsLow(gl, targets.foliageFramebuffer(), targets.maskAdd() != 0, settings);
        phase = Phase::Idle;
    }

    // What HostPasses calls (host_passes_impl.hpp): way (b)'s passes by name.
    PassInfo beginFoliagePass(FoliagePass which) {
        return which == FoliagePass::Mask ? beginMaskPass() : beginColorPass();
    }
    void endFoliagePass(FoliagePass which) {
        if (which == FoliagePass::Mask) endPass(Phase::InMaskPass, "endMaskPass");
        else endPass(Phase::InColorPass, "endColorPass");
    }

    // ---- Way (a): the built-in programs inside the passes ---------------------------------

    // The whole frame; a report only when the foliage was in view and every pass ran.
    FrameReport render(const FrameDesc& desc, DrawFoliage draw, void* user) {
        expect(Phase::Idle, "render");  // named as the host called it, not as beginFrame
        const FrameReport begun = beginFrame(desc);
        if (!begun.foliageInView) return {};
        const PassInfo maskPass = beginMaskPass();
        drawBuiltIn(mask, maskPass, draw, user);
        endPass(Phase::InMaskPass, "endMaskPass");
        const PassInfo colorPass = beginColorPass();
        drawBuiltIn(color, colorPass, draw, user);
        endPass(Phase::InColorPass, "endColorPass");
        compositeFrame();
        return begun;
    }

    void drawBuiltIn(const FoliageProgramObject& p, const PassInfo& pass, DrawFoliage draw, void* user) {
        // Generic values for attributes the host's VAO leaves disabled (initialize(), setAttributeLocations()). A
        // compatibility context has no generic value at location 0 (it is the vertex position).
        const AttributeLocations& at = attributes;
        const auto generic = [&](GLuint location, float x, float y, float z, float w) {
            if (location != 0 || !gl.compatibility) gl.VertexAttrib4f(location, x, y, z, w);
        };
        generic(at.normal, 0.0f, 0.0f, 1.0f, 1.0f);
        generic(at.uv, 0.0f, 0.0f, 0.0f, 1.0f);
        generic(at.color, 1.0f, 1.0f, 1.0f, 1.0f);
        for (unsigned int c = 0; c < 4; ++c) generic(at.instanceModel + c, c == 0, c == 1, c == 2, c == 3);
        generic(at.instanceTint, 1.0f, 1.0f, 1.0f, 1.0f);
        gl.UseProgram(p.id);
        gl.UniformMatrix4fv(p.viewProj, 1, GL_FALSE, frame.viewProj);
        const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        gl.UniformMatrix4fv(p.model, 1, GL_FALSE, identity);
        gl.Uniform4f(p.factor, 1.0f, 1.0f, 1.0f, 1.0f);
        gl.Uniform1i(p.hasTexture, 0);
        gl.Uniform1i(p.sampler, 0);
        if (pass.pass == FoliagePass::Color) {
            const Light& light = frame.light;
            const float length =
                std::sqrt(light.towardLight[0] * light.towardLight[0] + light.towardLight[1] * light.towardLight[1] +
                          light.towardLight[2] * light.towardLight[2]);
            float toward[3] = {0.0f, 0.0f, 0.0f};
            if (length > 0.0f && std::isfinite(length))
                for (int i = 0; i < 3; ++i) toward[i] = light.towardLight[i] / length;
            gl.Uniform1f(p.alphaReference, pass.alphaReference);
            gl.Uniform3fv(p.towardLight, 1, toward);
            gl.Uniform3fv(p.lightColor, 1, light.color);
            gl.Uniform3fv(p.ambient, 1, light.ambient);
        }
        FoliageProgram program;
        program.pass = pass.pass;
        program.program = p.id;
        program.modelUniform = p.model;
        program.baseColorFactorUniform = p.factor;
        program.hasTextureUniform = p.hasTexture;
        program.baseColorTextureUnit = 0;
        program.alphaReference = pass.alphaReference;
        program.gl = &gl;
        gl.ActiveTexture(GL_TEXTURE0);
        core::runDrawCallback("ssam::gl", pass.pass, [&] { draw(user, program); });
    }
};

// ---- Public calls: each one Impl step inside run() -----------------------------------------

namespace {

// A public call's frame: InvalidCall on a moved-from object, else `step(impl)` inside
// Impl::run, which turns a Failure (or any exception) into its Status and message.
template <class ImplPointer, class Step>
Status runStep(ImplPointer& impl, Step&& step) noexcept {
    if (!impl) return Status::InvalidCall;
    return impl->run([&] { step(*impl); });
}

}  // namespace

ScreenSpaceAlphaMaskGl::ScreenSpaceAlphaMaskGl() noexcept : impl_(new (std::nothrow) Impl) {}
ScreenSpaceAlphaMaskGl::~ScreenSpaceAlphaMaskGl() { release(); }
ScreenSpaceAlphaMaskGl::ScreenSpaceAlphaMaskGl(ScreenSpaceAlphaMaskGl&&) noexcept = default;
ScreenSpaceAlphaMaskGl& ScreenSpaceAlphaMaskGl::operator=(ScreenSpaceAlphaMaskGl&& other) noexcept {
    if (this != &other) {
        release();
        impl_ = std::move(other.impl_);
    }
    return *this;
}

Status ScreenSpaceAlphaMaskGl::initialize(GetProcAddress getProcAddress, const Settings& settings,
                                          const AttributeLocations& attributes, Api api) noexcept {
    if (!impl_) return Status::InvalidCall;
    if (!getProcAddress) return impl_->fail(Status::InvalidArgument, "ssam::gl: initialize() without a GL loader");
    return impl_->run([&] { impl_->initialize({getProcAddress, nullptr}, settings, attributes, api); });
}

Status ScreenSpaceAlphaMaskGl::initialize(GetProcAddressFunction getProcAddress, const Settings& settings,
                                          const AttributeLocations& attributes, Api api) noexcept {
    if (!impl_) return Status::InvalidCall;
    if (!getProcAddress) return impl_->fail(Status::InvalidArgument, "ssam::gl: initialize() without a GL loader");
    return impl_->run([&] { impl_->initialize({nullptr, getProcAddress}, settings, attributes, api); });
}

Status ScreenSpaceAlphaMaskGl::release() noexcept { return impl_ ? impl_->release() : Status::Ok; }

Status ScreenSpaceAlphaMaskGl::setSettings(const Settings& settings) noexcept {
    return runStep(impl_, [&](Impl& s) {
        core::expectNoFrame("ssam::gl", s.phase, "setSettings");
        validate(settings);
        if (s.initialized) Impl::checkContextHas(s.gl, settings);
        s.settings = settings;
        s.passes = core::describePasses(settings);
    });
}

Status ScreenSpaceAlphaMaskGl::setAttributeLocations(const AttributeLocations& attributes) noexcept {
    return runStep(impl_, [&](Impl& s) {
        core::expectNoFrame("ssam::gl", s.phase, "setAttributeLocations");
        validateAttributes(attributes);
        if (s.initialized && !sameLocations(attributes, s.attributes)) {
            // The new programs first: if they fail, the ones in use stay.
            if (!s.gl.GetString(GL_VERSION))
                throw Failure(Status::NoContext, "ssam::gl: setAttributeLocations() needs the GL context current");
            FoliageProgramObject newMask, newColor;
            try {
                s.compileFoliagePrograms(attributes, newMask, newColor);
            } catch (...) {
                if (newMask.id) s.gl.DeleteProgram(newMask.id);
                throw;
            }
            s.gl.DeleteProgram(s.mask.id);
            s.gl.DeleteProgram(s.color.id);
            s.mask = newMask, s.color = newColor;
        }
        s.attributes = attributes;
    });
}

const AttributeLocations& ScreenSpaceAlphaMaskGl::attributeLocations() const noexcept {
    static const AttributeLocations defaults;
    return impl_ ? impl_->attributes : defaults;
}

Intermediates ScreenSpaceAlphaMaskGl::intermediates() const noexcept {
    if (!impl_) return {};
    return {impl_->targets.mask(), impl_->targets.maskAdd(), impl_->targets.foliage()};
}

}  // namespace ssam::gl

// The calls ssam::gl shares with every host API, over Impl (host_passes_impl.hpp).
template class ssam::HostPasses<ssam::gl::ScreenSpaceAlphaMaskGl, ssam::gl::FrameDesc, ssam::gl::FoliageProgram,
                                ssam::gl::PassInfo>;
