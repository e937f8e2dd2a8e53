#!/usr/bin/env python3
"""Writes the small glTF fixtures of tests/unit/assets (committed; rerun after editing).

    python3 tests/data/gltf/make_fixtures.py

Valid files sit in this directory, hostile ones in hostile/ (one rule broken per file, named
after the rule). Draco fixtures are made by the tests themselves with the Draco encoder, and
the committed content/ trees are Draco files the tests load too.
"""
import base64
import copy
import json
import math
import pathlib
import sys
import struct

HERE = pathlib.Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(HERE.parent))
from png_bytes import png, png_header_only, png_typed  # noqa: E402 (after the path)
HOSTILE = HERE / "hostile"


def data_uri(data, mime="application/octet-stream"):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode("ascii"))


# A 4x4 leaf-ish texture: opaque green centre, transparent corners, soft edge.
LEAF = [[(40, 140 + 20 * x, 30, 255 if 1 <= x <= 2 and 1 <= y <= 2 else (128 if (x in (1, 2) or y in (1, 2)) else 0))
         for x in range(4)] for y in range(4)]
LEAF_PNG = png(4, 4, LEAF)


def triangle_bin(positions=None):
    positions = positions or [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    data = b"".join(struct.pack("<3f", *p) for p in positions)               # 0: 36 bytes
    data += b"".join(struct.pack("<3f", 0.0, 0.0, 1.0) for _ in range(3))   # 36: normals
    data += struct.pack("<6f", 0.0, 0.0, 1.0, 0.0, 0.0, 1.0)                 # 72: uvs, 24 bytes
    data += struct.pack("<3H", 0, 1, 2) + b"\x00\x00"                        # 96: indices + pad
    return data                                                              # 104 bytes


def triangle_doc(buffer_uri, bin_length=104):
    return {
        "asset": {"version": "2.0", "generator": "ssam make_fixtures.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 2]}],
        "nodes": [
            {"name": "root", "translation": [1.0, 2.0, 3.0], "children": [1]},
            {"name": "triangle", "mesh": 0, "scale": [2.0, 2.0, 2.0],
             "rotation": [0.0, 0.0, 0.7071067811865476, 0.7071067811865476]},
            {"name": "camera", "camera": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 5, 1]},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100.0,
                                                            "aspectRatio": 1.5}}],
        "meshes": [{"name": "triangle", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
        "materials": [{"name": "leaf", "pbrMetallicRoughness": {
            "baseColorFactor": [1.0, 0.5, 0.25, 1.0], "baseColorTexture": {"index": 0}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33648}],
        "images": [{"uri": "leaf4.png"}],
        "buffers": [{"uri": buffer_uri, "byteLength": bin_length}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 72, "byteStride": 12, "target": 34962},
            {"buffer": 0, "byteOffset": 72, "byteLength": 24, "target": 34962},
            {"buffer": 0, "byteOffset": 96, "byteLength": 6, "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 3, "type": "VEC3",
             "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 0.0]},
            {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
    }


def embedded_doc(bin_data=None):
    """The triangle with its buffer and image as data: URIs: self-contained."""
    doc = triangle_doc(data_uri(bin_data or triangle_bin()))
    doc["images"] = [{"uri": data_uri(LEAF_PNG, "image/png")}]
    return doc


def write_json(path, doc):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(doc, indent=1) + "\n")


def glb(doc, bin_data):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    bin_data += b"\x00" * (-len(bin_data) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(bin_data), 0x004E4942) + bin_data
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def glb_doc():
    """The triangle as a GLB: geometry and the PNG in the BIN chunk."""
    bin_data = triangle_bin() + LEAF_PNG
    bin_data += b"\x00" * (-len(bin_data) % 4)
    doc = triangle_doc(None, len(bin_data))
    del doc["buffers"][0]["uri"]
    doc["bufferViews"].append({"buffer": 0, "byteOffset": 104, "byteLength": len(LEAF_PNG)})
    doc["images"] = [{"bufferView": 3, "mimeType": "image/png"}]
    return doc, bin_data


def alpha_modes_doc():
    """One quad per material: OPAQUE, MASK (foliage), BLEND, unlit + texture transform; also a
    non-indexed primitive, a triangle strip, KHR_mesh_quantization positions and a sparse accessor."""
    quad = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)          # 0: 4 positions, 48 bytes
    uvs = struct.pack("<8f", 0, 0, 1, 0, 1, 1, 0, 1)                         # 48: 32 bytes
    idx = struct.pack("<6H", 0, 1, 2, 0, 2, 3)                               # 80: 12 bytes
    soup = struct.pack("<18f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0)  # 92: 6 vertices, 72
    quant = b"".join(struct.pack("<3hxx", *v) for v in                     # 164: 4 x 8 bytes (stride 8:
                     [(0, 0, 0), (32767, 0, 0), (32767, 32767, 0), (0, 32767, 0)])  # 4-byte aligned)
    sparse_idx = struct.pack("<H", 2) + b"\x00\x00"                           # 196: 4 bytes
    sparse_val = struct.pack("<3f", 5.0, 5.0, 5.0)                           # 200: 12 bytes
    data = quad + uvs + idx + soup + quant + sparse_idx + sparse_val         # 212 bytes
    prim = lambda material: {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": material}
    return {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_unlit", "KHR_texture_transform", "KHR_mesh_quantization"],
        "extensionsRequired": ["KHR_mesh_quantization"],
        "scenes": [{"nodes": [0, 1, 2, 3, 4, 5]}, {"nodes": [6, 7]}],
        "scene": 0,
        "nodes": [{"mesh": i, "translation": [2.0 * i, 0, 0]} for i in range(7)] + [{"camera": 0}],
        "cameras": [{"type": "orthographic", "orthographic": {"xmag": 2.0, "ymag": 1.5, "znear": 0.01, "zfar": 50.0}}],
        "meshes": [
            {"name": "opaque", "primitives": [prim(0)]},
            {"name": "mask", "primitives": [prim(1)]},
            {"name": "blend", "primitives": [prim(2)]},
            {"name": "unlit", "primitives": [prim(3)]},
            {"name": "soup", "primitives": [{"attributes": {"POSITION": 3}}]},
            {"name": "strip", "primitives": [{"attributes": {"POSITION": 0}, "mode": 5}]},
            {"name": "quantized", "primitives": [{"attributes": {"POSITION": 4}, "indices": 2}]},
        ],
        "materials": [
            {"name": "opaque", "alphaMode": "OPAQUE"},
            {"name": "mask", "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": True,
             "extras": {"foliage": True}},
            {"name": "blend", "alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.8, 0.5]}},
            {"name": "unlit", "extensions": {"KHR_materials_unlit": {}},
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {
                 "offset": [0.5, 0.0], "scale": [2.0, 2.0], "rotation": math.pi / 2}}}}},
        ],
        "textures": [{"source": 0}],
        "images": [{"uri": data_uri(LEAF_PNG, "image/png")}],
        "buffers": [{"uri": data_uri(data), "byteLength": len(data)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48, "target": 34962},
            {"buffer": 0, "byteOffset": 48, "byteLength": 32, "target": 34962},
            {"buffer": 0, "byteOffset": 80, "byteLength": 12, "target": 34963},
            {"buffer": 0, "byteOffset": 92, "byteLength": 72, "target": 34962},
            {"buffer": 0, "byteOffset": 164, "byteLength": 32, "byteStride": 8, "target": 34962},
            {"buffer": 0, "byteOffset": 196, "byteLength": 4},
            {"buffer": 0, "byteOffset": 200, "byteLength": 12},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [5, 5, 5],
             "sparse": {"count": 1, "indices": {"bufferView": 5, "componentType": 5123},
                        "values": {"bufferView": 6}}},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 3, "componentType": 5126, "count": 6, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 4, "componentType": 5122, "normalized": True, "count": 4, "type": "VEC3",
             "min": [0, 0, 0], "max": [32767, 32767, 0]},
        ],
    }


