#include "gradfric/fem/plate_model.hpp"

#include "gradfric/core/input_error.hpp"
#include "gradfric/core/options.hpp"
#include "gradfric/core/petsc_call.hpp"
#include "gradfric/core/run_limits.hpp"
#include "gradfric/fem/partition.hpp"

#include <petscds.h>
#include <petscfe.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gradfric::fem {

namespace {

// Generic reference: the RHS residual G = -int grad(phi) : sigma, E from the auxiliary field.
void g1Elastic(PetscInt dim, PetscInt, PetscInt, const PetscInt[], const PetscInt[], const PetscScalar[],
               const PetscScalar[], const PetscScalar u_x[], const PetscInt aOff[], const PetscInt[],
               const PetscScalar a[], const PetscScalar[], const PetscScalar[], PetscReal, const PetscReal[],
               PetscInt, const PetscScalar constants[], PetscScalar f1[]) {
  const double E = a[aOff[0]], nu = constants[0];
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  double trace = 0;
  for (PetscInt d = 0; d < dim; ++d) trace += u_x[d * dim + d];
  for (PetscInt c = 0; c < dim; ++c) {
    for (PetscInt d = 0; d < dim; ++d) f1[c * dim + d] = -mu * (u_x[c * dim + d] + u_x[d * dim + c]);
    f1[c * dim + c] -= lambda * trace;
  }
}

void createQ1(MPI_Comm comm, const char* name, PetscInt nc, PetscInt degree, PetscFE* fe) {
  GF_CALL(PetscFECreateLagrange(comm, 3, nc, PETSC_FALSE, degree, 1, fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(*fe), name));
}

struct FE {
  PetscFE fe = nullptr;
  ~FE() { PetscFEDestroy(&fe); }
};

}  // namespace

PlateModel::PlateModel(MPI_Comm comm, const FemParameters& params, const Grading& grading)
    : comm_(comm), params_(params), grading_(grading) {
  params_.resolveDerived();
  static PetscClassId classId = 0;
  if (!classId) {
    GF_CALL(PetscClassIdRegister("gradfric FEM", &classId));
  }
  GF_CALL(PetscLogEventRegister("GfFemRHS", classId, &evRhs_));
  GF_CALL(PetscLogEventRegister("GfFemElastic", classId, &evKernel_));
  GF_CALL(PetscLogEventRegister("GfFemContact", classId, &evContact_));
  GF_CALL(PetscLogEventRegister("GfFemGeneric", classId, &evGeneric_));
  element_ = makeBoxElement(params_.plate.length / params_.nx, params_.plate.length / params_.ny, params_.plate.thickness / params_.nz, params_.plate.poissonRatio);
  buildMesh();
  buildCells();
  buildNodes();
  computeStableStep();
  DM dmU = displacementDM();
  GF_CALL(DMCreateGlobalVector(dmU, uGlobal_.out()));
  GF_CALL(VecDuplicate(uGlobal_, fGlobal_.out()));
  GF_CALL(DMCreateLocalVector(dmU, uLocal_.out()));
  GF_CALL(VecDuplicate(uLocal_, fLocalU_.out()));
  PetscInt n = 0;
  GF_CALL(VecGetLocalSize(uGlobal_, &n));
  if (n != 3 * ownedBlocks_) throw std::runtime_error("plate mesh: displacement and state layouts differ");
}

void PlateModel::buildMesh() {
  const PetscInt faces[3] = {params_.nx, params_.ny, params_.nz};
  const PetscReal lower[3] = {0, 0, 0};
  const PetscReal upper[3] = {params_.plate.length, params_.plate.length, params_.plate.thickness};
  OwnedDM serial;
  GF_CALL(DMPlexCreateBoxMesh(comm_, 3, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, serial.out()));
  DM distributed = distributeMesh(serial, params_.partitioner);
  if (distributed) {
    dm_ = OwnedDM(distributed);
  } else {
    dm_ = std::move(serial);
  }
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(dm_.get()), "plate"));
  FE feU, feV;
  createQ1(comm_, "displacement", 3, 1, &feU.fe);
  createQ1(comm_, "velocity", 3, 1, &feV.fe);
  GF_CALL(DMSetField(dm_, 0, nullptr, reinterpret_cast<PetscObject>(feU.fe)));
  GF_CALL(DMSetField(dm_, 1, nullptr, reinterpret_cast<PetscObject>(feV.fe)));
  GF_CALL(DMCreateDS(dm_));
  GF_CALL(DMCreateLocalVector(dm_, xLocal_.out()));
  GF_CALL(VecDuplicate(xLocal_, fLocal_.out()));
}

