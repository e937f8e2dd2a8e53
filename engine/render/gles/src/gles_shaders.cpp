// SPDX-License-Identifier: MIT
#include "gles_shaders.hpp"

#include <regex>
#include <set>

#include "gl_api.hpp"

#include "engine/core/error.hpp"
#include "engine_render_gles_glsl.hpp"  // generated from glsl/

namespace engine::render::gles {
namespace {

// ES 3.00 §4.5.4 gives float no default precision in fragment shaders; highp is what the GL
// driver computes in, and what WebGL2 guarantees in both stages.
constexpr const char* kEsHead =
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "precision highp sampler2D;\n"
    // fwidthFine (GLSL 4.00 §8.13.3) is not in ES 3.00, whose fwidth takes the quad's
    // differences as the implementation chooses (coarse or fine): a sharpened alpha-to-coverage
    // edge ([Golus 2017]) may then differ from GL 4.5's by the other pixel pair's difference.
    "#define fwidthFine fwidth\n"
    // ldexp (GLSL 4.00, ES 3.10) as the exact power-of-two scale it is, for the exponents
    // float has normal values for (hashed alpha's cell scales are clamped to +-60).
    "float ldexp(float x, int e) { return x * uintBitsToFloat(uint(e + 127) << 23u); }\n"
    // `precise` (ES 3.20 §4.7) has no ES 3.00 equivalent: contraction stays the compiler's choice.
    "#define precise\n";

// A vertex stage's ending where the context lacks EXT_clip_control (core ES 3.0 has no clip
// control: origin lower-left, depth [-1, 1]). The program's own main runs first (renamed by
// `#define main`), then its clip position is changed so the window sees what
// glClipControl(UPPER_LEFT, ZERO_TO_ONE) gives (EXT_clip_control's equations):
//   - y: upper-left makes y_d = -y_c / w_c; negating y_c gives the lower-left origin the same
//     y_d, so the same window y: memory row 0 is the image's top in both cases, and
//     gl_FragCoord, derivatives, scissor rows, texelFetch reads of targets, blits and readbacks
//     see exactly what they see with the extension.
//   - z: zero-to-one makes z_w = z_c / w_c (depth range [0, 1]); -1-to-1 makes
//     z_w = (z_c' / w_c + 1) / 2, which for z_c' = 2 z_c - w_c is z_c / w_c again, and its clip
//     volume -w_c <= z_c' <= w_c is 0 <= z_c <= w_c. Equal up to rounding: 2 z_c is exact, the
//     subtraction and the window transform round. Depth passes through [-1, 1], where float's
//     steps near -1 are 2^-24, so window depth near 0 moves in steps of 2^-25 instead of
//     float's ever finer ones: reverse-Z (far at 0) loses its precision near the far plane.
//   - facing: upper-left also negates the polygon area that decides facing (EXT_clip_control,
//     glClipControl's reference page), so there facing is the winding in clip space; the
//     negated y_c reverses that winding and the lower-left origin has no negation to undo it,
//     so the driver reverses glFrontFace (gles_draw.cpp; GlesDifferences checks it culled).
constexpr const char* kClipRemapTail =
    "\n#undef main\n"
    "void main() {\n"
    "    esProgramMain();\n"
    "    gl_Position.y = -gl_Position.y;\n"
    "    gl_Position.z = 2.0 * gl_Position.z - gl_Position.w;\n"
    "}\n";

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

}  // namespace

std::string glslEs(std::string source, const std::string& program, bool remapClip) {
    const std::string line = source.substr(0, source.find('\n') + 1);
    if (line != "#version 450 core\n")
        throw Error("program '" + program + "': the GLES driver translates GLSL 4.50 stages, this one begins " + line);
    source.replace(0, line.size(), kEsHead);
    // Samplers' units: set by bindSamplerUnits after linking (ES 3.00 has no binding qualifier).
    source = std::regex_replace(source, std::regex(R"(layout\s*\(\s*binding\s*=\s*\d+\s*\)\s*)"), "");
    // Mip levels: the sampler's texture's, set per draw.
    const std::regex queryLevels(R"(textureQueryLevels\s*\(\s*(\w+)\s*\))");
    std::set<std::string> samplers;
    for (auto it = std::sregex_iterator(source.begin(), source.end(), queryLevels); it != std::sregex_iterator(); ++it)
        samplers.insert((*it)[1].str());
    if (!samplers.empty()) {
        source = std::regex_replace(source, queryLevels, "esLevels_$1");
        std::string declarations;
        for (const std::string& sampler : samplers)
            declarations += "uniform int " + levelsUniform(sampler.c_str()) + ";\n";
        source.insert(source.find("#define precise\n") + 16, declarations);
    }
    // The shared tail's sample mask (finish()): ES 3.00 has no gl_SampleMask.
    if (source.find("gl_SampleMask") != std::string::npos) {
        replaceAll(source, "gl_SampleMask", "esUnusedSampleMask");
        const std::size_t after = source.find("#define precise\n") + 16;
        source.insert(after, "int esUnusedSampleMask[1];\n");
    }
    if (remapClip) {
        if (source.find("gl_Position") == std::string::npos)
            throw Error("program '" + program +
                        "': the clip remap applies to vertex stages, this one has no gl_Position");
        source.insert(source.find("#define precise\n") + 16, "#define main esProgramMain\n");
        source += kClipRemapTail;
    }
    return source;
}

std::string levelsUniform(const char* sampler) { return std::string("esLevels_") + sampler; }

void bindSamplerUnits(unsigned int program, const GlslProgram& gl) {
    glUseProgram(program);
    for (const TextureField& t : gl.textures) {
        const GLint location = glGetUniformLocation(program, t.name);
        if (location >= 0) glUniform1i(location, t.unit);
    }
}

std::string depthToColorFragmentSource() { return glsl::kDepthToColorFragment; }

}  // namespace engine::render::gles
