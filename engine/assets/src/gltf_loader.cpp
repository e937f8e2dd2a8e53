// SPDX-License-Identifier: MIT
// glTF 2.0 loading: preflight checks, tinygltf parsing, then conversion with every index,
// range and value checked. What is refused (each with "<file>: <field>: <problem>"):
//   - missing, unreadable or over-size files (the glTF, its .bin files and images);
//   - GLB headers and chunk lengths that do not match the file (gltf_preflight.cpp);
//   - URIs that are absolute, contain "..", name a scheme other than data:, or resolve
//     outside the glTF's directory through a symbolic link, also after percent-decoding;
//   - unknown extensions in extensionsRequired (only-used ones are a warning);
//   - buffer, bufferView and accessor ranges outside their storage, computed in 64 bits with
//     overflow checks; strides smaller than an element; misaligned offsets; component types
//     glTF 2.0 does not have or that are not allowed for the attribute; zero counts;
//   - indices >= the vertex count; index counts that are not whole triangles;
//   - Draco data whose index or vertex count disagrees with its accessors (gltf_draco.cpp);
//   - NaN or infinite vertex attributes, transforms, factors and camera parameters
//     (decision: refused, never silently clamped: a NaN position poisons bounds, culling and
//     every pixel it touches, and only the author can say what was meant); likewise finite
//     values whose products overflow: world transforms, world-space bounds, baked UVs;
//   - alphaCutoff that is negative or not finite, unknown alphaMode strings;
//   - images over 16384 pixels on a side or 1 GiB decoded, refused from the header;
//   - indices into meshes, materials, textures, images, samplers, cameras and nodes that are
//     out of range; node hierarchies with cycles or shared children.
#include "engine/assets/gltf.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string_view>
#include <system_error>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <tiny_gltf.h>

#include "engine/core/error.hpp"
#include "gltf_accessor.hpp"
#include "gltf_context.hpp"
#include "gltf_draco.hpp"
#include "gltf_preflight.hpp"

namespace engine::assets {

const char* alphaModeName(AlphaMode mode) {
    switch (mode) {
        case AlphaMode::Opaque: return "OPAQUE";
        case AlphaMode::Mask: return "MASK";
        case AlphaMode::Blend: return "BLEND";
    }
    return "?";
}

glm::mat3 TextureTransform::matrix() const {
    // KHR_texture_transform README: translation * rotation * scale, GLSL column-major.
    const float c = std::cos(rotation);
    const float s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 r(c, s, 0, -s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return t * r * sc;
}

void Bounds::add(const Bounds& other, const glm::mat4& transform) {
    if (other.empty()) return;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? other.max.x : other.min.x, (corner & 2) ? other.max.y : other.min.y,
                          (corner & 4) ? other.max.z : other.min.z);
        add(glm::vec3(transform * glm::vec4(p, 1.0f)));
    }
}

namespace {

using namespace detail;

// ---------------------------------------------------------------------------------------
// tinygltf callbacks: images are captured undecoded (decoded later, after the checks, by
// OpenImageIO); the file system is confined to the glTF's directory, and ExpandFilePath does
// not run tinygltf's default wordexp() shell expansion on file-supplied names.

struct ParseState {
    const LoadContext* ctx = nullptr;
    std::map<int, std::vector<std::uint8_t>> embeddedImages;  // data: URI and bufferView images
};

bool captureImage(tinygltf::Image*, const int index, std::string*, std::string*, int, int, const unsigned char* bytes,
                  int size, void* user) {
    auto* state = static_cast<ParseState*>(user);
    if (bytes && size > 0) state->embeddedImages[index].assign(bytes, bytes + size);
    return true;
}

bool confinedFileExists(const std::string& path, void* user) {
    std::error_code ec;
    return isConfined(*static_cast<const LoadContext*>(user), path) && std::filesystem::is_regular_file(path, ec);
}

std::string noExpansion(const std::string& path, void*) { return path; }

bool confinedRead(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const auto& ctx = *static_cast<const LoadContext*>(user);
    try {
        if (!isConfined(ctx, path)) throw Error("'" + path + "' is outside the glTF file's directory");
        *out = readWholeFile(ctx, path, "buffer");
        return true;
    } catch (const std::exception& e) {
        if (err) *err += e.what();
        return false;
    }
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported";
    return false;
}

std::string trimmed(std::string text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    return text;
}

// The GLB tinygltf is given when preflight rewrote the JSON: the new JSON chunk (padded with
// spaces, glTF 2.0 §4.4.3.2) and the original BIN chunk; unknown chunks are dropped.
std::vector<std::uint8_t> rebuildGlb(const std::string& jsonText, const Container& container) {
    const auto le32 = [](std::vector<std::uint8_t>& out, std::uint64_t value) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    };
    const std::size_t jsonPadded = (jsonText.size() + 3) / 4 * 4;
    const std::size_t total = 12 + 8 + jsonPadded + (container.hasBin ? 8 + container.bin.size() : 0);
    std::vector<std::uint8_t> out;
    out.reserve(total);
    le32(out, 0x46546C67);  // "glTF"
    le32(out, 2);
    le32(out, total);
    le32(out, jsonPadded);
    le32(out, 0x4E4F534A);  // "JSON"
    out.insert(out.end(), jsonText.begin(), jsonText.end());
    out.resize(12 + 8 + jsonPadded, ' ');
    if (container.hasBin) {
        le32(out, container.bin.size());
        le32(out, 0x004E4942);  // "BIN"
        out.insert(out.end(), container.bin.begin(), container.bin.end());
    }
    return out;
}

