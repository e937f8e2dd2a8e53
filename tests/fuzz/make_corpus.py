#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the seed corpora of the fuzz targets (committed; rerun after editing).

    python3 tests/fuzz/make_corpus.py

corpus/<target>/ gets valid inputs (to start the fuzzer deep inside each format) and hostile
ones (one rule broken per file, named after it). Files named regress_* are reproducers that
fuzzing found; they are added by hand and never touched here. The glTF seeds reuse the
fixtures of tests/data/gltf (and its make_fixtures.py); the Draco seeds are the compressed
primitives of content/models/tree_palm.glb with a 4x4 texture. JPEG seeds are encoded by
oiiotool (openimageio-tools, in the Makefile's package list); PNG, TGA and EXR are written
here, byte by byte, so the hostile variants can lie exactly where intended.
"""
import copy
import json
import pathlib
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
CORPUS = HERE / "corpus"
GLTF_FIXTURES = ROOT / "tests" / "data" / "gltf"
SCENE_FIXTURES = ROOT / "tests" / "data" / "scene"
sys.path.insert(0, str(GLTF_FIXTURES))
import make_fixtures as fx  # noqa: E402  (png, triangle_doc, glb, ...)


def write(target, name, data):
    path = CORPUS / target / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data.encode() if isinstance(data, str) else data)


def compact(doc):
    return json.dumps(doc, separators=(",", ":"))


# ---------------------------------------------------------------------------------------
# Containers and images, byte by byte

def split_glb(data):
    """(json document, BIN payload) of a well-formed GLB."""
    json_length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + json_length])
    bin_header = 20 + json_length
    bin_length = struct.unpack_from("<I", data, bin_header)[0]
    return doc, data[bin_header + 8:bin_header + 8 + bin_length]


def png_chunk(tag, data):
    body = tag + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png_raw(width, height, bit_depth, color_type, raw_rows, extra=b"", interlace=0):
    """A PNG from already-packed rows (each without its filter byte)."""
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, interlace)
    idat = zlib.compress(b"".join(b"\x00" + row for row in raw_rows), 9)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + extra + png_chunk(b"IDAT", idat) +
            png_chunk(b"IEND", b""))


def tga(width, height, pixels_bgra, image_type=2, descriptor=0x28):
    """Uncompressed (type 2) 32-bit TGA, rows top to bottom (descriptor bit 5)."""
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, image_type, 0, 0, 0, 0, 0, width, height, 32, descriptor)
    return header + bytes(pixels_bgra)


def exr(width, height, channels, values, data_window=None, offsets=None):
    """A scanline EXR without compression. channels: [(name, pixel_type)], 1 = HALF, 2 = FLOAT;
    values(channel, x, y) -> float. Channels are sorted by name, as the format requires."""
    channels = sorted(channels)

    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    chlist = b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", t, 0, 1, 1) for n, t in channels) + b"\0"
    window = data_window or (0, 0, width - 1, height - 1)
    header = (struct.pack("<II", 20000630, 2) +
              attribute("channels", "chlist", chlist) +
              attribute("compression", "compression", b"\0") +
              attribute("dataWindow", "box2i", struct.pack("<4i", *window)) +
              attribute("displayWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1)) +
              attribute("lineOrder", "lineOrder", b"\0") +
              attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0)) +
              attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0.0, 0.0)) +
              attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    lines = []
    for y in range(height):
        data = b""
        for name, kind in channels:
            fmt = "<e" if kind == 1 else "<f"
            data += b"".join(struct.pack(fmt, values(name, x, y)) for x in range(width))
        lines.append(struct.pack("<ii", y, len(data)) + data)
    table_start = len(header)
    first = table_start + 8 * height
    starts = []
    for line in lines:
        starts.append(first)
        first += len(line)
    if offsets:
        starts = offsets(starts)
    return header + b"".join(struct.pack("<Q", s) for s in starts) + b"".join(lines)


def oiiotool_convert(png_bytes, suffix, *args):
    """png_bytes re-encoded by oiiotool (JPEG has no encoder here), or None without oiiotool."""
    if not shutil.which("oiiotool"):
        return None
    with tempfile.TemporaryDirectory() as tmp:
        # Relative names: oiiotool records its command line in the file's metadata.
        (pathlib.Path(tmp) / "in.png").write_bytes(png_bytes)
        subprocess.run(["oiiotool", "in.png", *args, "-o", "out" + suffix], check=True, cwd=tmp)
        return (pathlib.Path(tmp) / ("out" + suffix)).read_bytes()


def jpeg_with_size(jpeg, width, height):
    """The JPEG with its SOF0/SOF2 frame header claiming width x height."""
    data = bytearray(jpeg)
    i = 2
    while i + 4 < len(data):
        marker, length = data[i + 1], struct.unpack_from(">H", data, i + 2)[0]
        if marker in (0xC0, 0xC2):
            struct.pack_into(">HH", data, i + 5, height, width)
            return bytes(data)
        i += 2 + length
    raise ValueError("no SOF marker")


# ---------------------------------------------------------------------------------------
# Seeds per target

GRADIENT_RGBA = [[(x * 60, y * 60, 128, 255 - x * 40) for x in range(4)] for y in range(4)]


def image_seeds():
    """Valid and hostile PNG/JPEG shared by image_decode and capture_image."""
    rgba = fx.png(4, 4, GRADIENT_RGBA)
    seeds = {
        "png_rgba8.png": rgba,
        "png_grey8.png": fx.png_typed(2, 1, 0, [[(10,), (200,)]]),
        "png_grey_alpha8.png": fx.png_typed(2, 2, 4, [[(10, 0), (200, 255)], [(30, 128), (90, 64)]]),
        "png_rgb8.png": fx.png_typed(2, 1, 2, [[(255, 0, 0), (0, 0, 255)]]),
        "png_rgba16.png": png_raw(2, 2, 16, 6, [struct.pack(">8H", 0, 65535, 1000, 65535, 65535, 0, 0, 32768)] * 2),
        "png_grey1.png": png_raw(8, 2, 1, 0, [b"\xA5", b"\x5A"]),
        "png_palette_trns.png": png_raw(4, 1, 8, 3, [b"\x00\x01\x02\x01"],
                                        png_chunk(b"PLTE", b"\xff\x00\x00\x00\xff\x00\x00\x00\xff") +
                                        png_chunk(b"tRNS", b"\x80\xff\x00")),
        "png_interlaced_flag.png": png_raw(1, 1, 8, 6, [b"\x10\x20\x30\x40"], interlace=1),
        "png_gamma_linear.png": png_raw(1, 1, 8, 2, [b"\x80\x80\x80"], png_chunk(b"gAMA", struct.pack(">I", 100000))),
        # hostile: sizes from the header alone, lying chunks, broken compression
        "png_huge_header.png": fx.png_header_only(100000, 100000),
        "png_just_over_cap.png": fx.png_header_only(4097, 1),
        "png_zero_size.png": fx.png_header_only(0, 0),
        "png_max_uint_size.png": fx.png_header_only(0xFFFFFFFF, 0xFFFFFFFF),
        "png_truncated_idat.png": rgba[:len(rgba) - 20],
        "png_header_only_signature.png": rgba[:8],
        "png_bad_crc.png": rgba[:29] + b"\xde\xad\xbe\xef" + rgba[33:],
        "png_garbage_zlib.png": rgba[:41] + bytes((b * 7 + 3) & 0xFF for b in rgba[41:-12]) + rgba[-12:],
        "png_bad_bit_depth.png": png_raw(1, 1, 7, 6, [b"\x00\x00\x00\x00"]),
        "png_chunk_length_lies.png": rgba[:33] + struct.pack(">I", 0x7FFFFFF0) + rgba[37:],
        "png_no_iend.png": rgba[:-12],
        "png_palette_index_past_plte.png": png_raw(2, 1, 8, 3, [b"\x00\x09"], png_chunk(b"PLTE", b"\xff\x00\x00")),
    }
    # oiiotool writes Exif and Photoshop IPTC segments: the metadata paths of the JPEG reader.
    jpeg = oiiotool_convert(fx.png_typed(8, 8, 2, [[(x * 30, y * 30, 100) for x in range(8)] for y in range(8)]), ".jpg")
    if jpeg:
        seeds["jpeg_rgb.jpg"] = jpeg
        seeds["jpeg_truncated.jpg"] = jpeg[:len(jpeg) // 2]
        seeds["jpeg_huge_frame.jpg"] = jpeg_with_size(jpeg, 65500, 65500)
        seeds["jpeg_zero_frame.jpg"] = jpeg_with_size(jpeg, 0, 8)
        seeds["jpeg_magic_only.jpg"] = jpeg[:3]
    return seeds


def exr_seeds():
    colour = [("R", 1), ("G", 1), ("B", 1), ("A", 1)]
    ramp = lambda c, x, y: (x + y) / 4.0  # noqa: E731
    nan_inf = lambda c, x, y: [float("nan"), float("inf"), float("-inf"), 0.5][(x + 2 * y) % 4]  # noqa: E731
    layers = [("opaque.R", 1), ("opaque.G", 1), ("opaque.B", 1), ("opaque.A", 1), ("depth.Z", 2)]
    good = exr(3, 2, colour, ramp)
    return {
        "exr_rgba_half.exr": good,
        "exr_layers.exr": exr(2, 2, layers, ramp),
        "exr_depth_nan_inf.exr": exr(2, 2, [("depth.Z", 2)], nan_inf),
        "exr_float_nan_rgba.exr": exr(2, 2, [(c, 2) for c, _ in colour], nan_inf),
        # hostile
        "exr_huge_data_window.exr": exr(2, 1, colour, ramp, data_window=(0, 0, 1999999999, 0)),
        "exr_inverted_data_window.exr": exr(2, 1, colour, ramp, data_window=(5, 5, 0, 0)),
        "exr_negative_window_overflow.exr": exr(2, 1, colour, ramp, data_window=(-2147483647, 0, 2147483647, 0)),
        "exr_offsets_past_end.exr": exr(2, 2, colour, ramp, offsets=lambda s: [s[0], 0x7FFFFFFFFFFF]),
        "exr_offsets_backwards.exr": exr(2, 2, colour, ramp, offsets=lambda s: [s[1], s[0] - 7]),
        "exr_truncated.exr": good[:len(good) - 9],
        "exr_header_only.exr": good[:40],
    }


def tga_seeds():
    pixels = [v for y in range(2) for x in range(3) for v in (x * 80, y * 200, 40, 128 + x)]
    good = tga(3, 2, pixels)
    rle_lies = struct.pack("<BBBHHBHHHHBB", 0, 0, 10, 0, 0, 0, 0, 0, 64, 64, 32, 0x28) + b"\xff\x01\x02\x03\x04"
    return {
        "tga_rgba.tga": good,
        "tga_truncated.tga": good[:30],
        "tga_huge.tga": struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, 65535, 65535, 32, 0x28) + b"\0" * 16,
        "tga_rle_runs_past_end.tga": rle_lies,
        "tga_colormap_lies.tga": struct.pack("<BBBHHBHHHHBB", 0, 1, 1, 0, 65535, 24, 0, 0, 2, 2, 8, 0x20) + b"\x00\x05",
    }


# The Draco primitives of a real content asset, with the two textures replaced by one 4x4 PNG.
def palm_draco():
    doc, payload = split_glb((ROOT / "content" / "models" / "tree_palm.glb").read_bytes())
    views = doc["bufferViews"]
    draco_views = [p["extensions"]["KHR_draco_mesh_compression"]["bufferView"]
                   for p in doc["meshes"][0]["primitives"]]
    blob = bytearray(fx.LEAF_PNG)
    new_views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(fx.LEAF_PNG)}]
    for old in draco_views:
        blob += b"\0" * (-len(blob) % 4)
        view = views[old]
        new_views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": view["byteLength"]})
        blob += payload[view["byteOffset"]:view["byteOffset"] + view["byteLength"]]
        doc["meshes"][0]["primitives"][draco_views.index(old)]["extensions"]["KHR_draco_mesh_compression"][
            "bufferView"] = len(new_views) - 1
    blob += b"\0" * (-len(blob) % 4)
    doc["bufferViews"] = new_views
    doc["buffers"] = [{"byteLength": len(blob)}]
    for image in doc["images"]:
        image["bufferView"] = 0
    return doc, bytes(blob)


def mutated(doc, *path_and_value):
    doc = copy.deepcopy(doc)
    *path, value = path_and_value
    target = doc
    for key in path[:-1]:
        target = target[key]
    if value is DELETE:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return doc


DELETE = object()
DRACO = ("meshes", 0, "primitives", 0, "extensions", "KHR_draco_mesh_compression")


def gltf_glb_seeds():
    seeds = {
        "triangle.glb": (GLTF_FIXTURES / "triangle.glb").read_bytes(),
        "opaque_texture_alpha.glb": (SCENE_FIXTURES / "opaque_texture_alpha.glb").read_bytes(),
        "water.glb": (ROOT / "content" / "models" / "water.glb").read_bytes(),
    }
    for hostile in sorted((GLTF_FIXTURES / "hostile").glob("*.glb")):
        seeds[hostile.name] = hostile.read_bytes()

    palm, blob = palm_draco()
    seeds["draco_palm.glb"] = fx.glb(palm, blob)
    draco_view = palm["bufferViews"][1]
    start, length = draco_view["byteOffset"], draco_view["byteLength"]
    corrupt = bytearray(blob)
    for i in range(start + length // 3, start + length // 3 + 24):
        corrupt[i] ^= 0x5A
    seeds["draco_corrupt_payload.glb"] = fx.glb(palm, bytes(corrupt))
    seeds["draco_truncated_view.glb"] = fx.glb(mutated(palm, "bufferViews", 1, "byteLength", length // 2), blob)
    seeds["draco_vertex_count_lie.glb"] = fx.glb(mutated(palm, "accessors", 0, "count", 17), blob)
    seeds["draco_index_count_lie.glb"] = fx.glb(mutated(palm, "accessors", 3, "count", 45), blob)
    seeds["draco_unknown_attribute_id.glb"] = fx.glb(mutated(palm, *DRACO, "attributes", "POSITION", 9), blob)
    seeds["draco_bufferview_out_of_range.glb"] = fx.glb(mutated(palm, *DRACO, "bufferView", 7), blob)
    seeds["draco_indices_accessor_out_of_range.glb"] = fx.glb(
        mutated(palm, "meshes", 0, "primitives", 0, "indices", 99), blob)
    seeds["draco_without_indices.glb"] = fx.glb(mutated(palm, "meshes", 0, "primitives", 0, "indices", DELETE), blob)
    seeds["draco_normal_as_vec2.glb"] = fx.glb(mutated(palm, "accessors", 1, "type", "VEC2"), blob)
    seeds["draco_strip_mode.glb"] = fx.glb(mutated(palm, "meshes", 0, "primitives", 0, "mode", 5), blob)

    doc, bin_data = fx.glb_doc()
    seeds["accessor_out_of_range.glb"] = fx.glb(mutated(doc, "meshes", 0, "primitives", 0, "indices", 9), bin_data)
    seeds["accessor_count_past_view.glb"] = fx.glb(mutated(doc, "accessors", 0, "count", 7), bin_data)
    nan_bin = bytearray(bin_data)
    struct.pack_into("<f", nan_bin, 12, float("nan"))
    seeds["nan_position.glb"] = fx.glb(doc, bytes(nan_bin))
    huge_png = fx.png_header_only(100000, 100000)
    huge_bin = bin_data[:104] + huge_png + b"\0" * (-len(huge_png) % 4)
    seeds["image_huge_header.glb"] = fx.glb(mutated(doc, "bufferViews", 3, "byteLength", len(huge_png)), huge_bin)
    traversal = copy.deepcopy(doc)
    traversal["buffers"].append({"uri": "../../etc/passwd", "byteLength": 4})
    seeds["uri_traversal.glb"] = fx.glb(traversal, bin_data)
    unaligned = fx.glb(doc, bin_data)
    json_length = struct.unpack_from("<I", unaligned, 12)[0]
    seeds["chunk_length_unaligned.glb"] = (unaligned[:20 + json_length] + struct.pack("<I", len(bin_data) - 2) +
                                           unaligned[24 + json_length:])
    extra_chunk = unaligned + struct.pack("<II", 4, 0x12345678) + b"abcd"
    seeds["unknown_third_chunk.glb"] = extra_chunk[:8] + struct.pack("<I", len(extra_chunk)) + extra_chunk[12:]
    seeds["bin_chunk_first.glb"] = struct.pack("<III", 0x46546C67, 2, 28) + struct.pack("<II", 8, 0x004E4942) + b"\0" * 8
    seeds["version_one.glb"] = unaligned[:4] + struct.pack("<I", 1) + unaligned[8:]
    # Finite numbers whose products are not: scales of 1e30 on a parent and a child.
    overflow = mutated(doc, "nodes", 0, "scale", [1e30, 1e30, 1e30])
    overflow["nodes"][1]["scale"] = [1e30, 1e30, 1e30]
    seeds["world_transform_overflow.glb"] = fx.glb(overflow, bin_data)
    # A finite world transform (scale 1e20) times finite positions (1e20): world bounds overflow.
    far_bin = bytearray(bin_data)
    struct.pack_into("<9f", far_bin, 0, *([1e20] * 9))
    seeds["world_bounds_overflow.glb"] = fx.glb(mutated(doc, "nodes", 1, "scale", [1e20, 1e20, 1e20]), bytes(far_bin))
    return seeds


def gltf_text_seeds():
    seeds = {}
    for folder in (GLTF_FIXTURES, GLTF_FIXTURES / "hostile", SCENE_FIXTURES):
        for path in sorted(folder.glob("*.gltf")):
            seeds[path.name] = path.read_bytes()
    # Siblings the fuzz target provides next to the input (fuzz_gltf_text.cpp).
    doc = fx.triangle_doc("triangle.bin")
    # The image's or the buffer's URI, one per seed: {seed: uri} for each of the two.
    uris = {
        "images": {
            "sibling_texture_subdir.gltf": "textures/leaf4.png",
            "sibling_buffer_as_image.gltf": "triangle.bin",
            "sibling_dot_segments.gltf": "./textures/./leaf4.png",
        },
        "buffers": {
            "sibling_symlink_escape.gltf": "escape.bin",
            "sibling_directory_as_buffer.gltf": "textures",
            "sibling_image_as_buffer.gltf": "leaf4.png",
            "sibling_percent_encoded.gltf": "triangle%2Ebin",
            "sibling_self_as_buffer.gltf": "input.gltf",
            "uri_nul_byte.gltf": "triangle.bin%00.png",
            "uri_windows_drive.gltf": "C:\\Windows\\win.ini",
            "uri_home.gltf": "~/triangle.bin",
            "uri_bad_percent.gltf": "triangle%2",
        },
    }
    for array, seed_uris in uris.items():
        for name, uri in seed_uris.items():
            seeds[name] = compact(mutated(doc, array, 0, "uri", uri))

    palm, blob = palm_draco()
    palm["buffers"][0]["uri"] = fx.data_uri(blob)
    seeds["draco_palm_data_uri.gltf"] = compact(palm)
    # KHR_texture_transform with finite values whose baked UVs are not.
    embedded = fx.embedded_doc()
    transform = {"KHR_texture_transform": {"offset": [3e38, 3e38], "scale": [3e38, 3e38]}}
    embedded["extensionsUsed"] = ["KHR_texture_transform"]
    seeds["texture_transform_overflow.gltf"] = compact(
        mutated(embedded, "materials", 0, "pbrMetallicRoughness", "baseColorTexture", "extensions", transform))
    seeds["camera_orthographic_zero.gltf"] = compact(mutated(embedded, "cameras", 0, {
        "type": "orthographic", "orthographic": {"xmag": 0.0, "ymag": 1.0, "znear": 0.0, "zfar": 1.0}}))
    seeds["quaternion_zero.gltf"] = compact(mutated(embedded, "nodes", 1, "rotation", [0.0, 0.0, 0.0, 0.0]))
    seeds["sparse_index_out_of_range.gltf"] = compact(mutated(embedded, "accessors", 0, "sparse", {
        "count": 1, "indices": {"bufferView": 1, "byteOffset": 10, "componentType": 5123},  # 0x3F80
        "values": {"bufferView": 1, "byteOffset": 0}}))
    seeds["scene_out_of_range.gltf"] = compact(mutated(embedded, "scene", 5))
    seeds["quaternion_huge.gltf"] = compact(mutated(embedded, "nodes", 1, "rotation", [3e38, 0.0, 0.0, 3e38]))
    seeds["truncated_json.gltf"] = '{"asset": {"version": "2.0"'
    seeds["glb_magic_in_text.gltf"] = "glTF? no: {\"asset\": "
    seeds["json_array_top.gltf"] = "[1, 2, 3]"
    seeds["asset_version_1.gltf"] = compact({"asset": {"version": "1.0"}})
    seeds["minimal.gltf"] = compact({"asset": {"version": "2.0"}})
    return seeds


def racer_flags_seeds():
    return {
        "script_keys.txt": "2:3,4:C,0-9:W,10-14:shift+D,20:Esc",
        "script_window.txt": "5:size=400x300,8:minimize=200,1:shift+T,3:p",
        "script_every_key.txt": ",".join("%d:%s" % (i, k) for i, k in enumerate(
            "1 2 3 4 5 6 7 8 t c p esc w a s d q e space ctrl left right up down".split())),
        "script_unsorted.txt": "9:T,3:C,3-4:Up,0:size=1x1",
        "script_int_max.txt": "2147483647:C,0-2147483647:W",
        "script_int_overflow.txt": "2147483648:C",
        "script_negative.txt": "-1:C",
        "script_range_backwards.txt": "9-3:W",
        "script_range_change.txt": "1-3:size=10x10",
        "script_size_bad.txt": "1:size=0x32768,2:size=x,3:size=12,4:size=1x1x1",
        "script_minimize_bad.txt": "1:minimize=0,2:minimize=60001,3:minimize=",
        "script_trailing_comma.txt": "1:C,",
        "script_empty_entry.txt": ",,",
        "script_no_colon.txt": "C",
        "script_nul.txt": "1:C\0,2:T",
        "size_ok.txt": "1280x720",
        "size_huge.txt": "99999x99999",
        "size_zero.txt": "0x720",
        "size_leading_zeros.txt": "001280x00720",
        "camera_pan.txt": "pan",
        "technique_ssam.txt": "ssam",
        "technique_alpha_test.txt": "alpha-test",
    }


def main():
    images = image_seeds()
    for name, data in images.items():
        write("image_decode", name, data)
    capture = dict(images)
    capture.update(exr_seeds())
    capture.update(tga_seeds())
    for name, data in capture.items():
        write("capture_image", name, data)
    for name, data in gltf_glb_seeds().items():
        write("gltf_glb", name, data)
    for name, data in gltf_text_seeds().items():
        write("gltf_text", name, data)
    for name, data in racer_flags_seeds().items():
        write("racer_flags", name, data)


if __name__ == "__main__":
    main()
