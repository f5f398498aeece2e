#pragma once
/// @file MultiSectionCatenary.hpp
/// Multi-section elastic catenary from an anchor on a frictionless seabed: the sections (listed from the
/// anchor) keep their own weights, so a buoyancy section arches up as in a lazy or steep wave, which the
/// one-equivalent-section catenary cannot show. Unknowns: H and u, where u >= 0 is the grounded length
/// (fraction of L, vertical force 0 at the touchdown) and u < 0 the anchor's vertical force
/// (-u times the line's total |weight|). Per piece of length l, weight w, axial stiffness EA, from the
/// tension components (H, V0) to (H, V0 + w l) (Irvine 1981, eq. 2.16-2.17 per segment):
///   x = (H / w) (asinh(V1 / H) - asinh(V0 / H)) + H l / EA
///   z = (H / w) (sqrt(1 + (V1 / H)^2) - sqrt(1 + (V0 / H)^2)) + (V0 l + w l^2 / 2) / EA
/// (a straight piece when w = 0); the grounded part lies along the seabed stretched by H.
///
/// Used for the starting shape of a line with buoyant sections (initialLineShape, docs/theory.md 4.5).

#include <utility>
#include <vector>

#include "tangle/catenary/ElasticCatenary.hpp"

namespace tangle::catenary {

struct MultiSectionCatenary {
  /// The line of `sections` (from the anchor, or from end A when nothing can ground: `canGround` false);
  /// its length and weight scale follow from them.
  explicit MultiSectionCatenary(std::vector<CatenarySection> lineSections, bool groundable = true);

  std::vector<CatenarySection> sections;  ///< from the anchor (or end A when nothing can ground)
  double length = 0.0;                    ///< [m]
  double weightScale = 0.0;               ///< sum |w_i| L_i [N]
  double horizontal = 0.0;                ///< H [N]
  double grounded = 0.0;                  ///< grounded length [m]
  double anchorVertical = 0.0;            ///< vertical force at the anchor when nothing is grounded [N]
  bool canGround = true;                  ///< false: both ends above the seabed, u is -V_A / weightScale

  /// Sets H = exp(logH) [N] and the second unknown u [-] (see above).
  void setUnknowns(double logH, double u);
  /// (x, z) of the point at unstretched arc length s from the anchor [m].
  std::pair<double, double> at(double s) const;
  /// Whether every section with a grounded part is heavy (a buoyant one cannot rest on the seabed).
  bool groundedHeavy() const;
  /// Vertical tension at the far end [N]: the anchor's (0 when grounded) plus the suspended weight.
  double farEndVertical() const;
  /// Solves for the far end at horizontal distance `span` and height `height` [m] from (H, u) guesses (and
  /// the best point of a 41 x 41 grid) by damped Newton with a finite-difference Jacobian. @return whether
  /// it converged (end within 1e-9 L) with every grounded section heavy.
  bool solve(double span, double height, double guessH, double guessU);
};

}  // namespace tangle::catenary
