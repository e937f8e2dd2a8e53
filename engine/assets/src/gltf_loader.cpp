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
#include "gltf_scene_graph.hpp"
#include "gltf_values.hpp"

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

render::SamplerState convertSampler(const LoadContext& ctx, const tinygltf::Sampler& sampler,
                                    const std::string& field) {
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
    return convertEach<Texture>(
        model.textures, "textures", [&](const tinygltf::Texture& source, const std::string& field) {
            checkIndex(ctx, source.source, model.images.size(), field + ".source", "images");
            checkIndex(ctx, source.sampler, model.samplers.size(), field + ".sampler", "samplers");
            Texture texture;
            texture.name = source.name;
            texture.image = source.source;
            if (source.sampler >= 0)
                texture.sampler = convertSampler(ctx, model.samplers[static_cast<std::size_t>(source.sampler)],
                                                 indexed("samplers", static_cast<std::size_t>(source.sampler)));
            return texture;
        });
}

TextureRef convertTextureRef(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::TextureInfo& info,
                             const std::string& field) {
    TextureRef ref;
    if (info.index == -1) return ref;
    checkIndex(ctx, info.index, model.textures.size(), field + ".index", "textures", false);
    if (info.texCoord < 0 || info.texCoord > 7)
        ctx.fail(field + ".texCoord", std::to_string(info.texCoord) + " is not in [0, 7]");
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
    return convertEach<Material>(
        model.materials, "materials", [&](const tinygltf::Material& source, const std::string& field) {
            Material m;
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
            return m;
        });
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
        const auto decoded =
            draco ? draco->attributes.find(name) : std::map<std::string, std::vector<float>>::const_iterator{};
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
            ctx.fail(field + ".attributes." + name,
                     "has " + std::to_string(values.size() / static_cast<std::size_t>(comps)) +
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
    const std::vector<float> colors = attributes.read("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                                                      kFloatOnly | componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) |
                                                          componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT),
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
            vertex.color =
                glm::vec4(colors[c], colors[c + 1], colors[c + 2], colorComponents == 4 ? colors[c + 3] : 1.0f);
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

std::vector<Mesh> convertMeshes(const LoadContext& ctx, const tinygltf::Model& model,
                                const std::vector<Material>& materials,
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
            meshes[m].primitives.push_back(convertPrimitive(ctx, model, source, materials,
                                                            draco == dracoIndices.end() ? -1 : draco->second, field));
        }
    }
    return meshes;
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
    const std::string_view jsonText =
        checked.jsonForParser.empty()
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
            parsed = parser.LoadBinaryFromMemory(&model, &err, &warn, glb.data(), static_cast<unsigned int>(glb.size()),
                                                 baseDir);
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