def hostile():
    """One file per refused rule; most are the embedded triangle with one field broken."""
    files = {}

    def variant(name, mutate, base=None):
        doc = copy.deepcopy(base or embedded_doc())
        mutate(doc)
        files[name] = doc

    def set_path(*path_and_value):
        *path, value = path_and_value

        def mutate(doc):
            target = doc
            for key in path[:-1]:
                target = target[key]
            target[path[-1]] = value
        return mutate

    variant("uri_traversal.gltf", set_path("buffers", 0, "uri", "../../etc/passwd"))
    variant("uri_absolute.gltf", set_path("buffers", 0, "uri", "/etc/passwd"))
    variant("uri_scheme.gltf", set_path("buffers", 0, "uri", "https://example.com/triangle.bin"))
    variant("uri_file_scheme.gltf", set_path("buffers", 0, "uri", "file:///etc/passwd"))
    variant("uri_percent_traversal.gltf", set_path("buffers", 0, "uri", "%2e%2e/%2E%2E/etc/passwd"))
    variant("uri_backslash_traversal.gltf", set_path("buffers", 0, "uri", "sub\\..\\..\\secret.bin"))
    variant("image_uri_traversal.gltf", set_path("images", 0, "uri", "textures/../../secret.png"))
    variant("missing_bin.gltf", set_path("buffers", 0, "uri", "missing.bin"))
    variant("missing_image.gltf", set_path("images", 0, "uri", "missing.png"))
    variant("required_extension.gltf", set_path("extensionsRequired", ["KHR_mesh_quantization", "EXT_made_up_extension"]))
    variant("bufferview_out_of_range.gltf", set_path("bufferViews", 1, "byteLength", 64))
    variant("bufferview_offset_overflow.gltf", set_path("bufferViews", 2, "byteOffset", 18446744073709551610))
    variant("bufferview_bad_buffer.gltf", set_path("bufferViews", 2, "buffer", 7))
    variant("stride_out_of_range.gltf", set_path("bufferViews", 0, "byteStride", 2))
    variant("stride_too_small.gltf", set_path("bufferViews", 0, "byteStride", 8))
    variant("accessor_out_of_range.gltf", set_path("accessors", 2, "count", 4))
    variant("accessor_offset_past_view.gltf", set_path("accessors", 1, "byteOffset", 40))
    variant("accessor_huge_count.gltf", set_path("accessors", 0, "count", 4611686018427387904))
    variant("accessor_misaligned.gltf", set_path("accessors", 1, "byteOffset", 2))
    variant("component_type_double.gltf", set_path("accessors", 0, "componentType", 5130))
    variant("component_type_not_allowed.gltf", set_path("accessors", 3, "componentType", 5126))
    variant("accessor_bad_bufferview.gltf", set_path("accessors", 2, "bufferView", 9))
    variant("alpha_cutoff_negative.gltf", set_path("materials", 0, "alphaCutoff", -0.5))
    variant("alpha_mode_unknown.gltf", set_path("materials", 0, "alphaMode", "CUTOUT"))
    variant("texture_bad_source.gltf", set_path("textures", 0, "source", 3))
    variant("material_bad_texture.gltf", set_path("materials", 0, "pbrMetallicRoughness", "baseColorTexture", {"index": 5}))
    variant("node_bad_mesh.gltf", set_path("nodes", 1, "mesh", 4))
    variant("node_cycle.gltf", set_path("nodes", 1, "children", [0]))
    variant("node_two_parents.gltf", set_path("nodes", 2, "children", [1]))
    variant("camera_bad_yfov.gltf", set_path("cameras", 0, "perspective", "yfov", -1.0))

    def index_out_of_range(doc):
        data = bytearray(triangle_bin())
        struct.pack_into("<3H", data, 96, 0, 1, 7)
        doc["buffers"][0]["uri"] = data_uri(bytes(data))
    variant("index_out_of_range.gltf", index_out_of_range)

    def nan_position(doc):
        doc["buffers"][0]["uri"] = data_uri(triangle_bin([(0.0, 0.0, 0.0), (float("nan"), 0.0, 0.0), (0.0, 1.0, 0.0)]))
    variant("nan_position.gltf", nan_position)

    def inf_position(doc):
        doc["buffers"][0]["uri"] = data_uri(triangle_bin([(0.0, 0.0, 0.0), (1.0, float("inf"), 0.0), (0.0, 1.0, 0.0)]))
    variant("inf_position.gltf", inf_position)

    variant("image_too_large.gltf", set_path("images", 0, "uri", data_uri(png_header_only(20000, 20000), "image/png")))
    variant("image_not_png.gltf", set_path("images", 0, "uri", data_uri(b"GIF89a not really", "image/png")))

    def deep_extras(doc):
        value = True
        for _ in range(100):
            value = [value]
        doc["extras"] = value
    variant("json_too_deep.gltf", deep_extras)

    def draco_garbage(doc):
        doc["extensionsUsed"] = ["KHR_draco_mesh_compression"]
        doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]
        doc["meshes"][0]["primitives"][0]["extensions"] = {
            "KHR_draco_mesh_compression": {"bufferView": 1, "attributes": {"POSITION": 0}}}
    variant("draco_garbage.gltf", draco_garbage)

    for name, doc in files.items():
        write_json(HOSTILE / name, doc)

    # alphaCutoff of 1e400: JSON has no NaN or Inf, but a number this large parses as infinity.
    text = json.dumps(embedded_doc(), indent=1).replace('"name": "leaf",', '"name": "leaf", "alphaCutoff": 1e400,')
    (HOSTILE / "alpha_cutoff_infinite.gltf").write_text(text + "\n")

    # GLB container breakage.
    doc, bin_data = glb_doc()
    good = glb(doc, bin_data)
    (HOSTILE / "glb_length_mismatch.glb").write_bytes(good[:8] + struct.pack("<I", len(good) + 100) + good[12:])
    json_length = struct.unpack_from("<I", good, 12)[0]
    (HOSTILE / "glb_json_chunk_overrun.glb").write_bytes(good[:12] + struct.pack("<I", json_length + 4096) + good[16:])
    bin_header = 20 + json_length
    bin_length = struct.unpack_from("<I", good, bin_header)[0]
    (HOSTILE / "glb_bin_chunk_overrun.glb").write_bytes(
        good[:bin_header] + struct.pack("<I", bin_length + 64) + good[bin_header + 4:])
    (HOSTILE / "glb_truncated.glb").write_bytes(good[:10])
    (HOSTILE / "glb_bin_chunk_huge.glb").write_bytes(
        good[:bin_header] + struct.pack("<I", 0xFFFFFFFC) + good[bin_header + 4:])


def main():
    (HERE / "leaf4.png").write_bytes(LEAF_PNG)
    (HERE / "grey2x1.png").write_bytes(png_typed(2, 1, 0, [[(10,), (200,)]]))
    (HERE / "rgb2x1.png").write_bytes(png_typed(2, 1, 2, [[(255, 0, 0), (0, 0, 255)]]))
    (HERE / "triangle.bin").write_bytes(triangle_bin())
    write_json(HERE / "triangle.gltf", triangle_doc("triangle.bin"))
    write_json(HERE / "embedded.gltf", embedded_doc())
    doc, bin_data = glb_doc()
    (HERE / "triangle.glb").write_bytes(glb(doc, bin_data))
    write_json(HERE / "alpha_modes.gltf", alpha_modes_doc())
    used = embedded_doc()
    used["extensionsUsed"] = ["EXT_made_up_extension"]
    write_json(HERE / "used_extension.gltf", used)
    hostile()


if __name__ == "__main__":
    main()