void PlateModel::buildCells() {
  PetscInt cStart = 0, cEnd = 0;
  GF_CALL(DMPlexGetHeightStratum(dm_, 0, &cStart, &cEnd));
  GF_CALL(DMPlexGetDepthStratum(dm_, 0, &vStart_, &vEnd_));
  numCells_ = cEnd - cStart;
  PetscInt n = numCells_;
  GF_CALL_MPI(MPI_Allreduce(&n, &globalCells_, 1, MPIU_INT, MPI_SUM, comm_));
  globalVertices_ = static_cast<PetscInt>(params_.nx + 1) * (params_.ny + 1) * (params_.nz + 1);

  Vec coords = nullptr;
  PetscSection coordSection = nullptr, section = nullptr;
  GF_CALL(DMGetCoordinatesLocal(dm_, &coords));
  GF_CALL(DMGetCoordinateSection(dm_, &coordSection));
  GF_CALL(DMGetLocalSection(dm_, &section));
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(coords, &x));
  cellVertices_.assign(8 * numCells_, 0);
  cellStateOff_.assign(8 * numCells_, 0);
  cellModulus_.assign(numCells_, params_.plate.youngsModulus);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt np = 0;
    PetscInt* pts = nullptr;
    GF_CALL(DMPlexGetTransitiveClosure(dm_, c, PETSC_TRUE, &np, &pts));
    PetscInt verts[8];
    int nv = 0;
    double centre[3] = {0, 0, 0};
    for (PetscInt i = 0; i < np; ++i) {
      const PetscInt p = pts[2 * i];
      if (p < vStart_ || p >= vEnd_) continue;
      if (nv < 8) verts[nv] = p;
      ++nv;
      PetscInt off = 0;
      GF_CALL(PetscSectionGetOffset(coordSection, p, &off));
      for (int d = 0; d < 3; ++d) centre[d] += x[off + d] / 8.0;
    }
    GF_CALL(DMPlexRestoreTransitiveClosure(dm_, c, PETSC_TRUE, &np, &pts));
    if (nv != 8) throw std::runtime_error("plate mesh: a cell without 8 vertices");
    const PetscInt cell = c - cStart;
    bool seen[8] = {};
    for (int k = 0; k < 8; ++k) {
      PetscInt off = 0;
      GF_CALL(PetscSectionGetOffset(coordSection, verts[k], &off));
      const int a = (x[off] > centre[0] ? 1 : 0) + (x[off + 1] > centre[1] ? 2 : 0) + (x[off + 2] > centre[2] ? 4 : 0);
      if (seen[a]) throw std::runtime_error("plate mesh: a cell is not an axis-aligned box");
      seen[a] = true;
      cellVertices_[8 * cell + a] = verts[k] - vStart_;
      PetscInt soff = 0, voff = 0;
      GF_CALL(PetscSectionGetOffset(section, verts[k], &soff));
      GF_CALL(PetscSectionGetFieldOffset(section, verts[k], 1, &voff));
      if (voff != soff + 3) throw std::runtime_error("plate mesh: unexpected state layout");
      cellStateOff_[8 * cell + a] = soff;
    }
    cellModulus_[cell] = params_.plate.youngsModulus * grading_.modulusFactor(centre[0] / params_.plate.length);
  }
  GF_CALL(VecRestoreArrayRead(coords, &x));
}

