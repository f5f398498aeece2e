#pragma once
/// @file LineType.hpp
/// Properties of one kind of line cross-section (OrcaFlex "line type"): chain, wire, riser joint...

#include <string>

namespace tangle::section {

/// Cross-section properties of a line, per unit length where it applies.
/// A line type with bendingStiffness == 0 is a cable (chain, wire): it is meshed with bar elements
/// (3 DOF per node); otherwise with co-rotational beams (6 DOF per node).
struct LineType {
  std::string name;                 ///< identifier used by line sections
  double outerDiameter = 0.0;       ///< hydrodynamic diameter for drag and added mass [m]
  double buoyancyDiameter = 0.0;    ///< diameter of the displaced volume per length [m] (default: outerDiameter)
  double contactDiameter = 0.0;     ///< diameter used for line-to-line and seabed contact [m] (default: outerDiameter)
  double massPerLength = 0.0;       ///< structural mass per unit length, in air [kg/m]
  double axialStiffness = 0.0;      ///< EA [N]
  double bendingStiffness = 0.0;    ///< EI about both transverse axes [N m^2]; 0 for chain/wire
  double torsionalStiffness = 0.0;  ///< GJ [N m^2]; defaults to EI / 1.3 for beams when not given
  double dragNormal = 1.2;          ///< normal drag coefficient Cdn [-] (on outerDiameter)
  double dragAxial = 0.008;         ///< axial drag coefficient Cda [-] (on outerDiameter, per unit projected area pi D)
  double addedMassNormal = 1.0;     ///< normal added-mass coefficient Can [-]
  double addedMassAxial = 0.0;      ///< axial added-mass coefficient Caa [-]
  double axialDamping = 0.0;        ///< structural axial damping coefficient c [N s] (force = c * strain rate)
  /// Minimum breaking load, MBL [N] (line_types[].minimum_breaking_load); 0: not given. The run warns where
  /// the effective tension exceeds it and reports the largest tension over MBL of each line.
  double minimumBreakingLoad = 0.0;
  /// Cables only: fraction of EA kept while an element is shorter than its unstretched length [-]. Chain
  /// and wire rope carry no compression (they buckle at once); the small default keeps the tangent regular.
  /// 1 makes the bar a linear spring in compression too (e.g. a stiff link of a verification model).
  double compressionFactor = 1e-6;

  /// True when the type carries bending (and torsion): meshed with beams.
  bool isBeam() const { return bendingStiffness > 0.0; }
  /// Displaced volume per unit length [m^2] = pi/4 D_b^2.
  double displacedAreaPerLength() const { return 0.7853981633974483 * buoyancyDiameter * buoyancyDiameter; }
  /// Effective (submerged) weight per unit length [N/m] in a fluid of density rho [kg/m^3], gravity g [m/s^2].
  double submergedWeight(double rho, double g) const {
    return (massPerLength - rho * displacedAreaPerLength()) * g;
  }
};

}  // namespace tangle::section
