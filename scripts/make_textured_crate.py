#!/usr/bin/env python3
"""Writes the textured crate: assets/crate.gltf, its buffer assets/crate.bin, the sRGB colour
texture assets/crate_color.png (64x64 planks in a frame) and the tangent-space normal map
assets/crate_normal.png (32x32: a bevelled frame and grooves between the planks).

The crate is a 1 m cube centred on the origin with flat faces; each face shows the whole
texture, laid out as game::primitives::box lays out its UVs. Output is deterministic: run it
again and the files come out byte for byte the same (for a given zlib).

Usage: scripts/make_textured_crate.py [output directory, default assets/]
"""
import json
import os
import struct
import sys
import zlib

COLOR_SIZE = 64
NORMAL_SIZE = 32
PLANKS = 4  # horizontal planks, top to bottom
FRAME_WIDTH = 6  # colour texels; the normal map's bevel covers the same share of the face
FRAME_COLOR = (92, 62, 34)
SEAM_COLOR = (60, 40, 22)


def write_png(path, width, height, rows):
    """rows: `height` lists of (r, g, b) tuples. Writes an 8-bit RGB PNG, no interlacing."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    raw = b"".join(b"\0" + bytes(channel for pixel in row for channel in pixel) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit truecolour
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", header))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def grain(x, y, plank):
    """A small deterministic brightness wobble in [-4, 4], streaked along the plank (x)."""
    h = (x // 3 * 73856093) ^ (y * 19349663) ^ (plank * 83492791)
    return (h >> 7) % 9 - 4


def color_texel(x, y):
    size = COLOR_SIZE
    if min(x, y, size - 1 - x, size - 1 - y) < FRAME_WIDTH:
        return FRAME_COLOR
    plank_height = size // PLANKS
    plank = y // plank_height
    if y % plank_height == plank_height - 1:
        return SEAM_COLOR
    base = (168 - 10 * plank, 118 - 6 * plank, 66 - 3 * plank)
    wobble = grain(x, y, plank)
    return tuple(max(0, min(255, c + wobble)) for c in base)


def encode_normal(nx, ny):
    """Tangent space, +X right and +Y up in the image (glTF's convention), +Z out."""
    length = (nx * nx + ny * ny + 1.0) ** 0.5
    return tuple(int((c / length) * 127.5 + 127.5 + 0.5) for c in (nx, ny, 1.0))


def normal_texel(x, y):
    size = NORMAL_SIZE
    bevel = FRAME_WIDTH * NORMAL_SIZE // COLOR_SIZE
    tilt = 0.5
    nx = ny = 0.0
    # The frame rises towards the middle, so its slopes face the outer edges.
    if x < bevel:
        nx = -tilt
    elif x >= size - bevel:
        nx = tilt
    if y < bevel:
        ny = tilt
    elif y >= size - bevel:
        ny = -tilt
    elif nx == 0.0:
        # A groove along each plank seam: the row above slopes down into it, the row below up.
        plank_height = size // PLANKS
        row = y % plank_height
        if row == plank_height - 2:
            ny = -tilt
        elif row == 0:
            ny = tilt
    return encode_normal(nx, ny)


def box_faces():
    """(centre, right, up, normal) per face, in game::primitives::box's order."""
    h = 0.5
    return [
        ((h, 0, 0), (0, 0, -h), (0, h, 0), (1, 0, 0)),
        ((-h, 0, 0), (0, 0, h), (0, h, 0), (-1, 0, 0)),
        ((0, h, 0), (h, 0, 0), (0, 0, -h), (0, 1, 0)),
        ((0, -h, 0), (h, 0, 0), (0, 0, h), (0, -1, 0)),
        ((0, 0, h), (h, 0, 0), (0, h, 0), (0, 0, 1)),
        ((0, 0, -h), (-h, 0, 0), (0, h, 0), (0, 0, -1)),
    ]


def crate_geometry():
    positions, normals, uvs, indices = [], [], [], []
    for centre, right, up, normal in box_faces():
        first = len(positions)
        # Corners counter-clockwise from the front: bottom-left, bottom-right, top-right,
        # top-left. Image rows run downwards, so v = 1 at the bottom.
        for (sr, su), uv in zip([(-1, -1), (1, -1), (1, 1), (-1, 1)],
                                [(0, 1), (1, 1), (1, 0), (0, 0)]):
            positions.append(tuple(c + sr * r + su * u for c, r, u in zip(centre, right, up)))
            normals.append(normal)
            uvs.append(uv)
        indices += [first, first + 1, first + 2, first, first + 2, first + 3]
    return positions, normals, uvs, indices


def write_gltf(directory):
    positions, normals, uvs, indices = crate_geometry()
    pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    nrm_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
    uv_bytes = b"".join(struct.pack("<2f", *uv) for uv in uvs)
    idx_bytes = b"".join(struct.pack("<H", i) for i in indices)
    blob = pos_bytes + nrm_bytes + uv_bytes + idx_bytes
    offsets = [0, len(pos_bytes), len(pos_bytes) + len(nrm_bytes),
               len(pos_bytes) + len(nrm_bytes) + len(uv_bytes)]
    views = [
        {"buffer": 0, "byteOffset": offsets[0], "byteLength": len(pos_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": offsets[1], "byteLength": len(nrm_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": offsets[2], "byteLength": len(uv_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": offsets[3], "byteLength": len(idx_bytes), "target": 34963},
    ]
    gltf = {
        "asset": {"version": "2.0", "generator": "sightline scripts/make_textured_crate.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "crate", "mesh": 0}],
        "meshes": [{"name": "crate", "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
            "indices": 3,
            "material": 0,
        }]}],
        "materials": [{
            "name": "crate_wood",
            "pbrMetallicRoughness": {
                "baseColorFactor": [0.9, 0.85, 0.8, 1.0],
                "baseColorTexture": {"index": 0},
                "metallicFactor": 0.0,
                "roughnessFactor": 0.75,
            },
            "normalTexture": {"index": 1},
        }],
        "textures": [{"sampler": 0, "source": 0}, {"sampler": 0, "source": 1}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": "crate_color.png"}, {"uri": "crate_normal.png"}],
        "buffers": [{"uri": "crate.bin", "byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
            {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }
    with open(os.path.join(directory, "crate.bin"), "wb") as f:
        f.write(blob)
    with open(os.path.join(directory, "crate.gltf"), "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "assets"
    os.makedirs(directory, exist_ok=True)
    write_png(os.path.join(directory, "crate_color.png"), COLOR_SIZE, COLOR_SIZE,
              [[color_texel(x, y) for x in range(COLOR_SIZE)] for y in range(COLOR_SIZE)])
    write_png(os.path.join(directory, "crate_normal.png"), NORMAL_SIZE, NORMAL_SIZE,
              [[normal_texel(x, y) for x in range(NORMAL_SIZE)] for y in range(NORMAL_SIZE)])
    write_gltf(directory)


if __name__ == "__main__":
    main()