void PlateModel::buildNodes() {
  contactLaw_.sites.layout = SiteLayout::PerSite;  // one site per bottom node, in bottom_ order
  contactLaw_.criticalVelocity = params_.vC;
  // Assemble nodal quantities through the state layout: slot 0 lumped mass, 1 bottom area,
  // 2 bottom area x friction factor, 3 top area.
  const double rho = params_.plate.density, volume = element_.volume();
  GF_CALL(VecZeroEntries(fLocal_));
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArray(fLocal_, &f));
  for (PetscInt c = 0; c < numCells_; ++c)
    for (int a = 0; a < 8; ++a) f[cellStateOff_[8 * c + a]] += rho * volume / 8.0;  // density-weighted row sum
  PetscSection section = nullptr, coordSection = nullptr;
  GF_CALL(DMGetLocalSection(dm_, &section));
  Vec coords = nullptr;
  GF_CALL(DMGetCoordinatesLocal(dm_, &coords));
  GF_CALL(DMGetCoordinateSection(dm_, &coordSection));
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(coords, &x));
  DMLabel faceSets = nullptr;
  GF_CALL(DMGetLabel(dm_, "Face Sets", &faceSets));
  if (!faceSets) throw std::runtime_error("plate mesh: no Face Sets label");
  const double faceArea = element_.hx * element_.hy;
  for (PetscInt value : {1, 2}) {  // bottom z- = 1, top z+ = 2
    IS is = nullptr;
    GF_CALL(DMLabelGetStratumIS(faceSets, value, &is));
    if (!is) continue;
    PetscInt n = 0;
    const PetscInt* faces = nullptr;
    GF_CALL(ISGetLocalSize(is, &n));
    GF_CALL(ISGetIndices(is, &faces));
    for (PetscInt i = 0; i < n; ++i) {
      PetscInt np = 0;
      PetscInt* pts = nullptr;
      GF_CALL(DMPlexGetTransitiveClosure(dm_, faces[i], PETSC_TRUE, &np, &pts));
      double xc = 0;
      int nv = 0;
      PetscInt verts[4];
      for (PetscInt k = 0; k < np; ++k) {
        const PetscInt p = pts[2 * k];
        if (p < vStart_ || p >= vEnd_) continue;
        PetscInt off = 0;
        GF_CALL(PetscSectionGetOffset(coordSection, p, &off));
        const double zExpected = value == 1 ? 0.0 : params_.plate.thickness;
        if (std::fabs(x[off + 2] - zExpected) > 1e-9 * params_.plate.thickness)
          throw std::runtime_error("plate mesh: Face Sets value does not match the face position");
        xc += x[off] / 4.0;
        if (nv < 4) verts[nv] = p;
        ++nv;
      }
      GF_CALL(DMPlexRestoreTransitiveClosure(dm_, faces[i], PETSC_TRUE, &np, &pts));
      const double factor = grading_.frictionFactor(xc / params_.plate.length);
      for (int k = 0; k < std::min(nv, 4); ++k) {
        PetscInt soff = 0;
        GF_CALL(PetscSectionGetOffset(section, verts[k], &soff));
        if (value == 1) {
          f[soff + 1] += faceArea / 4.0;
          f[soff + 2] += faceArea / 4.0 * factor;
        } else {
          f[soff + 3] += faceArea / 4.0;
        }
      }
    }
    GF_CALL(ISRestoreIndices(is, &faces));
    GF_CALL(ISDestroy(&is));
  }
  GF_CALL(VecRestoreArray(fLocal_, &f));
  OwnedVec global;
  GF_CALL(DMCreateGlobalVector(dm_, global.out()));
  GF_CALL(VecZeroEntries(global));
  GF_CALL(DMLocalToGlobal(dm_, fLocal_, ADD_VALUES, global));
  PetscInt localSize = 0, rStart = 0, rEnd = 0;
  GF_CALL(VecGetLocalSize(global, &localSize));
  GF_CALL(VecGetOwnershipRange(global, &rStart, &rEnd));
  ownedBlocks_ = localSize / 6;
  const PetscScalar* g = nullptr;
  GF_CALL(VecGetArrayRead(global, &g));
  mass_.assign(ownedBlocks_, 0);
  invMass_.assign(ownedBlocks_, 0);
  for (PetscInt b = 0; b < ownedBlocks_; ++b) {
    mass_[b] = g[6 * b];
    invMass_[b] = 1.0 / g[6 * b];
  }
  PetscSection gsection = nullptr;
  GF_CALL(DMGetGlobalSection(dm_, &gsection));
  for (PetscInt p = vStart_; p < vEnd_; ++p) {
    PetscInt goff = 0;
    GF_CALL(PetscSectionGetOffset(gsection, p, &goff));
    if (goff < 0) continue;  // not owned
    const PetscInt b = (goff - rStart) / 6;
    PetscInt off = 0;
    GF_CALL(PetscSectionGetOffset(coordSection, p, &off));
    if (g[6 * b + 1] > 0) {
      BottomNode node;
      node.block = b;
      node.x = x[off];
      node.y = x[off + 1];
      node.area = g[6 * b + 1];
      const double factor = g[6 * b + 2] / g[6 * b + 1];  // area-weighted band factor
      contactLaw_.sites.staticStrength.push_back(params_.plate.muStatic * factor);
      contactLaw_.sites.kineticStrength.push_back(params_.plate.muKinetic * factor);
      bottom_.push_back(node);
    }
    if (g[6 * b + 3] > 0) top_.push_back({b, g[6 * b + 3]});
  }
  GF_CALL(VecRestoreArrayRead(global, &g));
  GF_CALL(VecRestoreArrayRead(coords, &x));
}

