#pragma once
/// @file SmoothCentreline.hpp
/// The C1 centreline through a line's nodes on which point-to-point contact is measured.
///
/// Why: the finite-element centreline is a polyline. At a node it has a corner, and the distance from
/// a corner to another line behaves like the distance to a sphere: the normal turns with any sideways
/// motion (a negative lateral stiffness -F/d) and the closest point hops between the two elements at the
/// node. Two beams crossing node on node (the seed paper's case 6.1 with 20 or 60 elements) then make
/// Newton cycle. Point-to-point contact of smooth beams (Wriggers & Zavarise 1997; Meier, Wall & Popp
/// 2017, who use C1 Hermite elements) assumes a unique closest point with a continuous normal.
///
/// What: on element e = (x1, x2) of a line, with neighbouring nodes x0 (before) and x3 (after), the
/// cubic Hermite curve
///     c(s) = h00(s) x1 + h01(s) x2 + h10(s) m1 + h11(s) m2,  s in [0, 1],
/// with the nodal tangents (in units of this element's parameter) of the three-point finite
/// difference on the rest arc lengths L0, L1, L2 of the elements before, at and after:
///     c'(node) / L = L1/(L0+L1) (x1-x0)/L0 + L0/(L0+L1) (x2-x1)/L1         (node 1, m1 = L1 c'/L)
/// and likewise at node 2 (a non-uniform Catmull-Rom spline). The tangent per unit rest arc length is the
/// same seen from both elements at a node, so the centreline is C1. At a line end the tangent is the
/// end element's chord (a single-element line is its straight segment). The curve passes through the
/// nodes and is a linear combination of the four node positions, c(s) = sum_k N_k(s) x_k, so forces go
/// to the nodes through N_k and the tangent stiffness follows from the same weights.
/// Deviation from the polyline: at most about kappa L^2 / 8 for curvature kappa and element length L.
///
/// Which lines: beams (a type with bending stiffness), whose true centreline is smooth. A cable (bar
/// elements) keeps its polyline: it really folds at a node where it is draped over another line (a
/// chain over a wire), and rounding that fold moves the contact off the node onto the two legs,
/// pushing them apart (measured: the horizontal tension of a chain draped over a wire 5.6 % low against
/// the catenary, 0.12 % with the contact at the node); LineContact moves such contacts to the node.

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {

/// A point of the smooth centreline: c(s) = sum_k N_k(s) x_{node_k} (k < 4; unused slots have zero weights).
struct CentrelineStencil {
  std::array<int, 4> node{};               ///< global node indices
  std::array<double, 4> N{}, dN{}, ddN{};  ///< weights [-] and their first and second s-derivatives [-]

  // Inline: the contact search evaluates them millions of times per run (DistributedContact::project).
  Vec3 point(const std::vector<Vec3>& x) const { return combine(N, x); }               ///< c(s) [m]
  Vec3 tangent(const std::vector<Vec3>& x) const { return combine(dN, x); }            ///< dc/ds [m]
  Vec3 secondDerivative(const std::vector<Vec3>& x) const { return combine(ddN, x); }  ///< d2c/ds2 [m]
  /// The same combination of a per-DOF field (velocity [m/s], acceleration [m/s^2]).
  Vec3 value(const model::DofMap& dofs, const VecX& field) const;

 private:
  Vec3 combine(const std::array<double, 4>& w, const std::vector<Vec3>& x) const;
};

/// True if `element` belongs to a line measured on the smooth centreline (a beam), false for a cable;
/// always true with smoothCables (the distributed formulation rounds cables too, DistributedContact.hpp).
bool hasSmoothCentreline(const model::Model& model, int element, bool smoothCables = false);

/// The part of an element's centreline that does not depend on the parameter: its four nodes and the
/// weights of its two nodal tangents (centrelineStencil). A search that evaluates the curve many times
/// keeps one per element (elementCurves): the same numbers, without the model lookups each time (8.5
/// million stencils for 40 steps of two risers side by side, 35 % of the run's instructions).
struct ElementCurve {
  std::array<int, 4> node{};  ///< previous node, the element's two, next node (repeated at a line end)
  bool smooth = false;        ///< C1 cubic (beams; cables with smoothCables), else the chord
  double a0 = 0.0, a1 = -1.0, a2 = 1.0;  ///< tangent at node 1: a0 x0 + a1 x1 + a2 x2 [-]
  double b1 = -1.0, b2 = 1.0, b3 = 0.0;  ///< tangent at node 2: b1 x1 + b2 x2 + b3 x3 [-]
};

/// The curve data of one element (see ElementCurve).
ElementCurve elementCurve(const model::Model& model, int element, bool smoothCables = false);
/// The curve data of every element of the model.
std::vector<ElementCurve> elementCurves(const model::Model& model, bool smoothCables = false);
/// The weights N_k(s) of a piece [-] (centrelineStencil's N).
inline std::array<double, 4> centrelineWeights(const ElementCurve& c, double s) {
  if (!c.smooth) return {0.0, 1.0 - s, s, 0.0};
  // Cubic Hermite basis.
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h01 = -2 * s3 + 3 * s2, h10 = s3 - 2 * s2 + s, h11 = s3 - s2;
  return {h10 * c.a0, h00 + h10 * c.a1 + h11 * c.b1, h01 + h10 * c.a2 + h11 * c.b2, h11 * c.b3};
}

/// Their first s-derivatives dN_k/ds [-] (centrelineStencil's dN).
inline std::array<double, 4> centrelineSlopeWeights(const ElementCurve& c, double s) {
  if (!c.smooth) return {0.0, -1.0, 1.0, 0.0};
  const double s2 = s * s;
  const double d00 = 6 * s2 - 6 * s, d01 = -6 * s2 + 6 * s, d10 = 3 * s2 - 4 * s + 1, d11 = 3 * s2 - 2 * s;
  return {d10 * c.a0, d00 + d10 * c.a1 + d11 * c.b1, d01 + d10 * c.a2 + d11 * c.b2, d11 * c.b3};
}

/// Their second s-derivatives [-] (centrelineStencil's ddN; zero on a chord).
inline std::array<double, 4> centrelineCurvatureWeights(const ElementCurve& c, double s) {
  if (!c.smooth) return {0.0, 0.0, 0.0, 0.0};
  const double e00 = 12 * s - 6, e01 = -12 * s + 6, e10 = 6 * s - 4, e11 = 6 * s - 2;
  return {e10 * c.a0, e00 + e10 * c.a1 + e11 * c.b1, e01 + e10 * c.a2 + e11 * c.b2, e11 * c.b3};
}

/// Their third s-derivatives [-] (constant on the cubic; zero on a chord): the derivative of
/// centrelineCurvatureWeights.
inline std::array<double, 4> centrelineThirdWeights(const ElementCurve& c) {
  if (!c.smooth) return {0.0, 0.0, 0.0, 0.0};
  return {6.0 * c.a0, 12.0 + 6.0 * (c.a1 + c.b1), -12.0 + 6.0 * (c.a2 + c.b2), 6.0 * c.b3};
}

/// A piece in the power basis about its first node x1: c(s) = x1 + q1 s + q2 s^2 + q3 s^3 [m], from the
/// Hermite form of centrelineWeights (h00 = 1 - 3s^2 + 2s^3, h01 = 3s^2 - 2s^3, h10 = s - 2s^2 + s^3,
/// h11 = s^3 - s^2 on the nodes x1, x2 and the node tangents m1 = a0 x0 + a1 x1 + a2 x2,
/// m2 = b1 x1 + b2 x2 + b3 x3; a chord: q1 = x2 - x1, q2 = q3 = 0). The same curve as the weights' up to
/// round-off; for a search that evaluates one piece many times (a Horner evaluation of the point and its
/// derivatives instead of three weight arrays and sums over the four nodes).
struct CentrelinePowerBasis {
  Vec3 q1, q2, q3;  ///< [m]
};
inline CentrelinePowerBasis centrelinePowerBasis(const ElementCurve& c, const std::vector<Vec3>& x) {
  const Vec3& x1 = x[c.node[1]];
  const Vec3& x2 = x[c.node[2]];
  if (!c.smooth) return {x2 - x1, Vec3::Zero(), Vec3::Zero()};
  const Vec3 m1 = c.a0 * x[c.node[0]] + c.a1 * x1 + c.a2 * x2;
  const Vec3 m2 = c.b1 * x1 + c.b2 * x2 + c.b3 * x[c.node[3]];
  const Vec3 rise = x2 - x1;
  return {m1, 3.0 * rise - 2.0 * m1 - m2, m1 + m2 - 2.0 * rise};
}

/// The parameter t in [lo, hi] [-] of the point of a piece (in the power basis about its first node, `b`)
/// nearest a point `offset` [m] given relative to that first node, from the start t0 [-]: projected Newton on
/// V(t) = |offset - c(t)|^2 / 2, held at a bound where V still falls outward, a gradient step where V is not
/// convex, stopped when t moves less than 1e-13 or after 30 iterations. Each iteration is a Horner
/// evaluation of c and its two derivatives. Used by the distributed contact's projections (range [0, 1]) and
/// by centrelineMinimum's valley floor (the piece's own parameter range).
inline double nearestOnPiece(const CentrelinePowerBasis& b, const Vec3& offset, double t0, double lo,
                             double hi) {
  double t = std::clamp(t0, lo, hi);
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Vec3 c2 = 2.0 * b.q2 + (6.0 * t) * b.q3;
    const Vec3 c1 = b.q1 + t * (2.0 * b.q2 + (3.0 * t) * b.q3);
    const Vec3 u = offset - t * (b.q1 + t * (b.q2 + t * b.q3));
    const double g = -u.dot(c1), h = c1.squaredNorm() - u.dot(c2);
    if ((t <= lo && g > 0.0) || (t >= hi && g < 0.0)) break;  // held at a bound
    const double step = h > 0.0 ? -g / h : -g / std::max(c1.squaredNorm(), 1e-300);
    const double next = std::clamp(t + step, lo, hi);
    const double moved = std::abs(next - t);
    t = next;
    if (moved < 1e-13) break;
  }
  return t;
}

