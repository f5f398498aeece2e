#pragma once
/// @file CoupledRun.hpp
/// A dynamic analysis driven step by step by a host program (co-simulation), as MoorDyn is driven by
/// OpenFAST, WEC-Sim or a user's own code: the host owns the motion of some points (fairleads on its
/// floating body), gives their positions and velocities at the start of each of its steps, and reads the
/// forces the lines exert on them at the end of the step.
///
/// Contract (MoorDyn v2's, MoorDyn2.h): initialize(x, xd) puts the coupled points at x and finds the
/// static equilibrium there (MoorDyn's initial conditions); step(x, xd, dt) advances the model from time()
/// to time() + dt while each coupled point moves as x + xd (tau - time()) (the host's kinematics at the
/// step start, extrapolated linearly over the step; their acceleration, for the held nodes' inertia, the
/// change of xd over the host's step divided by it, as MoorDyn's for coupled bodies), with the model's own
/// time steps (dynamics.time_step, cut back and regrown by the usual step control) inside the host's step;
/// forces() then gives the force the lines exert on each point at the end of the step [N] (minus the support
/// reactions, with the end nodes' inertia: the host's body feels the lines' pull and the end nodes' weight
/// and inertia, as MoorDyn's). Units: SI (m, m/s, N, s).

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::analysis {

/// A point whose motion the host imposes: either the line ends held there (line name, 0 = end A, 1 = end B),
/// each a held end (anchored, pinned or fixed) without a motion of its own; or the reference point of a
/// pinned free vessel (`vessel`, VesselSpec::pinned: the host moves its translations, its rotations are
/// solved; MoorDyn's CoupledPinned body), with no ends.
struct CoupledPointSpec {
  std::string name;
  std::vector<std::pair<std::string, int>> ends;
  std::string vessel;
};

class CoupledRun {
 public:
  /// @throws InputError when an end is unknown, not held, has its own motion or is in two points
  CoupledRun(model::ModelSpec spec, std::vector<CoupledPointSpec> points);
  ~CoupledRun();
  CoupledRun(const CoupledRun&) = delete;
  CoupledRun& operator=(const CoupledRun&) = delete;

  /// Number of coupled points (3 DOFs each).
  int pointCount() const { return static_cast<int>(m_points.size()); }
  /// Positions of the coupled points as the model gives them (x, y, z per point) [m].
  std::vector<double> modelPositions() const;
  /// Moves the coupled points to x (3 per point) [m] and solves the statics there; xd [m/s] is kept as the
  /// points' velocity until the first step. Throws ConvergenceError when the statics fail, Error when
  /// called twice.
  void initialize(std::span<const double> x, std::span<const double> xd);
  /// Advances by dt [s] > 0 with the coupled points moving from x [m] at velocity xd [m/s]. Throws
  /// ConvergenceError (the model's message: time, node, force) when the model cannot be advanced; the
  /// state is then the last converged one.
  void step(std::span<const double> x, std::span<const double> xd, double dt);
  /// Simulated time [s] (0 after initialize).
  double time() const;
  /// Force the lines exert on each coupled point at the current state (x, y, z per point) [N]; on a pinned
  /// vessel's point, what the vessel exerts on its support: the reaction at its held translations, with its
  /// inertia (the body's net force less its mass times the point's acceleration, MoorDyn's Body::getFnet).
  const std::vector<double>& forces() const { return m_forces; }
  /// Results along every line at the current state (positions, tensions, end forces), formed at the first
  /// call after initialize or a step (a host that reads only the forces does not pay for them). The
  /// reference is valid until the next step.
  const std::vector<solver::LineSnapshot>& lineResults();
  /// The line ends' results at the current state (solver::LineResultDetail::Ends: positions, end forces and
  /// end tensions; nothing inside the lines), formed at the first call after a step: a host's per-step
  /// reading of fairlead tensions. The whole results when they are formed already. Valid until the next
  /// step.
  const std::vector<solver::LineSnapshot>& lineEnds();
  /// Position and velocity of a coupled point at the current time [m], [m/s].
  Vec3 pointPosition(int point) const;
  Vec3 pointVelocity(int point) const;
  /// The analysis (model, state); valid after initialize.
  Simulation& simulation();
  bool initialized() const { return m_simulation != nullptr; }

 private:
  struct HostMotion;
  void refreshResults(bool dynamic);
  /// The host's positions x and velocities xd at t0 [s], dt [s] the step that follows (0 at initialize).
  void setHostMotion(std::span<const double> x, std::span<const double> xd, double t0, double dt);

  model::ModelSpec m_spec;
  std::vector<CoupledPointSpec> m_points;
  std::vector<std::pair<int, int>>
      m_pointOfEnd;                         ///< per coupled point, first and one-past-last index in m_ends
  std::vector<std::pair<int, int>> m_ends;  ///< (line index, end) of every coupled end
  std::vector<int> m_endPoint;              ///< coupled point of each entry of m_ends
  std::vector<int> m_vesselOfPoint;         ///< per coupled point, the pinned vessel it moves (-1: line ends)
  std::shared_ptr<HostMotion> m_motion;
  std::unique_ptr<Simulation> m_simulation;
  std::unique_ptr<time::DynamicAnalysis> m_dynamics;
  std::vector<double> m_forces;
  VecX m_supportForce;                        ///< Simulation::supportForce at the current state [N]
  bool m_dynamicResults = false;              ///< the current state is a dynamic one (results with inertia)
  std::vector<solver::LineSnapshot> m_lines;  ///< lineResults(), when m_linesCurrent
  std::vector<solver::LineSnapshot> m_endResults;  ///< lineEnds(), when m_endsCurrent
  bool m_linesCurrent = false;
  bool m_endsCurrent = false;
};

}  // namespace tangle::analysis