double stableTimeStep(const FemParameters& given, const Grading& grading) {
  FemParameters q = given;
  q.resolveDerived();
  const BoxElement element = makeBoxElement(q.plate.length / q.nx, q.plate.length / q.ny, q.plate.thickness / q.nz, q.plate.poissonRatio);
  double factor = 1.0;
  for (int band = 0; band < grading.bands; ++band)
    if (grading.gradesModulus()) factor = std::max(factor, grading.bandFactor(band));
  double omega2 = elementMaxFrequencySquared(element, q.plate.youngsModulus * factor, q.plate.density);
  // Penalty springs: k * area / nodal mass = 2 k / (rho hz) at every bottom node.
  if (q.contact) omega2 += 2.0 * std::max(q.kn, q.kt) / (q.plate.density * element.hz);
  const double omega = std::sqrt(omega2);
  const double gamma = std::max(q.settleDamping, q.slideDamping);
  const double xi = 0.5 * q.stiffnessDamping * omega + gamma / (2.0 * omega);
  return centralDifferenceStableStep(omega2, xi);
}

double chooseTimeStep(const FemParameters& q, const Grading& grading) {
  const double stable = stableTimeStep(q, grading);
  if (q.dt > 0) {
    if (q.dt > stable && q.dtCheck)
      throw InputError("-fem_dt", formatReal(q.dt),
                       "<= the stable step " + formatReal(stable) + " s (from mesh, wave speed, penalty, damping)");
    return q.dt;
  }
  return q.dtSafety * stable;
}

void requireFemRunLength(const FemParameters& q, const Grading& grading, const RunParameters* record) {
  const double duration = q.rampTime + q.settleTime + q.slideTime;
  requireResolvedTimescale(record, q.eq2PeakTime(), chooseTimeStep(q, grading), "-fem_dt",
                           {"-fem_", "-plate_", "-grading_"}, "Eq. 2 peak time");
  requireRunLength(record, duration, chooseTimeStep(q, grading), q.dtSafety * stableTimeStep(q, grading), "-fem_dt",
                   {"-fem_slide_time", "-fem_settle_time", "-fem_ramp_time"}, {"-fem_", "-plate_", "-grading_"},
                   "pressure step + sliding");
}

void PlateModel::computeStableStep() {
  stableDt_ = fem::stableTimeStep(params_, grading_);
  dt_ = fem::chooseTimeStep(params_, grading_);
  if (dt_ > stableDt_)  // only with -fem_dt_check false
    GF_CALL(PetscPrintf(comm_,
                        "WARNING: -fem_dt_check false (testing only): dt %.4g s is above the stable step %.4g s; the "
                        "blow-up monitor will stop the run\n",
                        dt_, stableDt_));
}

Vec PlateModel::createState() const {
  Vec X = nullptr;
  GF_CALL(DMCreateGlobalVector(dm_, &X));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(X), "state"));
  GF_CALL(VecZeroEntries(X));
  return X;
}

double PlateModel::pressureAt(double t) const {
  if (phase_ == Phase::Sliding || params_.rampTime <= 0) return params_.plate.pressure;
  return params_.plate.pressure * std::min(1.0, t / params_.rampTime);
}