/// sum_k w_k x_k over a piece's four nodes [m], in CentrelineStencil's order of operations (the same bits).
inline Vec3 combineNodes(const std::array<int, 4>& node, const std::array<double, 4>& w,
                         const std::vector<Vec3>& x) {
  Vec3 p = Vec3::Zero();
  for (int k = 0; k < 4; ++k) p += w[k] * x[node[k]];
  return p;
}

inline Vec3 CentrelineStencil::combine(const std::array<double, 4>& w, const std::vector<Vec3>& x) const {
  return combineNodes(node, w, x);
}

/// Stencil at parameter s of an element given by its curve data (inline: see CentrelineStencil::point).
inline CentrelineStencil centrelineStencil(const ElementCurve& c, double s) {
  CentrelineStencil st;
  st.node = c.node;
  st.N = centrelineWeights(c, s);
  st.dN = centrelineSlopeWeights(c, s);
  st.ddN = centrelineCurvatureWeights(c, s);
  return st;
}

/// The point c(s) of a piece [m]: centrelineStencil(c, s).point(x) without the derivatives' weights.
inline Vec3 centrelinePoint(const ElementCurve& c, double s, const std::vector<Vec3>& x) {
  return combineNodes(c.node, centrelineWeights(c, s), x);
}

/// Largest distance [m] of an element's piece of the centreline, s in [0, 1], from its chord at `position`:
/// the cubic is the chord's linear interpolation plus h10(s) (m1 - d) + h11(s) (m2 - d), d = x2 - x1 and
/// m1, m2 the nodal tangents, and |h10|, |h11| <= 4/27 on [0, 1], so the bound is 4/27 (|m1 - d| + |m2 - d|)
/// (0 for a chord). A cheap test that two pieces cannot touch: their chords farther apart than the radii
/// plus both bounds.
double chordDeviationBound(const ElementCurve& curve, const std::vector<Vec3>& position);
/// Largest distance [m] of the piece from its chord over its whole search range (centrelineDistance: [0, 1]
/// widened by kParameterOverlap at interior nodes): chordDeviationBound, which holds there too (|h10|, |h11|
/// <= 4/27 on [-0.05, 1.05]), plus the chord's line past its ends, kParameterOverlap |x2 - x1| (0 on a
/// chord, searched on [0, 1]). Two pieces' curves are no closer than their chords less both bounds.
double searchRangeDeviationBound(const ElementCurve& curve, const std::vector<Vec3>& position);
/// Bound of sum_k |N_k(s)| [-] over the piece's search range: a value interpolated on the curve (a velocity)
/// is at most this times the largest of its four nodes' values. h00 + h01 = 1 with both >= 0 there, and
/// |h10|, |h11| <= 4/27: 1 + 4/27 (|a0| + |a1| + |a2| + |b1| + |b2| + |b3|) (1 on a chord).
double centrelineWeightBound(const ElementCurve& curve);

