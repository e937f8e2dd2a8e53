// SPDX-License-Identifier: MIT
#include "gltf_preflight.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "engine/core/error.hpp"
#include "engine/core/file_signature.hpp"
#include "engine/core/log.hpp"

namespace engine::assets::detail {

using json = nlohmann::json;

// ---------------------------------------------------------------------------------------
// Context and files

void LoadContext::fail(const std::string& field, const std::string& problem) const {
    std::string message = file.string() + ": ";
    if (!field.empty()) message += field + ": ";
    throw Error(message + problem);
}

void LoadContext::warn(const std::string& field, const std::string& problem) const {
    std::string message = field.empty() ? problem : field + ": " + problem;
    log::warn(file.string(), ": ", message);
    if (warnings) warnings->push_back(std::move(message));
}

std::vector<std::uint8_t> readWholeFile(const LoadContext& ctx, const std::filesystem::path& path,
                                        const std::string& field) {
    namespace fs = std::filesystem;
    const std::string what = field.empty() ? std::string() : field;
    const std::string name = field.empty() ? std::string("file") : "file '" + path.string() + "'";
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) ctx.fail(what, name + " does not exist");
    if (fs::is_directory(status)) ctx.fail(what, name + " is a directory");
    // Only regular files: a FIFO or device would block or never end.
    if (!fs::is_regular_file(status)) ctx.fail(what, name + " is not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) ctx.fail(what, "cannot read the size of " + name + ": " + ec.message());
    const std::uint64_t cap = ctx.options ? ctx.options->maxFileBytes : (std::uint64_t{1} << 30);
    if (size > cap)
        ctx.fail(what, name + " is " + std::to_string(size) + " bytes, over the limit of " + std::to_string(cap));

    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in) ctx.fail(what, "cannot open " + name);
    if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
        ctx.fail(what, "cannot read " + name + " (it changed while being read?)");
    return bytes;
}

// ---------------------------------------------------------------------------------------
// GLB container (glTF 2.0 §4.4: 12-byte header, then chunks of 8-byte header + payload,
// the first JSON, the optional second BIN, every length a multiple of 4).

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

std::uint32_t readLe32(std::span<const std::uint8_t> bytes, std::size_t offset) {
    return static_cast<std::uint32_t>(bytes[offset]) | static_cast<std::uint32_t>(bytes[offset + 1]) << 8 |
           static_cast<std::uint32_t>(bytes[offset + 2]) << 16 | static_cast<std::uint32_t>(bytes[offset + 3]) << 24;
}

std::string hex32(std::uint32_t value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", value);
    return text;
}

// A file that is neither GLB nor text is refused by what it is ("starts with the PNG
// signature"), before a JSON parser quotes its bytes back. Text that is not JSON is left to
// the parser, whose message (made printable) says where it stopped.
void requireJsonText(const LoadContext& ctx, std::span<const std::uint8_t> file) {
    if (file.empty()) return;
    const std::uint8_t first = file[0];
    const bool text = (first >= 0x20 && first < 0x7F) || first == '\t' || first == '\n' || first == '\r' ||
                      first == 0xEF;  // the first byte of a UTF-8 byte-order mark
    if (!fileSignatureName(file).empty() || !text) ctx.fail("", describeFileStart(file) + ", not glTF JSON or GLB");
}

}  // namespace

