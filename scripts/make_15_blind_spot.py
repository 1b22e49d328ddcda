#!/usr/bin/env python3
"""Writes assets/15_swing_bridge.gltf (+ .bin): the swing bridge of levels/15_blind_spot.json.

A timber deck (2.6 m wide, 9.4 m long, along local Z, top at y = 0) with an iron railing on each
side, centred on the origin: the level turns the whole model about its vertical axis (the pier
under the middle of the canal), so deck and rails swing together. Run from the repository root:
python3 scripts/make_15_blind_spot.py
"""
import json
import struct

# (material index, centre, size)
BOXES = [(0, (0.0, -0.15, 0.0), (2.6, 0.3, 9.4))]
for x in (-1.22, 1.22):
    BOXES.append((1, (x, 0.95, 0.0), (0.08, 0.08, 9.2)))   # hand rail
    BOXES.append((1, (x, 0.45, 0.0), (0.05, 0.05, 9.2)))   # mid rail
    for i in range(7):
        z = -4.5 + i * 1.5
        BOXES.append((1, (x, 0.48, z), (0.1, 0.96, 0.1)))  # posts
BOXES.append((1, (0.0, -0.33, 0.0), (2.7, 0.08, 9.5)))     # iron under-frame

prims = {0: ([], [], []), 1: ([], [], [])}


def add_box(mat, c, s):
    pos, nrm, idx = prims[mat]
    hx, hy, hz = (v / 2 for v in s)
    faces = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
             ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
             ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
    for n, u, v in faces:
        base = len(pos)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [c[k] + n[k] * (hx, hy, hz)[k] + su * u[k] * (hx, hy, hz)[k] + sv * v[k] * (hx, hy, hz)[k]
                 for k in range(3)]
            pos.append(p)
            nrm.append(n)
        idx.extend([base, base + 1, base + 2, base, base + 2, base + 3])


for mat, c, s in BOXES:
    add_box(mat, c, s)

blob = b""
views, accessors, primitives = [], [], []
for mat in (0, 1):
    pos, nrm, idx = prims[mat]
    for data, fmt, target, typ, comp in ((pos, "<3f", 34962, "VEC3", 5126), (nrm, "<3f", 34962, "VEC3", 5126),
                                         (idx, "<I", 34963, "SCALAR", 5125)):
        raw = b"".join(struct.pack(fmt, *(d if isinstance(d, (list, tuple)) else (d,))) for d in data)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(raw), "target": target})
        acc = {"bufferView": len(views) - 1, "componentType": comp, "count": len(data), "type": typ}
        if typ == "VEC3" and data is pos:
            acc["min"] = [min(p[k] for p in pos) for k in range(3)]
            acc["max"] = [max(p[k] for p in pos) for k in range(3)]
        accessors.append(acc)
        blob += raw
    a = len(accessors) - 3
    primitives.append({"attributes": {"POSITION": a, "NORMAL": a + 1}, "indices": a + 2, "material": mat})

gltf = {
    "asset": {"version": "2.0", "generator": "sightline scripts/make_15_blind_spot.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "swing_bridge", "mesh": 0}],
    "meshes": [{"name": "swing_bridge", "primitives": primitives}],
    "materials": [
        {"name": "deck", "pbrMetallicRoughness": {"baseColorFactor": [0.36, 0.22, 0.12, 1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": 0.7}},
        {"name": "iron", "pbrMetallicRoughness": {"baseColorFactor": [0.16, 0.17, 0.18, 1.0],
                                                   "metallicFactor": 0.7, "roughnessFactor": 0.4}}],
    "buffers": [{"uri": "15_swing_bridge.bin", "byteLength": len(blob)}],
    "bufferViews": views,
    "accessors": accessors,
}
with open("assets/15_swing_bridge.bin", "wb") as f:
    f.write(blob)
with open("assets/15_swing_bridge.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
print(f"assets/15_swing_bridge.gltf: {sum(len(p[2]) for p in prims.values()) // 3} triangles")
