#pragma once
/// @file ElasticCatenary.hpp
/// Analytic elastic catenary of a single uniform line segment, used for the initial shape of the
/// finite-element static solve and as a verification reference: closed forms in their own module (below
/// the model, which builds its start shapes from them), not a solver of the model.
///
/// Conventions: the line is described in the vertical plane through its two ends; x is the
/// horizontal distance from end A (the anchor), z the height above end A (z up); s is the
/// unstretched arc length from end A; tensions are effective tensions (the weight per length w is
/// the submerged weight). The seabed, when present, is frictionless (Jonkman 2007, CB = 0).
///
/// References:
///  - J. Jonkman (2007), "Dynamics modeling and loads analysis of an offshore floating wind
///    turbine", NREL/TP-500-41958, quasi-static mooring line model: the equations of the fully
///    suspended line and of a line with a seabed portion (used here with CB = 0). Equation
///    numbers are not quoted; docs/theory.md (section 4) writes the equations out.
///  - H. M. Irvine (1981), "Cable Structures", MIT Press (inextensible and elastic catenary).
///  - A. H. Peyrot, A. M. Goulois (1979), "Analysis of cable structures", Computers & Structures
///    10, 805-813 (initial guess of the Newton iteration).
/// See docs/theory.md (section 4) for the equations.

#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::catenary {

/// Controls of the Newton iteration on (H, V).
struct CatenaryOptions {
  int maxIterations = 100;   ///< Newton iterations before tangle::ConvergenceError is thrown [-]
  double tolerance = 1e-13;  ///< converged when |residual| <= tolerance * max(L, X, |Z|) in x and z [-]
};

/// Which closed form describes the solved line.
enum class CatenaryRegime {
  /// Part of the line (groundedLength > 0, possibly all of it) rests on the frictionless seabed
  /// and the rest hangs as a catenary with a horizontal tangent at touchdown (Jonkman 2007,
  /// seabed-portion equations with CB = 0). Also covers a line stretched straight along the
  /// seabed (Z = 0, X > L).
  Grounded,
  /// The whole line is off the seabed: a catenary between two points (Jonkman 2007, fully suspended
  /// equations).
  Suspended,
  /// H = 0: the line hangs vertically below end B and the rest lies slack on the seabed, because
  /// it is too long to be tensioned (X <= L - Ls(Z)). The layout of a slack grounded part is
  /// indeterminate without friction: it is placed straight from end A to below end B, shortened
  /// to fit (a starting shape, not a physical one).
  SlackGrounded,
  /// X = 0 and H = 0: the line is vertical, either hanging taut between the ends or folded into a
  /// U between two ends on the same vertical (suspended two-point case only).
  Vertical,
};

/// Position in the vertical plane of the line: horizontal distance from end A and height above it.
struct CatenaryPoint {
  double x = 0.0;  ///< horizontal distance from end A towards end B [m]
  double z = 0.0;  ///< height above end A [m]
};

/// Single uniform line segment between end A (s = 0) and end B (s = L), end B at horizontal
/// distance `span` and height `height` from end A.
struct CatenaryInput {
  double span = 0.0;    ///< horizontal distance X from end A to end B [m], >= 0
  double height = 0.0;  ///< height Z of end B above end A [m] (>= 0 when end A is an anchor on the seabed)
  double length = 0.0;  ///< unstretched length L [m], > 0
  double weight = 0.0;  ///< submerged weight per unstretched length w [N/m], > 0
  double axialStiffness = 0.0;  ///< EA [N], > 0; +infinity for an inextensible line
};

/// Solution of the elastic catenary: end forces, touchdown, and the shape as a function of the
/// unstretched arc length. Produced by solveAnchoredCatenary() / solveSuspendedCatenary().
struct CatenarySolution {
  CatenaryInput input;                                ///< the problem that was solved
  CatenaryRegime regime = CatenaryRegime::Suspended;  ///< closed form used for the shape
  double horizontalTension = 0.0;                     ///< H, constant along the suspended part [N]
  double verticalTension = 0.0;  ///< V, vertical tension component at end B (fairlead) [N]
  double fairleadTension = 0.0;  ///< effective tension at end B, sqrt(H^2 + V^2) [N]
  /// Effective tension at end A [N]: H when part of the line is grounded (frictionless seabed,
  /// Jonkman 2007 with CB = 0), sqrt(H^2 + (V - wL)^2) when fully suspended.
  double anchorTension = 0.0;
  double groundedLength = 0.0;     ///< unstretched length Lb resting on the seabed [m] (0 if fully suspended)
  double touchdownDistance = 0.0;  ///< horizontal distance of the touchdown point from end A [m] (0 if none)
  int iterations = 0;              ///< Newton iterations used (0 for closed-form regimes) [-]