void PlateModel::rhs(double t, Vec X, Vec F) {
  GF_CALL(PetscLogEventBegin(evRhs_, 0, 0, 0, 0));
  // The elastic force needs only u (+ beta v): scatter 3 values per vertex through the
  // displacement DM rather than the 6 of the state (half the communication and copying).
  DM dmU = displacementDM();
  {
    const PetscScalar* x = nullptr;
    PetscScalar* u = nullptr;
    GF_CALL(VecGetArrayRead(X, &x));
    GF_CALL(VecGetArray(uGlobal_, &u));
    const double beta = params_.stiffnessDamping;
    if (beta != 0.0) {
      for (PetscInt b = 0; b < ownedBlocks_; ++b)
        for (int d = 0; d < 3; ++d) u[3 * b + d] = x[6 * b + d] + beta * x[6 * b + 3 + d];
    } else {
      for (PetscInt b = 0; b < ownedBlocks_; ++b)
        for (int d = 0; d < 3; ++d) u[3 * b + d] = x[6 * b + d];
    }
    GF_CALL(VecRestoreArray(uGlobal_, &u));
    GF_CALL(VecRestoreArrayRead(X, &x));
  }
  GF_CALL(DMGlobalToLocal(dmU, uGlobal_, INSERT_VALUES, uLocal_));
  GF_CALL(VecZeroEntries(fLocalU_));
  {
    const PetscScalar* ul = nullptr;
    PetscScalar* fl = nullptr;
    GF_CALL(VecGetArrayRead(uLocal_, &ul));
    GF_CALL(VecGetArray(fLocalU_, &fl));
    GF_CALL(PetscLogEventBegin(evKernel_, 0, 0, 0, 0));
    elasticKernel(numCells_, cellDispOff_.data(), cellModulus_.data(), element_.stiffness.data(), ul, nullptr, 0.0,
                  fl);
    GF_CALL(PetscLogEventEnd(evKernel_, 0, 0, 0, 0));
    GF_CALL(PetscLogFlops(2.0 * 576 * numCells_));
    GF_CALL(VecRestoreArrayRead(uLocal_, &ul));
    GF_CALL(VecRestoreArray(fLocalU_, &fl));
  }
  GF_CALL(VecZeroEntries(fGlobal_));
  GF_CALL(DMLocalToGlobal(dmU, fLocalU_, ADD_VALUES, fGlobal_));
  const PetscScalar* x = nullptr;
  PetscScalar* f = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  GF_CALL(VecGetArray(F, &f));
  {
    const PetscScalar* fe = nullptr;
    GF_CALL(VecGetArrayRead(fGlobal_, &fe));
    for (PetscInt b = 0; b < ownedBlocks_; ++b)
      for (int d = 0; d < 3; ++d) f[6 * b + 3 + d] = fe[3 * b + d];
    GF_CALL(VecRestoreArrayRead(fGlobal_, &fe));
  }
  const double pressure = pressureAt(t);
  for (const TopNode& n : top_) f[6 * n.block + 5] -= pressure * n.area;
  ContactTotals totals;
  if (params_.contact) {
    GF_CALL(PetscLogEventBegin(evContact_, 0, 0, 0, 0));
    const PenaltyStiffness k{params_.kn, params_.kt};
    for (std::size_t i = 0; i < bottom_.size(); ++i) {
      BottomNode& n = bottom_[i];
      const PetscScalar* xb = x + 6 * n.block;
      const ContactTraction r = penaltyContact(k, contactLaw_, int(i), xb[2], xb[0], xb[1], n.anchorX, n.anchorY,
                                               xb[3], xb[4], n.state == ContactState::Slip);
      n.pendingX = r.anchorX;
      n.pendingY = r.anchorY;
      n.pendingState = r.state;
      n.pressure = r.pressure;
      n.tx = r.tx;
      n.ty = r.ty;
      PetscScalar* fb = f + 6 * n.block;
      fb[3] += n.area * r.tx;
      fb[4] += n.area * r.ty;
      fb[5] += n.area * r.pressure;
      totals.fx += n.area * r.tx;
      totals.fy += n.area * r.ty;
      totals.fn += n.area * r.pressure;
      if (r.state == ContactState::Stick) ++totals.stick;
      else if (r.state == ContactState::Slip) ++totals.slip;
      else ++totals.open;
    }
    GF_CALL(PetscLogEventEnd(evContact_, 0, 0, 0, 0));
  }
  const double gamma = phase_ == Phase::Pressure ? params_.settleDamping : params_.slideDamping;
  for (PetscInt b = 0; b < ownedBlocks_; ++b) {
    PetscScalar* fb = f + 6 * b;
    const PetscScalar* xb = x + 6 * b;
    const double im = invMass_[b];
    for (int d = 0; d < 3; ++d) {
      fb[d] = xb[3 + d];
      fb[3 + d] = fb[3 + d] * im - gamma * xb[3 + d];
    }
  }
  // Energy accounting (blow-up monitor, tests): the pressure does work -p dZ with Z = sum a u_z
  // over the top nodes; in step 2 the slider holds the top's tangential acceleration at zero with a
  // force -m a that would otherwise act, its power is that force times v.
  for (const TopNode& n : top_) totals.topZ += n.area * x[6 * n.block + 2];
  if (phase_ == Phase::Sliding)  // the top moves with the slider tangentially, free vertically
    for (const TopNode& n : top_) {
      totals.driveX -= mass_[n.block] * f[6 * n.block + 3];
      totals.driveY -= mass_[n.block] * f[6 * n.block + 4];
      f[6 * n.block + 3] = f[6 * n.block + 4] = 0.0;
    }
  lastTotals_ = totals;
  GF_CALL(VecRestoreArrayRead(X, &x));
  GF_CALL(VecRestoreArray(F, &f));
  GF_CALL(PetscLogEventEnd(evRhs_, 0, 0, 0, 0));
}

