#pragma once
// Time integration of the spring-block lattice at a fixed step (classical RK4 or velocity
// Verlet) with stick/slip under a friction law (physics/friction_laws.hpp; Coulomb by default).
// Two implementations, both templated on the law, with the same semantics:
//   FastLattice      structure of arrays, each spring evaluated once, the four RK stages fused
//                    with the force sweep row by row (the production kernel);
//   ReferenceLattice a plain array of blocks, each block summing its 8 neighbours (every spring
//                    evaluated twice): the tests' reference (reference_lattice.hpp).
// Both run every law, those with a per-block state (GF_STATE_FRICTION_LAWS) included.
//
// Stick/slip and the RK stages (documented in README, "Spring-block model"):
//  - the stick state is frozen during a step: a stuck block has zero velocity and acceleration
//    in every stage; a slipping block feels the damping -m gamma v and the law's sliding force
//    (Coulomb: mu_k,i F_n; exponential: F_n mu(|v|)) that is also frozen for the step, direction
//    and magnitude: against the velocity at t_n and at its speed, or against F_mot and at speed
//    zero when the block starts from rest. (Re-evaluating its direction in every stage makes a
//    velocity that crosses zero inside a step chatter around zero instead of re-sticking.)
//  - at the start of each step, with F_mot of the new state: a stuck block with
//    |F_mot| > mu_s,i F_n starts to slip; a slipping block whose velocity reversed during the
//    last step (it points against that step's friction force) re-sticks (velocity set to zero)
//    if |F_mot| <= mu_s,i F_n, and slides on otherwise (the law's static threshold).
//  - a law with a per-block state (the state law, reference_lattice.hpp) puts the block's
//    strength at its current state in place of both mu_s,i F_n and the sliding force; the state
//    is advanced once per step, at its start, from the block's slip over the step that ended.
// Velocity Verlet (Parameters::integrator) needs one force evaluation per step instead of four,
// with the same stick/slip rule; between steps the velocities are the half-step ones.
#include "gradfric/physics/friction_laws.hpp"
#include "gradfric/sbm/lattice.hpp"

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace gradfric::sbm {

struct StepObservation {
  double time;          // t_n, the time of the state observed
  double sliderForceX;  // sum over blocks of the slider springs' forces at t_n [N]
  double sliderForceY;
};

struct Motion {
  double timeStep;          // dt [s]
  double damping;           // gamma [1/s]
  double mass;              // m [kg]
  double sliderVelocityX;   // v cos(theta) [m/s]
  double sliderVelocityY;   // v sin(theta)
  Integrator integrator = Integrator::RK4;
  // Skip work that cannot change the result (Parameters::skipIdle): FastLattice jumps over the
  // quiet phase before the first slip (quiet_phase.hpp). Off for a load that is not linear in t.
  bool skipIdle = true;
  // The law's per-site strengths stay as built: the active set may hold tiles whose blocks provably
  // stay stuck (slip_prediction.hpp). Off when a caller changes them between steps (the
  // load-dependent pressure, pressure_coupling.hpp).
  bool fixedStrengths = true;
};

Motion motionOf(const Parameters& parameters, double timeStep, double damping);

enum BlockState : std::uint8_t { Stuck = 0, Slipping = 1, Reversed = 2 };

// Does the law keep a per-block state (GF_STATE_FRICTION_LAWS)?
template <class Law>
struct HasBlockState : std::false_type {};
#define GF_SBM_BLOCK_STATE(Law) \
  template <>                   \
  struct HasBlockState<Law> : std::true_type {};
GF_STATE_FRICTION_LAWS(GF_SBM_BLOCK_STATE)
#undef GF_SBM_BLOCK_STATE
template <class Law>
constexpr bool hasBlockState = HasBlockState<Law>::value;

// A block's slip over a step from its displacement increment (dx, dy), as both kernels advance a
// per-block state from it (no std::hypot: its care for overflow costs a tenth of the fast
// kernel's state-law step, and increments of at most microns cannot overflow).
inline double slipOf(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

// The static test of a block at rest against its threshold: the law's own, or with a per-block
// state the shared rule applied to the block's current strength.
template <class Law>
inline bool holdsAtRest(double drivingForceSquared, double threshold) {
  if constexpr (hasBlockState<Law>) return StaticThreshold::holds(drivingForceSquared, threshold);
  else return Law::holds(drivingForceSquared, threshold);
}

// The stick/slip rule at the start of a step (see above), for both kernels: what happens to a
// block in `state` whose driving force the law's static threshold holds (or not).
enum class StickSlipChange { None, StartsToSlip, Resticks, SlidesOn };
inline StickSlipChange stickSlipChange(std::uint8_t state, bool holds) {
  if (state == Stuck) return holds ? StickSlipChange::None : StickSlipChange::StartsToSlip;
  if (state == Reversed) return holds ? StickSlipChange::Resticks : StickSlipChange::SlidesOn;
  return StickSlipChange::None;
}

// The friction force of the step per unit of the direction vector (velocity at t_n when moving,
// F_mot when starting from rest): the law's sliding strength at the block's speed, frozen for
// the step; zero for a stuck block (mobile = 0) or without a direction. frictionPerDirectionAt
// takes the sliding force itself (a law with a per-block state: the block's strength).
inline double frictionPerDirectionAt(double sliding, double mobile, double speed2, double force2) {
  const double norm2 = speed2 > 0.0 ? speed2 : force2;
  return norm2 > 0.0 ? mobile * sliding / std::sqrt(norm2) : 0.0;
}
template <class Law>
inline double frictionPerDirection(const Law& law, double staticStrength, double kineticStrength, double mobile,
                                   double speed2, double force2) {
  const double speed = Law::weakensWithSpeed && speed2 > 0.0 ? std::sqrt(speed2) : 0.0;
  const double sliding = law.slidingStrength(staticStrength, kineticStrength, speed);
  return frictionPerDirectionAt(sliding, mobile, speed2, force2);
}

struct VerletRow;  // the arrays of one row for Verlet's fused step (src/sbm/verlet_row.hpp)
struct RowPieces;  // the springs a row owns, as Verlet's step reads them (src/sbm/row_springs.hpp)

template <class Law>
class FastLattice {
public:
  FastLattice(const LatticeStiffness& stiffness, Law law, const Motion& motion);
  // Observes the state at t_n (slider force, new slips), then advances it to t_{n+1}.
  StepObservation step();
  double time() const { return double(steps_) * motion_.timeStep; }
  std::int64_t steps() const { return steps_; }
  int slippedBlocks() const { return slipped_; }  // blocks that have slipped at least once
  // Where to write each block's first-slip time (N_b^2, NaN-initialised by the caller), or nullptr.
  void recordFirstSlips(double* times) { firstSlip_ = times; }
  const double* displacementX() const { return ux_.data(); }
  const double* displacementY() const { return uy_.data(); }
  const double* velocityX() const { return vx_.data(); }
  const double* velocityY() const { return vy_.data(); }  // half-step velocity with Verlet
  std::vector<std::uint8_t> blockStates() const;  // Stuck or Slipping, per block
  // The first step the kernel integrates: 0, or with Motion::skipIdle the step of the first slip.
  std::int64_t quietSteps() const { return quietUntil_; }
  // The friction law and its per-site strengths: a caller may change the strengths between steps
  // (the load-dependent pressure, pressure_coupling.hpp), never their layout; not with skipIdle.
  Law& law() { return law_; }

  // The kernel's parts (public so that the per-ISA entry points can reach them).
  template <bool Graded, SiteLayout L, int Stage>
  void rk4Stage(double time, double& sumX, double& sumY);
  template <bool Graded, SiteLayout L>
  void verletStep(double time, double& sumX, double& sumY);
  template <bool Graded, SiteLayout L>
  void verletStepActive(double time, double& sumX, double& sumY);
  // Velocity Verlet steps taken on the active set (tiles of blocks that move or whose neighbours
  // moved), not the full sweep: for tests and benchmarks.
  std::int64_t activeSetSteps() const { return activeSetSteps_; }
  // Tile-steps the active set left out of the update because the tile provably held (all its
  // blocks stuck, nothing around moving; slip_prediction.hpp): for tests and benchmarks.
  std::int64_t heldTileSteps() const { return heldTileSteps_; }
  static constexpr int kTile = 8;  // columns per tile of the active set
  bool useActiveSet();  // decides, before a Verlet step, which of the two sweeps it takes

private:
  void dispatch(double& sumX, double& sumY);
  template <bool Graded, bool WantSum, class RowUpdate>
  void sweepRows(const double* px, const double* py, double t, double& sumX, double& sumY, RowUpdate update);
  template <bool Graded, bool WantSum>
  void rowForces(int r, const double* px, const double* py, double t, const double* carryX, const double* carryY,
                 double* nextX, double* nextY, double& sumX, double& sumY);
  template <SiteLayout L>
  void transitions(int r, double t);
  template <SiteLayout L, class PerBlock>
  void transitionsWith(int r, double t, PerBlock each);
  template <SiteLayout L>
  void frictionVector(int r);
  template <SiteLayout L>
  void frictionVectorRange(int r, int c0, int c1);
  void markReversals(int r);
  void markReversalsRange(int r, int c0, int c1);
  void firstSlips(int r, double t);
  void advanceStates(int r);                  // state laws, RK4: row r's states at t_n (block_state.hpp)
  void healHeldStates(int r, int c0, int c1);  // state laws: held blocks' states, no slip (block_state.hpp)
  void lastMovedAround(int r);  // movedAround_ for the tiles of row r
  template <SiteLayout L>
  VerletRow verletRow(int r, const RowPieces& pieces);  // the one builder of row r's VerletRow
  template <bool Graded, SiteLayout L>
  void verletRowStep(int r, const RowPieces& pieces, double t, double& sumX, double& sumY);
  template <bool Graded, SiteLayout L>
  bool verletColumns(int r, const VerletRow& row, int c0, int c1, double t);
  void finishRow(int r, double t, bool started, double& sumX, double& sumY);
  template <bool Graded, SiteLayout L>
  void holdTiles(int r, const VerletRow& row);  // the active set's held tiles (active_set.hpp)
  template <bool Graded>
  void ownSprings(int r, int c0, int c1, const RowPieces& pieces);  // springs of columns [c0, c1) of row r
  RowPieces rowPieces();        // the full sweep's row of pieces (rowPieces_)
  RowPieces keptPieces(int r);  // the active set's pieces of row r (piece*_)
  LatticeStiffness stiffness_;
  Law law_;  // owns the per-block friction strengths
  Motion motion_;
  int nb_;
  std::int64_t steps_ = 0;
  int slipped_ = 0;
  double* firstSlip_ = nullptr;
  // The quiet phase (quiet_phase.hpp): steps before quietUntil_ are known in closed form,
  // their slider-force sums included.
  std::int64_t quietUntil_ = 0;
  // The active set (Verlet, Motion::skipIdle; src/sbm/active_set.hpp): each row is cut into tiles of
  // kTile columns. The springs a tile owns (its horizontal springs and those to the row above,
  // "pieces") are kept from the step they were evaluated at (pieceStep_) while no block of the
  // tile, of the tile to its right or of the two tiles above moved since (mobileStep_: the last
  // step a tile held a slipping block). Only tiles whose pieces are stale are evaluated; the
  // forces are assembled from the pieces in the kernel's order, so the results are the full
  // sweep's bit for bit. A tile whose blocks provably stay stuck is held (holdFrom_, below): only
  // its slider forces and reactions are written. Most tiles stale: back to the full sweep,
  // checked every few steps.
  int tiles_ = 0;
  bool activeMode_ = false;
  std::int64_t activeSetSteps_ = 0, nextModeCheck_ = 0;
  int staleTiles_ = 0;  // tiles evaluated in the last active step
  // Row r's pieces start at index r (N_b + 1) + 1 of piece*_: index -1 of every row is its own.
  std::vector<double> pieceHx_, pieceHy_, pieceVx_, pieceVy_, pieceDx_, pieceDy_, pieceAx_, pieceAy_;
  std::vector<std::int64_t> pieceStep_, mobileStep_;
  // Held tiles: all stuck at step holdFrom_ and proven to hold until holdUntil_ (exclusive) while
  // nothing around them moves; heldRow_ marks the current row's tiles held this step.
  std::vector<std::int64_t> holdFrom_, holdUntil_;
  std::vector<std::uint8_t> heldRow_;
  std::vector<std::int64_t> movedAround_, columnMoved_;  // row work space of lastMovedAround
  std::int64_t heldTileSteps_ = 0;
  // State at t_n, stage evaluation point, RK accumulators (sum of weighted stage velocities and
  // accelerations); mobile_ is 1.0 for a slipping block, 0.0 for a stuck one.
  std::vector<double> ux_, uy_, vx_, vy_;
  std::vector<double> sx_, sy_, svx_, svy_;
  std::vector<double> accUx_, accUy_, accVx_, accVy_;
  std::vector<double> mobile_;
  std::vector<double> frictionX_, frictionY_;  // friction force of the step [N]
  // State laws only (their states theta_i are law_.state): each block's strength at its state of
  // the last step it was stepped [N], and its displacement at the start of the step that ended
  // (the slip of that step is the increment since).
  std::vector<double> strength_, startX_, startY_;
  std::vector<std::uint8_t> state_;  // RK4's stick states (Verlet's are mobile_)
  std::vector<std::uint8_t> everSlipped_;
  // Row work space: forces on the current row, carried forces for the next row, spring forces,
  // the row's slider forces; Verlet's row of spring pieces (8 arrays of N_b + 1, RowPieces).
  std::vector<double> fx_, fy_, carryX_, carryY_, nextX_, nextY_, springX_, springY_, sliderRowX_, sliderRowY_;
  std::vector<double> rowPieces_;
};

}  // namespace gradfric::sbm
