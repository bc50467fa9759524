#!/usr/bin/python3
"""Writes the small maps the field scenes use (input/fields/), so they can be rebuilt and checked.

  linear_ramp.h5  dataset 'factor' [18][18]: f = 1 + 0.2 (2 x/L - 1) at the pixel centres, extent one
                  pixel beyond the 5 mm plate on every side (bilinear sampling then reproduces the
                  linear profile exactly on the plate: a test compares the two)
  pillars.png     32 x 32 8-bit greyscale: a 4 x 4 array of round pillars (white) on black
Usage: scripts/make_field_maps.py [out_dir]   (default: input/fields next to this script)
"""
import os
import struct
import sys
import zlib

import h5py
import numpy as np

L = 5e-3


def write_grey_png(path, pixels):
    """8-bit greyscale PNG (colour type 0), rows top to bottom."""
    height, width = pixels.shape
    raw = b"".join(b"\x00" + bytes(row) for row in pixels.astype(np.uint8))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "input", "fields")
    os.makedirs(out, exist_ok=True)
    n, dx = 18, L / 16
    centres = -dx + (np.arange(n) + 0.5) * dx
    ramp = 1.0 + 0.2 * (2.0 * centres / L - 1.0)
    with h5py.File(os.path.join(out, "linear_ramp.h5"), "w") as f:
        d = f.create_dataset("factor", data=np.tile(ramp, (n, 1)))
        d.attrs["extent"] = np.array([-dx, L + dx, -dx, L + dx])
        d.attrs["description"] = "f = 1 + 0.2 (2 x/L - 1) at pixel centres, [ny][nx], extent x0,x1,y0,y1 [m]"
    side = 32
    y, x = np.mgrid[0:side, 0:side] + 0.5
    cell = side / 4
    r = np.hypot((x % cell) - cell / 2, (y % cell) - cell / 2)
    write_grey_png(os.path.join(out, "pillars.png"), np.where(r < cell * 0.3, 255, 0))


if __name__ == "__main__":
    main()
