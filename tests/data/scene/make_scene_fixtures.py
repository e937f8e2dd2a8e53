#!/usr/bin/env python3
"""Writes the small glTF files `racer --scene` is tested with (committed; rerun after editing).

    python3 tests/data/scene/make_scene_fixtures.py

Every file is a unit quad (or a few) with KHR_materials_unlit, so a pixel's colour is the
material's colour exactly and the tests in tests/capture/scene can check it with the glTF
2.0 §3.9.4 formulas. Textures are tiny PNGs sampled NEAREST, so a texel maps to a known
half of the quad. Draco files are made by the test itself with the Draco encoder.
"""
import base64
import json
import pathlib
import sys
import struct

HERE = pathlib.Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, str(HERE.parent))
from png_bytes import png  # noqa: E402 (after the path)
NEAREST, CLAMP = 9728, 33071
FLOAT, USHORT, SHORT, UBYTE = 5126, 5123, 5122, 5121


class Doc:
    """A glTF document whose binary data all lives in one buffer."""

    def __init__(self):
        self.bin = bytearray()
        self.gltf = {"asset": {"version": "2.0", "generator": "ssam make_scene_fixtures.py"},
                     "extensionsUsed": ["KHR_materials_unlit"], "scene": 0, "scenes": [], "nodes": [],
                     "meshes": [], "materials": [], "accessors": [], "bufferViews": [], "buffers": []}

    def view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin += data
        self.gltf["bufferViews"].append(view)
        return len(self.gltf["bufferViews"]) - 1

    def accessor(self, fmt, component, type_, values, normalized=False, minmax=False, target=34962):
        flat = [c for v in values for c in (v if isinstance(v, tuple) else (v,))]
        data = struct.pack("<%d%s" % (len(flat), fmt), *flat)
        stride = None
        per = len(data) // len(values)
        if type_ != "SCALAR" and per % 4:  # vertex attributes: elements 4-byte aligned (glTF 2.0 §3.6.2.4)
            stride = per + 4 - per % 4
            data = b"".join(data[i * per:(i + 1) * per] + b"\0" * (stride - per) for i in range(len(values)))
        view = self.view(data, target)
        if stride:
            self.gltf["bufferViews"][view]["byteStride"] = stride
        accessor = {"bufferView": view, "componentType": component, "count": len(values), "type": type_}
        if normalized:
            accessor["normalized"] = True
        if minmax:
            accessor["min"] = [min(v[i] for v in values) for i in range(len(values[0]))]
            accessor["max"] = [max(v[i] for v in values) for i in range(len(values[0]))]
        self.gltf["accessors"].append(accessor)
        return len(self.gltf["accessors"]) - 1

    def texture(self, pixels):
        g = self.gltf
        g.setdefault("samplers", [{"magFilter": NEAREST, "minFilter": NEAREST, "wrapS": CLAMP, "wrapT": CLAMP}])
        g.setdefault("images", []).append({"bufferView": self.view(png(len(pixels[0]), len(pixels), pixels)),
                                           "mimeType": "image/png"})
        g.setdefault("textures", []).append({"sampler": 0, "source": len(g["images"]) - 1})
        return len(g["textures"]) - 1

    def material(self, mode="OPAQUE", factor=(1, 1, 1, 1), texture=None, cutoff=None, double_sided=False,
                 transform=None):
        pbr = {"baseColorFactor": list(factor), "metallicFactor": 0.0}
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
            if transform:
                pbr["baseColorTexture"]["extensions"] = {"KHR_texture_transform": transform}
        m = {"pbrMetallicRoughness": pbr, "extensions": {"KHR_materials_unlit": {}}}
        if mode != "OPAQUE":
            m["alphaMode"] = mode
        if cutoff is not None:
            m["alphaCutoff"] = cutoff
        if double_sided:
            m["doubleSided"] = True
        self.gltf["materials"].append(m)
        return len(self.gltf["materials"]) - 1

    def quad(self, material, x0=-1.0, x1=1.0, z=0.0, flipped=False, quantized=False):
        """A primitive: the quad [x0, x1] x [-1, 1] at depth z facing +Z (flipped: facing -Z)."""
        pos = [(x0, -1.0, z), (x1, -1.0, z), (x1, 1.0, z), (x0, 1.0, z)]
        uv = [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)]  # glTF: v = 0 is the image's top row
        if quantized:  # KHR_mesh_quantization: SHORT positions, normalized UNSIGNED_BYTE texcoords
            attributes = {"POSITION": self.accessor("h", SHORT, "VEC3", [tuple(int(c) for c in p) for p in pos], minmax=True),
                          "TEXCOORD_0": self.accessor("B", UBYTE, "VEC2", [tuple(int(c * 255) for c in t) for t in uv],
                                                      normalized=True)}
        else:
            attributes = {"POSITION": self.accessor("f", FLOAT, "VEC3", pos, minmax=True),
                          "NORMAL": self.accessor("f", FLOAT, "VEC3", [(0.0, 0.0, -1.0 if flipped else 1.0)] * 4),
                          "TEXCOORD_0": self.accessor("f", FLOAT, "VEC2", uv)}
        order = [0, 2, 1, 0, 3, 2] if flipped else [0, 1, 2, 0, 2, 3]
        return {"attributes": attributes, "indices": self.accessor("H", USHORT, "SCALAR", order, target=34963),
                "material": material}

    def mesh_node(self, primitives, translation=None):
        self.gltf["meshes"].append({"primitives": primitives})
        node = {"mesh": len(self.gltf["meshes"]) - 1}
        if translation:
            node["translation"] = list(translation)
        self.gltf["nodes"].append(node)
        return len(self.gltf["nodes"]) - 1

    def write(self, name):
        g = dict(self.gltf)
        for key in [k for k, v in g.items() if v == []]:
            del g[key]
        g["buffers"] = [{"byteLength": len(self.bin)}]
        path = HERE / name
        if name.endswith(".glb"):
            text = json.dumps(g, separators=(",", ":")).encode()
            text += b" " * (-len(text) % 4)
            body = bytes(self.bin) + b"\0" * (-len(self.bin) % 4)
            out = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + 8 + len(body))
            out += struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(body), 0x004E4942) + body
            path.write_bytes(out)
        else:
            g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()
            path.write_text(json.dumps(g, indent=1) + "\n")


