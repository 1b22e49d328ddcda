#!/usr/bin/env python3
"""Writes assets/14_searchlight.gltf (+ .bin): the searchlight drum of levels/14_lamp_room.json.

A closed iron drum (radius R, height 2*H, centred on the origin, where the level puts its lamp)
with one slit facing local -Z: the slit is SLIT_DEGREES wide and open from under the drum (a
wedge of its floor is cut away too) up to SLIT_TOP, so the lamp inside throws a downward wedge of light that sweeps the floor
as the drum turns. Outer and inner walls are both written (the drum is seen from outside, the
lamp lights its inside). Run from the repository root: python3 scripts/make_lamp_room.py
"""
import json
import math
import struct

R = 0.34
H = 0.30
SEGMENTS = 48
SLIT_DEGREES = 50.0
SLIT_TOP = 0.04

positions, normals, indices = [], [], []


def vertex(p, n):
    positions.append(p)
    normals.append(n)
    return len(positions) - 1


def quad(a, b, c, d, n):
    i = [vertex(p, n) for p in (a, b, c, d)]
    indices.extend([i[0], i[1], i[2], i[0], i[2], i[3]])


def wall(a0, a1, y0, y1):
    # angle measured from -Z towards +X (so the slit, centred on 0, faces -Z)
    p = lambda a, r, y: (r * math.sin(a), y, -r * math.cos(a))
    am = 0.5 * (a0 + a1)
    n_out = (math.sin(am), 0.0, -math.cos(am))
    n_in = tuple(-c for c in n_out)
    quad(p(a0, R, y0), p(a1, R, y0), p(a1, R, y1), p(a0, R, y1), n_out)
    quad(p(a0, R, y1), p(a1, R, y1), p(a1, R, y0), p(a0, R, y0), n_in)


step = 2 * math.pi / SEGMENTS
half_slit = math.radians(SLIT_DEGREES) / 2
for s in range(SEGMENTS):
    a0, a1 = s * step - math.pi, (s + 1) * step - math.pi
    am = 0.5 * (a0 + a1)
    wall(a0, a1, SLIT_TOP, H)
    if abs(am) > half_slit:
        wall(a0, a1, -H, SLIT_TOP)

# caps (both sides), as fans
for y, up in ((H, 1.0), (-H, -1.0)):
    for side in (1.0, -1.0):
        n = (0.0, up * side, 0.0)
        c = vertex((0.0, y, 0.0), n)
        ring = [vertex((R * math.sin(s * step), y, -R * math.cos(s * step)), n)
                for s in range(SEGMENTS)]
        for s in range(SEGMENTS):
            am = (s + 0.5) * step
            am = am - 2 * math.pi if am > math.pi else am
            if up < 0 and abs(am) <= half_slit:
                continue  # the slit goes on under the drum: the wedge of light reaches the post
            a, b = ring[s], ring[(s + 1) % SEGMENTS]
            indices.extend([c, a, b] if up * side < 0 else [c, b, a])

# sides of the slit (the cut faces)
for a in (-half_slit, half_slit):
    a_snap = round((a + math.pi) / step) * step - math.pi
    t = (math.cos(a_snap), 0.0, math.sin(a_snap))
    for sgn in (1.0, -1.0):
        n = tuple(sgn * c for c in t)
        p0 = (0.0, -H, 0.0)
        quad((R * 0.9 * math.sin(a_snap), -H, -R * 0.9 * math.cos(a_snap)),
             (R * math.sin(a_snap), -H, -R * math.cos(a_snap)),
             (R * math.sin(a_snap), SLIT_TOP, -R * math.cos(a_snap)),
             (R * 0.9 * math.sin(a_snap), SLIT_TOP, -R * 0.9 * math.cos(a_snap)), n)

pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
nrm_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
idx_bytes = b"".join(struct.pack("<I", i) for i in indices)
blob = pos_bytes + nrm_bytes + idx_bytes
mins = [min(p[k] for p in positions) for k in range(3)]
maxs = [max(p[k] for p in positions) for k in range(3)]

gltf = {
    "asset": {"version": "2.0", "generator": "sightline scripts/make_lamp_room.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "searchlight", "mesh": 0}],
    "meshes": [{"name": "searchlight", "primitives": [
        {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
    "materials": [{"name": "iron", "pbrMetallicRoughness": {
        "baseColorFactor": [0.18, 0.17, 0.16, 1.0], "metallicFactor": 0.6, "roughnessFactor": 0.45}}],
    "buffers": [{"uri": "14_searchlight.bin", "byteLength": len(blob)}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(pos_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(pos_bytes), "byteLength": len(nrm_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(pos_bytes) + len(nrm_bytes), "byteLength": len(idx_bytes),
         "target": 34963},
    ],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
         "min": mins, "max": maxs},
        {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
    ],
}

with open("assets/14_searchlight.bin", "wb") as f:
    f.write(blob)
with open("assets/14_searchlight.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
print(f"assets/14_searchlight.gltf: {len(positions)} vertices, {len(indices) // 3} triangles")
