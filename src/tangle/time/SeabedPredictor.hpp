#pragma once
/// @file SeabedPredictor.hpp
/// The seabed's share of the step predictor of GeneralizedAlpha (issue 48, theory manual 8.2).
///
/// The constant-acceleration predictor dq = dt v_n + dt^2 a_n / 2 assumes that the force on every node stays
/// what it was at t_n. On the seabed that is far from true: the normal spring (1e5 N/m per metre of line is
/// typical) is as stiff as a node's inertia over a step (m / (beta dt^2)), and a node landing, lifting off or
/// bouncing on it changes its reaction within the step. Measured on the mooring example (200 bars,
/// undamped seabed): the predictor missed the touchdown nodes by 1-11 mm at dt 0.05 s (1e4 N out of balance
/// against an allowance of 63 N) while every other node was within 0.2 mm.
///
/// This class corrects the predicted increment of each cable node, and of each beam node whose bending holds
/// it far less than the seabed does (a flexible's; a steel riser's bending is of the order of the seabed's,
/// or stiffer: movableNodes in the .cpp), on, or predicted onto, the seabed, where the step does not resolve
/// the node's oscillation on the seabed spring (omega dt >= 1, omega^2 = k L / m), along the seabed's normal
/// n by the scalar e that balances the node's own inertia against the change of its seabed reaction (spring,
/// dashpot, C1 onset; seabed::Seabed::reaction, the law the assembly uses):
///
///   (1 - alpha_m) m e / (beta dt^2) - (1 - alpha_f) [N(x_p + e n, v_p + gamma e n / (beta dt)) - N(x_n,
///   v_n)] = 0,
///
/// where x_p, v_p are the predicted position and velocity, N the normal reaction [N] and m the node's
/// mass along n (structural and added: M n . n with the mass of the last evaluation). This is the node's
/// row of the generalized-alpha residual, linear in everything but the seabed, under the predictor's own
/// assumption that the rest of the force is unchanged over the step: for a node whose reaction does not
/// change, e = 0 and the predictor is the constant-acceleration one. The left side increases strictly
/// with e (the reaction falls as the node rises or moves up faster), so the root is unique; it is found by
/// Newton's method safeguarded by bisection. The neighbours' coupling (tension over length, ~2e4 N/m here
/// against ~1e6 N/m of inertia and seabed) is left to the Newton iterations that follow; the prediction
/// only moves where the iterations start, never what they converge to (the residual test is unchanged).
/// Measured (same example, dt 0.05 s): the touchdown nodes' predictor error falls to 0.1-0.6 mm.

#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/State.hpp"
#include "tangle/seabed/Seabed.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::time {

/// The generalized-alpha coefficients the seabed predictor needs (GeneralizedAlpha's AlphaParameters).
struct PredictorCoefficients {
  double beta = 0.25;          ///< Newmark beta [-]
  double gamma = 0.5;          ///< Newmark gamma [-]
  double inertiaWeight = 1.0;  ///< 1 - alpha_m: weight of a_{n+1} in the residual [-]
  double forceWeight = 1.0;    ///< 1 - alpha_f: weight of F_{n+1} in the residual [-]
};

class SeabedPredictor {
 public:
  /// @param assembler the model's assembler (its model's seabed, node radii, tributary lengths and mass)
  explicit SeabedPredictor(solver::Assembler& assembler);

  /// Corrects dq (increment over the step of every full DOF [m], as GeneralizedAlpha's predictor set it
  /// from `start`) at the nodes it may move (cable nodes and soft beams' nodes free in all three
  /// translations) that touch the seabed at the start or at the predicted position. `start` holds x_n, v_n,
  /// a_n; the force of the last evaluation must be that at `start` (its added mass is used). @param dt step
  /// [s]. @param allowed each node's allowed out-of-balance force [N] (the Newton iteration's convergence
  /// test): a node whose reaction changes by less than a tenth of it is left as predicted. @return the number
  /// of nodes corrected.
  int correct(const model::State& start, const PredictorCoefficients& coefficients, double dt,
              const std::vector<double>& allowed, VecX& dq);
  /// Whether a step of dt [s] resolves the oscillation on the seabed spring of every node it may move
  /// (omega dt < 1, omega^2 = k L / m; true when there is none), with the masses of `start` (the
  /// same ones correct() uses: call it first, for the same `start`).
  bool resolves(const model::State& start, double dt);

 private:
  /// Sets the mass along the seabed normal of every node it may move at `start` and the
  /// largest k L / m among them.
  void updateMass(const model::State& start);
  /// Steps the mass along the normal is kept for.
  static constexpr int kMassAge = 100;

  solver::Assembler* m_assembler;
  seabed::Seabed m_bed;
  std::vector<char> m_movable;  // per node: the predictor may move it (cable or soft beam node, free)
  std::vector<int> m_nodes;    // this step's nodes on or onto the seabed
  std::vector<Vec3> m_normal;  // their seabed normals [-]
  // The mass along the normal: the normal under each node when it was computed [-], M n [kg] and the
  // steps it is kept for.
  std::vector<Vec3> m_cachedNormal;
  VecX m_direction, m_massAlong;
  int m_massAge = 0;
  double m_largestOmegaSquared = 0.0;  // the largest k L / m of those nodes [1/s^2]
};

}  // namespace tangle::time