// ---------------------------------------------------------------------------------------
// Small checked readers of tinygltf's parsed values

float finite(const LoadContext& ctx, double value, const std::string& field) {
    if (!std::isfinite(value)) ctx.fail(field, std::to_string(value) + " is not a finite number");
    const double limit = static_cast<double>(std::numeric_limits<float>::max());
    if (value > limit || value < -limit) ctx.fail(field, std::to_string(value) + " is out of the float range");
    return static_cast<float>(value);
}

bool allFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool allFinite(const glm::mat4& m) {
    const float* values = glm::value_ptr(m);
    return std::all_of(values, values + 16, [](float v) { return std::isfinite(v); });
}

template <int N>
glm::vec<N, float> finiteVector(const LoadContext& ctx, const std::vector<double>& values, const std::string& field) {
    if (values.size() != static_cast<std::size_t>(N))
        ctx.fail(field, "has " + std::to_string(values.size()) + " numbers, expected " + std::to_string(N));
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i) out[i] = finite(ctx, values[static_cast<std::size_t>(i)], indexed(field.c_str(), static_cast<std::size_t>(i)));
    return out;
}

void checkIndex(const LoadContext& ctx, int index, std::size_t count, const std::string& field, const char* what,
                bool optional = true) {
    if (optional && index == -1) return;
    if (index < 0 || static_cast<std::size_t>(index) >= count)
        ctx.fail(field, std::to_string(index) + " is out of range: the file has " + std::to_string(count) + " " + what);
}

float valueNumber(const LoadContext& ctx, const tinygltf::Value& value, const std::string& field) {
    if (!value.IsNumber()) ctx.fail(field, "must be a number");
    return finite(ctx, value.GetNumberAsDouble(), field);
}

glm::vec2 valueVec2(const LoadContext& ctx, const tinygltf::Value& value, const std::string& field) {
    if (!value.IsArray() || value.ArrayLen() != 2) ctx.fail(field, "must be an array of 2 numbers");
    return {valueNumber(ctx, value.Get(0), field + "[0]"), valueNumber(ctx, value.Get(1), field + "[1]")};
}

// ---------------------------------------------------------------------------------------
// Images, samplers, textures, materials

std::vector<Image> convertImages(const LoadContext& ctx, const tinygltf::Model& model, ParseState& state) {
    std::vector<Image> images(model.images.size());
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        const tinygltf::Image& source = model.images[i];
        Image& image = images[i];
        image.name = source.name;
        const std::string field = indexed("images", i);
        const auto embedded = state.embeddedImages.find(static_cast<int>(i));
        if (embedded == state.embeddedImages.end() && !source.uri.empty()) image.uri = source.uri;
        if (!ctx.options->loadImages) continue;
        const std::string name = ctx.file.string() + ": " + field + (image.uri.empty() ? "" : " '" + image.uri + "'");
        if (embedded != state.embeddedImages.end()) {
            image.pixels = decodeImage(embedded->second, name, ctx.options->imageLimits);
            embedded->second = {};  // the encoded bytes are no longer needed
        } else if (!image.uri.empty()) {
            const std::string relative = checkUri(ctx, field + ".uri", image.uri);
            const auto path = resolveConfined(ctx, field + ".uri", image.uri, relative);
            image.pixels = decodeImage(readWholeFile(ctx, path, field + ".uri"), name, ctx.options->imageLimits);
        } else {
            ctx.fail(field, "has no image data");
        }
    }
    return images;
}

