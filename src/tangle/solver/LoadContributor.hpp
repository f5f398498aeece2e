#pragma once
/// @file LoadContributor.hpp
/// The interface of every force source that is not a structural element (hydrodynamics, contact, vessels):
/// what an assembly asks of it (AssemblyRequest, AssemblyPart), its loads, and the one trial / commit
/// protocol of its state along the path, in statics and dynamics alike.

#include <limits>
#include <string>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/SystemMatrix.hpp"

namespace tangle::solver {

/// What an assembly call should compute.
struct AssemblyRequest {
  double time = 0.0;        ///< time [s] (environment, prescribed motions)
  double loadFactor = 1.0;  ///< multiplies weight and buoyancy [-] (the statics load incrementation)
  bool dynamic = false;  ///< include velocity-dependent forces (drag with structure velocity, seabed damping
                         ///< and friction)
  bool waves =
      true;  ///< with `dynamic`: include wave kinematics (false in dynamic relaxation, a statics method)
  /// With `dynamic`: dynamic relaxation (a statics method, time::DynamicRelaxation): the seabed friction is
  /// the velocity-regularised law whatever the model's `friction_model` (it damps the relaxation and leaves
  /// the held lengths to the Newton solve that follows, as before the elastic law became the default).
  bool relaxation = false;
  double kf = 1.0;         ///< factor on the stiffness dF/dq in H
  double cf = 0.0;         ///< factor on the damping dF/dv in H
  bool wantMatrix = true;  ///< assemble H
  /// Statics: include the drag's follower stiffness (its dependence on the element directions, Morison.hpp)
  /// in H. It makes H non-symmetric: the caller must solve with a general (LU) factorisation.
  bool dragStiffness = false;
  /// Statics: include the drag's dependence on a downstream element's position through its wake's deficit
  /// (HydroLoads, WakeInterference::velocityChangeGradient) in H. Non-symmetric, as dragStiffness; asked
  /// for by the arc-length continuation past the wake-induced collapse (StaticSolver), where the path's
  /// corrections converge only with it.
  bool wakeDragStiffness = false;
  /// Statics: multiplies the current's velocity (and its wake's) at the lines and their attachments [-]; the
  /// current continuation (StaticSolver) ramps the drag, which goes with its square, from still water.
  /// Vessels' current loads are not scaled. Ignored in dynamics.
  double currentFactor = 1.0;
};

/// The part of the model whose out-of-balance forces change when only some nodes move: a modified Newton
/// iteration that corrects a few nodes (the touchdown zone of a mooring line) re-evaluates this part
/// instead of the whole model (GeneralizedAlpha; theory manual 8.2). Built by Assembler::selectPart.
struct AssemblyPart {
  /// Nodes whose entries of F and M a are recomputed: the moved nodes and every node that shares an
  /// element with one (ascending).
  std::vector<int> nodes;
  /// Every element with a node in `nodes` (ascending, so that each entry sums the same terms in the same
  /// order as a full assembly).
  std::vector<int> elements;
  /// Indices into Model::attachments() of the attachments at a node in `nodes` (ascending).
  std::vector<int> attachments;
  /// Every node of `elements` (ascending): the work space entries the part writes.
  std::vector<int> writtenNodes;
  /// Made with the coupled contributors' nodes allowed (Assembler::selectPart's `coupled`).
  bool coupledAllowed = false;
};

/// Kinds of load contributor (LoadContributor::source).
enum class LoadSource {
  Hydrodynamic,  ///< Morison drag and inertia, wakes (hydro::HydroLoads)
  Contact,       ///< line-to-line contact and its friction (contact::LineContact)
  Vessels,       ///< vessels, their loads and the links to line ends (vessel::VesselSystem)
  Junctions,     ///< the ties of line ends at free points (solver::JunctionTies): supports, as vessels' links
  Other,         ///< anything else
};

/// A source of forces that is not a structural element (hydrodynamics, contact, vessels...).
class LoadContributor {
 public:
  virtual ~LoadContributor() = default;
  /// Adds this contributor's part of F (full-DOF vector, out-of-balance sign convention: external
  /// loads are subtracted) and, when matrix != nullptr, of H.
  virtual void addForces(const model::State& state, const AssemblyRequest& request, VecX& force,
                         SystemMatrix* matrix) = 0;
  /// Adds mf * M_contributor to matrix (if not null) and M_contributor * acceleration to out (if not null).
  virtual void addMass(const model::State& /*state*/, double /*mf*/, SystemMatrix* /*matrix*/,
                       const VecX* /*acceleration*/, VecX* /*out*/) {}
  /// True if a part of the model can be assembled with this contributor: either addPartForces and
  /// addPartMass give its terms of the part (its forces at a node depend only on the elements and
  /// attachments at that node: HydroLoads), or its loads act at a few nodes that it marks in
  /// markLoadedNodes (a vessel and the line ends tied to it; the elements near a contact), and parts that
  /// hold none of them leave it out. A contributor that couples nodes otherwise (wakes) returns false, and
  /// the whole model is assembled each time.
  virtual bool supportsParts() const { return false; }
  /// The second way above: sets mark[node] = 1 for every node this contributor loads or whose state it
  /// reads in this step (called once after each whole assembly that a part follows) and returns true; the
  /// contributor is then left out of parts, which Assembler::selectPart refuses when they hold a marked node
  /// (its loads are zero at the part's nodes and unchanged elsewhere, since no node it reads moved). False
  /// (the default): the contributor's terms come from addPartForces / addPartMass.
  virtual bool markLoadedNodes(std::vector<char>& /*mark*/) const { return false; }
  /// A third way, for a contributor that marks its nodes (markLoadedNodes) and whose loads at them depend on
  /// one another's positions (line contact: the force on one line at a crossing moves with the other line's
  /// nodes): true here, and a part that holds any of its marked nodes may hold them all instead of being
  /// refused (Assembler::selectPart with `coupled`, which adds them), the contributor's whole addForces /
  /// addMass then giving its terms (those landing outside the part are discarded). A part that holds none of
  /// them leaves it out, as for the second way.
  virtual bool coupledInParts() const { return false; }
  /// As addForces, for the elements and attachments of `part` only (Assembler::assemblePart keeps the
  /// entries of part.nodes; what lands elsewhere is discarded); `matrix` (when not null) receives their
  /// entries of H (Assembler::addPartMatrix: a refresh of independent blocks).
  virtual void addPartForces(const model::State& /*state*/, const AssemblyRequest& /*request*/,
                             const AssemblyPart& /*part*/, VecX& /*force*/, SystemMatrix* /*matrix*/) {}
  /// As addMass, for the elements and attachments of `part` only.
  virtual void addPartMass(const model::State& /*state*/, const AssemblyPart& /*part*/, double /*mf*/,
                           SystemMatrix* /*matrix*/, const VecX* /*acceleration*/, VecX* /*out*/) {}
  /// What kind of load this is, for the accounts that split the loads by source (equilibrium audit,
  /// energy account).
  virtual LoadSource source() const { return LoadSource::Other; }

