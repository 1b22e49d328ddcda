#!/usr/bin/env python3
"""Writes assets/14_flagstones.png: the Lamp Room's floor, one image over the whole 16.4 x 34.4 m
floor box top (box faces take the whole texture), so the slabs are laid out in metres here.
Pure Python (zlib), no dependencies. Run from the repository root."""
import random, struct, zlib

def write_png(path, w, h, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

def stones(path, size_m, px_per_m, stone_m, grout_m, base, spread, grout, seed, stagger=0.5):
    rnd = random.Random(seed)
    w, h = int(size_m[0] * px_per_m), int(size_m[1] * px_per_m)
    sw, sh = stone_m
    tone = {}
    rows = []
    for y in range(h):
        row = []
        zm = y / px_per_m
        r = int(zm // sh)
        off = (r % 2) * stagger * sw
        for x in range(w):
            xm = x / px_per_m + off
            c = int(xm // sw)
            if (r, c) not in tone:
                tone[(r, c)] = 1.0 + rnd.uniform(-spread, spread)
            fx, fy = xm - c * sw, zm - r * sh
            edge = min(fx, sw - fx, fy, sh - fy)
            n = rnd.uniform(-0.05, 0.05)
            if edge < grout_m:
                v = [grout * (1 + n)] * 3
            else:
                t = tone[(r, c)] * (1 + n) * (0.93 + 0.07 * min(1.0, edge / (3 * grout_m)))
                v = [b * t for b in base]
            row += [max(0, min(255, int(255 * q))) for q in v]
        rows.append(row)
    write_png(path, w, h, rows)

if __name__ == "__main__":
    stones("assets/14_flagstones.png", (16.4, 34.4), 16, (1.2, 0.8), 0.05,
           (0.92, 0.88, 0.82), 0.12, 0.35, 14)