render::SamplerState convertSampler(const LoadContext& ctx, const tinygltf::Sampler& sampler, const std::string& field) {
    render::SamplerState state;
    switch (sampler.minFilter) {
        case -1:
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: state.filter = render::Filter::Trilinear; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
        case TINYGLTF_TEXTURE_FILTER_NEAREST: state.filter = render::Filter::Nearest; break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR: state.filter = render::Filter::Bilinear; break;
        default: ctx.fail(field + ".minFilter", std::to_string(sampler.minFilter) + " is not a glTF filter");
    }
    if (sampler.magFilter != -1 && sampler.magFilter != TINYGLTF_TEXTURE_FILTER_NEAREST &&
        sampler.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
        ctx.fail(field + ".magFilter", std::to_string(sampler.magFilter) + " is not a glTF magnification filter");
    const auto wrap = [&](int mode, const char* name) {
        switch (mode) {
            case TINYGLTF_TEXTURE_WRAP_REPEAT: return render::AddressMode::Wrap;
            case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return render::AddressMode::Clamp;
            case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return render::AddressMode::Mirror;
            default: ctx.fail(field + "." + name, std::to_string(mode) + " is not a glTF wrap mode");
        }
    };
    state.addressU = wrap(sampler.wrapS, "wrapS");
    state.addressV = wrap(sampler.wrapT, "wrapT");
    return state;
}

std::vector<Texture> convertTextures(const LoadContext& ctx, const tinygltf::Model& model) {
    std::vector<Texture> textures(model.textures.size());
    for (std::size_t i = 0; i < model.textures.size(); ++i) {
        const tinygltf::Texture& source = model.textures[i];
        const std::string field = indexed("textures", i);
        checkIndex(ctx, source.source, model.images.size(), field + ".source", "images");
        checkIndex(ctx, source.sampler, model.samplers.size(), field + ".sampler", "samplers");
        textures[i].name = source.name;
        textures[i].image = source.source;
        if (source.sampler >= 0)
            textures[i].sampler = convertSampler(ctx, model.samplers[static_cast<std::size_t>(source.sampler)],
                                                 indexed("samplers", static_cast<std::size_t>(source.sampler)));
    }
    return textures;
}

TextureRef convertTextureRef(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::TextureInfo& info,
                             const std::string& field) {
    TextureRef ref;
    if (info.index == -1) return ref;
    checkIndex(ctx, info.index, model.textures.size(), field + ".index", "textures", false);
    if (info.texCoord < 0 || info.texCoord > 7) ctx.fail(field + ".texCoord", std::to_string(info.texCoord) + " is not in [0, 7]");
    ref.texture = info.index;
    ref.texCoord = info.texCoord;
    const auto ext = info.extensions.find("KHR_texture_transform");
    if (ext != info.extensions.end()) {
        const std::string extField = field + ".extensions.KHR_texture_transform";
        const tinygltf::Value& t = ext->second;
        if (!t.IsObject()) ctx.fail(extField, "must be an object");
        ref.hasTransform = true;
        if (t.Has("offset")) ref.transform.offset = valueVec2(ctx, t.Get("offset"), extField + ".offset");
        if (t.Has("rotation")) ref.transform.rotation = valueNumber(ctx, t.Get("rotation"), extField + ".rotation");
        if (t.Has("scale")) ref.transform.scale = valueVec2(ctx, t.Get("scale"), extField + ".scale");
        if (t.Has("texCoord")) {
            const tinygltf::Value& texCoord = t.Get("texCoord");
            if (!texCoord.IsInt() || texCoord.Get<int>() < 0 || texCoord.Get<int>() > 7)
                ctx.fail(extField + ".texCoord", "must be an integer in [0, 7]");
            ref.texCoord = texCoord.Get<int>();
        }
    }
    return ref;
}

std::vector<Material> convertMaterials(const LoadContext& ctx, const tinygltf::Model& model) {
    std::vector<Material> materials(model.materials.size());
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& source = model.materials[i];
        Material& m = materials[i];
        const std::string field = indexed("materials", i);
        m.name = source.name;

        if (source.alphaMode == "OPAQUE" || source.alphaMode.empty()) m.alphaMode = AlphaMode::Opaque;
        else if (source.alphaMode == "MASK") m.alphaMode = AlphaMode::Mask;
        else if (source.alphaMode == "BLEND") m.alphaMode = AlphaMode::Blend;
        else ctx.fail(field + ".alphaMode", "'" + source.alphaMode + "': must be OPAQUE, MASK or BLEND");
        if (!std::isfinite(source.alphaCutoff) || source.alphaCutoff < 0.0)
            ctx.fail(field + ".alphaCutoff", std::to_string(source.alphaCutoff) + ": must be a finite number >= 0");
        m.alphaCutoff = static_cast<float>(source.alphaCutoff);
        m.doubleSided = source.doubleSided;

        const auto& pbr = source.pbrMetallicRoughness;
        const std::string pbrField = field + ".pbrMetallicRoughness";
        m.baseColorFactor = finiteVector<4>(ctx, pbr.baseColorFactor, pbrField + ".baseColorFactor");
        m.metallicFactor = finite(ctx, pbr.metallicFactor, pbrField + ".metallicFactor");
        m.roughnessFactor = finite(ctx, pbr.roughnessFactor, pbrField + ".roughnessFactor");
        m.baseColorTexture = convertTextureRef(ctx, model, pbr.baseColorTexture, pbrField + ".baseColorTexture");
        if (!source.emissiveFactor.empty())
            m.emissiveFactor = finiteVector<3>(ctx, source.emissiveFactor, field + ".emissiveFactor");

        m.unlit = source.extensions.count("KHR_materials_unlit") != 0;
        if (source.extras.IsObject() && source.extras.Has("foliage")) {
            const tinygltf::Value& foliage = source.extras.Get("foliage");
            if (!foliage.IsBool()) ctx.fail(field + ".extras.foliage", "must be true or false");
            m.foliage = foliage.Get<bool>();
        }
    }
    return materials;
}

