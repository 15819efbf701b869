#!/usr/bin/env python3
"""Writes the binary and generated fixtures of tests/data/ (one per failure mode of bad input).

Run from anywhere: `python3 tests/data/make_fixtures.py`. Needs only the standard library; the
output is byte-for-byte reproducible, so re-running it leaves `git status` clean. The fixtures
are committed so the tests (and the fuzzers' seed corpora) do not depend on this script.

Layout:
  images/     equirect images: valid oddities (grey, grey+alpha, RGBA, 16-bit, extreme texels)
              and broken files (empty, truncated, wrong format, headers claiming huge sizes)
  cubemaps/   cubemap folders: missing face, mixed sizes, non-square, 1x1 (valid), 16K headers
  obj/        extra OBJ/MTL cases (the hand-written ones already there are kept)
  cache/      a file that is not a transport cache
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def out(relative, data):
    path = os.path.join(HERE, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(path, "wb") as f:
        f.write(data)


# ---- PNG ------------------------------------------------------------------------------------
def png_chunk(kind, payload):
    return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))


def png(width, height, colour_type, bit_depth, rows, ihdr_size=None):
    """rows: list of bytes (one per scanline, without the filter byte). ihdr_size overrides the
    size written in the header (to fake a huge image whose pixel data is tiny)."""
    w, h = ihdr_size or (width, height)
    ihdr = struct.pack(">IIBBBBB", w, h, bit_depth, colour_type, 0, 0, 0)
    raw = b"".join(b"\x00" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) +
            png_chunk(b"IDAT", zlib.compress(raw, 9)) + png_chunk(b"IEND", b""))


def grey_rows(width, height, channels, depth=8, level=128):
    sample = struct.pack(">H", level * 257) if depth == 16 else bytes([level])
    return [sample * (channels * width) for _ in range(height)]


# ---- Radiance HDR (RGBE) --------------------------------------------------------------------
def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes([0, 0, 0, 0])
    mant, exp = math.frexp(m)
    scale = mant * 256.0 / m
    return bytes([int(r * scale), int(g * scale), int(b * scale), exp + 128])


def hdr(width, height, texel, rle=False, keep=None):
    head = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width)
    body = b""
    for y in range(height):
        px = [rgbe(*texel(x, y)) for x in range(width)]
        if rle:  # new-style RLE scanline: 2 2 hi lo, then each component as literal runs
            body += bytes([2, 2, width >> 8, width & 255])
            for c in range(4):
                body += bytes([width]) + bytes(p[c] for p in px)
        else:
            body += b"".join(px)
    data = head + body
    return data if keep is None else data[:len(head) + keep]


# ---- OpenEXR (uncompressed scanlines, 32-bit float channels B G R) ----------------------------
def exr(width, height, texel, data_window=None, keep=None):
    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    chlist = b"".join(c + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    x1, y1 = data_window or (width - 1, height - 1)
    box = struct.pack("<iiii", 0, 0, x1, y1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<I", 2) +
              attr("channels", "chlist", chlist) + attr("compression", "compression", b"\0") +
              attr("dataWindow", "box2i", box) + attr("displayWindow", "box2i", box) +
              attr("lineOrder", "lineOrder", b"\0") + attr("pixelAspectRatio", "float", struct.pack("<f", 1)) +
              attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0)) +
              attr("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0")
    blocks = []
    for y in range(height):
        px = [texel(x, y) for x in range(width)]
        data = b"".join(struct.pack("<%df" % width, *[p[c] for p in px]) for c in (2, 1, 0))
        blocks.append(struct.pack("<ii", y, len(data)) + data)
    table_size = 8 * height
    offsets, pos = [], len(header) + table_size
    for b in blocks:
        offsets.append(pos)
        pos += len(b)
    data = header + b"".join(struct.pack("<Q", o) for o in offsets) + b"".join(blocks)
    return data if keep is None else data[:keep]


# ---- JPEG: a header that ends before the scan (stb reads the size, then fails) ----------------
def jpeg_header_only(width, height):
    app0 = b"\xff\xe0" + struct.pack(">H", 16) + b"JFIF\0\x01\x01\0\0\x01\0\x01\0\0"
    dqt = b"\xff\xdb" + struct.pack(">H", 67) + b"\0" + bytes([1] * 64)
    sof = b"\xff\xc0" + struct.pack(">HBHHB", 11, 8, height, width, 1) + b"\x01\x11\x00"
    return b"\xff\xd8" + app0 + dqt + sof


def main():
    nan, inf = float("nan"), float("inf")
    not_an_image = "This is a text file, not an image.\n"

    # Valid equirects (8x4) in every pixel layout stb reads.
    out("images/grey8.png", png(8, 4, 0, 8, grey_rows(8, 4, 1)))
    out("images/grey_alpha8.png", png(8, 4, 4, 8, grey_rows(8, 4, 2)))
    out("images/rgba8.png", png(8, 4, 6, 8, grey_rows(8, 4, 4)))
    out("images/rgb16.png", png(8, 4, 2, 16, grey_rows(8, 4, 3, 16)))
    out("images/grey16.png", png(8, 4, 0, 16, grey_rows(8, 4, 1, 16)))

    # Extreme texels: RGBE cannot hold NaN, Inf or negatives, so the HDR has 1e30 only; the EXR
    # (32-bit floats) has NaN, +Inf, -Inf, a negative value and 1e30 in one row.
    out("images/extreme_1e30.hdr", hdr(8, 4, lambda x, y: (1e30, 1.0, 1.0) if (x, y) == (2, 1) else (1.0, 1.0, 1.0)))
    specials = {0: (nan, 1, 1), 1: (inf, 1, 1), 2: (-inf, 1, 1), 3: (-1, -1, -1), 4: (1e30, 1e30, 1e30)}
    out("images/extreme_texels.exr", exr(8, 4, lambda x, y: specials.get(x, (1, 1, 1)) if y == 1 else (1, 1, 1)))
    out("images/valid.hdr", hdr(16, 8, lambda x, y: (0.5, 1.0, 2.0), rle=True))
    out("images/valid.exr", exr(8, 4, lambda x, y: (0.5, 1.0, 2.0)))

    # Broken files behind the right extension.
    for ext in ("png", "jpg", "hdr", "exr"):
        out("images/empty." + ext, b"")
        out("images/text_as." + ext, not_an_image)
    full_png = png(16, 8, 2, 8, grey_rows(16, 8, 3))
    out("images/truncated.png", full_png[:len(full_png) // 2])
    out("images/truncated.jpg", jpeg_header_only(16, 8))
    out("images/truncated.hdr", hdr(16, 8, lambda x, y: (1.0, 1.0, 1.0), rle=True, keep=100))
    out("images/truncated_flat.hdr", hdr(4, 4, lambda x, y: (1.0, 1.0, 1.0), keep=30))
    # An RLE count byte of 0 (a literal run of no bytes): stb 2.27 would loop forever on it.
    zero_run = bytearray(hdr(16, 8, lambda x, y: (1.0, 1.0, 1.0), rle=True))
    zero_run[zero_run.index(b"\x02\x02\x00\x10") + 4] = 0
    out("images/rle_zero_count.hdr", bytes(zero_run))
    full_exr = exr(8, 4, lambda x, y: (1, 1, 1))
    out("images/truncated.exr", full_exr[:len(full_exr) - 60])

    # Headers that claim huge images (the files are tiny: nothing may allocate the pixels).
    out("images/huge_16384x16384.png", png(1, 1, 2, 8, grey_rows(1, 1, 3), ihdr_size=(16384, 16384)))
    out("images/huge_40000x20000.png", png(1, 1, 2, 8, grey_rows(1, 1, 3), ihdr_size=(40000, 20000)))
    out("images/huge_20000x1.exr", exr(1, 1, lambda x, y: (1, 1, 1), data_window=(19999, 0)))

    # Cubemap folders.
    faces = ("posx", "negx", "posy", "negy", "posz", "negz")
    small = png(2, 2, 2, 8, grey_rows(2, 2, 3))
    for f in faces:
        if f != "negy":
            out("cubemaps/missing_face/%s.png" % f, small)
        out("cubemaps/mixed_sizes/%s.png" % f, png(4, 4, 2, 8, grey_rows(4, 4, 3)) if f == "posz" else small)
        out("cubemaps/non_square/%s.png" % f, png(2, 4, 2, 8, grey_rows(2, 4, 3)) if f == "negx" else small)
        out("cubemaps/one_by_one/%s.png" % f, png(1, 1, 2, 8, grey_rows(1, 1, 3)))
        out("cubemaps/face_16k/%s.png" % f, png(1, 1, 2, 8, grey_rows(1, 1, 3), ihdr_size=(16384, 16384)))
        out("cubemaps/truncated_face/%s.png" % f, small[:45] if f == "posy" else small)

    # OBJ / MTL.
    out("obj/empty.obj", b"")
    out("obj/binary.obj", full_png)
    out("obj/truncated.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4")
    out("obj/negative_indices.obj",
        "# Relative (negative) indices: valid, two triangles.\n"
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf -3 -1 -2\n")
    out("obj/negative_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -5 -2 -1\n")
    ring = "".join("v %.6f %.6f 0\n" % (math.cos(2 * math.pi * k / 100), math.sin(2 * math.pi * k / 100))
                   for k in range(100))
    out("obj/polygon_100.obj", "# One convex polygon of 100 vertices: 98 triangles.\n" + ring +
        "f " + " ".join(str(k + 1) for k in range(100)) + "\n")
    out("obj/huge_coordinates.obj",
        "# Coordinates of 1e7: valid, the camera frames them.\n"
        "v -1e7 -1e7 0\nv 1e7 -1e7 0\nv 0 1e7 0\nv 0 0 1e7\nf 1 2 3\nf 1 2 4\nf 2 3 4\nf 3 1 4\n")
    out("obj/garbage_mtl.obj", "mtllib garbage_mtl.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n")
    out("obj/garbage_mtl.mtl", full_png)
    # Windows line ends: line numbers and quoted text as with \n (the \r is no part of the line).
    out("obj/crlf_garbage.obj", "v 0 0 0\r\nv 1 0 0\r\nnot obj\r\nv 0 1 0\r\nf 1 2 3\r\n")

    # Cache.
    out("cache/text.cache", "not a prt transport cache\n")


if __name__ == "__main__":
    main()
