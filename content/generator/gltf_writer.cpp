// SPDX-License-Identifier: MIT
#include "gltf_writer.hpp"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <cstring>
#include <limits>

#include "engine/core/error.hpp"

namespace content {

namespace {

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;

ordered_json vec3Json(glm::vec3 v) { return ordered_json::array({v.x, v.y, v.z}); }

void boundsOf(const std::vector<glm::vec3>& points, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(std::numeric_limits<float>::max());
    hi = -lo;
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

}  // namespace

GlbWriter::GlbWriter() = default;

int GlbWriter::addView(const void* data, std::size_t size, int target) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);  // every view starts 4-byte aligned
    ordered_json view = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
    if (target != 0) view["target"] = target;
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    bin_.insert(bin_.end(), bytes, bytes + size);
    views_.push_back(view);
    return static_cast<int>(views_.size() - 1);
}

int GlbWriter::addAccessor(ordered_json accessor) {
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size() - 1);
}

int GlbWriter::addPngImage(const std::vector<std::uint8_t>& png, const std::string& name) {
    const int view = addView(png.data(), png.size(), 0);
    images_.push_back({{"name", name}, {"bufferView", view}, {"mimeType", "image/png"}});
    return static_cast<int>(images_.size() - 1);
}

int GlbWriter::addTexture(int image, int wrap) {
    int sampler = -1;
    for (std::size_t i = 0; i < samplers_.size(); ++i)
        if (samplers_[i]["wrapS"] == wrap) sampler = static_cast<int>(i);
    if (sampler < 0) {
        samplers_.push_back({{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", wrap}, {"wrapT", wrap}});
        sampler = static_cast<int>(samplers_.size() - 1);
    }
    textures_.push_back({{"sampler", sampler}, {"source", image}});
    return static_cast<int>(textures_.size() - 1);
}

int GlbWriter::addMaterial(ordered_json material) {
    materials_.push_back(std::move(material));
    return static_cast<int>(materials_.size() - 1);
}

ordered_json GlbWriter::plainPrimitive(const MeshData& mesh) {
    const std::size_t n = mesh.vertexCount();
    glm::vec3 lo, hi;
    boundsOf(mesh.positions, lo, hi);
    ordered_json attributes;
    attributes["POSITION"] =
        addAccessor({{"bufferView", addView(mesh.positions.data(), n * sizeof(glm::vec3), kArrayBuffer)},
                     {"componentType", kFloat},
                     {"count", n},
                     {"type", "VEC3"},
                     {"min", vec3Json(lo)},
                     {"max", vec3Json(hi)}});
    attributes["NORMAL"] =
        addAccessor({{"bufferView", addView(mesh.normals.data(), n * sizeof(glm::vec3), kArrayBuffer)},
                     {"componentType", kFloat},
                     {"count", n},
                     {"type", "VEC3"}});
    attributes["TEXCOORD_0"] =
        addAccessor({{"bufferView", addView(mesh.uvs.data(), n * sizeof(glm::vec2), kArrayBuffer)},
                     {"componentType", kFloat},
                     {"count", n},
                     {"type", "VEC2"}});
    int indices;
    if (n <= 65536) {
        std::vector<std::uint16_t> narrow(mesh.indices.begin(), mesh.indices.end());
        indices = addAccessor({{"bufferView", addView(narrow.data(), narrow.size() * 2, kElementArrayBuffer)},
                               {"componentType", kUnsignedShort},
                               {"count", narrow.size()},
                               {"type", "SCALAR"}});
    } else {
        indices =
            addAccessor({{"bufferView", addView(mesh.indices.data(), mesh.indices.size() * 4, kElementArrayBuffer)},
                         {"componentType", kUnsignedInt},
                         {"count", mesh.indices.size()},
                         {"type", "SCALAR"}});
    }
    return {{"attributes", attributes}, {"indices", indices}};
}

ordered_json GlbWriter::dracoPrimitive(const MeshData& mesh) {
    // The mesh as Draco sees it: one point per vertex, each attribute mapped one to one.
    draco::Mesh source;
    const auto n = static_cast<std::uint32_t>(mesh.vertexCount());
    source.set_num_points(n);
    const auto addAttribute = [&](draco::GeometryAttribute::Type type, int components, const float* values) {
        draco::GeometryAttribute attribute;
        attribute.Init(type, nullptr, static_cast<std::uint8_t>(components), draco::DT_FLOAT32, false,
                       static_cast<std::int64_t>(sizeof(float)) * components, 0);
        const int id = source.AddAttribute(attribute, true, n);
        for (std::uint32_t i = 0; i < n; ++i)
            source.attribute(id)->SetAttributeValue(
                draco::AttributeValueIndex(i),
                values + static_cast<std::size_t>(i) * static_cast<std::size_t>(components));
        return id;
    };
    const int pos = addAttribute(draco::GeometryAttribute::POSITION, 3, &mesh.positions[0].x);
    const int nor = addAttribute(draco::GeometryAttribute::NORMAL, 3, &mesh.normals[0].x);
    const int tex = addAttribute(draco::GeometryAttribute::TEX_COORD, 2, &mesh.uvs[0].x);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        source.AddFace({draco::PointIndex(mesh.indices[t]), draco::PointIndex(mesh.indices[t + 1]),
                        draco::PointIndex(mesh.indices[t + 2])});

    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, draco_.positionBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, draco_.normalBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, draco_.texCoordBits);
    encoder.SetSpeedOptions(3, 3);
    draco::EncoderBuffer encoded;
    const draco::Status status = encoder.EncodeMeshToBuffer(source, &encoded);
    if (!status.ok()) throw engine::Error("Draco encoding failed: " + status.error_msg_string());

    // Counts and bounds come from decoding what we wrote: Draco may split vertices and
    // quantises positions, and the accessors must describe the decoded data.
    draco::DecoderBuffer buffer;
    buffer.Init(encoded.data(), encoded.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) throw engine::Error("Draco round trip failed: " + decoded.status().error_msg_string());
    const draco::Mesh& back = *decoded.value();
    const draco::PointAttribute* positions = back.GetAttributeByUniqueId(source.attribute(pos)->unique_id());
    std::vector<glm::vec3> points(back.num_points());
    for (draco::PointIndex i(0); i < back.num_points(); ++i)
        positions->ConvertValue<float>(positions->mapped_index(i), 3, &points[i.value()].x);
    glm::vec3 lo, hi;
    boundsOf(points, lo, hi);

    const std::size_t count = back.num_points();
    ordered_json attributes;
    attributes["POSITION"] = addAccessor(
        {{"componentType", kFloat}, {"count", count}, {"type", "VEC3"}, {"min", vec3Json(lo)}, {"max", vec3Json(hi)}});
    attributes["NORMAL"] = addAccessor({{"componentType", kFloat}, {"count", count}, {"type", "VEC3"}});
    attributes["TEXCOORD_0"] = addAccessor({{"componentType", kFloat}, {"count", count}, {"type", "VEC2"}});
    const int indices = addAccessor({{"componentType", count <= 65536 ? kUnsignedShort : kUnsignedInt},
                                     {"count", static_cast<std::size_t>(back.num_faces()) * 3},
                                     {"type", "SCALAR"}});
    const int view = addView(encoded.data(), encoded.size(), 0);
    usesDraco_ = true;
    return {{"attributes", attributes},
            {"indices", indices},
            {"extensions",
             {{"KHR_draco_mesh_compression",
               {{"bufferView", view},
                {"attributes",
                 {{"POSITION", source.attribute(pos)->unique_id()},
                  {"NORMAL", source.attribute(nor)->unique_id()},
                  {"TEXCOORD_0", source.attribute(tex)->unique_id()}}}}}}}};
}

int GlbWriter::addMesh(const std::string& name, const std::vector<Part>& parts, bool draco, ordered_json extras) {
    ordered_json primitives = ordered_json::array();
    for (const Part& part : parts) {
        ordered_json primitive = draco ? dracoPrimitive(*part.mesh) : plainPrimitive(*part.mesh);
        primitive["material"] = part.material;
        primitives.push_back(std::move(primitive));
    }
    ordered_json mesh = {{"name", name}, {"primitives", primitives}};
    if (!extras.is_null()) mesh["extras"] = std::move(extras);
    meshes_.push_back(std::move(mesh));
    return static_cast<int>(meshes_.size() - 1);
}

int GlbWriter::addNode(ordered_json node) {
    nodes_.push_back(std::move(node));
    return static_cast<int>(nodes_.size() - 1);
}

void GlbWriter::setSceneNodes(std::vector<int> nodes) { scenes_.front() = std::move(nodes); }

int GlbWriter::addScene(std::vector<int> nodes) {
    scenes_.push_back(std::move(nodes));
    return static_cast<int>(scenes_.size() - 1);
}

std::vector<std::uint8_t> GlbWriter::glb() const {
    ordered_json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "ssam content-generator"}};
    if (usesDraco_) {
        doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    }
    doc["scene"] = 0;
    doc["scenes"] = ordered_json::array();
    for (const std::vector<int>& nodes : scenes_) doc["scenes"].push_back({{"nodes", nodes}});
    doc["nodes"] = nodes_;
    doc["meshes"] = meshes_;
    if (!materials_.empty()) doc["materials"] = materials_;
    if (!textures_.empty()) doc["textures"] = textures_;
    if (!samplers_.empty()) doc["samplers"] = samplers_;
    if (!images_.empty()) doc["images"] = images_;
    doc["accessors"] = accessors_;
    doc["bufferViews"] = views_;
    std::vector<std::uint8_t> bin = bin_;
    while (bin.size() % 4 != 0) bin.push_back(0);
    doc["buffers"] = ordered_json::array({{{"byteLength", bin.size()}}});

    std::string text = doc.dump();
    while (text.size() % 4 != 0) text.push_back(' ');  // glTF 2.0 §4.4.3.2: JSON padded with spaces
    const auto le32 = [](std::vector<std::uint8_t>& out, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    };
    std::vector<std::uint8_t> out;
    le32(out, 0x46546C67);  // "glTF"
    le32(out, 2);
    le32(out, static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
    le32(out, static_cast<std::uint32_t>(text.size()));
    le32(out, 0x4E4F534A);  // "JSON"
    out.insert(out.end(), text.begin(), text.end());
    le32(out, static_cast<std::uint32_t>(bin.size()));
    le32(out, 0x004E4942);  // "BIN"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

}  // namespace content