// ---------------------------------------------------------------------------------------
// Meshes

// Converts a primitive's index list to a triangle list (glTF 2.0 §3.7.2.1 topology rules).
std::vector<std::uint32_t> triangulate(const LoadContext& ctx, std::vector<std::uint32_t> indices, int mode,
                                       const std::string& field) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (indices.size() % 3 != 0)
            ctx.fail(field, std::to_string(indices.size()) + " indices do not make whole triangles");
        return indices;
    }
    std::vector<std::uint32_t> out;
    if (indices.size() < 3) return out;
    out.reserve((indices.size() - 2) * 3);
    for (std::size_t i = 0; i + 2 < indices.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // p_i = {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}}
            out.insert(out.end(), {indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]});
        } else {  // fan: p_i = {v_{i+1}, v_{i+2}, v_0}
            out.insert(out.end(), {indices[i + 1], indices[i + 2], indices[0]});
        }
    }
    return out;
}

struct AttributeSource {
    const LoadContext& ctx;
    const tinygltf::Model& model;
    const tinygltf::Primitive& primitive;
    const DracoPrimitive* draco;
    std::string field;

    // The attribute's floats (count * components), or empty when the primitive lacks it.
    std::vector<float> read(const std::string& name, std::initializer_list<int> types, std::uint32_t componentTypes,
                            int& components) const {
        const auto it = primitive.attributes.find(name);
        if (it == primitive.attributes.end()) return {};
        const std::string usage = field + ".attributes." + name;
        checkIndex(ctx, it->second, model.accessors.size(), usage, "accessors", false);
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(it->second)];
        components = componentCount(accessor.type);
        std::vector<float> values;
        const auto decoded = draco ? draco->attributes.find(name) : std::map<std::string, std::vector<float>>::const_iterator{};
        if (draco && decoded != draco->attributes.end()) {
            if (std::find(types.begin(), types.end(), accessor.type) == types.end())
                ctx.fail(accessorField(it->second, usage) + ".type", "is not allowed for " + name);
            values = decoded->second;
        } else {
            values = readFloats(ctx, model, it->second, {usage, types, componentTypes, ctx.options->maxVertices});
        }
        for (std::size_t v = 0; v < values.size(); ++v)
            if (!std::isfinite(values[v]))
                ctx.fail(accessorField(it->second, usage),
                         "element " + std::to_string(v / static_cast<std::size_t>(components)) +
                             " has a non-finite component (NaN or infinity)");
        return values;
    }
};