/// Stencil of the smooth centreline (the chord's linear interpolation for a cable) on `element` at parameter
/// s (s may lie a little outside [0, 1]: the cubic is extrapolated).
CentrelineStencil centrelineStencil(const model::Model& model, int element, double s,
                                    bool smoothCables = false);

/// Range of the parameter of an element's piece searched for a closest point: [0, 1], widened by
/// kParameterOverlap at an interior node of a beam, so that a minimum at or near a node is strictly inside
/// the range of at least one of the two elements there (one of them is kept as the local minimum).
inline constexpr double kParameterOverlap = 0.05;

/// Closest points of the smooth centrelines of two elements.
struct CentrelineDistance {
  double s = 0.0, t = 0.0;          ///< parameters on element A and B [-]
  bool sFree = true, tFree = true;  ///< strictly inside the search range (a stationary point in it)
  CentrelineStencil a, b;           ///< stencils at s and t
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();  ///< closest points [m]
  double distance = 0.0;                              ///< |pointA - pointB| [m]
};

/// Minimises |c_A(s) - c_B(t)| over the search ranges of the two elements by a projected Newton method
/// with a backtracking line search on the squared distance, started from (s0, t0) (the closest points
/// of the two chords). holdS (holdT) keeps s = s0 (t = t0): the closest point of B's centreline to a given
/// point of A's (then not free).
/// smoothCables: cables on their C1 centreline too (the distributed formulation).
/// curves: elementCurves(model, smoothCables), if the caller keeps them (the same result, faster).
CentrelineDistance centrelineDistance(const model::Model& model, const std::vector<Vec3>& position,
                                      int elementA, int elementB, double s0, double t0, bool holdS = false,
                                      bool holdT = false, bool smoothCables = false,
                                      const std::vector<ElementCurve>* curves = nullptr);