Container splitContainer(const LoadContext& ctx, std::span<const std::uint8_t> file) {
    Container container;
    if (file.size() < 4 || readLe32(file, 0) != kGlbMagic) {
        requireJsonText(ctx, file);
        container.json = file;
        return container;
    }
    container.binary = true;
    if (file.size() < 12)
        ctx.fail("GLB header",
                 "truncated: the file has " + std::to_string(file.size()) + " bytes, the header needs 12");
    const std::uint32_t version = readLe32(file, 4);
    if (version != 2) ctx.fail("GLB header version", std::to_string(version) + ": only version 2 is supported");
    const std::uint32_t length = readLe32(file, 8);
    if (length != file.size())
        ctx.fail("GLB header length",
                 std::to_string(length) + " does not match the file size of " + std::to_string(file.size()) + " bytes");

    std::uint64_t offset = 12;
    for (int chunk = 0; offset < file.size(); ++chunk) {
        const std::string field = "GLB chunk " + std::to_string(chunk);
        if (file.size() - offset < 8)
            ctx.fail(field,
                     "header truncated at byte " + std::to_string(offset) + " of " + std::to_string(file.size()));
        const std::uint32_t chunkLength = readLe32(file, static_cast<std::size_t>(offset));
        const std::uint32_t chunkType = readLe32(file, static_cast<std::size_t>(offset) + 4);
        const std::uint64_t payload = offset + 8;
        // 64-bit: payload + chunkLength cannot wrap.
        if (payload + chunkLength > file.size())
            ctx.fail(field + " length", std::to_string(chunkLength) + " runs past the end of the file (" +
                                            std::to_string(file.size() - payload) + " bytes left)");
        if (chunkLength % 4 != 0) ctx.fail(field + " length", std::to_string(chunkLength) + " is not a multiple of 4");
        const auto data = file.subspan(static_cast<std::size_t>(payload), chunkLength);
        if (chunk == 0) {
            if (chunkType != kChunkJson)
                ctx.fail(field + " type",
                         hex32(chunkType) + ": the first chunk must be JSON (" + hex32(kChunkJson) + ")");
            if (chunkLength == 0) ctx.fail(field + " length", "0: the JSON chunk is empty");
            container.json = data;
        } else if (chunk == 1 && chunkType == kChunkBin) {
            container.bin = data;
            container.hasBin = true;
        } else if (chunkType == kChunkJson || chunkType == kChunkBin) {
            ctx.fail(field + " type",
                     hex32(chunkType) + ": only one JSON chunk (first) and one BIN chunk (second) are allowed");
        } else {
            ctx.warn(field, "unknown chunk type " + hex32(chunkType) + " ignored");
        }
        offset = payload + chunkLength;
    }
    if (container.json.empty()) ctx.fail("GLB", "the file has no JSON chunk");
    return container;
}

// ---------------------------------------------------------------------------------------
// URIs (glTF 2.0 §3.6.1: relative references or data: URIs; we refuse every other scheme).

bool isDataUri(std::string_view uri) {
    if (uri.size() < 5) return false;
    for (std::size_t i = 0; i < 5; ++i)
        if (std::tolower(static_cast<unsigned char>(uri[i])) != "data:"[i]) return false;
    return true;
}

namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// A URI scheme: ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":" before any '/', '?' or '#'.
// A Windows drive ("C:") reads as a one-letter scheme and is refused with the others.
std::string schemeOf(std::string_view uri) {
    const std::size_t colon = uri.find(':');
    if (colon == std::string_view::npos || colon == 0) return {};
    if (!std::isalpha(static_cast<unsigned char>(uri[0]))) return {};
    for (std::size_t i = 1; i < colon; ++i) {
        const unsigned char c = static_cast<unsigned char>(uri[i]);
        if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return {};
    }
    return std::string(uri.substr(0, colon));
}

bool hasDotDotSegment(std::string_view path) {
    std::size_t start = 0;
    while (start <= path.size()) {
        std::size_t end = path.find_first_of("/\\", start);
        if (end == std::string_view::npos) end = path.size();
        if (path.substr(start, end - start) == "..") return true;
        start = end + 1;
    }
    return false;
}

}  // namespace

std::string checkUri(const LoadContext& ctx, const std::string& field, const std::string& uri) {
    const std::string where = field + " '" + (uri.size() > 80 ? uri.substr(0, 80) + "..." : uri) + "'";
    if (uri.empty()) ctx.fail(field, "empty URI");
    if (isDataUri(uri)) {
        if (uri.find(";base64,") == std::string::npos) ctx.fail(where, "only base64 data: URIs are supported");
        return {};
    }
    // Percent-decode (tinygltf decodes the same way before opening the file).
    std::string decoded;
    decoded.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%') {
            const int hi = i + 2 < uri.size() ? hexValue(uri[i + 1]) : -1;
            const int lo = i + 2 < uri.size() ? hexValue(uri[i + 2]) : -1;
            if (hi < 0 || lo < 0) ctx.fail(where, "malformed percent-encoding");
            decoded.push_back(static_cast<char>(hi * 16 + lo));
            i += 2;
        } else {
            decoded.push_back(uri[i]);
        }
    }
    for (const std::string* form : std::initializer_list<const std::string*>{&uri, &decoded}) {
        const std::string scheme = schemeOf(*form);
        if (!scheme.empty())
            ctx.fail(where, "scheme '" + scheme + ":' is not allowed (only relative paths and data: URIs)");
        if (form->find('\0') != std::string::npos) ctx.fail(where, "NUL byte in the path");
        if ((*form)[0] == '/' || (*form)[0] == '\\') ctx.fail(where, "absolute paths are not allowed");
        if ((*form)[0] == '~') ctx.fail(where, "home-directory paths are not allowed");
        if (hasDotDotSegment(*form)) ctx.fail(where, "path traversal is not allowed");
    }
    return decoded;
}