// dracoIndices: the Draco primitive's indices accessor, which preflight kept from tinygltf.
Primitive convertPrimitive(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& source,
                           const std::vector<Material>& materials, int dracoIndices, const std::string& field) {
    Primitive out;
    checkIndex(ctx, source.material, model.materials.size(), field + ".material", "materials");
    out.material = source.material;

    DracoPrimitive draco;
    const bool compressed = source.extensions.count(kDracoExtension) != 0;
    if (compressed) draco = decodeDraco(ctx, model, source, dracoIndices, field);
    const AttributeSource attributes{ctx, model, source, compressed ? &draco : nullptr, field};

    int components = 0;
    // KHR_mesh_quantization allows 8/16-bit positions, normals and texture coordinates.
    const std::vector<float> positions =
        attributes.read("POSITION", {TINYGLTF_TYPE_VEC3}, kFloatOnly | kSmallInts, components);
    if (positions.empty()) ctx.fail(field + ".attributes", "POSITION is missing");
    const std::size_t vertexCount = positions.size() / 3;

    const auto sameCount = [&](const std::vector<float>& values, int comps, const char* name) {
        if (!values.empty() && values.size() != vertexCount * static_cast<std::size_t>(comps))
            ctx.fail(field + ".attributes." + name, "has " + std::to_string(values.size() / static_cast<std::size_t>(comps)) +
                                                        " elements, POSITION has " + std::to_string(vertexCount));
    };
    int normalComponents = 3;
    const std::vector<float> normals =
        attributes.read("NORMAL", {TINYGLTF_TYPE_VEC3}, kFloatOnly | kSmallInts, normalComponents);
    sameCount(normals, 3, "NORMAL");

    TextureRef textureRef;
    if (out.material >= 0) textureRef = materials[static_cast<std::size_t>(out.material)].baseColorTexture;
    const std::string texCoordName = "TEXCOORD_" + std::to_string(textureRef.texCoord);
    int uvComponents = 2;
    const std::vector<float> uvs =
        attributes.read(texCoordName, {TINYGLTF_TYPE_VEC2}, kFloatOnly | kSmallInts, uvComponents);
    sameCount(uvs, 2, texCoordName.c_str());

    int colorComponents = 4;
    const std::vector<float> colors = attributes.read(
        "COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
        kFloatOnly | componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) | componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT),
        colorComponents);
    sameCount(colors, colorComponents, "COLOR_0");

    out.hasNormals = !normals.empty();
    out.hasTexCoords = !uvs.empty();
    out.hasColors = !colors.empty();
    const bool bake = ctx.options->bakeTextureTransform && textureRef.hasTransform;
    const glm::mat3 uvTransform = textureRef.transform.matrix();
    out.vertices.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        render::Vertex& vertex = out.vertices[v];
        vertex.position = glm::vec3(positions[v * 3], positions[v * 3 + 1], positions[v * 3 + 2]);
        out.bounds.add(vertex.position);
        if (out.hasNormals) vertex.normal = glm::vec3(normals[v * 3], normals[v * 3 + 1], normals[v * 3 + 2]);
        if (out.hasTexCoords) {
            vertex.uv = glm::vec2(uvs[v * 2], uvs[v * 2 + 1]);
            if (bake) {
                // Finite UVs and a finite transform can still overflow (scale 1e38 * uv 10).
                vertex.uv = glm::vec2(uvTransform * glm::vec3(vertex.uv, 1.0f));
                if (!std::isfinite(vertex.uv.x) || !std::isfinite(vertex.uv.y))
                    ctx.fail(field + ".attributes." + texCoordName,
                             "element " + std::to_string(v) + ": KHR_texture_transform of material " +
                                 std::to_string(out.material) + " takes the UV out of the float range");
            }
        }
        if (out.hasColors) {
            const std::size_t c = v * static_cast<std::size_t>(colorComponents);
            vertex.color = glm::vec4(colors[c], colors[c + 1], colors[c + 2], colorComponents == 4 ? colors[c + 3] : 1.0f);
        }
    }

    std::vector<std::uint32_t> indices;
    std::string indexField = field + ".indices";
    if (compressed) {
        indices = std::move(draco.indices);
    } else if (source.indices >= 0) {
        indices = readIndices(ctx, model, source.indices, indexField, ctx.options->maxVertices * 8);
        indexField = accessorField(source.indices, indexField);
    } else {
        indices.resize(vertexCount);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= vertexCount)
            ctx.fail(indexField, "index " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
                                     " is out of range for " + std::to_string(vertexCount) + " vertices");
    out.indices = triangulate(ctx, std::move(indices), source.mode, indexField);
    return out;
}