/// The smallest distance of two pieces over their search ranges, for a caller that needs the least gap (the
/// clearances of the envelope and the clash report) rather than a local minimum near the start:
/// centrelineDistance, except where the pieces are nearly parallel (V's Hessian not positive definite, flat
/// or falling along its valley, where centrelineDistance descends by small scaled steps and ends where its
/// iteration cap stops it): there the minimum along the valley's floor, f(s) = min over t of V(s, t), from
/// samples of s's range refined by Brent's method. No parameter is held; the same arguments as
/// centrelineDistance's otherwise. Not for the contact's forces or step limit: where Brent's method stops
/// within its tolerance moves from one state to the next, and runs that passed stopped (docs/performance.md).
CentrelineDistance centrelineMinimum(const model::Model& model, const std::vector<Vec3>& position,
                                     int elementA, int elementB, double s0, double t0,
                                     bool smoothCables = false,
                                     const std::vector<ElementCurve>* curves = nullptr);

/// The surfaces' distance [m] of a pair of pieces as a clearance measures it: centrelineDistance's `c` where
/// its closest points lie on the pieces' own parts (s and t in [0, 1]), else the distance of the points at s
/// and t clamped there (a pair of points of the two lines: never below the lines' distance; the neighbouring
/// piece measures past the node). The search range runs past interior nodes (kParameterOverlap): there a
/// piece's extrapolated cubic is not the line, and the radius at the clamped parameter not its surface's (at
/// a change of section the clash report read 0.2965 m for a 0.300 m gap, 2026-12-07).
double ownPartsDistance(const CentrelineDistance& c, const ElementCurve& a, const ElementCurve& b,
                        const std::vector<Vec3>& position);