void PlateModel::commitContact() {
  for (BottomNode& n : bottom_) {
    n.anchorX = n.pendingX;
    n.anchorY = n.pendingY;
    n.state = n.pendingState;
  }
}

void PlateModel::startSliding(Vec X) {
  phase_ = Phase::Sliding;
  const double theta = params_.plate.slidingAngle * M_PI / 180.0;
  PetscScalar* x = nullptr;
  GF_CALL(VecGetArray(X, &x));
  for (const TopNode& n : top_) {
    x[6 * n.block + 3] = params_.plate.velocity * std::cos(theta);
    x[6 * n.block + 4] = params_.plate.velocity * std::sin(theta);
  }
  GF_CALL(VecRestoreArray(X, &x));
}

ContactTotals PlateModel::contactTotals() const {
  double local[6] = {lastTotals_.fx, lastTotals_.fy, lastTotals_.fn, lastTotals_.topZ, lastTotals_.driveX,
                     lastTotals_.driveY},
         sum[6];
  long long counts[3] = {lastTotals_.stick, lastTotals_.slip, lastTotals_.open}, csum[3];
  GF_CALL_MPI(MPI_Allreduce(local, sum, 6, MPI_DOUBLE, MPI_SUM, comm_));
  GF_CALL_MPI(MPI_Allreduce(counts, csum, 3, MPI_LONG_LONG, MPI_SUM, comm_));
  ContactTotals t;
  t.fx = sum[0];
  t.fy = sum[1];
  t.fn = sum[2];
  t.topZ = sum[3];
  t.driveX = sum[4];
  t.driveY = sum[5];
  t.stick = csum[0];
  t.slip = csum[1];
  t.open = csum[2];
  return t;
}

double PlateModel::kineticEnergy(Vec X) const {
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  double e = 0;
  for (PetscInt b = 0; b < ownedBlocks_; ++b)
    for (int d = 3; d < 6; ++d) e += 0.5 * mass_[b] * x[6 * b + d] * x[6 * b + d];
  GF_CALL(VecRestoreArrayRead(X, &x));
  double sum = 0;
  GF_CALL_MPI(MPI_Allreduce(&e, &sum, 1, MPI_DOUBLE, MPI_SUM, comm_));
  return sum;
}

double PlateModel::elasticEnergy(Vec X) {
  GF_CALL(DMGlobalToLocal(dm_, X, INSERT_VALUES, xLocal_));
  GF_CALL(VecZeroEntries(fLocal_));
  const PetscScalar* xl = nullptr;
  PetscScalar* fl = nullptr;
  GF_CALL(VecGetArrayRead(xLocal_, &xl));
  GF_CALL(VecGetArray(fLocal_, &fl));
  elasticKernel(numCells_, cellStateOff_.data(), cellModulus_.data(), element_.stiffness.data(), xl, nullptr, 0.0, fl);
  GF_CALL(VecRestoreArrayRead(xLocal_, &xl));
  GF_CALL(VecRestoreArray(fLocal_, &fl));
  OwnedVec F;
  GF_CALL(VecDuplicate(X, F.out()));
  GF_CALL(VecZeroEntries(F));
  GF_CALL(DMLocalToGlobal(dm_, fLocal_, ADD_VALUES, F));
  const PetscScalar *x = nullptr, *f = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  GF_CALL(VecGetArrayRead(F, &f));
  double e = 0;
  for (PetscInt b = 0; b < ownedBlocks_; ++b)
    for (int d = 0; d < 3; ++d) e -= 0.5 * x[6 * b + d] * f[6 * b + d];
  GF_CALL(VecRestoreArrayRead(X, &x));
  GF_CALL(VecRestoreArrayRead(F, &f));
  double sum = 0;
  GF_CALL_MPI(MPI_Allreduce(&e, &sum, 1, MPI_DOUBLE, MPI_SUM, comm_));
  return sum;
}

