#!/usr/bin/python3
"""The tables of docs/flutter.md: the growing root eta = c/c_s of a plane-strain elastic half-space
sliding in +x on a rigid flat with constant Coulomb friction mu, computed independently of the
C++ closed form (src/physics/sliding_dispersion.cpp):

- the partial waves come from the Navier equation itself: u = a exp(i k (x + p z - c t)), k = 1,
  rho = c_s = 1; the 2 x 2 Christoffel determinant is a quadratic in q = p^2 whose roots numpy
  solves; each wave keeps the p with Im p > 0 (decay into the body z > 0) or, when p is real, the
  one carrying energy into the body (Re p Re eta > 0, the limit from Im eta > 0);
- the boundary determinant is u_z = 0 and sigma_xz + mu sigma_zz = 0 (the flat presses the body,
  t_z = -sigma_zz = p > 0, and the friction opposes the sliding, t_x = -sigma_xz = -mu p);
- the root is followed by continuation in mu from the neutral root sqrt(2) at mu = 1, Muller's
  method at each step, and checked to be the only growing one by the winding of det / eta^2 on a
  rectangle in the upper half plane (dense sampling).
- with a normal-stress memory (relaxation time T, K = |k| c_s T; here k = c_s = 1, so K = T) the
  friction row becomes sigma_xz (1 - i K eta) + mu sigma_zz = 0 (the filtered pressure is
  p / (1 - i omega T)); K_c is where the root continued in K from the Coulomb one reaches the real
  axis (secant on Im eta(K) = 0), and the memory's mode against the sliding is continued in K from
  the neutral Coulomb root beyond -c_p/c_s, its largest K Im(eta) taken over K in (0, 100].
Shear speed from the defaults of include/gradfric/physics/plate.hpp: c_s = sqrt(E / (2 (1 + nu) rho)).

    flutter_roots.py                      print the tables (markdown)
    flutter_roots.py --check docs/flutter.md
                                          exit 1 if the doc's generated block differs from them

numpy only.
"""
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PLATE = os.path.join(HERE, "..", "include", "gradfric", "physics", "plate.hpp")
BEGIN = "<!-- BEGIN generated: scripts/flutter_roots.py -->"
END = "<!-- END generated -->"
MU_TABLE = [1.0, 1.1, 1.2, 1.3, 1.4, 1.6, 2.0]
NU_TABLE = [(0.25, "0.25"), (1.0 / 3.0, "1/3"), (0.45, "0.45")]
WAVELENGTHS = [25e-6, 100e-6]


def plate_defaults():
    """E [Pa], nu, rho [kg/m^3] as the Plate struct initialises them."""
    text = open(PLATE, encoding="utf-8").read()

    def value(name):
        m = re.search(r"\b" + name + r"\s*=\s*([0-9eE.+\-*/ ]+);", text)
        if not m or not re.fullmatch(r"[0-9eE.+\-*/ ]+", m.group(1)):
            sys.exit("flutter_roots: no default for %s in %s" % (name, PLATE))
        return float(eval(m.group(1), {"__builtins__": {}}))  # digits and + - * / only (checked)

    return value("youngsModulus"), value("poissonRatio"), value("density")


