#!/usr/bin/env python3
"""Writes assets/18_observatory_dome.gltf: the observatory's drum wall and dome for
levels/18_observatory.json. Node "Drum": an open cylinder wall (radius 9, y 0..7); node "Dome":
a hemisphere (radius 9, centred at y 7) with the observing slit cut out on its west side, where
the sunbeam comes in; node "Ribs": thin meridian ribs on the dome's inside. Normals face inwards.
Run from the repository root: python3 scripts/make_18_observatory.py"""
import base64, json, math, struct

R = 9.0
BASE = 7.0
SEG = 32          # around
RINGS = 8         # dome, equator to top
# the slit: azimuth around west (-X), elevation band (degrees)
SLIT_AZ = 180.0
SLIT_HALF_AZ = 12.0
SLIT_EL = (22.5, 33.75)


def az_of(i):
    return 360.0 * i / SEG


def pt(az, el, r=R):
    a, e = math.radians(az), math.radians(el)
    return (r * math.cos(e) * math.cos(a), BASE + r * math.sin(e), -r * math.cos(e) * math.sin(a))


def inward(p):
    d = (-p[0], BASE - p[1], -p[2])
    n = math.sqrt(sum(c * c for c in d)) or 1.0
    return tuple(c / n for c in d)


def drum():
    pos, nrm, idx = [], [], []
    for i in range(SEG + 1):
        a = math.radians(az_of(i))
        x, z = R * math.cos(a), -R * math.sin(a)
        for y in (0.0, BASE):
            pos.append((x, y, z)); nrm.append((-math.cos(a), 0.0, math.sin(a)))
    for i in range(SEG):
        a, b, c, d = 2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3
        idx += [a, c, b, b, c, d]
    return pos, nrm, idx


def dome(ribs=False):
    pos, nrm, idx = [], [], []
    def quad(p0, p1, p2, p3, top=False):
        base = len(pos)
        for p in (p0, p1, p2, p3):
            pos.append(p); nrm.append(inward(p))
        idx.extend([base, base + 1, base + 2])
        if not top:  # the top ring's quads are triangles (their top corners meet at the pole)
            idx.extend([base, base + 2, base + 3])
    for j in range(RINGS):
        e0, e1 = 90.0 * j / RINGS, 90.0 * (j + 1) / RINGS
        for i in range(SEG):
            a0, a1 = az_of(i), az_of(i + 1)
            am, em = 0.5 * (a0 + a1), 0.5 * (e0 + e1)
            in_slit = abs(am - SLIT_AZ) < SLIT_HALF_AZ and SLIT_EL[0] < em < SLIT_EL[1]
            if ribs:
                if i % 4 == 0 and not in_slit:
                    w = 0.7  # degrees of azimuth
                    r = R - 0.12
                    quad(pt(a0 - w, e0, r), pt(a0 + w, e0, r), pt(a0 + w, e1, r), pt(a0 - w, e1, r), e1 >= 90.0)
                continue
            if in_slit:
                continue
            quad(pt(a0, e0), pt(a1, e0), pt(a1, e1), pt(a0, e1), e1 >= 90.0)
    return pos, nrm, idx


meshes = [("Drum", drum()), ("Dome", dome()), ("Ribs", dome(ribs=True))]
blob = bytearray()
accessors, views, gmeshes, nodes = [], [], [], []
for name, (pos, nrm, idx) in meshes:
    prim = {}
    for key, data in (("POSITION", pos), ("NORMAL", nrm)):
        off = len(blob)
        for v in data:
            blob += struct.pack("<3f", *v)
        views.append({"buffer": 0, "byteOffset": off, "byteLength": len(blob) - off})
        acc = {"bufferView": len(views) - 1, "componentType": 5126, "count": len(data), "type": "VEC3"}
        if key == "POSITION":
            acc["min"] = [min(v[k] for v in data) for k in range(3)]
            acc["max"] = [max(v[k] for v in data) for k in range(3)]
        accessors.append(acc)
        prim[key] = len(accessors) - 1
    off = len(blob)
    for i in idx:
        blob += struct.pack("<I", i)
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(blob) - off})
    accessors.append({"bufferView": len(views) - 1, "componentType": 5125, "count": len(idx), "type": "SCALAR"})
    gmeshes.append({"name": name, "primitives": [{"attributes": prim, "indices": len(accessors) - 1}]})
    nodes.append({"mesh": len(gmeshes) - 1, "name": name})

gltf = {
    "asset": {"version": "2.0", "generator": "sightline scripts/make_18_observatory.py"},
    "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes, "meshes": gmeshes,
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    "bufferViews": views, "accessors": accessors,
}
with open("assets/18_observatory_dome.gltf", "w") as f:
    json.dump(gltf, f, indent=1)
print("wrote assets/18_observatory_dome.gltf,", len(blob), "bytes of buffer")
