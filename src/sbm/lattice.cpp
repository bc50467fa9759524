#include "gradfric/sbm/lattice.hpp"

#include "gradfric/physics/property_sampler.hpp"
#include "gradfric/physics/random_surface.hpp"
#include "gradfric/sbm/spring.hpp"

#include <algorithm>
#include <cmath>

namespace gradfric::sbm {

namespace {

double seriesStiffness(double a, double b) { return 2.0 * a * b / (a + b); }

double columnCentre(int column, int blocksPerSide) { return (column + 0.5) / blocksPerSide; }
// Per-column properties: an E field that varies along x only is the same on every row, so any
// row will do.
constexpr double kMiddleRow = 0.5;

// The vertical spring between two blocks of a column: k itself when they have the same E (the
// per-column lattice's rule, exact), their series stiffness otherwise.
double verticalStiffness(double below, double above) { return below == above ? below : seriesStiffness(below, above); }

// Per block: every spring from the axial stiffnesses k of its two blocks (see lattice.hpp).
void buildPerBlock(const Parameters& p, const PropertySampler& sampler, LatticeStiffness& s) {
  const int nb = p.blocksPerSide, inner = std::max(nb - 1, 0);
  std::vector<double> k(std::size_t(nb) * nb);
  s.slider.resize(k.size());
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) {
      const double modulus = p.plate.youngsModulus * sampler.modulus(columnCentre(c, nb), columnCentre(r, nb));
      k[std::size_t(r) * nb + c] = p.axialStiffness(modulus);
      s.slider[std::size_t(r) * nb + c] = p.sliderStiffness(modulus);
    }
  s.horizontal.assign(std::size_t(nb) * inner, 0.0);
  s.vertical.assign(std::size_t(nb) * nb, 0.0);
  s.diagonal.assign(std::size_t(nb) * inner, 0.0);
  s.antiDiagonal.assign(std::size_t(nb) * inner, 0.0);
  auto at = [&](int r, int c) { return k[std::size_t(r) * nb + c]; };
  for (int r = 0; r < nb; ++r) {
    for (int c = 0; c + 1 < nb; ++c) s.horizontal[std::size_t(r) * inner + c] = seriesStiffness(at(r, c), at(r, c + 1));
    if (r + 1 == nb) continue;  // the top row has no row above
    for (int c = 0; c < nb; ++c) s.vertical[std::size_t(r) * nb + c] = verticalStiffness(at(r, c), at(r + 1, c));
    for (int c = 0; c + 1 < nb; ++c) {
      s.diagonal[std::size_t(r) * inner + c] = seriesStiffness(0.5 * at(r, c), 0.5 * at(r + 1, c + 1));
      s.antiDiagonal[std::size_t(r) * inner + c] = seriesStiffness(0.5 * at(r, c + 1), 0.5 * at(r + 1, c));
    }
  }
}

}  // namespace

double LatticeStiffness::largestAxial() const {
  double largest = 0.0;
  for (double k : vertical) largest = std::max(largest, k);
  return largest;
}

LatticeStiffness buildStiffness(const Parameters& p, const Grading& grading, bool forcePerBlock) {
  const int nb = p.blocksPerSide;
  LatticeStiffness s;
  s.blocksPerSide = nb;
  s.spacing = p.spacing();
  const PropertySampler sampler(grading, nb, nb);
  s.graded = sampler.gradesModulus();
  s.smallStrain = p.smallStrain;
  s.perBlock = forcePerBlock || sampler.modulusVariesAlongY();
  if (s.perBlock) {
    s.graded = true;  // the per-block row pointers need the graded kernels
    buildPerBlock(p, sampler, s);
    return s;
  }
  std::vector<double> modulus(nb);
  for (int c = 0; c < nb; ++c) modulus[c] = p.plate.youngsModulus * sampler.modulus(columnCentre(c, nb), kMiddleRow);
  s.vertical.resize(nb);
  s.slider.resize(nb);
  for (int c = 0; c < nb; ++c) {
    s.vertical[c] = p.axialStiffness(modulus[c]);
    s.slider[c] = p.sliderStiffness(modulus[c]);
  }
  s.horizontal.resize(std::max(nb - 1, 0));
  s.diagonal.resize(std::max(nb - 1, 0));
  for (int c = 0; c + 1 < nb; ++c) {
    s.horizontal[c] = seriesStiffness(s.vertical[c], s.vertical[c + 1]);
    s.diagonal[c] = seriesStiffness(0.5 * s.vertical[c], 0.5 * s.vertical[c + 1]);
  }
  return s;
}