def partial_waves(eta, nu):
    """(p, a_x, a_z) of the P-like and of the S-like wave at each eta (arrays; a: the displacement
    amplitude), and the Lame constants (lam, g)."""
    eta = np.asarray(eta, dtype=complex)
    g = 1.0
    lam = (2.0 - 2.0 * nu) / (1.0 - 2.0 * nu) - 2.0 * g  # rho c_p^2 - 2 G with rho = c_s = 1
    w2 = eta * eta
    # det [[lam + 2g + g q - w2, (lam + g) p], [(lam + g) p, (lam + 2g) q + g - w2]] = c2 q^2 + c1 q + c0.
    c0 = (lam + 2 * g - w2) * (g - w2)
    c1 = (lam + 2 * g - w2) * (lam + 2 * g) + g * (g - w2) - (lam + g) ** 2
    c2 = g * (lam + 2 * g)
    root = np.sqrt(c1 * c1 - 4 * c2 * c0)
    big = np.where(np.abs(-c1 + root) >= np.abs(-c1 - root), -c1 + root, -c1 - root) / (2 * c2)
    waves = []
    for q in (big, c0 / (c2 * big)):  # the two roots, the small one without cancellation
        p = np.sqrt(q)
        radiating = np.abs(p.imag) <= 1e-12 * (1.0 + np.abs(p))
        p = np.where(radiating, np.where(p.real * eta.real > 0, p, -p), np.where(p.imag > 0, p, -p))
        # Null vectors of the first and of the second row of the Christoffel matrix.
        first_row = ((lam + g) * p, -(lam + 2 * g + g * p * p - w2))
        second_row = ((lam + 2 * g) * p * p + g - w2, -(lam + g) * p)
        waves.append((p, first_row, second_row))

    # P-like: displacement along the wave vector (1, p), div u != 0; S-like: across it, div u = 0
    # (the ratio is scale-free; the larger null vector decides).
    def divergence(wave):
        p, v1, v2 = wave
        use1 = np.abs(v1[0]) + np.abs(v1[1]) >= np.abs(v2[0]) + np.abs(v2[1])
        ax, az = np.where(use1, v1[0], v2[0]), np.where(use1, v1[1], v2[1])
        return np.abs(ax + p * az) / (np.abs(ax) + np.abs(az))

    swap = divergence(waves[1]) > divergence(waves[0])
    p_wave = [np.where(swap, waves[1][i], waves[0][i]) for i in range(3)]
    s_wave = [np.where(swap, waves[0][i], waves[1][i]) for i in range(3)]
    # The amplitude must be analytic in eta (Muller, winding), so one row per wave, never a switch:
    # the second row's null vector for the P wave (the first's is prop. to p (1, p), zero at
    # grazing, eta = c_p/c_s), the first row's for the S wave (prop. to (p, -1), never zero).
    pw = [p_wave[0], p_wave[2][0], p_wave[2][1]]
    sw = [s_wave[0], s_wave[1][0], s_wave[1][1]]
    return pw, sw, lam, g


def determinant(eta, mu, nu, memory=0.0):
    """u_z = 0 and sigma_xz (1 - i K eta) + mu sigma_zz = 0 on the two waves (d/dx -> i, d/dz -> i p)."""
    pw, sw, lam, g = partial_waves(eta, nu)
    cols = []
    for p, ax, az in (pw, sw):
        s_zz = lam * 1j * (ax + p * az) + 2 * g * 1j * p * az
        s_xz = g * (1j * p * ax + 1j * az)
        cols.append((az, s_xz * (1 - 1j * memory * eta) + mu * s_zz))
    det = cols[0][0] * cols[1][1] - cols[1][0] * cols[0][1]
    return det if np.ndim(eta) else complex(det)


def muller(f, x0, x1, x2, tol=1e-15, iterations=100):
    f0, f1, f2 = f(x0), f(x1), f(x2)
    for _ in range(iterations):
        h1, h2 = x1 - x0, x2 - x1
        d1, d2 = (f1 - f0) / h1, (f2 - f1) / h2
        a = (d2 - d1) / (h2 + h1)
        b = a * h2 + d2
        disc = np.sqrt(b * b - 4 * f2 * a)
        den = b + disc if abs(b + disc) >= abs(b - disc) else b - disc
        step = -2 * f2 / den
        x0, x1, x2 = x1, x2, x2 + step
        f0, f1, f2 = f1, f2, f(x2)
        if abs(step) < tol * (1 + abs(x2)) or f2 == 0:
            break
    return x2


def growing_root(mu, nu, step=0.01):
    """Continuation in mu from eta = sqrt(2) at mu = 1 (neutral there: 2 - eta^2 = 0)."""
    eta, previous = complex(math.sqrt(2.0)), None
    n = int(round((mu - 1.0) / step))
    for j in range(1, n + 1):
        m = 1.0 + (mu - 1.0) * j / n
        guess = eta if previous is None else 2 * eta - previous
        guess = complex(guess.real, max(guess.imag, 1e-4))
        f = lambda z, m=m: determinant(z, m, nu)
        previous, eta = eta, muller(f, guess, guess + 1e-3, guess + 1e-3j)
    return eta