def single(name, material_args, pixels=None, **quad_args):
    d = Doc()
    tex = d.texture(pixels) if pixels else None
    d.gltf["scenes"].append({"nodes": [d.mesh_node([d.quad(d.material(texture=tex, **material_args), **quad_args)])]})
    return d


# OPAQUE: texture alpha 0.2 (left) and 0 (right), factor alpha 0.3: all ignored.
OPAQUE_TEXELS = [[(200, 40, 40, 51), (40, 200, 40, 0)]]
single("opaque", {"factor": (1, 1, 1, 0.3)}, OPAQUE_TEXELS).write("opaque_texture_alpha.gltf")
single("opaque", {"factor": (1, 1, 1, 0.3)}, OPAQUE_TEXELS).write("opaque_texture_alpha.glb")
# MASK with alphaCutoff 0.6, texel alphas 0.3 | 0.55 | 0.9 (thirds of the quad): the first
# two are cut (the 0.55 one only by the material's cutoff, not by the default 0.5), the
# third is kept. Black, because the foliage techniques light MASK surfaces with the scene's
# sun even when unlit: black stays black under any light, so the test sees only coverage.
single("mask", {"mode": "MASK", "cutoff": 0.6}, [[(0, 0, 0, 77), (0, 0, 0, 140), (0, 0, 0, 230)]]).write("mask_cutoff.gltf")
# BLEND: white texel alpha 128/255 times factor (0.2, 0.6, 1.0, 0.8): alpha 0.4016 over the background.
single("blend", {"mode": "BLEND", "factor": (0.2, 0.6, 1.0, 0.8)}, [[(255, 255, 255, 128)]]).write("blend_factor.gltf")