ColumnProperties columnProperties(const Parameters& p, const Grading& grading) {
  const int nb = p.blocksPerSide;
  const PropertySampler sampler(grading, nb, nb);
  ColumnProperties c;
  for (int column = 0; column < nb; ++column) {
    const double x = columnCentre(column, nb);
    c.modulus.push_back(p.plate.youngsModulus * sampler.modulus(x, kMiddleRow));
    c.muStatic.push_back(p.plate.muStatic * sampler.muStatic(x, kMiddleRow));
    c.muKinetic.push_back(p.plate.muKinetic * sampler.muKinetic(x, kMiddleRow));
  }
  return c;
}

BlockProperties blockProperties(const Parameters& p, const Grading& grading) {
  const int nb = p.blocksPerSide;
  const PropertySampler sampler(grading, nb, nb);
  BlockProperties b;
  for (int r = 0; r < nb; ++r)
    for (int column = 0; column < nb; ++column) {
      const double u = columnCentre(column, nb), v = columnCentre(r, nb);
      b.modulus.push_back(p.plate.youngsModulus * sampler.modulus(u, v));
      b.muStatic.push_back(p.plate.muStatic * sampler.muStatic(u, v));
      b.muKinetic.push_back(p.plate.muKinetic * sampler.muKinetic(u, v));
      b.pressure.push_back(p.plate.pressure * sampler.pressure(u, v));
    }
  return b;
}

FrictionField buildFriction(const Parameters& p, const Grading& grading, StreamKey key) {
  const int nb = p.blocksPerSide;
  const double normal = p.normalForcePerBlock();
  const PropertySampler sampler(grading, nb, nb);
  FrictionField f;
  f.columns = nb;
  const SurfaceSettings surface = p.surfaceOf();
  const bool dispersed = surface.sigmaStatic > 0.0 || surface.sigmaKinetic > 0.0;
  if (dispersed || sampler.frictionVariesAlongY()) {
    f.layout = SiteLayout::PerSite;
  } else if (sampler.gradesFriction()) {
    f.layout = SiteLayout::PerColumn;
  } else {
    f.layout = SiteLayout::Uniform;
  }
  // Mean coefficients and normal force of a block (row r, column c): the fields' or the bands'.
  struct Mean {
    double muS, muK, normal;
  };
  auto meanAt = [&](int r, int c) {
    const double u = columnCentre(c, nb), v = columnCentre(r, nb);
    return Mean{p.plate.muStatic * sampler.muStatic(u, v), p.plate.muKinetic * sampler.muKinetic(u, v),
                grading.fields && grading.fields->pressure ? normal * sampler.pressure(u, v) : normal};
  };
  if (!dispersed) {
    const int rows = f.layout == SiteLayout::PerSite ? nb : 1;
    const int columns = f.layout == SiteLayout::Uniform ? 1 : nb;
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c) {
        const Mean m = meanAt(rows == 1 ? nb / 2 : r, c);
        f.staticStrength.push_back(m.muS * m.normal);
        f.kineticStrength.push_back(m.muK * m.normal);
      }
    return f;
  }
  f.staticStrength.resize(std::size_t(nb) * nb);
  f.kineticStrength.resize(std::size_t(nb) * nb);
  if (surface.kind == SurfaceKind::Blocks) {  // one draw per block, redrawn: the model before the surface
    const RandomStream stream(key);
    for (int r = 0; r < nb; ++r) {
      for (int c = 0; c < nb; ++c) {
        const int i = r * nb + c;
        const Mean m = meanAt(r, c);
        double muS = 0.0, muK = 0.0;
        for (std::uint32_t attempt = 0;; ++attempt) {
          const auto [zs, zk] = stream.normalPair(std::uint64_t(i), 0, attempt);
          muS = m.muS * (1.0 + surface.sigmaStatic * zs);
          muK = m.muK * (1.0 + surface.sigmaKinetic * zk);
          if (muK > 0.0 && muK <= muS) break;
          if (attempt == 0) ++f.redrawnBlocks;
        }
        f.staticStrength[i] = muS * m.normal;
        f.kineticStrength[i] = muK * m.normal;
      }
    }
    return f;
  }
  // The field averaged over each block; the same surface on any lattice (the block edges L c / N_b
  // fall on the cells' edges where they are aligned, random_surface.hpp).
  SurfaceSettings seeded = surface;
  seeded.seed = key.seed;
  const RandomSurface field(seeded, p.plate.length, key.realisation, key.sweepIndex);
  std::vector<double> edges(nb + 1);
  for (int c = 0; c <= nb; ++c) edges[c] = p.plate.length * c / nb;
  const std::vector<SurfaceDeviations> z = field.averageOverLattice(edges, edges);
  for (int r = 0; r < nb; ++r) {
    for (int c = 0; c < nb; ++c) {
      const int i = r * nb + c;
      const Mean m = meanAt(r, c);
      const SurfaceCoefficients k = surfaceCoefficients(m.muS, m.muK, 1.0, surface, z[i]);
      if (k.clipped) ++f.redrawnBlocks;
      f.staticStrength[i] = k.muStatic * m.normal;
      f.kineticStrength[i] = k.muKinetic * m.normal;
    }
  }
  return f;
}

