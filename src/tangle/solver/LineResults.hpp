#pragma once
/// @file LineResults.hpp
/// Per-node results along each line (what range graphs and result tables show), computed from a state.

#include <algorithm>
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
  std::vector<double> tension;       ///< effective tension [N]: mean of the adjacent elements; at the end nodes the end tensions below
  std::vector<double> bendingMoment; ///< magnitude of the bending moment [N m] (0 for cables)
  std::vector<Vec3> bendingMomentVector;  ///< bending moment vector, global axes [N m]
  std::vector<double> curvature;     ///< [1/m]: M/EI for beams, discrete geometric curvature for cables
  std::vector<double> torque;        ///< torsional moment about the line axis [N m] (0 for cables)
  std::vector<Vec3> rotation;        ///< orientation of the node triad as a rotation vector from the global
                                     ///< axes [deg] (zero for cable nodes, which carry no rotation)
  /// End tension: the effective tension at the end point itself [N] (axial: beams' shear excluded), the one
  /// definition used by the terminal, summary.json and end_forces.csv. The element force vectors (tension
  /// along each chord) are taken at the element mid-points and extrapolated linearly in unstretched arc
  /// length to the end node (exact for a uniform catenary, whose force vector is linear in arc length); the
  /// element next to it is used only when no point load sits between the two (same line type, no attachment).
  /// An end element without such a neighbour (a one-element line or end section, an attachment at its inner
  /// node) takes its own distributed weight as the slope: half an element of (submerged) weight beyond its
  /// mid-point (none where it lies on the seabed); its drag and inertia are left out. A cable's end (a bar
  /// carries no compression) whose extrapolation turns against the end element's chord is slack: 0 (a
  /// tension front next to the end, as in a snap, across which the extrapolation does not hold).
  double endTensionA = 0.0;
  double endTensionB = 0.0;
  /// Force the line exerts on whatever is at its end (support, vessel, attached mass), global axes [N],
  /// pointing from the end into the line: the section force of the end elements extrapolated as above,
  /// with the shear of beam lines (e x (M2 - M1) / L per element, LineResults.cpp) as well as the
  /// tension; for bar lines |endTensionForceA| = endTensionA. At a free end with nothing attached exactly 0
  /// (the extrapolation would give the end element's own section force, e.g. an LMRP's weight).
  /// The static results (Simulation::snapshot in statics) replace both end forces and end tensions by the
  /// exact ones, the end element's section force plus the line's own loads lumped on the end node
  /// (analysis::setStaticEndForces), which the equilibrium audit checks.
  Vec3 endTensionForceA = Vec3::Zero();
  Vec3 endTensionForceB = Vec3::Zero();
  /// Force the line exerts on its support at the end node: minus the out-of-balance force there (which is
  /// the support's reaction on the line), global axes [N]; for a hanging line it points down, into the line.
  /// Differs from the end tension by the loads lumped on the end node itself (half an element of weight,
  /// drag, inertia, seabed contact); kept for equilibrium checks and for a coupled host's force.
  Vec3 endForceA = Vec3::Zero();
  Vec3 endForceB = Vec3::Zero();
  /// Arc length from end A of the touchdown point [m], -1 if none. Interpolated between the last grounded
  /// and the first suspended node: the height above the seabed grows quadratically from a tangent
  /// touchdown, so sqrt(height) of the next two suspended nodes is extrapolated linearly to zero (clamped
  /// to the element).
  double touchdownArcLength = -1.0;
  int seabedNodes = 0;               ///< nodes in contact with the seabed
  /// Pipe lines only (model::Line::pipe; empty otherwise): the internal pressure p_i [Pa] at each node
  /// (Model::internalPressure) and the wall tension T_w = T_e + p_i A_i - p_e A_e [N] (Sparks 1984), with
  /// p_e = rho g max(0, -z) the still-water hydrostatic pressure at the node, A_i the bore and A_e the
  /// area the buoyancy displaces (the mean over the node's elements where two line types meet).
  std::vector<double> internalPressure;
  std::vector<double> wallTension;
  /// The line has beam elements: bending moment, torque and node rotations are results of it. A cable
  /// line (bars only) has none (the fields above stay zero): the result tables leave them out.
  bool hasBending = false;
};

/// Section force of element `el` [N]: the force its node-2 side exerts on its node-1 side across a cut,
/// constant along the element: `tension` along the chord and, for a beam (`beam` not null), the shear
/// e x (M2 - M1) / L (LineResults.cpp).
Vec3 elementSectionForce(const model::State& state, const model::LineElement& el, double tension,
                         const element::BeamSectionForces* beam);

/// The pressure part of the wall tension of a section of line type `type` at height `z` [m] with internal
/// pressure `internalPressure` [Pa]: p_i A_i - p_e A_e [N], p_e = rho g max(0, -z) the still-water pressure
/// (`rhoG` = rho g [N/m^3]) on the buoyancy area; T_w = T_e + this (Sparks 1984). One formula for the result
/// tables and fatigue.
inline double wallTensionPressureTerm(const section::LineType& type, double internalPressure, double z,
                                      double rhoG) {
  return internalPressure * type.internalArea() - rhoG * std::max(0.0, -z) * type.displacedAreaPerLength();
}

/// Sets `s.internalPressure` and `s.wallTension` of line `line` from `s.position` and `s.tension` (cleared
/// for a line that is not a pipe). computeLineResults calls it; a caller that changes `s.tension` afterwards
/// (the static end tensions) calls it again.
void setWallTension(const model::Model& model, int line, LineSnapshot& s);

/// What computeLineResults fills in.
enum class LineResultDetail {
  All,            ///< every field of LineSnapshot
  SectionForces,  ///< all but `rotation` (left zero) and the touchdown (-1, 0 nodes): the range graphs'
  Ends,           ///< the line ends' results only: `position`, endForceA/B, endTensionForceA/B, endTensionA/B
                  ///< and `tension` at the two end nodes; every other entry zero (tension inside, moments,
                  ///< curvature, rotation), no touchdown (-1), no wall tension (empty). A coupled host's
                  ///< per-step reading of its fairlead tensions (analysis::CoupledRun::lineEnds).
};

/// Computes the snapshot of every line. `fullForce` is the assembled out-of-balance force at `state`
/// without the forces of whatever holds the line ends (then its values at the end nodes are the
/// support reactions: the force the line pulls its support with is minus that).
std::vector<LineSnapshot> computeLineResults(const model::Model& model, const Assembler& assembler,
                                             const model::State& state, const VecX& fullForce);
/// The same into `out` (one snapshot per line; the vectors keep their capacity, so a caller that computes
/// the results at every step allocates nothing after the first). Without `fullForce` (null) the support
/// reactions endForceA/B are zero (the section results come from the elements alone).
void computeLineResults(const model::Model& model, const Assembler& assembler, const model::State& state,
                        const VecX* fullForce, std::vector<LineSnapshot>& out,
                        LineResultDetail detail = LineResultDetail::All);

}  // namespace tangle::solver
