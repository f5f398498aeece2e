#pragma once
/// @file LineType.hpp
/// Properties of one kind of line cross-section (OrcaFlex "line type"): chain, wire, riser joint...

#include <memory>
#include <string>

#include "tangle/core/PiecewiseLinear.hpp"

namespace tangle::section {

/// A viscoelastic (polyester) rope's axial behaviour beside its static EA (line_types[].viscoelastic;
/// MoorDyn's "EA|EA_d" or "EA|alphaMBL|vbeta" with "BA|BA_d"): element::ViscoelasticAxialLaw.
/// dynamicStiffness 0: none.
struct Viscoelasticity {
  double dynamicStiffness = 0.0;       ///< EA_d0 [N]: the dynamic stiffness at zero mean load, > EA
  double dynamicStiffnessSlope = 0.0;  ///< beta [-]: d EA_d / d T_mean (0: constant)
  double slowDamping = 0.0;            ///< BA [N s]: the dashpot parallel to the static branch
  double dynamicDamping = 0.0;         ///< BA_d [N s]: the dashpot parallel to the dynamic spring
  bool present() const { return dynamicStiffness > 0.0; }
};

/// A SYROPE rope's curves (line_types[].syrope; MoorDyn's "SYROPE:file|alphaMBL|vbeta"):
/// element::SyropeAxialLaw. Its dynamic branch (alpha, beta, BA, BA_d) is in LineType::viscoelastic
/// (dynamicStiffness = alpha).
struct SyropeCurves {
  enum class Form { Linear, Quadratic, Exponential };
  std::shared_ptr<const core::PiecewiseLinear> originalCurve;  ///< the OWC: tension [N] against strain [-]
  Form form = Form::Linear;                                    ///< the working curves' formula
  double k1 = 0.0;                     ///< its first parameter [-] (linear with k1 >= 1: a slope [N])
  double k2 = 0.0;                     ///< its second parameter [-]
  double initialMaxMeanTension = 0.0;  ///< Tmax at the start [N]: its working curve is the statics' law
};

/// Cross-section properties of a line, per unit length where it applies.
/// A line type with bendingStiffness == 0 is a cable (chain, wire): it is meshed with bar elements
/// (3 DOF per node); otherwise with co-rotational beams (6 DOF per node).
struct LineType {
  std::string name;                 ///< identifier used by line sections
  double outerDiameter = 0.0;       ///< hydrodynamic diameter for drag and added mass [m]
  double buoyancyDiameter = 0.0;    ///< diameter of the displaced volume per length [m] (default: outerDiameter)
  double contactDiameter = 0.0;     ///< diameter used for line-to-line and seabed contact [m] (default: outerDiameter)
  double massPerLength = 0.0;       ///< structural mass per unit length, in air, without contents [kg/m]
  /// Bore of a pipe (riser, flowline, hose) [m]: the area A_i = pi/4 D_i^2 that holds the contents and on
  /// which the internal pressure acts (line_types[].internal_diameter); 0 for a line without a bore.
  double internalDiameter = 0.0;
  /// Density of the contents filling the bore [kg/m^3] (lines[].contents, sections[].contents_density). Not
  /// an input of the line type: the model gives each section of a line with contents its own copy.
  double contentsDensity = 0.0;
  /// EA [N]; with a tension-strain curve, the curve's largest slope (the reference of step limits and
  /// round-off: the stiffest the line gets).
  double axialStiffness = 0.0;
  /// Cables only: tension [N] against engineering strain [-] from (0, 0) (line_types[].tension_strain: a
  /// fibre rope's nonlinear stiffness); null: linear, EA.
  std::shared_ptr<const core::PiecewiseLinear> tensionStrain;
  double bendingStiffness = 0.0;    ///< EI about both transverse axes [N m^2]; 0 for chain/wire
  double torsionalStiffness = 0.0;  ///< GJ [N m^2]; defaults to EI / 1.3 for beams when not given
  double dragNormal = 1.2;          ///< normal drag coefficient Cdn [-] (on outerDiameter)
  double dragAxial = 0.008;         ///< axial drag coefficient Cda [-] (on outerDiameter, per unit projected area pi D)
  double addedMassNormal = 1.0;     ///< normal added-mass coefficient Can [-]
  double addedMassAxial = 0.0;      ///< axial added-mass coefficient Caa [-]
  double axialDamping = 0.0;        ///< structural axial damping coefficient c [N s] (force = c * strain rate)
  /// Cables only: a viscoelastic rope's dynamic stiffness and dashpots; the dynamics follows them, the
  /// statics the static EA (axialStiffness: the rope relaxed).
  Viscoelasticity viscoelastic;
  /// Cables only: a SYROPE rope (with `viscoelastic` for its dynamic branch); null: none. tensionStrain then
  /// holds the working curve of its initial Tmax (the statics' law).
  std::shared_ptr<const SyropeCurves> syrope;
  /// Minimum breaking load, MBL [N] (line_types[].minimum_breaking_load); 0: not given. The run warns where
  /// the effective tension exceeds it and reports the largest tension over MBL of each line.
  double minimumBreakingLoad = 0.0;
  /// Axial strain above which the run warns [-] (line_types[].maximum_strain); 0: the default of its kind,
  /// strainWarningLimit().
  double maximumStrain = 0.0;
  /// Cables only: fraction of EA kept while an element is shorter than its unstretched length [-]. Chain
  /// and wire rope carry no compression (they buckle at once); the small default keeps the tangent regular.
  /// 1 makes the bar a linear spring in compression too (e.g. a stiff link of a verification model).
  double compressionFactor = 1e-6;