LatticeEnergy latticeEnergy(const LatticeStiffness& s, double mass, const double* ux, const double* uy,
                            const double* vx, const double* vy, double sliderX, double sliderY) {
  const int nb = s.blocksPerSide;
  const double l = s.spacing, ld = std::sqrt(2.0) * l;
  LatticeEnergy e;
  auto spring = [&](int i, int j, double k, double restX, double restY, double restLength) {
    const double dx = restX + ux[j] - ux[i], dy = restY + uy[j] - uy[i];
    const double length = std::sqrt(dx * dx + dy * dy);
    const double dux = ux[j] - ux[i], duy = uy[j] - uy[i];
    const double extension = s.smallStrain ? (restX * dux + restY * duy) / restLength  // e . du
                                           : (2.0 * (restX * dux + restY * duy) + dux * dux + duy * duy) / (length + restLength);
    e.internal += 0.5 * k * extension * extension;
  };
  for (int r = 0; r < nb; ++r) {
    for (int c = 0; c < nb; ++c) {
      const int i = r * nb + c;
      e.kinetic += 0.5 * mass * (vx[i] * vx[i] + vy[i] * vy[i]);
      const double sx = sliderX - ux[i], sy = sliderY - uy[i];
      const RowStiffness k = s.row(r);
      e.slider += 0.5 * k.slider[c] * (sx * sx + sy * sy);
      if (c + 1 < nb) spring(i, i + 1, k.horizontal[c], l, 0, l);
      if (r + 1 < nb) {
        spring(i, i + nb, k.vertical[c], 0, l, l);
        if (c + 1 < nb) {
          spring(i, i + nb + 1, k.diagonal[c], l, l, ld);
          spring(i + 1, i + nb, k.antiDiagonal[c], -l, l, ld);
        }
      }
    }
  }
  return e;
}

void blockStress(const LatticeStiffness& s, double thickness, const double* ux, const double* uy, int r, int c,
                 double stress[3]) {
  const int nb = s.blocksPerSide;
  const double l = s.spacing;
  const double diagonalLength = std::sqrt(2.0) * l;
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  auto add = [&](int rr, int cc, double k, double restX, double restY, double restLength) {
    if (rr < 0 || rr >= nb || cc < 0 || cc >= nb) return;
    const int i = r * nb + c, j = rr * nb + cc;
    const auto [fx, fy] = s.smallStrain ? latticeSpringForce<true>(k, restX, restY, restLength, ux[j] - ux[i], uy[j] - uy[i])
                                        : latticeSpringForce<false>(k, restX, restY, restLength, ux[j] - ux[i], uy[j] - uy[i]);
    const double dx = restX + ux[j] - ux[i], dy = restY + uy[j] - uy[i];
    sxx += dx * fx;
    syy += dy * fy;
    sxy += 0.5 * (dx * fy + dy * fx);
  };
  // Row r's springs, and the row below's for those that reach down to r.
  const RowStiffness here = s.row(r), below = s.row(std::max(r - 1, 0));
  if (c + 1 < nb) add(r, c + 1, here.horizontal[c], l, 0, l);
  if (c > 0) add(r, c - 1, here.horizontal[c - 1], -l, 0, l);
  add(r + 1, c, here.vertical[c], 0, l, l);
  if (r > 0) add(r - 1, c, below.vertical[c], 0, -l, l);
  if (c + 1 < nb) {
    add(r + 1, c + 1, here.diagonal[c], l, l, diagonalLength);
    if (r > 0) add(r - 1, c + 1, below.antiDiagonal[c], l, -l, diagonalLength);
  }
  if (c > 0) {
    add(r + 1, c - 1, here.antiDiagonal[c - 1], -l, l, diagonalLength);
    if (r > 0) add(r - 1, c - 1, below.diagonal[c - 1], -l, -l, diagonalLength);
  }
  // Each spring is shared by two blocks: half of its virial belongs to this block.
  const double volume = l * l * thickness;
  stress[0] = 0.5 * sxx / volume;
  stress[1] = 0.5 * syy / volume;
  stress[2] = 0.5 * sxy / volume;
}

void longitudinalStress(const LatticeStiffness& s, double thickness, double pressure, const double* ux,
                        const double* uy, double* sigmaXOverP) {
  const int nb = s.blocksPerSide;
  for (int r = 0; r < nb; ++r)
    for (int c = 0; c < nb; ++c) {
      double stress[3];
      blockStress(s, thickness, ux, uy, r, c, stress);
      sigmaXOverP[r * nb + c] = stress[0] / pressure;
    }
}

}  // namespace gradfric::sbm