  /// Stretched position of the material point at unstretched arc length s [m] from end A,
  /// 0 <= s <= L (Jonkman 2007, line-profile equations of the suspended and grounded cases; their
  /// H -> 0 limit for the SlackGrounded and Vertical regimes). Throws tangle::Error for s outside
  /// [0, L].
  CatenaryPoint position(double s) const;
  /// Effective tension [N] at unstretched arc length s [m] from end A, 0 <= s <= L:
  /// sqrt(H^2 + (V - w (L - s))^2) on the suspended part, H on the grounded part.
  double tension(double s) const;
};

/// Elastic catenary of a line from an anchor on a flat frictionless seabed (end A, s = 0) to a
/// fairlead (end B) at horizontal distance X and height Z >= 0 above the anchor. Covers the line
/// with a grounded portion, fully suspended (anchor uplift, V >= wL), stretched straight along the
/// seabed (Z = 0), slack (X <= L - Ls(Z), H = 0) and vertical (X = 0).
/// Solves the Jonkman (2007) fully suspended or seabed-portion (CB = 0) equations for (H, V) by
/// Newton's method with the analytic Jacobian, from the Peyrot & Goulois (1979) initial guess.
/// Throws tangle::Error on invalid input or when no solution exists (an inextensible line not
/// longer than the chord), tangle::ConvergenceError (with the inputs and last iterate) when Newton
/// does not converge within options.maxIterations. With finite EA a solution always exists.
CatenarySolution solveAnchoredCatenary(const CatenaryInput& input, const CatenaryOptions& options = {});

/// Elastic catenary hanging freely between two points with no seabed: end B at horizontal distance
/// X and height Z (any sign) from end A. Solves the Jonkman (2007) fully suspended equations for
/// (H, V) by Newton's method (regime Suspended); X = 0 is solved in closed form (regime Vertical).
/// The lowest point of the line is at unstretched arc length L - V/w from end A when that lies in
/// [0, L]. Errors as for solveAnchoredCatenary().
CatenarySolution solveSuspendedCatenary(const CatenaryInput& input, const CatenaryOptions& options = {});

/// One uniform section of a multi-section line, listed from end A to end B.
struct CatenarySection {
  double length = 0.0;          ///< unstretched length [m], > 0
  double weight = 0.0;          ///< submerged weight per unstretched length [N/m]; <= 0 for buoyant sections
  double axialStiffness = 0.0;  ///< EA [N], finite and > 0
};

/// How initialLineShape() built the shape.
enum class InitialShapeKind {
  Taut,       ///< chord >= unstretched length: straight line, each section uniformly stretched
  Anchored,   ///< one end on the seabed: solveAnchoredCatenary() on the equivalent single segment
  Suspended,  ///< both ends above the seabed: solveSuspendedCatenary() on the equivalent segment
              ///< (points below the seabed lifted onto it)
  Straight,   ///< total submerged weight <= 0 (buoyant line) and slack: straight chord, uniformly shortened
  Fallback,   ///< the catenary did not converge: straight chord, uniformly shortened (caller should warn)
};

/// Starting shape of a line for the finite-element static solve.
struct InitialShape {
  std::vector<Vec3> positions;  ///< positions at the requested arc lengths [m] (global frame, z up)
  InitialShapeKind kind = InitialShapeKind::Straight;  ///< how the shape was built
  double horizontalTension = 0.0;  ///< H of the equivalent catenary, or the tension of a taut line [N]
};

/// Initial shape of a multi-section line from end A to end B over a flat seabed at z = -seabedDepth.
/// The sections are replaced by one equivalent segment: total length, length-weighted mean
/// submerged weight, series axial stiffness L / sum(L_i / EA_i). Then:
///  - chord >= L: straight line, stretched with the uniform tension T = (chord - L) / sum(L_i / EA_i);
///  - mean weight <= 0 (buoyant overall): straight chord, uniformly shortened (documented shortcut);
///  - an end on the seabed (z <= -depth + 1e-6 max(1, L)): anchored catenary from that end; when
///    the line is slack (regime SlackGrounded) its grounded part is laid on the seabed as a
///    strain-free circular arc of its own length from the anchor to below the other end (bulging
///    to the left of the anchor-to-end direction; a full circle when that end is straight above);
///  - both ends above the seabed: two-point suspended catenary.
/// End points (arc lengths within 1e-12 L of 0 or L) are returned exactly as given; other points
/// below the seabed are lifted onto it.
/// Never returns NaN: a catenary that fails to converge falls back to kind Fallback.
/// @param arcLengths unstretched arc lengths from end A [m], each in [0, L] (tangle::Error otherwise)
/// Throws tangle::Error on invalid sections (none, length <= 0, EA <= 0 or not finite, NaN weight).
InitialShape initialLineShape(const Vec3& endA, const Vec3& endB,
                              const std::vector<CatenarySection>& sections, double seabedDepth,
                              const std::vector<double>& arcLengths, const CatenaryOptions& options = {});

}  // namespace tangle::catenary
