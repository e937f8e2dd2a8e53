// SPDX-License-Identifier: MIT
#include "ssam/gl/ssam_gl.hpp"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "engine/core/error.hpp"
#include "engine/render/screen_bounds.hpp"
#include "gl_objects.hpp"
#include "gl_state_guard.hpp"
#include "shaders.hpp"

namespace ssam::gl {

using engine::Error;
using engine::render::Rect;

const char* foliagePassName(FoliagePass pass) { return pass == FoliagePass::Mask ? "mask" : "colour"; }

void FoliageProgram::setModel(const glm::mat4& model) const {
    glUniformMatrix4fv(modelUniform, 1, GL_FALSE, glm::value_ptr(model));
}
void FoliageProgram::setBaseColorFactor(const glm::vec4& factor) const {
    glUniform4fv(baseColorFactorUniform, 1, glm::value_ptr(factor));
}
void FoliageProgram::bindBaseColorTexture(unsigned int texture) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(baseColorTextureUnit));
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(hasTextureUniform, texture != 0 ? 1 : 0);
}

namespace {

GLenum toGl(engine::render::CompareFunc f) {
    using engine::render::CompareFunc;
    switch (f) {
        case CompareFunc::Never: return GL_NEVER;
        case CompareFunc::Less: return GL_LESS;
        case CompareFunc::Equal: return GL_EQUAL;
        case CompareFunc::LessEqual: return GL_LEQUAL;
        case CompareFunc::Greater: return GL_GREATER;
        case CompareFunc::NotEqual: return GL_NOTEQUAL;
        case CompareFunc::GreaterEqual: return GL_GEQUAL;
        case CompareFunc::Always: return GL_ALWAYS;
    }
    return GL_LESS;
}

bool isColorFormat(GLint f) { return f == GL_RGBA8 || f == GL_SRGB8_ALPHA8 || f == GL_RGBA16F || f == GL_RGBA32F; }
bool isDepthFormat(GLint f) {
    return f == GL_DEPTH_COMPONENT16 || f == GL_DEPTH_COMPONENT24 || f == GL_DEPTH_COMPONENT32F ||
           f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8;
}
bool hasStencil(GLint f) { return f == GL_DEPTH24_STENCIL8 || f == GL_DEPTH32F_STENCIL8; }

GLuint createTarget(GLint internalFormat, int width, int height) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    const bool isFloat = internalFormat == GL_RGBA16F || internalFormat == GL_RGBA32F || internalFormat == GL_R16F;
    const GLenum format = internalFormat == GL_R16F ? GL_RED : GL_RGBA;
    // Immutable storage where there is (GL 4.2): hosts can then make views of SSAM's targets.
    static const bool immutable = epoxy_gl_version() >= 42 || epoxy_has_gl_extension("GL_ARB_texture_storage");
    if (immutable)
        glTexStorage2D(GL_TEXTURE_2D, 1, static_cast<GLenum>(internalFormat), width, height);
    else
        glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, isFloat ? GL_FLOAT : GL_UNSIGNED_BYTE,
                     nullptr);
    // Sampled with texelFetch only; a non-mipmap filter makes the texture complete.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return t;
}

struct FoliageProgramObject {
    GLuint id = 0;
    GLint viewProj = -1, model = -1, factor = -1, hasTexture = -1, sampler = -1, alphaReference = -1,
          towardLight = -1, lightColor = -1, ambient = -1;
    void locate() {
        viewProj = glGetUniformLocation(id, "u_viewProj");
        model = glGetUniformLocation(id, "u_model");
        factor = glGetUniformLocation(id, "u_baseColorFactor");
        hasTexture = glGetUniformLocation(id, "u_hasTexture");
        sampler = glGetUniformLocation(id, "u_baseColor");
        alphaReference = glGetUniformLocation(id, "u_alphaReference");
        towardLight = glGetUniformLocation(id, "u_towardLight");
        lightColor = glGetUniformLocation(id, "u_lightColor");
        ambient = glGetUniformLocation(id, "u_ambient");
    }
};

}  // namespace

struct ScreenSpaceAlphaMaskGl::Impl {
    bool perBufferBlend = false;
    bool clipControl = false;
    FoliageProgramObject mask, color;
    GLuint composite = 0;
    GLint compositeFoliage = -1, compositeMask = -1, compositeMaskAdd = -1, compositeHasMaskAdd = -1,
          compositeMaskLerp = -1, compositeSquare = -1;
    GLuint emptyVao = 0;
    GLuint maskFbo = 0, foliageFbo = 0, compositeFbo = 0;
    // SSAM's targets, (re)created when size, precision or colour format change.
    GLuint maskTex = 0, maskAddTex = 0, foliageTex = 0;
    int width = 0, height = 0;
    GLint foliageFormat = 0;
    std::optional<MaskPrecision> precision;
    // The engine's textures currently attached.
    GLuint attachedColor = 0, attachedDepth = 0;
    bool attachedDepthStencil = false;