double PlateModel::totalMass() const {
  double m = 0, sum = 0;
  for (double mb : mass_) m += mb;
  GF_CALL_MPI(MPI_Allreduce(&m, &sum, 1, MPI_DOUBLE, MPI_SUM, comm_));
  return sum;
}

double PlateModel::topArea() const {
  double a = 0, sum = 0;
  for (const TopNode& n : top_) a += n.area;
  GF_CALL_MPI(MPI_Allreduce(&a, &sum, 1, MPI_DOUBLE, MPI_SUM, comm_));
  return sum;
}

void PlateModel::bottomPenetration(Vec X, double* mean, double* minimum, double* maximum) const {
  const PetscScalar* x = nullptr;
  GF_CALL(VecGetArrayRead(X, &x));
  double s[2] = {0, 0}, lo = 1e300, hi = -1e300;
  for (const BottomNode& n : bottom_) {
    const double pen = -x[6 * n.block + 2];
    s[0] += pen;
    s[1] += 1;
    lo = std::min(lo, pen);
    hi = std::max(hi, pen);
  }
  GF_CALL(VecRestoreArrayRead(X, &x));
  double sum[2];
  GF_CALL_MPI(MPI_Allreduce(s, sum, 2, MPI_DOUBLE, MPI_SUM, comm_));
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, comm_));
  GF_CALL_MPI(MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, comm_));
  *mean = sum[0] / sum[1];
  *minimum = lo;
  *maximum = hi;
}

void PlateModel::cellStresses(Vec X, std::vector<std::array<double, 6>>* stress) {
  GF_CALL(DMGlobalToLocal(dm_, X, INSERT_VALUES, xLocal_));
  const PetscScalar* xl = nullptr;
  GF_CALL(VecGetArrayRead(xLocal_, &xl));
  stress->resize(numCells_);
  for (PetscInt c = 0; c < numCells_; ++c) {
    double ue[24];
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d) ue[3 * a + d] = xl[cellStateOff_[8 * c + a] + d];
    (*stress)[c] = cellAverageStress(element_, cellModulus_[c], ue);
  }
  GF_CALL(VecRestoreArrayRead(xLocal_, &xl));
}

// ---- displacement-only DM: the specialised kernel against PETSc's generic residual ----

DM PlateModel::displacementDM() {
  if (genericReady_) return dmU_;
  setupGeneric();
  return dmU_;
}