std::vector<Mesh> convertMeshes(const LoadContext& ctx, const tinygltf::Model& model, const std::vector<Material>& materials,
                                const std::map<std::pair<std::size_t, std::size_t>, int>& dracoIndices) {
    std::vector<Mesh> meshes(model.meshes.size());
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        meshes[m].name = model.meshes[m].name;
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& source = model.meshes[m].primitives[p];
            const std::string field = indexed("meshes", m) + "." + indexed("primitives", p);
            if (source.mode >= TINYGLTF_MODE_POINTS && source.mode <= TINYGLTF_MODE_LINE_STRIP) {
                ctx.warn(field + ".mode", "points and lines are not drawn; primitive skipped");
                continue;
            }
            if (source.mode != TINYGLTF_MODE_TRIANGLES && source.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                source.mode != TINYGLTF_MODE_TRIANGLE_FAN)
                ctx.fail(field + ".mode", std::to_string(source.mode) + " is not a glTF primitive mode");
            const auto draco = dracoIndices.find({m, p});
            meshes[m].primitives.push_back(
                convertPrimitive(ctx, model, source, materials, draco == dracoIndices.end() ? -1 : draco->second, field));
        }
    }
    return meshes;
}

// ---------------------------------------------------------------------------------------
// Cameras, nodes, scenes

std::vector<Camera> convertCameras(const LoadContext& ctx, const tinygltf::Model& model) {
    std::vector<Camera> cameras(model.cameras.size());
    for (std::size_t i = 0; i < model.cameras.size(); ++i) {
        const tinygltf::Camera& source = model.cameras[i];
        Camera& c = cameras[i];
        const std::string field = indexed("cameras", i);
        c.name = source.name;
        if (source.type == "perspective") {
            const auto& p = source.perspective;
            const std::string pf = field + ".perspective";
            c.type = Camera::Type::Perspective;
            c.yfov = finite(ctx, p.yfov, pf + ".yfov");
            if (c.yfov <= 0.0f || c.yfov >= 3.14159265f) ctx.fail(pf + ".yfov", std::to_string(c.yfov) + ": must be in (0, pi)");
            c.aspectRatio = finite(ctx, p.aspectRatio, pf + ".aspectRatio");
            if (c.aspectRatio < 0.0f) ctx.fail(pf + ".aspectRatio", std::to_string(c.aspectRatio) + ": must be > 0");
            c.znear = finite(ctx, p.znear, pf + ".znear");
            if (c.znear <= 0.0f) ctx.fail(pf + ".znear", std::to_string(c.znear) + ": must be > 0");
            if (p.zfar != 0.0) {  // tinygltf's 0: absent, an infinite projection
                c.zfar = finite(ctx, p.zfar, pf + ".zfar");
                if (c.zfar <= c.znear) ctx.fail(pf + ".zfar", std::to_string(c.zfar) + ": must be greater than znear");
            }
        } else if (source.type == "orthographic") {
            const auto& o = source.orthographic;
            const std::string of = field + ".orthographic";
            c.type = Camera::Type::Orthographic;
            c.xmag = finite(ctx, o.xmag, of + ".xmag");
            c.ymag = finite(ctx, o.ymag, of + ".ymag");
            if (c.xmag == 0.0f || c.ymag == 0.0f) ctx.fail(of, "xmag and ymag must not be zero");
            c.znear = finite(ctx, o.znear, of + ".znear");
            c.zfar = finite(ctx, o.zfar, of + ".zfar");
            if (c.znear < 0.0f) ctx.fail(of + ".znear", std::to_string(c.znear) + ": must be >= 0");
            if (c.zfar <= c.znear) ctx.fail(of + ".zfar", std::to_string(c.zfar) + ": must be greater than znear");
        } else {
            ctx.fail(field + ".type", "'" + source.type + "': must be perspective or orthographic");
        }
    }
    return cameras;
}

