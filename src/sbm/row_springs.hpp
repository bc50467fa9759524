#pragma once
// Private to the fast spring-block kernel: the internal springs of one row of the lattice, added
// to the row's forces (rowSprings, RK4) or kept as values (tileSprings, velocity Verlet), and the
// stiffness pointers of a row (RowStiffness, the one place that says where a row's stiffnesses are).
#include "gradfric/sbm/lattice.hpp"
#include "gradfric/sbm/spring.hpp"
#include "kernel_inline.hpp"

namespace gradfric::sbm {

// The stiffness pointers of row r (RowStiffness, lattice.hpp): per column every row points at the
// same column arrays, per block row r at its own. The kernels index them by column alone, so both
// layouts run the same arithmetic. Without grading (Graded false) they read only element 0.
inline RowStiffness rowStiffnessOf(const LatticeStiffness& s, int row) { return s.row(row); }

// The springs from row r (rx, ry) to row r+1 (qx, qy): vertical, diagonal (c -> c+1 above) and
// anti-diagonal (c+1 -> c above). Adds their forces to row r (fx, fy) and writes the reactions on
// row r+1 into (nextX, nextY). The arrays are distinct: __restrict lets the loops vectorise.
template <bool Graded, bool Small>
GF_ALWAYS_INLINE void springsToRowAbove(int nb, double l, double diagonalLength, const double* __restrict kV,
                                        const double* __restrict kD, const double* __restrict kA,
                                        const double* __restrict rx,
                                        const double* __restrict ry, const double* __restrict qx,
                                        const double* __restrict qy, double* __restrict fx, double* __restrict fy,
                                        double* __restrict nextX, double* __restrict nextY) {
  const double kV0 = kV[0], kD0 = kD[0], kA0 = kA[0];
  for (int c = 0; c < nb; ++c) {
    const auto [ax, ay] = latticeSpringForce<Small>(Graded ? kV[c] : kV0, 0.0, l, l, qx[c] - rx[c], qy[c] - ry[c]);
    fx[c] += ax;
    fy[c] += ay;
    nextX[c] = -ax;
    nextY[c] = -ay;
  }
  for (int c = 0; c + 1 < nb; ++c) {
    const auto [ax, ay] = latticeSpringForce<Small>(Graded ? kD[c] : kD0, l, l, diagonalLength, qx[c + 1] - rx[c], qy[c + 1] - ry[c]);
    fx[c] += ax;
    fy[c] += ay;
    nextX[c + 1] -= ax;
    nextY[c + 1] -= ay;
  }
  for (int c = 0; c + 1 < nb; ++c) {
    const auto [ax, ay] = latticeSpringForce<Small>(Graded ? kA[c] : kA0, -l, l, diagonalLength, qx[c] - rx[c + 1], qy[c] - ry[c + 1]);
    fx[c + 1] += ax;
    fy[c + 1] += ay;
    nextX[c] -= ax;
    nextY[c] -= ay;
  }
}

// The internal springs of one row: its horizontal springs and those to the row above.
struct RowSprings {
  int nb;
  bool above;  // a row above exists
  double l, diagonalLength;
  const double* kH;
  const double* kV;
  const double* kD;
  const double* kA;  // anti-diagonal (per column: the diagonal's array)
  const double* rx;  // positions of the row (the row above follows at + nb)
  const double* ry;
  double* hx;  // horizontal spring forces (work space)
  double* hy;
  double* fx;  // forces on the row
  double* fy;
  double* nextX;  // reactions on the row above
  double* nextY;
};

// Adds the row's springs to its forces, in the kernel's fixed order (horizontal, then the springs
// to the row above).
template <bool Graded, bool Small>
GF_ALWAYS_INLINE void rowSprings(const RowSprings& s) {
  const int nb = s.nb;
  const double l = s.l;
  const double* __restrict kH = s.kH;
  const double* __restrict rx = s.rx;
  const double* __restrict ry = s.ry;
  double* __restrict hx = s.hx;
  double* __restrict hy = s.hy;
  double* __restrict fx = s.fx;
  double* __restrict fy = s.fy;
  const double kH0 = kH[0];
  for (int c = 0; c + 1 < nb; ++c) {
    const Force2 f = latticeSpringForce<Small>(Graded ? kH[c] : kH0, l, 0.0, l, rx[c + 1] - rx[c], ry[c + 1] - ry[c]);
    hx[c] = f.x;
    hy[c] = f.y;
  }
  for (int c = 0; c + 1 < nb; ++c) {
    fx[c] += hx[c];
    fy[c] += hy[c];
  }
  for (int c = 0; c + 1 < nb; ++c) {
    fx[c + 1] -= hx[c];
    fy[c + 1] -= hy[c];
  }
  if (s.above)
    springsToRowAbove<Graded, Small>(nb, l, s.diagonalLength, s.kV, s.kD, s.kA, rx, ry, rx + nb, ry + nb, fx, fy,
                                     s.nextX, s.nextY);
}

// The springs a row owns, evaluated at u_n: horizontal h[c] (c -> c+1), and to the row above
// vertical v[c], diagonal d[c] (c -> c+1 above) and anti-diagonal a[c] (c+1 -> c above), as the
// fused Verlet step reads them (verlet_row.hpp). Each array is readable from index -1 to nb-1;
// the entries no spring owns (-1 and nb-1 of h, d, a) hold the identity of the way the step uses
// them: -0.0 where it adds them (x + -0.0 == x for every x, -0.0 included) and +0.0 where it
// subtracts them (x - +0.0 == x), so the edge columns run the interior's arithmetic, bit for bit.
struct RowPieces {
  double* hx;
  double* hy;
  double* vx;
  double* vy;
  double* dx;
  double* dy;
  double* ax;
  double* ay;
};

// Writes those identities (see RowPieces); no spring evaluation ever overwrites them.
inline void padRowPieces(const RowPieces& p, int nb) {
  for (double* added : {p.hx, p.hy, p.dx, p.dy}) added[nb - 1] = -0.0;
  for (double* subtracted : {p.hx, p.hy, p.dx, p.dy}) subtracted[-1] = +0.0;
  for (double* added : {p.ax, p.ay}) added[-1] = -0.0;
  for (double* subtracted : {p.ax, p.ay}) subtracted[nb - 1] = +0.0;
}

// Evaluates the springs of columns c0 <= c < c1 of row r into its pieces (the full sweep: the
// whole row; the active set: one stale tile): horizontal and, with a row above, vertical,
// diagonal and anti-diagonal. springEnd = min(c1, nb - 1): the last column owns no horizontal,
// diagonal or anti-diagonal spring.
template <bool Graded, bool Small>
GF_ALWAYS_INLINE void tileSprings(int c0, int c1, int springEnd, bool above, double l, double diagonalLength,
                                  const double* __restrict kH, const double* __restrict kV,
                                  const double* __restrict kD, const double* __restrict kA,
                                  const double* __restrict rx, const double* __restrict ry,
                                  const double* __restrict qx, const double* __restrict qy, RowPieces p) {
  const double kH0 = kH[0], kV0 = kV[0], kD0 = kD[0], kA0 = kA[0];
  double* __restrict hx = p.hx;
  double* __restrict hy = p.hy;
  double* __restrict vx = p.vx;
  double* __restrict vy = p.vy;
  double* __restrict dx = p.dx;
  double* __restrict dy = p.dy;
  double* __restrict ax = p.ax;
  double* __restrict ay = p.ay;
  for (int c = c0; c < springEnd; ++c) {
    const Force2 f = latticeSpringForce<Small>(Graded ? kH[c] : kH0, l, 0.0, l, rx[c + 1] - rx[c], ry[c + 1] - ry[c]);
    hx[c] = f.x;
    hy[c] = f.y;
  }
  if (!above) return;
  for (int c = c0; c < c1; ++c) {
    const Force2 f = latticeSpringForce<Small>(Graded ? kV[c] : kV0, 0.0, l, l, qx[c] - rx[c], qy[c] - ry[c]);
    vx[c] = f.x;
    vy[c] = f.y;
  }
  for (int c = c0; c < springEnd; ++c) {
    const Force2 f =
        latticeSpringForce<Small>(Graded ? kD[c] : kD0, l, l, diagonalLength, qx[c + 1] - rx[c], qy[c + 1] - ry[c]);
    dx[c] = f.x;
    dy[c] = f.y;
  }
  for (int c = c0; c < springEnd; ++c) {
    const Force2 f =
        latticeSpringForce<Small>(Graded ? kA[c] : kA0, -l, l, diagonalLength, qx[c] - rx[c + 1], qy[c] - ry[c + 1]);
    ax[c] = f.x;
    ay[c] = f.y;
  }
}

}  // namespace gradfric::sbm