namespace {

bool isUnder(const std::filesystem::path& path, const std::filesystem::path& base) {
    auto p = path.begin();
    for (auto b = base.begin(); b != base.end(); ++b, ++p) {
        if (b->empty()) continue;  // a trailing separator
        if (p == path.end() || *p != *b) return false;
    }
    return true;
}

}  // namespace

bool isConfined(const LoadContext& ctx, const std::filesystem::path& path) {
    std::error_code ec;
    const auto resolved = std::filesystem::canonical(path, ec);
    if (ec) return false;
    const auto base = std::filesystem::canonical(ctx.baseDir.empty() ? "." : ctx.baseDir, ec);
    if (ec) return false;
    return isUnder(resolved, base);
}

std::filesystem::path resolveConfined(const LoadContext& ctx, const std::string& field, const std::string& uri,
                                      const std::string& relative) {
    const std::string where = field + " '" + uri + "'";
    const auto path = (ctx.baseDir.empty() ? std::filesystem::path(".") : ctx.baseDir) / relative;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) ctx.fail(where, "file '" + path.string() + "' does not exist");
    if (!isConfined(ctx, path)) ctx.fail(where, "resolves outside the glTF file's directory (symbolic link?)");
    return std::filesystem::canonical(path);
}

// ---------------------------------------------------------------------------------------
// The JSON document

namespace {

struct DepthExceeded {};

// The parser's message quotes what it last read, which in a damaged file may be any byte:
// every byte outside printable ASCII is written as \xNN instead.
std::string printable(std::string_view message) {
    std::string out;
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7F) {
            out += c;
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
            out += escaped;
        }
    }
    return out;
}