    ~Impl() {
        // Nothing created yet (the constructor threw), or the host's context is already gone
        // (its objects went with it): calling GL would abort inside libepoxy.
        if (!emptyVao || !hasCurrentContext()) return;
        for (GLuint p : {mask.id, color.id, composite})
            if (p) glDeleteProgram(p);
        destroyTargets();
        const GLuint fbos[] = {maskFbo, foliageFbo, compositeFbo};
        glDeleteFramebuffers(3, fbos);
        glDeleteVertexArrays(1, &emptyVao);
    }

    void destroyTargets() {
        const GLuint textures[] = {maskTex, maskAddTex, foliageTex};
        glDeleteTextures(3, textures);
        maskTex = maskAddTex = foliageTex = 0;
        width = height = 0;
        precision.reset();
        foliageFormat = 0;
    }
};

namespace {

// Throws unless a GL 3.3+ core context is current; returns whether per-buffer blending exists.
bool requireContext() {
    if (!hasCurrentContext()) throw Error("ssam_gl: no OpenGL context is current on this thread (no current EGL or GLX context)");
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (!version) throw Error("ssam_gl: no OpenGL context is current on this thread");
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 3 || (major == 3 && minor < 3))
        throw Error(std::string("ssam_gl: OpenGL 3.3 core or newer needed, the current context is ") + version);
    return major >= 4 || epoxy_has_gl_extension("GL_ARB_draw_buffers_blend");
}

}  // namespace

ScreenSpaceAlphaMaskGl::ScreenSpaceAlphaMaskGl(const Config& config) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.perBufferBlend = requireContext();
    s.clipControl = epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_clip_control");
    setConfig(config);
    // Objects first: ~Impl releases whatever exists if a program below does not compile.
    glGenVertexArrays(1, &s.emptyVao);
    glGenFramebuffers(1, &s.maskFbo);
    glGenFramebuffers(1, &s.foliageFbo);
    glGenFramebuffers(1, &s.compositeFbo);
    s.mask.id = compileProgram("ssam_gl mask", shaders::kFoliageVertex, shaders::kMaskFragment);
    s.mask.locate();
    s.color.id = compileProgram("ssam_gl colour", shaders::kFoliageVertex, shaders::kColorFragment);
    s.color.locate();
    s.composite = compileProgram("ssam_gl composite", shaders::kFullscreenVertex, shaders::kCompositeFragment.c_str());
    s.compositeFoliage = glGetUniformLocation(s.composite, "u_foliage");
    s.compositeMask = glGetUniformLocation(s.composite, "u_mask");
    s.compositeMaskAdd = glGetUniformLocation(s.composite, "u_maskAdd");
    s.compositeHasMaskAdd = glGetUniformLocation(s.composite, "u_hasMaskAdd");
    s.compositeMaskLerp = glGetUniformLocation(s.composite, "u_maskLerp");
    s.compositeSquare = glGetUniformLocation(s.composite, "u_squareMask");
}

ScreenSpaceAlphaMaskGl::~ScreenSpaceAlphaMaskGl() = default;

void ScreenSpaceAlphaMaskGl::setConfig(const Config& config) {
    config.validate();
    if (config.maskPrecision == MaskPrecision::RG16F && impl_ && !impl_->perBufferBlend)
        throw Error("ssam_gl config: maskPrecision rg16f needs per-buffer blend equations (OpenGL 4.0 or "
                    "GL_ARB_draw_buffers_blend); use rgba16f");
    config_ = config;
}

GlIntermediates ScreenSpaceAlphaMaskGl::intermediates() const {
    return {impl_->maskTex, impl_->maskAddTex, impl_->foliageTex};
}

namespace {

// The composite's scissor in GL window coordinates, or nullopt when no bound is in view.
// screenBounds() expects our backend's clip conventions (z in [0, w], NDC +y = row 0): the
// engine's are read from glClipControl's state and mapped to them.
std::optional<Rect> compositeRegion(const FrameDesc& frame, bool clipControl) {
    if (!frame.foliageBounds) return Rect{0, 0, frame.width, frame.height};
    GLint origin = GL_LOWER_LEFT, depthMode = GL_NEGATIVE_ONE_TO_ONE;
    if (clipControl) {
        glGetIntegerv(GL_CLIP_ORIGIN, &origin);
        glGetIntegerv(GL_CLIP_DEPTH_MODE, &depthMode);
    }
    glm::mat4 viewProj = frame.viewProj;
    if (depthMode == GL_NEGATIVE_ONE_TO_ONE) {
        glm::mat4 toZeroToOne(1.0f);  // z' = (z + w) / 2
        toZeroToOne[2][2] = 0.5f;
        toZeroToOne[3][2] = 0.5f;
        viewProj = toZeroToOne * viewProj;
    }
    Rect region;
    bool any = false;
    for (const engine::render::BoundingBox& b : *frame.foliageBounds) {
        const std::optional<Rect> r = screenBounds(b, viewProj, frame.width, frame.height);
        if (!r) continue;
        region = unite(region, *r);
        any = true;
    }
    if (!any) return std::nullopt;
    // screenBounds's rows count from NDC +1; with GL_LOWER_LEFT that is the top window row.
    if (origin == GL_LOWER_LEFT) region.y = frame.height - (region.y + region.height);
    return region;
}

void attachDepth(GLuint fbo, GLuint depth, bool depthStencil) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, depthStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                           GL_TEXTURE_2D, depth, 0);
}

}  // namespace

