#pragma once
/// @file Simulation.hpp
/// One analysis of one model: owns the mesh, the assembler and every load source, and runs the static
/// solve and the dynamic run. The CLI and the tests both drive analyses through this class.

#include <memory>
#include <vector>

#include "tangle/analysis/LineFailure.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/contact/StartShapeCrossings.hpp"
#include "tangle/core/ConsoleProgress.hpp"
#include "tangle/hydro/HydroLoads.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/JunctionTies.hpp"
#include "tangle/solver/LineResults.hpp"
#include "tangle/solver/StaticSolver.hpp"
#include "tangle/time/DynamicAnalysis.hpp"
#include "tangle/vessel/HullContact.hpp"
#include "tangle/vessel/VesselSystem.hpp"

namespace tangle::analysis {

/// A model ready to analyse.
class Simulation {
 public:
  /// Meshes the model and sets up loads. Throws InputError for inconsistent input.
  explicit Simulation(model::ModelSpec spec);
  ~Simulation();

  model::Model& model() { return *m_model; }
  solver::Assembler& assembler() { return *m_assembler; }
  hydro::HydroLoads& hydro() { return *m_hydro; }
  /// Line-to-line contact, or nullptr when the model has no contact block.
  contact::LineContact* contact() { return m_contact.get(); }
  /// The vessels, or nullptr when the model has none.
  vessel::VesselSystem* vessels() { return m_vessels.get(); }
  /// The contact with vessels' hulls, or nullptr when no vessel has a hull.
  const vessel::HullContact* hullContact() const { return m_hullContact.get(); }
  /// The lines' failures (lines[].failure), or nullptr when no line has one.
  const LineFailure* lineFailure() const { return m_failure.get(); }
  /// The current state (initial shape, static equilibrium after solveStatics, then the dynamic state).
  model::State& state() { return m_state; }
  /// The program's start shapes that passed through each other and were laid one over the other
  /// (contact::liftCrossedStartShapes) by the first solveStatics, for the run log. That solve lays them only
  /// when the state is still the initial one (a caller that set its own start state keeps it).
  const std::vector<contact::StartShapeLift>& startShapeLifts() const { return m_startShapeLifts; }

  /// Static equilibrium from the initial shape; when the Newton solve fails, from the shape reached by
  /// dynamic relaxation (time::DynamicRelaxation; not for models with line contact or free vessels).
  /// `progress`: a solve that takes more than a few seconds prints its progress and each fallback it tries on
  /// stderr (core::ConsoleProgress).
  solver::StaticResult solveStatics(bool progress = false);
  /// Results along every line at the current state.
  std::vector<solver::LineSnapshot> snapshot(bool dynamic = false);
  /// The assembled out-of-balance force at the current state with the forces of whatever holds the line ends
  /// left out [N], in the model's DOFs: at a held end node it is the support's reaction on the line. Only
  /// the end nodes' entries are meant (elsewhere it may hold only part of the terms:
  /// Assembler::assemblePart).
  VecX supportForce(bool dynamic = false);
  /// The same into `force` (its storage reused: a coupled host's every step).
  void supportForce(bool dynamic, VecX& force);
  /// snapshot() from a supportForce() of the current state, into `out` (capacity kept). In statics the
  /// results are always whole (`detail` All) and the end forces the discrete model's exact ones.
  void lineResults(const VecX& supportForce, bool dynamic, std::vector<solver::LineSnapshot>& out,
                   solver::LineResultDetail detail = solver::LineResultDetail::All);
  /// The same results without the support reactions (endForceA/B are zero): tensions, moments,
  /// curvatures and end tensions come from the elements alone, so no force assembly is needed. For
  /// per-step work such as range graphs, where a full assembly per step would be wasted. Neither are the
  /// node rotations and the touchdown point (left zero and -1: no range graph uses them; docs/performance.md). The reference is to a buffer of this Simulation,
  /// valid until the next call (no allocation per step).
  const std::vector<solver::LineSnapshot>& sectionSnapshot() const;
  /// Runs the dynamic analysis from the current state (the static equilibrium); `observer` gets every
  /// output time, `stepObserver` (optional) every accepted step. `progress` prints a progress line on stderr.
  /// `stop` (optional) is asked before every step; true ends the run as an interruption.
  time::DynamicResult runDynamics(const time::DynamicAnalysis::Observer& observer, bool progress = false,
                                  const time::DynamicAnalysis::StepObserver& stepObserver = {},
                                  const time::DynamicAnalysis::StopRequest& stop = {});

 private:
  /// Refuses a user start shape (lines[].start_shape) that passes through another line (InputError).
  void checkStartShapes() const;
  /// The dynamic-relaxation fallback of solveStatics: on success replaces `result` and m_state.
  bool relaxThenSolve(solver::StaticResult& result);
  /// The first fallback of solveStatics in a current: solves again from `start` with the drag's follower
  /// stiffness in the tangent (StaticSolver::setDragStiffness). On success replaces `result` and m_state.
  bool solveWithDragStiffness(const model::State& start, solver::StaticResult& result);
  /// The mesh-continuation fallback of solveStatics: solves the same model with sections of about a
  /// quarter of the elements, interpolates that equilibrium onto this mesh (positions on a cubic Hermite
  /// curve in unstretched arc length, beam triads by slerp turned onto its tangent) and solves from there.
  /// On success replaces `result` and m_state; on failure m_state is the interpolated shape (where the
  /// relaxation fallback starts).
  bool solveFromCoarserMesh(solver::StaticResult& result);

  std::unique_ptr<model::Model> m_model;
  std::unique_ptr<solver::Assembler> m_assembler;
  std::unique_ptr<hydro::HydroLoads> m_hydro;
  std::unique_ptr<contact::LineContact> m_contact;
  std::unique_ptr<solver::JunctionTies> m_junctions;
  std::unique_ptr<vessel::VesselSystem> m_vessels;
  std::unique_ptr<vessel::HullContact> m_hullContact;
  std::unique_ptr<LineFailure> m_failure;
  model::State m_state;
  std::vector<contact::StartShapeLift> m_startShapeLifts;
  std::vector<Vec3> m_startPositions;  // the initial positions until the first solveStatics (with contact)
  core::ConsoleProgress* m_staticsProgress = nullptr;  // progress lines of the statics under way (solveStatics)
  bool m_coarseFallback = true;  ///< false in the coarse model of solveFromCoarserMesh (no recursion)
  mutable std::vector<solver::LineSnapshot> m_sectionSnapshot;  // sectionSnapshot's buffer
  std::vector<int> m_snapshotEnds;      // the lines' end nodes (ascending; snapshot fills it once)
  solver::AssemblyPart m_snapshotPart;  // and the part assembled for them
  VecX m_supportInertia;                // supportForce's work space: the inertia at the ends [N]
};

}  // namespace tangle::analysis