glm::mat4 localTransform(const LoadContext& ctx, const tinygltf::Node& node, const std::string& field) {
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) ctx.fail(field + ".matrix", "must have 16 numbers");
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)  // column-major, as glTF stores it
            glm::value_ptr(m)[i] = finite(ctx, node.matrix[static_cast<std::size_t>(i)], field + ".matrix[" + std::to_string(i) + "]");
        return m;
    }
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
        const glm::vec3 t = finiteVector<3>(ctx, node.translation, field + ".translation");
        m[3] = glm::vec4(t, 1.0f);
    }
    if (!node.rotation.empty()) {
        const glm::vec4 q = finiteVector<4>(ctx, node.rotation, field + ".rotation");  // x, y, z, w
        // In double: the squares of components near FLT_MAX overflow a float, and a length of
        // infinity would silently turn the rotation into the identity.
        const double length = glm::length(glm::dvec4(q));
        if (!(length > 1e-6)) ctx.fail(field + ".rotation", "is not a unit quaternion");
        const glm::dvec4 unit = glm::dvec4(q) / length;
        m = m * glm::mat4_cast(glm::quat(static_cast<float>(unit.w), static_cast<float>(unit.x),
                                         static_cast<float>(unit.y), static_cast<float>(unit.z)));
    }
    if (!node.scale.empty()) {
        const glm::vec3 s = finiteVector<3>(ctx, node.scale, field + ".scale");
        m = m * glm::mat4(glm::vec4(s.x, 0, 0, 0), glm::vec4(0, s.y, 0, 0), glm::vec4(0, 0, s.z, 0), glm::vec4(0, 0, 0, 1));
    }
    return m;
}

std::vector<Node> convertNodes(const LoadContext& ctx, const tinygltf::Model& model) {
    const std::size_t count = model.nodes.size();
    std::vector<Node> nodes(count);
    for (std::size_t i = 0; i < count; ++i) {
        const tinygltf::Node& source = model.nodes[i];
        Node& node = nodes[i];
        const std::string field = indexed("nodes", i);
        node.name = source.name;
        checkIndex(ctx, source.mesh, model.meshes.size(), field + ".mesh", "meshes");
        checkIndex(ctx, source.camera, model.cameras.size(), field + ".camera", "cameras");
        node.mesh = source.mesh;
        node.camera = source.camera;
        node.local = localTransform(ctx, source, field);
        node.children = source.children;
    }
    // glTF 2.0 §3.5.3: the nodes form disjoint strict trees: every node has at most one
    // parent and there are no cycles.
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < nodes[i].children.size(); ++c) {
            const int child = nodes[i].children[c];
            const std::string field = indexed("nodes", i) + "." + indexed("children", c);
            checkIndex(ctx, child, count, field, "nodes", false);
            Node& childNode = nodes[static_cast<std::size_t>(child)];
            if (childNode.parent != -1)
                ctx.fail(field, "node " + std::to_string(child) + " already has parent node " +
                                    std::to_string(childNode.parent) + " (nodes must form trees)");
            childNode.parent = static_cast<int>(i);
        }
    // World transforms from the roots down; a node never reached is on a cycle.
    std::vector<bool> reached(count, false);
    std::vector<int> stack;
    for (std::size_t i = 0; i < count; ++i)
        if (nodes[i].parent == -1) stack.push_back(static_cast<int>(i));
    while (!stack.empty()) {
        const auto n = static_cast<std::size_t>(stack.back());
        stack.pop_back();
        reached[n] = true;
        nodes[n].world = nodes[n].parent == -1 ? nodes[n].local
                                               : nodes[static_cast<std::size_t>(nodes[n].parent)].world * nodes[n].local;
        // Finite local transforms can multiply to infinity (two nested scales of 1e30).
        if (!allFinite(nodes[n].world))
            ctx.fail(indexed("nodes", n), "the world transform (the parents' transforms times this node's) "
                                          "overflows the float range");
        for (int child : nodes[n].children) stack.push_back(child);
    }
    for (std::size_t i = 0; i < count; ++i)
        if (!reached[i]) ctx.fail(indexed("nodes", i), "is part of a cycle in the node hierarchy");
    return nodes;
}

