#pragma once
/// @file WakeInterference.hpp
/// Wake interference between lines: for every element of a downstream line, the wake of its upstream
/// line(s) at the element midpoint, found from the positions of both lines at the state assembled
/// (docs/theory.md sec. 12.2).
///
/// Geometry, per downstream element midpoint p and upstream line:
///  - the upstream element whose axis p projects onto (parameter s in [0, 1]), found by walking along the
///    upstream line from the element found last time (a few steps per call once the lines have settled);
///    p beyond either end of the upstream line projects onto that end, and its distance across the wake
///    includes its overshoot along the line, so the wake fades past the end over its own width (C1; a cut
///    at the end switched part of an element's drag on and off);
///  - the incident flow is the steady current at p's depth, its component normal to that upstream element,
///    U_n = U_c - (U_c . t) t, speed U = |U_n| and direction e_x = U_n / U;
///  - with d = p - q (q the projection of p on the upstream axis), x = d . e_x downstream and
///    y = |d - x e_x - (d . t) t| across, both in the plane normal to the upstream element (beyond an end
///    y = |d - x e_x|);
///  - the upstream diameter D and drag coefficient C_d are the means of D and of C_d D over the upstream
///    line within `blendLength` of q (arc length, clipped at the line's ends), not the values of the one
///    element q lies on: where the upstream line changes section (a lazy wave's buoyancy: 0.35 -> 0.9 m)
///    the wake would otherwise jump as q crosses the node, a force step of a third of an element's drag
///    that no time step resolves (the dynamics stopped at steps of 1e-5 s, Newton flipping between the two
///    sides). The mean over 2 D_max of the line is continuous in q and changes nothing within a section;
///  - the deficit and lift rise from zero level with the upstream centre (x = 0) to their full values at its
///    rear surface (x = D / 2) by a smoothstep (wakeAtPoint): cut off at x = 0 they jumped by 0.6 U (Huse,
///    on the axis) as a point passed level with the centre.
/// The downstream element then sees the current U_c - (u / U) U e_x (the deficit reduces the normal flow
/// component; waves and the line's own motion are added as usual) and, for Blevins, the lift
/// 1/2 rho CL D_d U^2 along the transverse direction, projected normal to the downstream element.
/// Several upstream lines: the one with the largest deficit acts (wakes are not superposed).
///
/// The wake comes from the steady current only and follows the upstream line as it is at the assembled
/// state (in dynamics its instantaneous position; no convection delay). The tangent includes the
/// derivative of the lift with respect to the downstream element's position (liftGradient(), used by
/// HydroLoads); the drag's dependence on it through the deficit only when asked for
/// (velocityChangeGradient, AssemblyRequest::wakeDragStiffness), with its dependence on the upstream
/// element's nodes (a coupling block between the lines; the lift's is left out).

#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/hydro/CurrentProfile.hpp"
#include "tangle/hydro/WakeModel.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::hydro {

/// The wake at one downstream element.
struct ElementWake {
  Vec3 velocityChange = Vec3::Zero();  ///< change of the current at the midpoint [m/s]
  Vec3 liftPerLength = Vec3::Zero();   ///< Blevins lift per unit length, normal to the element [N/m]
  double deficit = 0.0;                ///< u / U [-] of the acting wake
  int upstreamLine = -1;               ///< index of the line whose wake acts (-1: none)
  int upstreamElement = -1;            ///< the upstream element the midpoint projects onto
  double upstreamParameter = 0.0;      ///< where along it [-] (0 at its node1)
};

/// Derivatives of ElementWake::velocityChange at a downstream element's midpoint [1/s].
struct WakeGradient {
  Mat3 midpoint = Mat3::Zero();  ///< with respect to the midpoint
  /// With respect to the upstream element's two nodes (-1: none). The wake depends on the midpoint's
  /// position relative to the upstream element, so translating both moves it by -midpoint; split as the
  /// projection's weights (1 - s, s), which leaves out the upstream element's turning.
  int upstreamNode1 = -1, upstreamNode2 = -1;
  Mat3 upstream1 = Mat3::Zero(), upstream2 = Mat3::Zero();
};

