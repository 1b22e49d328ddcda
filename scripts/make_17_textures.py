#!/usr/bin/env python3
"""Writes the Drawbridge's cobble textures, one per ledge box top (box faces take the whole
texture, so each image is laid out in metres for its own ledge). Run from the repository root."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_14_textures import stones

if __name__ == "__main__":
    for name, size, seed in (("near", (20, 7), 171), ("back", (20, 9), 172), ("far", (20, 20), 173)):
        stones("assets/17_cobble_%s.png" % name, size, 20, (0.45, 0.3), 0.045,
               (0.9, 0.9, 0.92), 0.18, 0.25, seed)