def winding(mu, nu, bottom=1e-6, half_width=60.0, notch=0.05, samples=4000):
    """Roots of det / eta^2 in the box [-w, w] x [bottom, w] less the half disc |eta| < notch
    (the double root eta = 0, a rigid shift, where the two partial waves coincide), counted
    counter-clockwise: the phase summed over samples refined (midpoints inserted) until no step
    turns it by more than 0.3 rad."""
    paths = [lambda t: complex(-half_width, bottom) + (half_width - notch) * t,
             lambda t: notch * np.exp(1j * np.pi * (1.0 - t)) + 1j * bottom,
             lambda t: complex(notch, bottom) + (half_width - notch) * t,
             lambda t: complex(half_width, bottom) + 1j * (half_width - bottom) * t,
             lambda t: complex(half_width, half_width) - 2 * half_width * t,
             lambda t: complex(-half_width, half_width) - 1j * (half_width - bottom) * t]
    total = 0.0
    for path in paths:
        t = np.linspace(0.0, 1.0, samples + 1)
        for _ in range(60):
            z = path(t)
            values = determinant(z, mu, nu) / (z * z)
            jumps = np.angle(values[1:] / values[:-1])
            coarse = np.abs(jumps) > 0.3
            if not coarse.any():
                break
            t = np.sort(np.concatenate([t, 0.5 * (t[:-1] + t[1:])[coarse]]))
        else:
            sys.exit("flutter_roots: winding not resolved at mu %g nu %g" % (mu, nu))
        total += jumps.sum()
    return total / (2 * math.pi)


def root_checked(mu, nu):
    eta = growing_root(mu, nu) if mu > 1.0 else complex(math.sqrt(2.0))
    scale = abs(determinant(eta + 0.01, mu, nu))
    if abs(determinant(eta, mu, nu)) > 1e-10 * scale:
        sys.exit("flutter_roots: no root at mu %g nu %g" % (mu, nu))
    turns, expected = winding(mu, nu), (1 if mu > 1.0 else 0)
    if abs(turns - expected) > 1e-3 or (expected and not eta.imag > 1e-3):
        sys.exit("flutter_roots: %.3f growing roots at mu %g nu %g, expected %d" % (turns, mu, nu, expected))
    return eta


MEMORY_MU = [1.1, 1.2, 1.3, 1.4, 1.6, 2.0]


def follow_in_memory(eta, mu, nu, grid, stop_at_axis=False):
    """The root continued from eta (a root at K = grid[0]) over the memories in grid (Muller);
    with stop_at_axis, up to the last K where Im eta > 2e-4."""
    roots, previous = [eta], None
    for K in grid[1:]:
        guess = eta if previous is None else 2 * eta - previous
        f = lambda z, K=K: determinant(z, mu, nu, K) / (z * z)  # without the double root eta = 0
        with np.errstate(all="ignore"):
            z = muller(f, guess, guess + 1e-4, guess + 1e-4j)
        if stop_at_axis and not (np.isfinite(z) and z.imag > 2e-4 and abs(z - eta) < 0.02):
            break  # next to the axis: the crossing is solved on the axis itself
        previous, eta = eta, z
        roots.append(eta)
    return roots


def memory_cutoff(mu, nu):
    """(K_c, eta_c, largest K Im eta below K_c): the flutter root continued in K towards the real
    axis; there the determinant, linear in K (det = A + K B), vanishes at a real eta and a real K:
    Im(A/B) = 0 by the secant method from the last growing root, K_c = -Re(A/B)."""
    grid = np.linspace(0.0, 4.0, 801)
    roots = follow_in_memory(growing_root(mu, nu), mu, nu, grid, stop_at_axis=True)
    ratio = lambda e: determinant(e, mu, nu) / (determinant(e, mu, nu, 1.0) - determinant(e, mu, nu))
    x0, x1 = roots[-1].real, roots[-1].real + 1e-4
    for _ in range(100):
        f0, f1 = ratio(complex(x0)).imag, ratio(complex(x1)).imag
        if f1 == f0 or abs(x1 - x0) < 1e-15:
            break
        x0, x1 = x1, x1 - f1 * (x1 - x0) / (f1 - f0)
    kc = -ratio(complex(x1)).real
    if not (abs(x1 - roots[-1].real) < 1e-2 and 0 < kc and abs(kc - grid[len(roots) - 1]) < 0.02):
        sys.exit("flutter_roots: no real-axis crossing found at mu %g" % mu)
    return kc, complex(x1), max(k * z.imag for k, z in zip(grid, roots))


