#pragma once
/// @file ForceBalance.hpp
/// Results of the equilibrium audit (analysis/EquilibriumAudit computes them; theory manual 7.8): the
/// forces on each line and free vessel by source and what they leave out of balance.

#include <string>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::solver {

/// The balance of one body (a line or a vessel): the forces on it by source.
struct ForceBalance {
  std::string name;                                ///< line or vessel name
  std::vector<std::pair<std::string, Vec3>> terms;  ///< force on the body from each source, global axes [N]
  Vec3 residual = Vec3::Zero();                    ///< sum of the terms [N] (zero in equilibrium)
  double scale = 1.0;  ///< reference force [N]: the line's submerged weight (Assembler::nodeForceScale), or
                       ///< the largest term of a vessel
  /// Largest relative residual a converged solution can leave [-]: the static solver brings every node's
  /// out-of-balance force below tolerance x Assembler::forceScale (StaticSpec::tolerance), so a body of n
  /// nodes sums to at most n tolerance forceScale / scale. Above it the result is not the physics.
  double tolerance = 0.0;
  double relativeResidual() const { return residual.norm() / scale; }  ///< |residual| / scale [-]
  bool balanced() const { return relativeResidual() <= tolerance; }
};

/// Audit of a static solution.
struct EquilibriumAudit {
  std::vector<ForceBalance> lines;
  std::vector<ForceBalance> vessels;  ///< free vessels only (a held vessel's balance is its reaction)
  std::vector<ForceBalance> points;   ///< free points joining line ends (ModelSpec::points)
  /// Largest relative residual over lines, vessels and points [-].
  double worstRelativeResidual() const;
  /// One message per body out of balance (ForceBalance::balanced; empty when the audit closes).
  std::vector<std::string> warnings() const;
};

}  // namespace tangle::solver
