#pragma once
// The elastic operator of the plate: the internal force f = -sum_cells E_c K_hat (u_e + beta v_e)
// through the specialised kernel (one precomputed 24x24 box-cell stiffness scaled by each cell's
// graded E), with PETSc's generic PetscFE residual of the same operator kept as its reference
// (elastic_reference.cpp). Works on a displacement-only DM (3 values per vertex): half the
// communication of the 6-value state.
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/plate_mesh.hpp"
#include "gradfric/fem/plate_properties.hpp"

#include <array>
#include <vector>

namespace gradfric::fem {

// The kernel: f += -sum_cells E_c K_hat (u_e + beta v_e), scattered into f. cellOffsets: 8 local
// offsets per cell (element node order); u, v, f index with them. v may be null (beta ignored).
// outOffsets, when given, are where f takes the cells' forces instead (8 per cell: the ordered
// assembly's slots). Hot: one clone per instruction set (elastic_kernel.cpp). cellShape, when
// given (an edge-graded mesh), indexes each cell's 576 values in the stiffness table.
void elasticKernel(PetscInt numCells, const PetscInt* cellOffsets, const double* cellModulus, const double* stiffness,
                   const double* u, const double* v, double beta, double* f, const PetscInt* outOffsets = nullptr,
                   const int* cellShape = nullptr);

// The box cell's stiffness in the basis of its three mirror symmetries (elastic_kernel.cpp): the
// 8 diagonal 3 x 3 blocks of H K_hat H / 64, H the Walsh-Hadamard transform over the corners.
// False when K_hat is not block diagonal in that basis (then the dense kernel must be used).
bool reflectionBlocks(const double* stiffness, std::array<double, 72>* blocks);
// The same force as elasticKernel (u only) through the blocks: ~4 x fewer flops, equal to
// round-off; the scatter-add keeps the cell order. cellShape, when given, indexes each cell's 72
// values in the blocks table (each SIMD lane takes its cell's).
void elasticKernelBlocked(PetscInt numCells, const PetscInt* cellOffsets, const double* cellModulus,
                          const double* blocks, const double* u, double* f, const PetscInt* outOffsets = nullptr,
                          const int* cellShape = nullptr);

struct ElasticSettings {
  double poissonRatio = 1.0 / 3.0;
  double stiffnessDamping = 0.0;  // Rayleigh beta [s]
  // The hexahedron whose box-cell stiffness the kernel applies; PETSc's generic reference
  // (forceGeneric) is the trilinear one only.
  ElementType element = ElementType::Trilinear;
  bool blockedKernel = false;  // elasticKernelBlocked instead of the dense product (equal to round-off)
  bool energyAudit = false;    // integrate the stiffness-proportional dissipation (one more pass a step)
};

// The elastic layer: always on, first in the list (it sets the force slots).
class ElasticOperator : public Layer {
public:
  // E of a cell: properties.cellModulus() (the graded E at the cell centre).
  ElasticOperator(const PlateMesh& mesh, const PlateProperties& properties, const ElasticSettings& settings);
  ElasticOperator(const ElasticOperator&) = delete;
  ElasticOperator& operator=(const ElasticOperator&) = delete;

  // The layer: the internal force of the global state X (displacement + beta velocity) into the
  // force slots of F; with the energy audit, the power of the stiffness damping, whose work the
  // post-step integrates.
  const char* name() const override { return "elastic"; }
  void addForce(const LayerContext& ctx, Vec X, Vec F, ContactSums& sums) override;
  void postStep(double dt) override { stiffnessWork_ += stiffnessPower_ * dt; }
  LayerWork work() const override;
  void archive(StateArchive& a) override;
  std::string describe() const override;
  void writeProperties(PropertySink& sink) const override;
  bool setsForce() const override { return true; }

  double energy(Vec X);  // (1/2) u . K u, summed over ranks [J]
  // Rayleigh beta [s] from now on (the damping switched on at the confirmed peak).
  void setStiffnessDamping(double beta) { beta_ = beta; }
  double stiffnessDamping() const { return beta_; }
  // Per local cell the average stress (Voigt) of the state X.
  void cellStresses(Vec X, std::vector<std::array<double, 6>>* stress);

  // The displacement-only DM and the force on its global vectors, f = -K u: the specialised kernel
  // and PETSc's generic PetscFE residual (the reference the kernel is tested against).
  DM displacementDM() const { return dmU_; }
  void forceSpecialised(Vec u, Vec f);
  // diag += the diagonal of K on a global vector of the displacement DM (Jacobi preconditioner of
  // the static pressure step).
  void addStiffnessDiagonal(Vec diag);
  void forceGeneric(Vec u, Vec f);

  // Round-off studies (bench_fem_roundoff): the cells of this rank taken in a shuffled order
  // (pattern seed; 0 keeps the mesh's order), so every node sums its cells' forces in another
  // order, as on another number of ranks. The same forces to round-off.
  void shuffleCellOrder(unsigned seed);

  // The box element of each cell shape (mesh.shapes(); one on a uniform mesh).
  const BoxElement& element() const { return elements_.front(); }
  const std::vector<BoxElement>& elements() const { return elements_; }
  const std::vector<double>& cellModulus() const { return cellModulus_; }

private:
  void setupReference();  // elastic_reference.cpp
  void kernelForce(Vec uLocal, Vec fLocal);
  bool lastForceIsFor(Vec X);  // collective: uGlobal_/fGlobal_ hold X's displacements and force
  // f += -sum_cells E_c K_hat u_e (the blocked kernel when the element allows it).
  void applyKernel(const double* u, double* f) const;  // on cellDispOff_
  // The sums at the vertices shared with other ranks redone in the global cell order (plate_mesh's
  // OrderedAssembly): global is a global displacement-DM array holding the assembled force.
  void reorderSharedSums(const double* uLocal, double* global);
  void fixSharedSums(Vec uLocal, Vec fGlobal);  // the same on PETSc vectors
  double stiffnessDampingPower(Vec X);  // beta v . K v over ranks [W]

  const PlateMesh& mesh_;
  ElasticSettings settings_;
  std::vector<BoxElement> elements_;  // per shape
  double beta_;
  double stiffnessPower_ = 0, stiffnessWork_ = 0;  // over ranks (energy audit only)
  OwnedVec velocityAsDisplacement_;             // for the audit: v in the displacement slots
  std::vector<double> cellModulus_;
  std::vector<double> shuffledModulus_;  // in the order of cellDispOff_ after shuffleCellOrder (else empty)
  std::vector<double> stiffnesses_, blocks_;  // per shape: 576 and 72 values
  // Per cell its shape in those tables, only when there is more than one (else the kernels take
  // the single shape's values and no index: the uniform mesh's loops, unchanged).
  std::vector<int> cellShape_, shuffledShape_, boundaryShape_;
  bool blocked_ = false;  // K_hat is block diagonal in the mirror basis (every box cell)
  std::vector<PetscInt> cellDispOff_;  // 8 offsets into a local displacement vector per cell
  // The ordered assembly's boundary cells: their displacement offsets, E and force slots.
  bool shared_ = false;
  std::vector<PetscInt> boundaryDispOff_, boundarySlots_;
  std::vector<double> boundaryModulus_, slots_;
  OwnedDM dmU_, dmAux_;
  OwnedVec auxLocal_, uGlobal_, fGlobal_, uLocal_, fLocalU_, xLocal_, energyU_, energyF_;
  bool haveForce_ = false;  // fGlobal_ = -K uGlobal_ from the last setForce
  PetscLogEvent evKernel_ = 0, evGeneric_ = 0;
};

}  // namespace gradfric::fem