json parseJson(const LoadContext& ctx, std::span<const std::uint8_t> text) {
    const json::parser_callback_t limitDepth = [](int depth, json::parse_event_t, json&) {
        if (depth > kMaxJsonDepth) throw DepthExceeded{};
        return true;
    };
    try {
        json doc = json::parse(text.begin(), text.end(), limitDepth);
        if (!doc.is_object()) ctx.fail("JSON", "the top level is not an object");
        return doc;
    } catch (const DepthExceeded&) {
        ctx.fail("JSON", "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    } catch (const json::exception& e) {
        ctx.fail("JSON", "not valid JSON: " + printable(e.what()));
    }
}

const json* member(const json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

// An optional array member; fails if present but not an array.
const json* arrayMember(const LoadContext& ctx, const json& object, const char* key, const std::string& field) {
    const json* value = member(object, key);
    if (value && !value->is_array()) ctx.fail(field, "must be an array");
    return value;
}

const json& objectAt(const LoadContext& ctx, const json& array, std::size_t i, const std::string& field) {
    const json& value = array[i];
    if (!value.is_object()) ctx.fail(field, "must be an object");
    return value;
}

// A non-negative integer member (JSON numbers like 1e3 or 2.0 are not integers here).
std::uint64_t unsignedMember(const LoadContext& ctx, const json& object, const char* key, const std::string& field,
                             bool required, std::uint64_t fallback = 0) {
    const json* value = member(object, key);
    if (!value) {
        if (required) ctx.fail(field, "required property '" + std::string(key) + "' is missing");
        return fallback;
    }
    if (value->is_number_unsigned()) return value->get<std::uint64_t>();
    if (value->is_number_integer() && value->get<std::int64_t>() >= 0) return value->get<std::uint64_t>();
    ctx.fail(field + "." + key, value->dump() + ": must be a non-negative integer");
}

// An index member checked against the size of the array it points into.
std::uint64_t indexMember(const LoadContext& ctx, const json& object, const char* key, const std::string& field,
                          std::size_t count, const char* target) {
    const std::uint64_t index = unsignedMember(ctx, object, key, field, true);
    if (index >= count)
        ctx.fail(field + "." + key,
                 std::to_string(index) + " is out of range: the file has " + std::to_string(count) + " " + target);
    return index;
}

bool isSupportedExtension(const std::string& name) {
    static constexpr std::array<std::string_view, 4> kSupported = {"KHR_draco_mesh_compression", "KHR_materials_unlit",
                                                                   "KHR_texture_transform", "KHR_mesh_quantization"};
    return std::find(kSupported.begin(), kSupported.end(), name) != kSupported.end();
}

void checkExtensions(const LoadContext& ctx, const json& doc) {
    if (const json* used = arrayMember(ctx, doc, "extensionsUsed", "extensionsUsed")) {
        for (std::size_t i = 0; i < used->size(); ++i) {
            const json& name = (*used)[i];
            if (!name.is_string()) ctx.fail(indexed("extensionsUsed", i), "must be a string");
            if (!isSupportedExtension(name.get<std::string>()))
                ctx.warn(indexed("extensionsUsed", i),
                         "extension '" + name.get<std::string>() + "' is not supported and is ignored");
        }
    }
    if (const json* required = arrayMember(ctx, doc, "extensionsRequired", "extensionsRequired")) {
        for (std::size_t i = 0; i < required->size(); ++i) {
            const json& name = (*required)[i];
            if (!name.is_string()) ctx.fail(indexed("extensionsRequired", i), "must be a string");
            if (!isSupportedExtension(name.get<std::string>()))
                ctx.fail(indexed("extensionsRequired", i) + " '" + name.get<std::string>() + "'",
                         "required extension is not supported");
        }
    }
}

}  // namespace

Preflight preflight(const LoadContext& ctx, const Container& container) {
    Preflight result;
    json doc = parseJson(ctx, container.json);

    const json* asset = member(doc, "asset");
    if (!asset || !asset->is_object()) ctx.fail("asset", "required object is missing");
    const json* version = member(*asset, "version");
    if (!version || !version->is_string()) ctx.fail("asset.version", "required string is missing");
    if (version->get<std::string>().rfind("2.", 0) != 0)
        ctx.fail("asset.version", "'" + version->get<std::string>() + "': only glTF 2.x is supported");

    checkExtensions(ctx, doc);

    // buffers: URIs, declared lengths, and the sizes of the files they name.
    std::vector<std::uint64_t> bufferLengths;
    if (const json* buffers = arrayMember(ctx, doc, "buffers", "buffers")) {
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            const std::string field = indexed("buffers", i);
            const json& buffer = objectAt(ctx, *buffers, i, field);
            const std::uint64_t byteLength = unsignedMember(ctx, buffer, "byteLength", field, true);
            if (byteLength == 0) ctx.fail(field + ".byteLength", "0: a buffer must hold at least one byte");
            if (byteLength > ctx.options->maxFileBytes)
                ctx.fail(field + ".byteLength", std::to_string(byteLength) + " is over the limit of " +
                                                    std::to_string(ctx.options->maxFileBytes) + " bytes");
            const json* uri = member(buffer, "uri");
            if (!uri) {
                // glTF 2.0 §4.4.3.3: only a GLB's first buffer may omit the URI; it is the BIN chunk.
                if (!container.binary || i != 0)
                    ctx.fail(field + ".uri", "missing (only the first buffer of a GLB may omit it)");
                if (!container.hasBin) ctx.fail(field, "refers to the GLB BIN chunk, but the file has none");
                if (byteLength > container.bin.size())
                    ctx.fail(field + ".byteLength", std::to_string(byteLength) + " is larger than the GLB BIN chunk (" +
                                                        std::to_string(container.bin.size()) + " bytes)");
            } else {
                if (!uri->is_string()) ctx.fail(field + ".uri", "must be a string");
                const std::string text = uri->get<std::string>();
                const std::string relative = checkUri(ctx, field + ".uri", text);
                if (!relative.empty()) {
                    const auto path = resolveConfined(ctx, field + ".uri", text, relative);
                    std::error_code ec;
                    const std::uintmax_t size = std::filesystem::file_size(path, ec);
                    if (ec) ctx.fail(field + ".uri '" + text + "'", "cannot read the file size: " + ec.message());
                    if (size != byteLength)
                        ctx.fail(field + ".byteLength", std::to_string(byteLength) + " does not match the size of '" +
                                                            text + "' (" + std::to_string(size) + " bytes)");
                }
            }
            bufferLengths.push_back(byteLength);
        }
    }

    // bufferViews: every view lies inside its buffer (64-bit, overflow-checked).
    std::size_t viewCount = 0;
    if (const json* views = arrayMember(ctx, doc, "bufferViews", "bufferViews")) {
        viewCount = views->size();
        for (std::size_t i = 0; i < views->size(); ++i) {
            const std::string field = indexed("bufferViews", i);
            const json& view = objectAt(ctx, *views, i, field);
            const std::uint64_t buffer = indexMember(ctx, view, "buffer", field, bufferLengths.size(), "buffers");
            const std::uint64_t byteOffset = unsignedMember(ctx, view, "byteOffset", field, false, 0);
            const std::uint64_t byteLength = unsignedMember(ctx, view, "byteLength", field, true);
            if (byteLength == 0) ctx.fail(field + ".byteLength", "0: a bufferView must hold at least one byte");
            std::uint64_t end = 0;
            if (!checkedAdd(byteOffset, byteLength, end) || end > bufferLengths[buffer])
                ctx.fail(field, "byteOffset " + std::to_string(byteOffset) + " + byteLength " +
                                    std::to_string(byteLength) + " exceeds " + indexed("buffers", buffer) +
                                    ".byteLength " + std::to_string(bufferLengths[buffer]));
            if (member(view, "byteStride")) {
                const std::uint64_t stride = unsignedMember(ctx, view, "byteStride", field, true);
                if (stride < 4 || stride > 252 || stride % 4 != 0)
                    ctx.fail(field + ".byteStride", std::to_string(stride) + ": must be a multiple of 4 in [4, 252]");
            }
        }
    }

    // images: URIs (external files must exist inside the base directory) or bufferViews.
    if (const json* images = arrayMember(ctx, doc, "images", "images")) {
        for (std::size_t i = 0; i < images->size(); ++i) {
            const std::string field = indexed("images", i);
            const json& image = objectAt(ctx, *images, i, field);
            const json* uri = member(image, "uri");
            const bool hasView = member(image, "bufferView") != nullptr;
            if ((uri != nullptr) == hasView) ctx.fail(field, "must have exactly one of 'uri' and 'bufferView'");
            if (hasView) {
                indexMember(ctx, image, "bufferView", field, viewCount, "bufferViews");
                continue;
            }
            if (!uri->is_string()) ctx.fail(field + ".uri", "must be a string");
            const std::string text = uri->get<std::string>();
            const std::string relative = checkUri(ctx, field + ".uri", text);
            if (!relative.empty() && ctx.options->loadImages) resolveConfined(ctx, field + ".uri", text, relative);
        }
    }

    // Draco: the compressed data's bufferView must exist before tinygltf parses the primitive,
    // and the primitive's indices are taken out of tinygltf's sight (see Preflight).
    const json* accessors = arrayMember(ctx, doc, "accessors", "accessors");
    const std::size_t accessorCount = accessors ? accessors->size() : 0;
    arrayMember(ctx, doc, "meshes", "meshes");
    for (std::size_t m = 0; doc.contains("meshes") && m < doc["meshes"].size(); ++m) {
        const std::string meshField = indexed("meshes", m);
        json& mesh = doc["meshes"][m];
        if (!mesh.is_object()) ctx.fail(meshField, "must be an object");
        arrayMember(ctx, mesh, "primitives", meshField + ".primitives");
        for (std::size_t p = 0; mesh.contains("primitives") && p < mesh["primitives"].size(); ++p) {
            const std::string field = meshField + "." + indexed("primitives", p);
            json& primitive = mesh["primitives"][p];
            if (!primitive.is_object()) ctx.fail(field, "must be an object");
            const json* extensions = member(primitive, "extensions");
            if (!extensions || !extensions->is_object()) continue;
            const json* draco = member(*extensions, "KHR_draco_mesh_compression");
            if (!draco) continue;
            const std::string dracoField = field + ".extensions.KHR_draco_mesh_compression";
            if (!draco->is_object()) ctx.fail(dracoField, "must be an object");
            indexMember(ctx, *draco, "bufferView", dracoField, viewCount, "bufferViews");
            const json* attributes = member(*draco, "attributes");
            if (!attributes || !attributes->is_object())
                ctx.fail(dracoField + ".attributes", "required object is missing");
            for (const auto& [name, id] : attributes->items())
                if (!id.is_number_unsigned() && !(id.is_number_integer() && id.get<std::int64_t>() >= 0))
                    ctx.fail(dracoField + ".attributes." + name, id.dump() + ": must be a non-negative integer");
            if (primitive.contains("indices")) {
                const std::uint64_t indices = indexMember(ctx, primitive, "indices", field, accessorCount, "accessors");
                result.dracoIndices[{m, p}] = static_cast<int>(indices);
                primitive.erase("indices");
            }
        }
    }
    if (!result.dracoIndices.empty()) result.jsonForParser = doc.dump();
    return result;
}

}  // namespace engine::assets::detail