void selectScene(const LoadContext& ctx, const tinygltf::Model& model, LoadedModel& out) {
    const int requested = ctx.options->scene;
    if (requested >= 0) {
        if (static_cast<std::size_t>(requested) >= model.scenes.size())
            ctx.fail("scene", "LoadOptions::scene " + std::to_string(requested) + " is out of range: the file has " +
                                  std::to_string(model.scenes.size()) + " scenes" +
                                  (model.scenes.empty() ? std::string(" (it has none to choose)")
                                                        : " (valid: 0.." + std::to_string(model.scenes.size() - 1) + ")"));
        out.scene = requested;
    } else if (model.defaultScene >= 0) {
        checkIndex(ctx, model.defaultScene, model.scenes.size(), "scene", "scenes", false);
        out.scene = model.defaultScene;
    } else if (!model.scenes.empty()) {
        out.scene = 0;
    }
    if (out.scene >= 0) {
        const tinygltf::Scene& scene = model.scenes[static_cast<std::size_t>(out.scene)];
        std::vector<bool> seen(out.nodes.size(), false);
        for (std::size_t k = 0; k < scene.nodes.size(); ++k) {
            const int node = scene.nodes[k];
            const std::string field = indexed("scenes", static_cast<std::size_t>(out.scene)) + "." + indexed("nodes", k);
            checkIndex(ctx, node, out.nodes.size(), field, "nodes", false);
            if (out.nodes[static_cast<std::size_t>(node)].parent != -1)
                ctx.fail(field, "node " + std::to_string(node) + " is not a root node");
            if (seen[static_cast<std::size_t>(node)]) ctx.fail(field, "node " + std::to_string(node) + " is listed twice");
            seen[static_cast<std::size_t>(node)] = true;
            out.sceneRoots.push_back(node);
        }
    } else {
        for (std::size_t i = 0; i < out.nodes.size(); ++i)
            if (out.nodes[i].parent == -1) out.sceneRoots.push_back(static_cast<int>(i));
    }
    // Depth-first, parents before children, in file order.
    std::vector<int> stack(out.sceneRoots.rbegin(), out.sceneRoots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        out.sceneNodes.push_back(n);
        const auto& children = out.nodes[static_cast<std::size_t>(n)].children;
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }
    for (int n : out.sceneNodes) {
        const Node& node = out.nodes[static_cast<std::size_t>(n)];
        if (node.mesh < 0) continue;
        for (const Primitive& primitive : out.meshes[static_cast<std::size_t>(node.mesh)].primitives)
            out.bounds.add(primitive.bounds, node.world);
        if (!out.bounds.empty() && !(allFinite(out.bounds.min) && allFinite(out.bounds.max)))
            ctx.fail(indexed("nodes", static_cast<std::size_t>(n)) + ".mesh",
                     "the mesh's bounds in world space overflow the float range");
    }
}

}  // namespace

LoadedModel loadGltf(const std::filesystem::path& path, const LoadOptions& options) {
    LoadedModel out;
    out.source = path;
    LoadContext ctx;
    ctx.file = path;
    ctx.baseDir = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
    ctx.options = &options;
    ctx.warnings = &out.warnings;

    const std::vector<std::uint8_t> bytes = readWholeFile(ctx, path, "");
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) ctx.fail("", "the file is too large for tinygltf");
    const Container container = splitContainer(ctx, bytes);
    const Preflight checked = preflight(ctx, container);
    const std::vector<std::uint8_t> glb =
        container.binary && !checked.jsonForParser.empty() ? rebuildGlb(checked.jsonForParser, container) : bytes;
    const std::string_view jsonText = checked.jsonForParser.empty()
                                          ? std::string_view(reinterpret_cast<const char*>(container.json.data()), container.json.size())
                                          : std::string_view(checked.jsonForParser);

    tinygltf::Model model;
    ParseState state;
    state.ctx = &ctx;
    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(&captureImage, &state);
    parser.SetFsCallbacks({&confinedFileExists, &noExpansion, &confinedRead, &refuseWrite, &ctx});
    std::string err;
    std::string warn;
    bool parsed = false;
    try {
        const std::string baseDir = ctx.baseDir.string();
        if (container.binary)
            parsed = parser.LoadBinaryFromMemory(&model, &err, &warn, glb.data(), static_cast<unsigned int>(glb.size()), baseDir);
        else
            parsed = parser.LoadASCIIFromString(&model, &err, &warn, jsonText.data(),
                                                static_cast<unsigned int>(jsonText.size()), baseDir);
    } catch (const std::exception& e) {
        ctx.fail("", std::string("cannot parse: ") + e.what());
    }
    if (!parsed) ctx.fail("", "cannot parse: " + trimmed(err.empty() ? "tinygltf gave no reason" : err));
    if (!trimmed(err).empty()) ctx.warn("", "tinygltf: " + trimmed(err));
    if (!trimmed(warn).empty()) ctx.warn("", "tinygltf: " + trimmed(warn));

    out.images = convertImages(ctx, model, state);
    out.textures = convertTextures(ctx, model);
    out.materials = convertMaterials(ctx, model);
    out.meshes = convertMeshes(ctx, model, out.materials, checked.dracoIndices);
    out.cameras = convertCameras(ctx, model);
    out.nodes = convertNodes(ctx, model);
    selectScene(ctx, model, out);
    return out;
}

}  // namespace engine::assets
