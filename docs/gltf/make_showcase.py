#!/usr/bin/env python3
"""Writes the glTF models of docs/gltf/showcase.json, the level that shows what Sightline draws
of a glTF material: a cube with a material per face, a gold sphere (glTF's default metallic 1),
a leafy screen cut out by alphaMode MASK and a blue pane of alphaMode BLEND.

Run from anywhere: python3 docs/gltf/make_showcase.py (standard library only)."""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png(width, height, rgba_rows):
    """An RGBA8 PNG of `rgba_rows` (rows top to bottom, each a bytes of width * 4)."""
    raw = b"".join(b"\x00" + row for row in rgba_rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9))
            + chunk(b"IEND", b""))


class Model:
    """A glTF document with one embedded buffer, one view per accessor."""

    def __init__(self):
        self.buffer = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "docs/gltf/make_showcase.py"},
                    "bufferViews": [], "accessors": [], "meshes": [], "nodes": [],
                    "scenes": [{"nodes": []}], "scene": 0}

    def accessor(self, values, component, count, kind, fmt, minmax=None):
        while len(self.buffer) % 4:
            self.buffer.append(0)
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        self.doc["bufferViews"].append(
            {"buffer": 0, "byteOffset": len(self.buffer), "byteLength": len(data)})
        self.buffer += data
        accessor = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component,
                    "count": count, "type": kind}
        if minmax:
            accessor["min"], accessor["max"] = minmax
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def primitive(self, positions, normals, uvs, indices, material):
        flat = [c for p in positions for c in p]
        lo = [min(flat[i::3]) for i in range(3)]
        hi = [max(flat[i::3]) for i in range(3)]
        attributes = {
            "POSITION": self.accessor(flat, 5126, len(positions), "VEC3", "f", (lo, hi)),
            "NORMAL": self.accessor([c for n in normals for c in n], 5126, len(normals), "VEC3",
                                    "f"),
            "TEXCOORD_0": self.accessor([c for t in uvs for c in t], 5126, len(uvs), "VEC2", "f"),
        }
        return {"attributes": attributes,
                "indices": self.accessor(indices, 5125, len(indices), "SCALAR", "I"),
                "material": material}

    def add_mesh(self, name, primitives):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        self.doc["nodes"].append({"name": name, "mesh": len(self.doc["meshes"]) - 1})
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def add_png_texture(self, data):
        self.doc.setdefault("images", []).append(
            {"uri": "data:image/png;base64," + base64.b64encode(data).decode()})
        self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def write(self, name):
        self.doc["buffers"] = [{"byteLength": len(self.buffer),
                                "uri": "data:application/octet-stream;base64,"
                                       + base64.b64encode(bytes(self.buffer)).decode()}]
        with open(os.path.join(HERE, name), "w") as out:
            json.dump(self.doc, out, indent=1)
            out.write("\n")


def quad(corner, u_side, v_side):
    """Four corners, normal, UVs and two triangles of the quad corner + a u_side + b v_side."""
    c = corner
    points = [c, [c[i] + u_side[i] for i in range(3)],
              [c[i] + u_side[i] + v_side[i] for i in range(3)], [c[i] + v_side[i] for i in range(3)]]
    n = [u_side[1] * v_side[2] - u_side[2] * v_side[1], u_side[2] * v_side[0] - u_side[0] * v_side[2],
         u_side[0] * v_side[1] - u_side[1] * v_side[0]]
    length = math.sqrt(sum(x * x for x in n))
    n = [x / length for x in n]
    return points, [n] * 4, [[0, 1], [1, 1], [1, 0], [0, 0]], [0, 1, 2, 0, 2, 3]


def material(name, color, metallic=0.0, roughness=0.6, **extra):
    result = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": color,
                                                     "metallicFactor": metallic,
                                                     "roughnessFactor": roughness}}
    result.update(extra)
    return result


def cube():
    """A 1 m cube, each face a primitive with a material of its own."""
    model = Model()
    h = 0.5
    faces = [([h, -h, h], [0, 0, -1], [0, 1, 0]), ([-h, -h, -h], [0, 0, 1], [0, 1, 0]),
             ([-h, h, h], [1, 0, 0], [0, 0, -1]), ([-h, -h, -h], [1, 0, 0], [0, 0, 1]),
             ([-h, -h, h], [1, 0, 0], [0, 1, 0]), ([h, -h, -h], [-1, 0, 0], [0, 1, 0])]
    colors = [[0.8, 0.1, 0.1, 1], [0.1, 0.6, 0.1, 1], [0.9, 0.8, 0.1, 1], [0.5, 0.5, 0.5, 1],
              [0.1, 0.25, 0.8, 1], [0.8, 0.3, 0.7, 1]]
    names = ["red", "green", "yellow", "grey", "blue", "pink"]
    model.doc["materials"] = [material(n, c) for n, c in zip(names, colors)]
    model.add_mesh("cube", [model.primitive(*quad(*face), material=i) for i, face in enumerate(faces)])
    model.write("cube_six_materials.gltf")


def sphere():
    """A gold sphere of radius 0.5: glTF's default metallicFactor (1), a gold base colour."""
    model = Model()
    positions, normals, uvs, indices = [], [], [], []
    rings, segments = 20, 40
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
            positions.append([0.5 * x for x in n])
            normals.append(n)
            uvs.append([s / segments, r / rings])
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            if r > 0:  # the top ring's first triangle would have two corners on the pole
                indices += [a, a + 1, b]
            if r < rings - 1:
                indices += [a + 1, b + 1, b]
    model.doc["materials"] = [{"name": "gold", "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 0.71, 0.29, 1.0], "roughnessFactor": 0.35}}]
    model.add_mesh("sphere", [model.primitive(positions, normals, uvs, indices, 0)])
    model.write("gold_sphere.gltf")


def screen():
    """A 1.2 m square screen, alphaMode MASK: a texture of round leaves with clear gaps."""
    model = Model()
    size = 64
    rows = []
    for y in range(size):
        row = bytearray()
        for x in range(size):
            cx, cy = (x % 16) - 7.5, (y % 16) - 7.5
            inside = cx * cx + cy * cy < 42
            row += bytes([60, 150, 40, 255]) if inside else bytes([0, 0, 0, 0])
        rows.append(bytes(row))
    texture = model.add_png_texture(png(size, size, rows))
    model.doc["materials"] = [material("leaves", [1, 1, 1, 1], alphaMode="MASK", alphaCutoff=0.5,
                                       doubleSided=True)]
    model.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": texture}
    model.add_mesh("screen", [model.primitive(*quad([-0.6, 0, 0], [1.2, 0, 0], [0, 1.2, 0]),
                                               material=0)])
    model.write("leaf_screen.gltf")


def pane():
    """A 1.2 m square pane, alphaMode BLEND: blue at alpha 0.6."""
    model = Model()
    model.doc["materials"] = [material("blue pane", [0.2, 0.4, 1.0, 0.6], roughness=0.1,
                                       alphaMode="BLEND")]
    model.add_mesh("pane", [model.primitive(*quad([-0.6, 0, 0], [1.2, 0, 0], [0, 1.2, 0]),
                                             material=0)])
    model.write("blue_pane.gltf")


if __name__ == "__main__":
    cube()
    sphere()
    screen()
    pane()