  /// The strain the run warns above [-]: maximumStrain, or 1 % for a beam (no steel or flexible pipe is
  /// stretched that far in service: a line length mistake) and 5 % for a cable (chain and wire break at a
  /// few percent; fibre ropes stretch more: give theirs).
  double strainWarningLimit() const { return maximumStrain > 0.0 ? maximumStrain : isBeam() ? 0.01 : 0.05; }
  /// True when the type carries bending (and torsion): meshed with beams.
  bool isBeam() const { return bendingStiffness > 0.0; }
  /// Displaced volume per unit length [m^2] = pi/4 D_b^2.
  double displacedAreaPerLength() const { return 0.7853981633974483 * buoyancyDiameter * buoyancyDiameter; }
  /// Area of the bore A_i = pi/4 D_i^2 [m^2].
  double internalArea() const { return 0.7853981633974483 * internalDiameter * internalDiameter; }
  /// Mass of the contents per unit length rho_c A_i [kg/m].
  double contentsMassPerLength() const { return contentsDensity * internalArea(); }
  /// Normal added mass per unit length Ca_n rho pi/4 D^2 [kg/m] in a fluid of density rho [kg/m^3], on the
  /// outer diameter (as Morison's inertia term, hydro/Morison.cpp).
  double normalAddedMassPerLength(double rho) const {
    return addedMassNormal * rho * 0.25 * 3.141592653589793 * outerDiameter * outerDiameter;
  }
  /// Mass per unit length that weighs and moves: the structure's and its contents' [kg/m] (the contents move
  /// with the pipe, axially and transversely: no flow is modelled).
  double totalMassPerLength() const { return massPerLength + contentsMassPerLength(); }
  /// Effective (submerged) weight per unit length [N/m] in a fluid of density rho [kg/m^3], gravity g [m/s^2]:
  /// (m_s + rho_c A_i - rho A_e) g, the weight whose equilibrium is that of the effective tension (Sparks 1984).
  double submergedWeight(double rho, double g) const {
    return (totalMassPerLength() - rho * displacedAreaPerLength()) * g;
  }
};

}  // namespace tangle::section