void PlateModel::setupGeneric() {
  GF_CALL(DMClone(dm_, dmU_.out()));
  FE feU, feE;
  createQ1(comm_, "displacement", 3, 1, &feU.fe);
  GF_CALL(DMSetField(dmU_, 0, nullptr, reinterpret_cast<PetscObject>(feU.fe)));
  GF_CALL(DMCreateDS(dmU_));
  PetscDS ds = nullptr;
  GF_CALL(DMGetDS(dmU_, &ds));
  GF_CALL(PetscDSSetRHSResidual(ds, 0, nullptr, g1Elastic));
  GF_CALL(PetscDSSetImplicit(ds, 0, PETSC_FALSE));  // else the RHS residual is silently zero (3.18)
  const PetscScalar constants[1] = {params_.plate.poissonRatio};
  GF_CALL(PetscDSSetConstants(ds, 1, const_cast<PetscScalar*>(constants)));
  // E per cell as a piecewise-constant auxiliary field.
  GF_CALL(DMClone(dm_, dmAux_.out()));
  GF_CALL(PetscFECreateLagrange(comm_, 3, 1, PETSC_FALSE, 0, 1, &feE.fe));
  GF_CALL(PetscFECopyQuadrature(feU.fe, feE.fe));
  GF_CALL(PetscObjectSetName(reinterpret_cast<PetscObject>(feE.fe), "E"));
  GF_CALL(DMSetField(dmAux_, 0, nullptr, reinterpret_cast<PetscObject>(feE.fe)));
  GF_CALL(DMCreateDS(dmAux_));
  GF_CALL(DMCreateLocalVector(dmAux_, auxLocal_.out()));
  PetscSection auxSection = nullptr, uSection = nullptr;
  GF_CALL(DMGetLocalSection(dmAux_, &auxSection));
  GF_CALL(DMGetLocalSection(dmU_, &uSection));
  PetscInt cStart = 0, cEnd = 0;
  GF_CALL(DMPlexGetHeightStratum(dm_, 0, &cStart, &cEnd));
  PetscScalar* a = nullptr;
  GF_CALL(VecGetArray(auxLocal_, &a));
  for (PetscInt c = cStart; c < cEnd; ++c) {
    PetscInt off = 0;
    GF_CALL(PetscSectionGetOffset(auxSection, c, &off));
    a[off] = cellModulus_[c - cStart];
  }
  GF_CALL(VecRestoreArray(auxLocal_, &a));
  GF_CALL(DMSetAuxiliaryVec(dmU_, nullptr, 0, 0, auxLocal_));
  GF_CALL(DMSetAuxiliaryVec(dmU_, nullptr, 0, 100, auxLocal_));
  cellDispOff_.assign(8 * numCells_, 0);
  for (PetscInt c = 0; c < numCells_; ++c)
    for (int a8 = 0; a8 < 8; ++a8) {
      PetscInt off = 0;
      GF_CALL(PetscSectionGetOffset(uSection, cellVertices_[8 * c + a8] + vStart_, &off));
      cellDispOff_[8 * c + a8] = off;
    }
  genericReady_ = true;
}

void PlateModel::elasticForceSpecialised(Vec u, Vec f) {
  DM dmU = displacementDM();
  OwnedVec uLoc, fLoc;
  GF_CALL(DMGetLocalVector(dmU, uLoc.out()));
  GF_CALL(DMGetLocalVector(dmU, fLoc.out()));
  GF_CALL(DMGlobalToLocal(dmU, u, INSERT_VALUES, uLoc));
  GF_CALL(VecZeroEntries(fLoc));
  const PetscScalar* ul = nullptr;
  PetscScalar* fl = nullptr;
  GF_CALL(VecGetArrayRead(uLoc, &ul));
  GF_CALL(VecGetArray(fLoc, &fl));
  GF_CALL(PetscLogEventBegin(evKernel_, 0, 0, 0, 0));
  elasticKernel(numCells_, cellDispOff_.data(), cellModulus_.data(), element_.stiffness.data(), ul, nullptr, 0.0, fl);
  GF_CALL(PetscLogEventEnd(evKernel_, 0, 0, 0, 0));
  GF_CALL(VecRestoreArrayRead(uLoc, &ul));
  GF_CALL(VecRestoreArray(fLoc, &fl));
  GF_CALL(VecZeroEntries(f));
  GF_CALL(DMLocalToGlobal(dmU, fLoc, ADD_VALUES, f));
  Vec a = uLoc.release(), b = fLoc.release();
  GF_CALL(DMRestoreLocalVector(dmU, &a));
  GF_CALL(DMRestoreLocalVector(dmU, &b));
}

void PlateModel::elasticForceGeneric(Vec u, Vec f) {
  DM dmU = displacementDM();
  Vec uLoc = nullptr, fLoc = nullptr;
  GF_CALL(DMGetLocalVector(dmU, &uLoc));
  GF_CALL(DMGetLocalVector(dmU, &fLoc));
  GF_CALL(DMGlobalToLocal(dmU, u, INSERT_VALUES, uLoc));
  GF_CALL(VecZeroEntries(fLoc));
  GF_CALL(PetscLogEventBegin(evGeneric_, 0, 0, 0, 0));
  GF_CALL(DMPlexTSComputeRHSFunctionFEM(dmU, 0.0, uLoc, fLoc, nullptr));
  GF_CALL(PetscLogEventEnd(evGeneric_, 0, 0, 0, 0));
  GF_CALL(VecZeroEntries(f));
  GF_CALL(DMLocalToGlobal(dmU, fLoc, ADD_VALUES, f));
  GF_CALL(DMRestoreLocalVector(dmU, &uLoc));
  GF_CALL(DMRestoreLocalVector(dmU, &fLoc));
}

}  // namespace gradfric::fem
