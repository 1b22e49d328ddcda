#!/usr/bin/env python3
"""Writes assets/obelisk.gltf: a tapered square column with a pyramid cap, flat-shaded,
one mesh with positions, normals and 16-bit indices in an embedded buffer."""
import base64, json, struct, sys

def quad_faces():
    base, top, cap = 0.35, 0.22, 2.3  # half-widths at y=0 and y=2, apex height
    corners = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    low = [(x * base, 0.0, z * base) for x, z in corners]
    high = [(x * top, 2.0, z * top) for x, z in corners]
    apex = (0.0, cap, 0.0)
    triangles = []
    for i in range(4):
        j = (i + 1) % 4
        # Side quads wind counter-clockwise seen from outside.
        triangles += [(low[i], low[j], high[j]), (low[i], high[j], high[i])]
        triangles.append((high[i], high[j], apex))
    triangles += [(low[0], low[2], low[1]), (low[0], low[3], low[2])]  # bottom, facing -Y
    return triangles

def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def normalize(v):
    length = sum(x * x for x in v) ** 0.5
    return tuple(x / length for x in v)

positions, normals, indices = [], [], []
for a, b, c in quad_faces():
    n = normalize(cross(sub(b, a), sub(c, a)))
    for p in (a, b, c):
        indices.append(len(positions))
        positions.append(p)
        normals.append(n)

pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
nrm_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
idx_bytes = b"".join(struct.pack("<H", i) for i in indices)
idx_bytes += b"\0" * ((4 - len(idx_bytes) % 4) % 4)
blob = pos_bytes + nrm_bytes + idx_bytes
mins = [min(p[k] for p in positions) for k in range(3)]
maxs = [max(p[k] for p in positions) for k in range(3)]
gltf = {
    "asset": {"version": "2.0", "generator": "sightline scripts/make_obelisk_gltf.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "obelisk"}],
    "meshes": [{"name": "obelisk", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(pos_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(pos_bytes), "byteLength": len(nrm_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(pos_bytes) + len(nrm_bytes), "byteLength": len(indices) * 2, "target": 34963},
    ],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": mins, "max": maxs},
        {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
    ],
}
out = sys.argv[1] if len(sys.argv) > 1 else "assets/obelisk.gltf"
with open(out, "w") as f:
    json.dump(gltf, f, indent=1)
    f.write("\n")