def memory_mode_growth(mu, nu):
    """Largest K Im eta of the mode against the sliding, and the K at which it peaks."""
    start = muller(lambda e: determinant(e, mu, nu), -2.1 + 0j, -2.101 + 0j, -2.102 + 0j)
    grid = np.concatenate([[0.0], np.geomspace(1e-3, 100.0, 1001)])
    roots = follow_in_memory(start, mu, nu, grid)
    if not all(np.isfinite(z) for z in roots):
        sys.exit("flutter_roots: the memory's mode was lost at mu %g" % mu)
    scaled = [k * z.imag for k, z in zip(grid, roots)]
    j = int(np.argmax(scaled))
    if not (0 < j < len(grid) - 1) or roots[j].real >= 0:
        sys.exit("flutter_roots: the memory's mode peaks at the scan's end at mu %g" % mu)
    fine = np.linspace(grid[j - 1], grid[j + 1], 201)
    best = max(k * muller(lambda e, k=k: determinant(e, mu, nu, k), roots[j], roots[j] + 1e-5,
                          roots[j] + 1e-5j).imag for k in fine)
    return best, grid[j]


def memory_table(nu, cs):
    lines = ["", "With a normal-stress memory (relaxation time T, K = |k| c_s T) at nu = %.4f: the flutter "
             "branch grows only for K < K_c; lambda_c = 2 pi c_s T / K_c at the plate's c_s and T = 1 us; "
             "the largest growth rate times T of the flutter branch (K < K_c) and of the memory's mode "
             "against the sliding (any K):" % nu, "",
             "| mu | K_c | eta_c | lambda_c / (c_s T) | lambda_c, T = 1 us | flutter: max growth x T "
             "| mode against the sliding: max growth x T (at K) |",
             "|---:|---:|---:|---:|---:|---:|---:|"]
    for mu in MEMORY_MU:
        kc, etac, flutter = memory_cutoff(mu, nu)
        other, at = memory_mode_growth(mu, nu)
        lines.append("| %.1f | %.4f | %.4f | %.2f | %.0f um | %.4f | %.4f (%.2f) |" % (
            mu, kc, etac.real, 2 * math.pi / kc, 2 * math.pi * cs * 1e-6 / kc * 1e6, flutter, other, at))
    return lines


def tables():
    young, nu, rho = plate_defaults()
    cs = math.sqrt(young / (2 * (1 + nu) * rho))
    lines = ["Plate defaults (include/gradfric/physics/plate.hpp): E = %g Pa, nu = %.4f, rho = %g kg/m^3, "
             "so c_s = %.2f m/s." % (young, nu, rho, cs), "",
             "The growing root for k > 0 at the plate's nu = %.4f (c_p/c_s = %.4f):" % (
                 nu, math.sqrt((2 - 2 * nu) / (1 - 2 * nu))), ""]
    lines.append("| mu | Re eta | Im eta | e-folding time, lambda = 25 um | lambda = 100 um "
                 "| shear-wave decay depth 1/(k Re beta) |")
    lines.append("|---:|---:|---:|---:|---:|---:|")
    for mu in MU_TABLE:
        eta = root_checked(mu, nu)
        depth = 1.0 / (2 * math.pi * complex(partial_waves(eta, nu)[1][0]).imag) if eta.imag > 0 else math.inf
        cells = ["%.1f" % mu, "%.4f" % eta.real, "%.4f" % eta.imag]
        for wavelength in WAVELENGTHS:
            rate = 2 * math.pi / wavelength * cs * eta.imag
            cells.append("%.3f us" % (1e6 / rate) if rate > 0 else "infinite (neutral)")
        cells.append("%.2f lambda" % depth if math.isfinite(depth) else "infinite (radiates)")
        lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "Against nu at mu = 1.2:", "",
              "| nu | c_p/c_s | Re eta (mu 1.2) | Im eta (mu 1.2) |", "|---:|---:|---:|---:|"]
    for value, label in NU_TABLE:
        eta = root_checked(1.2, value)
        ratio = math.sqrt((2 - 2 * value) / (1 - 2 * value))
        lines.append("| %s | %.4f | %.4f | %.4f |" % (label, ratio, eta.real, eta.imag))
    lines += memory_table(nu, cs)
    return "\n".join(lines) + "\n"


def main(argv):
    text = tables()
    if len(argv) == 1:
        sys.stdout.write(text)
        return 0
    if len(argv) == 3 and argv[1] == "--check":
        doc = open(argv[2], encoding="utf-8").read()
        m = re.search(re.escape(BEGIN) + r"\n(.*?)" + re.escape(END), doc, re.S)
        if not m:
            print("flutter_roots: no generated block in %s" % argv[2])
            return 1
        if m.group(1) != text:
            print("flutter_roots: the tables in %s differ from scripts/flutter_roots.py's output" % argv[2])
            return 1
        print("flutter_roots: tables in %s OK" % argv[2])
        return 0
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
