#!/usr/bin/env python3
"""The FEM-measured pressure response g against the moment-balance shape on the block lattice.

Reads /fem/pressure_response/g of a gradfric-fem results file, samples it bilinearly at the centres of
an N x N block lattice (as -pressure_response fem does), removes its mean, and finds the edge decay
length lambda of the moment-balance shape (-pressure_response moment) closest to it in the least
squares over the lattice. Prints the column profiles and the fit (docs/fields.md).
  python3 scripts/pressure_response_fit.py run.h5 [N] [L] [H]
"""
import sys

import h5py
import numpy as np


def sample(g, extent, n, length):
    ny, nx = g.shape
    x0, x1, y0, y1 = extent
    dx, dy = (x1 - x0) / nx, (y1 - y0) / ny
    centres = (np.arange(n) + 0.5) * length / n
    fx = np.clip((centres - x0) / dx - 0.5, 0, nx - 1)
    fy = np.clip((centres - y0) / dy - 0.5, 0, ny - 1)
    ix, iy = np.minimum(fx.astype(int), nx - 2), np.minimum(fy.astype(int), ny - 2)
    tx, ty = fx - ix, fy - iy
    rows = g[iy, :] * (1 - ty)[:, None] + g[iy + 1, :] * ty[:, None]
    return rows[:, ix] * (1 - tx)[None, :] + rows[:, ix + 1] * tx[None, :]


def moment_shape(n, length, thickness, lam):
    l = length / n
    k = np.arange(n)
    edge = np.exp(-(n - 1 - k) * l / lam) - np.exp(-k * l / lam)
    s = (k + 0.5) * l - length / 2
    return edge * thickness / np.mean(s * edge)


def main():
    path = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 120
    length = float(sys.argv[3]) if len(sys.argv) > 3 else 5e-3
    thickness = float(sys.argv[4]) if len(sys.argv) > 4 else 5e-5
    with h5py.File(path, "r") as f:
        d = f["/fem/pressure_response/g" if "fem" in f else "/pressure_response/g"]  # older files: /pressure_response
        g, extent = d[...], d.attrs["extent"]
        print(f"FEM map {g.shape}, moment_over_H {float(d.attrs['moment_over_H']):.4f}, "
              f"mean {float(d.attrs['mean']):.2e}, window {d.attrs['mu_window']}, samples {int(d.attrs['samples'])}")
    print(f"FEM nodal g: trailing edge line {g[:, 0].mean():+.3f}, leading {g[:, -1].mean():+.3f}, "
          f"centre {g[:, g.shape[1] // 2].mean():+.4f}")
    blocks = sample(g, extent, n, length)
    blocks -= blocks.mean()
    s = (np.arange(n) + 0.5) * length / n - length / 2
    print(f"sampled at {n} x {n} block centres: moment / H = {np.mean(blocks * s[None, :]) / thickness:.4f}")
    column = blocks.mean(axis=0)
    best = None
    for lam in np.linspace(0.05, 4.0, 400) * thickness:
        shape = moment_shape(n, length, thickness, lam)
        err = np.sqrt(np.mean((shape - column) ** 2))
        if best is None or err < best[1]:
            best = (lam, err)
    lam, err = best
    shape = moment_shape(n, length, thickness, lam)
    print(f"best moment-balance fit: lambda = {lam / thickness:.3f} H, rms difference {err:.4f} "
          f"(rms of g {np.sqrt(np.mean(column ** 2)):.4f})")
    print("column  FEM g (sampled, row mean)  moment shape")
    for c in list(range(4)) + [n // 4, n // 2] + list(range(n - 4, n)):
        print(f"  {c:4d}  {column[c]:+.4f}  {shape[c]:+.4f}")


if __name__ == "__main__":
    main()