/// The distance between the closest points and the eight slots of the two stencils (A's four, then B's
/// four; a node in both gets both contributions): grad d = weight_k normal per slot.
struct CentrelineSlots {
  double distance = 0.0;           ///< sign * |pA - pB| [m]
  Vec3 normal = Vec3::UnitZ();     ///< sign * (pA - pB) / |pA - pB|
  std::array<int, 8> node{};       ///< global node of each slot
  std::array<double, 8> weight{};  ///< N_k for A's slots, -N_k for B's
  std::array<bool, 8> used{};      ///< false for a slot with N_k, dN_k and ddN_k all zero (no node there)
};
/// @param sign -1 to measure along the reversed direction (lines that passed each other)
CentrelineSlots centrelineSlots(const CentrelineDistance& d, double sign);

/// The distance between the closest points and its exact derivatives with respect to the eight node
/// positions of the two stencils (CentrelineSlots).
struct CentrelineKinematics : CentrelineSlots {
  Eigen::Matrix<double, 24, 1> gradient = Eigen::Matrix<double, 24, 1>::Zero();   ///< d distance / dx [-]
  Eigen::Matrix<double, 24, 24> hessian = Eigen::Matrix<double, 24, 24>::Zero();  ///< [1/m]
};

/// The second-order part of the distance's derivatives in factored form (centrelineKinematics' slots): with
/// the weights w (N_k on A, -N_k on B), the unit normal n and the closest points' distance d,
///     Hess d = (w w^T (x) (I - n n^T) - sum_ab b_a Vinv_ab b_b^T) / d,
/// b_a (a 3-vector per slot) the mixed derivative V_xp of the free parameter a, w_i c_a' + dw_i/dp_a u (c_a'
/// the curve's tangent, signed as in u), and Vinv the inverse of V_pp over the free parameters (none when
/// V_pp is not positive definite: no correction). Assembling a contact's 3 x 3 blocks from it costs 9 (1 +
/// free) multiply-adds each, where the 24 x 24 matrix costs its 576 entries several times over
/// (DistributedContact::addForces).
struct DistanceCurvature {
  int free = 0;                                       ///< free parameters in the correction (0, 1 or 2)
  std::array<std::array<Vec3, 2>, 8> mixed{};         ///< b_a per slot [m]
  Eigen::Matrix2d inverse = Eigen::Matrix2d::Zero();  ///< Vinv [1/m^2]
};
DistanceCurvature distanceCurvature(const std::vector<Vec3>& position, const CentrelineDistance& d,
                                    const std::array<double, 8>& weight);

/// Value-function derivatives (envelope theorem) over the free parameters: with u = c_A(s) - c_B(t) and
/// V = |u|^2 / 2 minimised over the free parameters p,
///     Hess V* = V_xx - V_xp V_pp^-1 V_px,   V_pp = [[cA'.cA' + u.cA'', -cA'.cB'], [., cB'.cB' - u.cB'']],
/// and d = sqrt(2 V*): grad d = w_k n, Hess d = (Hess V* - grad d grad d^T) / d (docs/theory.md 9.3).
/// @param sign -1 to measure along the reversed direction (lines that passed each other)
CentrelineKinematics centrelineKinematics(const std::vector<Vec3>& position, const CentrelineDistance& d,
                                          double sign, bool wantHessian);

}  // namespace tangle::contact