class WakeInterference {
 public:
  /// @param model the meshed model (its spec().wakes name the pairs)
  /// @param current the steady current profile
  WakeInterference(const model::Model& model, const CurrentProfile& current);

  bool empty() const { return m_pairs.empty(); }
  /// True when element e belongs to a downstream line.
  bool isDownstream(int element) const { return m_downstream[static_cast<std::size_t>(element)]; }

  /// The wake at every element midpoint for `state` (zero for elements of lines with no upstream line).
  /// @param rho water density [kg/m^3] (for the lift)
  void evaluate(const model::State& state, double rho, std::vector<ElementWake>& out);
  /// Derivative of the lift per length [N/m^2] of downstream element `element` with respect to its
  /// midpoint (central differences, one-sided at the wake's edges; the upstream line held where it is);
  /// zero where no Blevins wake acts. For the tangent: the Blevins lift stiffness is of the order of a
  /// tensioned riser's own lateral stiffness (a fixed-point iteration without it converges slowly).
  Mat3 liftGradient(const model::State& state, int element, double rho);
  /// Derivative of the change of the current at downstream element `element`'s midpoint
  /// (ElementWake::velocityChange, [m/s]) with respect to that midpoint [1/s], of the acting wake (the
  /// largest deficit), by the same differences as liftGradient; zero where no wake acts. For the tangent of
  /// the statics' arc-length continuation (AssemblyRequest::wakeDragStiffness): the drag a line loses as it
  /// closes in behind another is the negative stiffness of the wake-induced collapse (docs/theory.md 12.2).
  WakeGradient velocityChangeGradient(const model::State& state, int element, double rho);

 private:
  struct Pair {
    int upstream = -1;
    int downstream = -1;
    WakeCoefficients coefficients;
    double dragCoefficient = 0.0;  ///< 0: each upstream element's type dragNormal
    double blendLength = 0.0;      ///< half-length of the mean of the upstream D and C_d D: D_max [m]
    std::vector<int> guess;        ///< per downstream element: upstream element found last time
  };
  /// The wake acting at a downstream element's midpoint: of the pairs with the element downstream, the one
  /// with the largest deficit there (evaluate()'s choice; `pair` null where none acts).
  struct ActingWake {
    Pair* pair = nullptr;
    int k = -1;          ///< the element's index within the pair's downstream line
    Vec3 midpoint;       ///< [m]
    Vec3 tangent;        ///< unit chord [-]
    double step = 0.0;   ///< finite-difference step h [m]: 1e-4 of the diameter (the wake varies over ~D)
    ElementWake centre;  ///< the wake at the midpoint
  };
  ActingWake actingWake(const model::State& state, int element, double rho);
  /// Central differences [per m] of `field` of pair's wake at downstream element k's point p with respect
  /// to p, steps of h [m]; one-sided where a step leaves the wake of `centre` (the wake at p), zero where
  /// both do.
  Mat3 difference(const model::State& state, Pair& pair, int k, const Vec3& p, const Vec3& td, double rho,
                  double h, const ElementWake& centre, Vec3 ElementWake::*field);
  /// The wake of pair's upstream line at point p of the pair's downstream element k (tangent td).
  ElementWake wakeAtPoint(const model::State& state, Pair& pair, int k, const Vec3& p, const Vec3& td,
                          double rho) const;
  /// The upstream line's mean diameter [m] and drag coefficient [-] (mean of C_d D over mean D) within
  /// pair.blendLength of arc around parameter s of its element j.
  std::pair<double, double> upstreamSection(const model::State& state, const Pair& pair, int j,
                                            double s) const;

  const model::Model* m_model;
  const CurrentProfile* m_current;
  std::vector<Pair> m_pairs;
  std::vector<bool> m_downstream;
};

}  // namespace tangle::hydro