# BLEND sorting: one mesh, the near red quad (z = 0.5) first in the file, the far green one second.
d = Doc()
near = d.quad(d.material("BLEND", (1, 0, 0, 0.5)), z=0.5)
far = d.quad(d.material("BLEND", (0, 1, 0, 0.5)), z=0.0)
d.gltf["scenes"].append({"nodes": [d.mesh_node([near, far])]})
d.write("blend_sorted.gltf")

# doubleSided: both quads face away from the front camera; only the right one is double-sided.
d = Doc()
left = d.quad(d.material(factor=(1, 0, 1, 1)), x0=-2.0, x1=0.0, flipped=True)
right = d.quad(d.material(factor=(0, 1, 1, 1), double_sided=True), x0=0.0, x1=2.0, flipped=True)
d.gltf["scenes"].append({"nodes": [d.mesh_node([left, right])]})
d.write("double_sided.gltf")
# The same for BLEND (alpha 0.75, so the drawn one is 75% cyan over the background).
d = Doc()
left = d.quad(d.material("BLEND", (1, 0, 1, 0.75)), x0=-2.0, x1=0.0, flipped=True)
right = d.quad(d.material("BLEND", (0, 1, 1, 0.75), double_sided=True), x0=0.0, x1=2.0, flipped=True)
d.gltf["scenes"].append({"nodes": [d.mesh_node([left, right])]})
d.write("blend_double_sided.gltf")

# KHR_texture_transform: u' = 0.5 + 0.5 u shows only the right (green) texel.
d = single("transform", {"transform": {"offset": [0.5, 0.0], "scale": [0.5, 1.0]}}, [[(220, 30, 30, 255), (30, 220, 30, 255)]])
d.gltf["extensionsUsed"].append("KHR_texture_transform")
d.write("texture_transform.gltf")

# KHR_mesh_quantization (required): SHORT positions, normalized UNSIGNED_BYTE texcoords.
d = single("quantized", {}, [[(30, 30, 220, 255), (30, 30, 220, 255)]], quantized=True)
d.gltf["extensionsUsed"].append("KHR_mesh_quantization")
d.gltf["extensionsRequired"] = ["KHR_mesh_quantization"]
d.write("quantized.gltf")

# Cameras: scene 0 has a red quad at the origin and a blue one at x = 10, with
# cameras[0] (perspective) and cameras[2] (orthographic, ymag 2) looking at the red one and
# cameras[1] (infinite perspective) at the blue one. Scene 1: a green quad, no camera.
d = Doc()
red = d.mesh_node([d.quad(d.material(factor=(1, 0, 0, 1)))])
blue = d.mesh_node([d.quad(d.material(factor=(0, 0, 1, 1)))], translation=(10, 0, 0))
green = d.mesh_node([d.quad(d.material(factor=(0, 1, 0, 1)))])
d.gltf["cameras"] = [
    {"type": "perspective", "name": "red", "perspective": {"yfov": 0.5, "znear": 0.1, "zfar": 100.0}},
    {"type": "perspective", "name": "blue", "perspective": {"yfov": 0.5, "znear": 0.1}},
    {"type": "orthographic", "name": "red ortho", "orthographic": {"xmag": 2.0, "ymag": 2.0, "znear": 0.0, "zfar": 50.0}},
]
d.gltf["nodes"] += [{"camera": 0, "translation": [0, 0, 3]}, {"camera": 1, "translation": [10, 0, 3]},
                    {"camera": 2, "translation": [0, 0, 5]}]
d.gltf["scenes"] = [{"nodes": [red, blue, 3, 4, 5]}, {"nodes": [green]}]
d.write("cameras.gltf")
