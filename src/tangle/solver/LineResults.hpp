#pragma once
/// @file LineResults.hpp
/// Per-node results along each line (what range graphs and result tables show), computed from a state.

#include <string>
#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::solver {

/// Results along one line at one instant.
struct LineSnapshot {
  std::string name;
  std::vector<double> arcLength;     ///< unstretched arc length from end A [m]
  std::vector<Vec3> position;        ///< [m]
  std::vector<double> tension;       ///< effective tension [N] (mean of adjacent elements)
  std::vector<double> bendingMoment; ///< magnitude of the bending moment [N m] (0 for cables)
  std::vector<Vec3> bendingMomentVector;  ///< bending moment vector, global axes [N m]
  std::vector<double> curvature;     ///< [1/m]: M/EI for beams, discrete geometric curvature for cables
  Vec3 endForceA = Vec3::Zero();     ///< force the line exerts on its end-A support, global axes [N]
  Vec3 endForceB = Vec3::Zero();     ///< force the line exerts on its end-B support [N]
  double touchdownArcLength = -1.0;  ///< arc length from end A of the touchdown point [m], -1 if none
  int seabedNodes = 0;               ///< nodes in contact with the seabed
};

/// Computes the snapshot of every line. `fullForce` is the assembled out-of-balance force at `state`
/// without the forces of whatever holds the line ends (then its values at the end nodes are the
/// support reactions: the force the line pulls its support with is minus that).
std::vector<LineSnapshot> computeLineResults(const model::Model& model, const Assembler& assembler,
                                             const model::State& state, const VecX& fullForce);

}  // namespace tangle::solver