  // ---- Path-dependent state: one trial / commit protocol for statics and dynamics -----------------------
  // (OpenSees' trial / commit / revert.) addForces() reads committed data and computes trial data; only a
  // commit makes the trial data the committed data, so a rejected iterate, increment or step leaves no trace.
  // The solvers call, where the reader can see it:
  //   statics (StaticSolver):  beginStatic(start); per load increment: beginStep(), per Newton iteration
  //     limitIncrement(); when Newton converges updateActiveSet() (iterate again if true), rejectState();
  //     then commitIncrement(state), or beginStatic(last converged state) to revert and retry shorter.
  //     Once the static solution is final (Simulation, after its fallbacks): commitStep(state, 0).
  //   dynamics (DynamicAnalysis / GeneralizedAlpha): per step limitStep(); beginStep(); when Newton
  //     converges updateActiveSet(), rejectStep(before, after) (a rejected step is undone and cut);
  //     commitStep(state, dt) for an accepted step; finish(time) at the end of the run.
  //   dynamic relaxation (a statics method): rejectStep() only; nothing is committed.

  /// A new step (or load increment, or retry of a step) starts: reset per-step active sets.
  virtual void beginStep() {}
  /// Newton has converged with the current active set; return true if the contributor changed it
  /// (e.g. released a contact that carries tension), so the caller must iterate again.
  virtual bool updateActiveSet() { return false; }
  /// Statics: the largest fraction in (0, 1] of the proposed increment `fullIncrement` (full DOFs, from
  /// `state`) that this contributor accepts (e.g. so that no two lines close by more than a fraction of
  /// their radii in one Newton iteration). 1 accepts the whole increment.
  virtual double limitIncrement(const model::State& /*state*/, const VecX& /*fullIncrement*/) { return 1.0; }
  /// True if limitIncrement must also filter the Newton corrections of dynamics (a barrier that no iterate
  /// may jump past); the dynamics then calls it with the correction of the displacements.
  virtual bool limitsDynamicIncrements() const { return false; }
  /// Raises `floor` [N] (per node) to the round-off of this contributor's stiffest springs at the nodes they
  /// act on, 16 eps k |x| as an element's (Assembler::nodeRoundoffFloor): a penalty link 100 times as stiff
  /// as a line's end element leaves 100 times its round-off in the out-of-balance force there.
  virtual void raiseRoundoffFloor(const model::State& /*state*/, std::vector<double>& /*floor*/) const {}
  /// True if raiseRoundoffFloor raises any floor (Assembler::roundoffFloorNegligible then does not apply).
  virtual bool raisesRoundoffFloor() const { return false; }
  /// Statics starts (or restarts, or reverts to its last converged increment) from `state`: the reference
  /// for rejectState until the next commitIncrement (a contributor that tracks crossings compares with it).
  virtual void beginStatic(const model::State& /*state*/) {}
  /// Statics: an empty string if `state` is admissible as a converged equilibrium, otherwise why not
  /// (e.g. two lines have passed through each other). A solver never reports such a state as converged.
  virtual std::string rejectState(const model::State& /*state*/) { return {}; }
  /// Statics: a load increment has converged at `state`; commit path-dependent data (trial -> committed).
  virtual void commitIncrement(const model::State& /*state*/) {}
  /// Dynamics: the largest time step [s] this contributor allows from `state` (e.g. so that an impact is
  /// resolved in enough steps); +inf for no limit. `step` [s] is the longest step that can be taken from
  /// `state`: the answer is only compared with it, so any value >= step says "no limit" (a contributor may
  /// skip what cannot limit a step that long).
  virtual double limitStep(const model::State& /*state*/, double /*step*/) {
    return std::numeric_limits<double>::infinity();
  }
  /// Dynamics: the largest ratio [-] of a time step to the one before it that this contributor allows (the
  /// step controller's default is 2; DynamicAnalysis), asked after limitStep at the same state.
  virtual double maxStepGrowth() const { return 2.0; }
  /// Dynamics and dynamic relaxation: empty if the converged step from `before` to `after` is acceptable,
  /// otherwise why not (e.g. two lines passed through each other): the step is undone and cut.
  virtual std::string rejectStep(const model::State& /*before*/, const model::State& /*after*/) { return {}; }
  /// True if rejectStep can refuse a step: only then do the solvers keep a copy of the state before each step
  /// (a copy of the whole state per step is not free on a large model).
  virtual bool rejectsSteps() const { return false; }
  /// An accepted state: a dynamic step of `dt` [s] > 0, or, with dt = 0, the final static solution (the
  /// start of the dynamics). May change the velocities of `state` (an impulse model's velocity jump).
  virtual void commitStep(model::State& /*state*/, double /*dt*/) {}
  /// The dynamics end at `time` [s] (completed, stopped or interrupted): close what is still open.
  virtual void finish(double /*time*/) {}
};

}  // namespace tangle::solver