FrameReport ScreenSpaceAlphaMaskGl::render(const FrameDesc& frame, const DrawFoliage& drawFoliage) {
    Impl& s = *impl_;
    requireContext();
    if (frame.width <= 0 || frame.height <= 0)
        throw Error("ssam_gl: frame size " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                    " is not positive");
    if (!drawFoliage) throw Error("ssam_gl: no foliage callback given");
    const GlStateGuard guard(s.perBufferBlend);

    // The engine's textures: 2D, supported formats, the frame's size.
    const TextureInfo color = inspectTexture2D(frame.colorTexture, "colour texture");
    const TextureInfo depth = inspectTexture2D(frame.depthTexture, "depth texture");
    if (!isColorFormat(color.internalFormat))
        throw Error(std::string("ssam_gl: colour texture ") + std::to_string(frame.colorTexture) + " has format " +
                    internalFormatName(color.internalFormat) +
                    "; use GL_RGBA8, GL_SRGB8_ALPHA8, GL_RGBA16F or GL_RGBA32F");
    if (!isDepthFormat(depth.internalFormat))
        throw Error(std::string("ssam_gl: depth texture ") + std::to_string(frame.depthTexture) + " has format " +
                    internalFormatName(depth.internalFormat) + "; use a GL_DEPTH_COMPONENT* or depth-stencil format");
    for (const auto& [info, what] : {std::pair{color, "colour"}, std::pair{depth, "depth"}})
        if (info.width != frame.width || info.height != frame.height)
            throw Error(std::string("ssam_gl: the ") + what + " texture is " + std::to_string(info.width) + "x" +
                        std::to_string(info.height) + " but the frame is " + std::to_string(frame.width) + "x" +
                        std::to_string(frame.height));

    const std::optional<Rect> region = compositeRegion(frame, s.clipControl);
    if (!region) return {};  // no foliage in view: SSAM costs nothing (not even its targets)

    // SSAM's targets (§3.5): rt_mask in the configured precision, rt_foliage in the colour's format.
    if (s.width != frame.width || s.height != frame.height || s.precision != config_.maskPrecision ||
        s.foliageFormat != color.internalFormat) {
        s.destroyTargets();
        switch (config_.maskPrecision) {
            case MaskPrecision::RGBA8: s.maskTex = createTarget(GL_RGBA8, frame.width, frame.height); break;
            case MaskPrecision::RGBA16F: s.maskTex = createTarget(GL_RGBA16F, frame.width, frame.height); break;
            case MaskPrecision::RG16F:
                s.maskTex = createTarget(GL_R16F, frame.width, frame.height);
                s.maskAddTex = createTarget(GL_R16F, frame.width, frame.height);
                break;
        }
        s.foliageTex = createTarget(color.internalFormat, frame.width, frame.height);
        s.width = frame.width, s.height = frame.height;
        s.precision = config_.maskPrecision;
        s.foliageFormat = color.internalFormat;
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.maskFbo);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s.maskTex, 0);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, s.maskAddTex, 0);
        const GLenum maskBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glDrawBuffers(s.maskAddTex ? 2 : 1, maskBuffers);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.foliageFbo);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s.foliageTex, 0);
        s.attachedDepth = 0;  // re-check completeness below
    }
    const bool depthStencil = hasStencil(depth.internalFormat);
    if (s.attachedDepth != frame.depthTexture || s.attachedDepthStencil != depthStencil) {
        attachDepth(s.maskFbo, frame.depthTexture, depthStencil);
        checkDrawFramebuffer("mask pass");
        attachDepth(s.foliageFbo, frame.depthTexture, depthStencil);
        checkDrawFramebuffer("colour pass");
        s.attachedDepth = frame.depthTexture;
        s.attachedDepthStencil = depthStencil;
    }
    if (s.attachedColor != frame.colorTexture) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.compositeFbo);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, frame.colorTexture, 0);
        checkDrawFramebuffer("composite");
        s.attachedColor = frame.colorTexture;
    }

    // State shared by the foliage passes: full viewport, no scissor, both faces (§3.5.2-3),
    // no stencil / polygon offset / alpha-to-coverage / logic op, sRGB targets blended in linear.
    // Left as the host set them: clip control (its depth convention), polygon mode, depth clamp,
    // sampler objects (they apply to the host's base-colour texture).
    glViewport(0, 0, frame.width, frame.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_COLOR_LOGIC_OP);  // a logic op would replace blending
    glDisable(GL_RASTERIZER_DISCARD);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(toGl(config_.depthFunc));
    // Generic values for attributes the engine's VAO leaves disabled (AttributeLocations).
    glVertexAttrib3f(AttributeLocations::normal, 0.0f, 0.0f, 1.0f);
    glVertexAttrib2f(AttributeLocations::uv, 0.0f, 0.0f);
    glVertexAttrib4f(AttributeLocations::color, 1.0f, 1.0f, 1.0f, 1.0f);
    for (unsigned int c = 0; c < 4; ++c)
        glVertexAttrib4f(AttributeLocations::instanceModel + c, c == 0, c == 1, c == 2, c == 3);

    auto runFoliage = [&](const FoliageProgramObject& p, FoliagePass pass, float alphaReference) {
        glUseProgram(p.id);
        glUniformMatrix4fv(p.viewProj, 1, GL_FALSE, glm::value_ptr(frame.viewProj));
        const glm::mat4 identity(1.0f);
        glUniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(identity));
        glUniform4f(p.factor, 1.0f, 1.0f, 1.0f, 1.0f);
        glUniform1i(p.hasTexture, 0);
        glUniform1i(p.sampler, 0);
        FoliageProgram program;
        program.pass = pass;
        program.program = p.id;
        program.modelUniform = p.model;
        program.baseColorFactorUniform = p.factor;
        program.hasTextureUniform = p.hasTexture;
        program.baseColorTextureUnit = 0;
        program.alphaReference = alphaReference;
        glActiveTexture(GL_TEXTURE0);
        drawFoliage(program);
    };

    // 1. Mask pass (§3.5.2, Table 3.1): cleared to black; RGB = MAX, A = ADD, all ONE (RG16F:
    //    MAX into target 0, ADD into target 1); depth test without write; nothing rejected.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.maskFbo);
    const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, black);
    if (s.maskAddTex) glClearBufferfv(GL_COLOR, 1, black);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    if (s.maskAddTex) {
        glBlendEquationi(0, GL_MAX);
        glBlendEquationi(1, GL_FUNC_ADD);
    } else {
        glBlendEquationSeparate(GL_MAX, GL_FUNC_ADD);
    }
    runFoliage(s.mask, FoliagePass::Mask, 0.0f);

    // 2. Colour pass (§3.5.3): cleared to the clear colour (§3.6.1); alpha test at the colour
    //    reference; depth test and write into the engine's depth (§3.7); no blending.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.foliageFbo);
    glClearBufferfv(GL_COLOR, 0, glm::value_ptr(config_.foliageClearColor));
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glUseProgram(s.color.id);
    const float lightLength = glm::length(frame.light.towardLight);
    const glm::vec3 towardLight = lightLength > 0.0f ? frame.light.towardLight / lightLength : glm::vec3(0.0f);
    glUniform1f(s.color.alphaReference, config_.colorAlphaReference);
    glUniform3fv(s.color.towardLight, 1, glm::value_ptr(towardLight));
    glUniform3fv(s.color.lightColor, 1, glm::value_ptr(frame.light.color));
    glUniform3fv(s.color.ambient, 1, glm::value_ptr(frame.light.ambient));
    runFoliage(s.color, FoliagePass::Color, config_.colorAlphaReference);

    // 3. Composite (§3.5.4, Listing 3.2): (foliage, mask') blended SRC_ALPHA / INV_SRC_ALPHA onto
    //    the engine's colour = lerp(opaque, foliage, mask'); its alpha kept; scissored.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.compositeFbo);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(region->x, region->y, region->width, region->height);
    glUseProgram(s.composite);
    const GLuint inputs[3] = {s.foliageTex, s.maskTex, s.maskAddTex};
    for (GLuint unit = 0; unit < 3; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, inputs[unit] ? inputs[unit] : s.maskTex);
    }
    glUniform1i(s.compositeFoliage, 0);
    glUniform1i(s.compositeMask, 1);
    glUniform1i(s.compositeMaskAdd, 2);
    glUniform1i(s.compositeHasMaskAdd, s.maskAddTex ? 1 : 0);
    glUniform1f(s.compositeMaskLerp, config_.maskLerp);
    glUniform1i(s.compositeSquare, config_.squareMask ? 1 : 0);
    glBindVertexArray(s.emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    FrameReport report;
    report.passesRun = 3;
    report.compositeRegion = *region;
    return report;
}

}  // namespace ssam::gl
