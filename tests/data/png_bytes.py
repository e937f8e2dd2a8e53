"""PNG files written byte by byte for the fixture generators (no imaging library needed)."""
import struct
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"


def chunk(tag, data):
    """One PNG chunk: length, tag, data, CRC of tag and data."""
    body = tag + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png_typed(width, height, color_type, rows):
    """An 8-bit PNG of any colour type; rows are lists of byte tuples."""
    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)
    ihdr = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    return SIGNATURE + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def png(width, height, pixels):
    """RGBA8 PNG; pixels is a list of rows of (r, g, b, a)."""
    return png_typed(width, height, 6, pixels)


def png_header_only(width, height):
    """A PNG whose header claims width x height; the (empty) pixel data never gets read."""
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return SIGNATURE + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(b"\x00" * 16)) + chunk(b"IEND", b"")
