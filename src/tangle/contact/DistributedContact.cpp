#include "tangle/contact/DistributedContact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tangle/contact/CentrelineBlocks.hpp"
#include "tangle/contact/ContactKinematics.hpp"
#include "tangle/contact/ContinuumImpactMass.hpp"
#include "tangle/contact/ReducedMass.hpp"
#include "tangle/core/BrentMinimum.hpp"
#include "tangle/core/PointArrays.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Automatic stiffness: the point formulation's 0.1 EA / L with L = l_ref (file comment of the header).
constexpr double kAutoStiffnessFactor = 0.1;
/// Gauss points per piece of an interval (pieces between its ends and cuts: contactIntervals).
constexpr int kPoints = 4;
constexpr double kGaussX[kPoints] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                     0.8611363115940526};
constexpr double kGaussW[kPoints] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                     0.3478548451374538};
/// Steps per impact duration (as the point formulation's LineContact::limitStep).
constexpr double kImpactSteps = 40.0;
/// Restitution's smoothing speed v_s as a fraction of omega p0 (restitutionSpeed) [-].
constexpr double kRestitutionSpeedFraction = 0.1;
/// ... widened by this fraction of the sliding speed (finishSamples) [-].
constexpr double kRestitutionSlidingFraction = 0.05;
/// Tolerance on an interval end's parameter [-]. The integrand vanishes with its slope there, so an error
/// delta of the end changes the integral only by O(delta^3), but the Gauss points move with the end: at
/// 1e-7 their forces moved by ~1e-4 N from iterate to iterate at random (a wire folded over another), above
/// the Newton tolerance; the ends are found to round-off instead (bracketed Newton: contactIntervals).
constexpr double kRootTolerance = 1e-15;
/// A bracketed Newton step this short ends the search for an interval end [-] (contactIntervals).
constexpr double kNewtonRootStep = 1e-10;
/// Tolerance on the parameter of a dip's deepest point [-] (contactIntervals): the depth found is then
/// exact to about the centreline's curvature times 1e-18 m.
constexpr double kMinimumTolerance = 1e-9;

/// The root of f between a and b, where f(a) and f(b) have opposite signs, to round-off (the Illinois
/// variant of regula falsi: superlinear, and the bracket always holds the root) [same unit as a, b].
template <typename F>
double signChange(const F& f, double a, double fa, double b, double fb) {
  double x = a;
  int kept = 0;  // which end stayed last time: -1 a, +1 b
  for (int iteration = 0; iteration < 100; ++iteration) {
    double next = (a * fb - b * fa) / (fb - fa);
    if (!(next > std::min(a, b) && next < std::max(a, b))) next = 0.5 * (a + b);
    if (std::abs(next - x) <= kRootTolerance * std::max(1.0, std::abs(x)) && iteration > 0) return next;
    x = next;
    const double fx = f(x);
    if (fx == 0.0) return x;
    if ((fx < 0.0) == (fb < 0.0)) {
      b = x;
      fb = fx;
      if (kept == -1) fa *= 0.5;
      kept = -1;
    } else {
      a = x;
      fa = fx;
      if (kept == 1) fb *= 0.5;
      kept = 1;
    }
  }
  return x;
}
/// Depths of a ridge between two dips, over the shallower dip's, at which its cut has full weight and none
/// (contactIntervals) [-].
constexpr double kRidgeDepths[2] = {0.02, 0.2};
/// Largest closing of a pair in one Newton iteration, as a fraction of the sum of the radii (as statics'
/// point formulation), and the fraction of what is left to the barrier's limit an iterate may close.
constexpr double kClosingFraction = 0.25;
constexpr double kBarrierFraction = 0.8;

/// Curvature [1/m] of a centreline at a stencil: |c' x c''| / |c'|^3 (parametrisation-invariant).
double curvature(const CentrelineStencil& st, const std::vector<Vec3>& x) {
  const Vec3 c1 = st.tangent(x), c2 = st.secondDerivative(x);
  const double speed = c1.norm();
  return speed > 0.0 ? c1.cross(c2).norm() / (speed * speed * speed) : 0.0;
}

/// The length a pair's law is scaled with [m]: the smaller diameter, 2 min(rA, rB), so a thin line's
/// overlap with a thick one is bounded by its own radius. (The sum of the radii let a 2 cm rope sink 3 cm
/// into a 0.5 m bollard, which wrapped it over a longer arc: the capstan's ratio came out 4.4 % above
/// exp(mu pi) with sharp friction; with this scale the taut string on a rigid support of twice its
/// diameter, which stalled at 2.5 N when this was first tried, converges since the committed-slip friction.)
double contactScale(double radiusA, double radiusB) { return 2.0 * std::min(radiusA, radiusB); }

/// The pair of lines of a sample, the lower index first (the key of per-pair data).
std::pair<int, int> linePair(const ContactSample& smp) {
  return {std::min(smp.lineA, smp.lineB), std::max(smp.lineA, smp.lineB)};
}

}  // namespace

DistributedContact::DistributedContact(const model::Model& model, const model::ContactSpec& spec,
                                       const std::vector<double>& radius)
    : m_model(&model),
      m_spec(spec),
      m_radius(radius),
      m_hysteresis(HystereticRestitution::amplitudeFor(spec.restitution)),
      m_curves(elementCurves(model, true)),
      m_profile(model, radius) {
  m_lineAxialStiffness.assign(model.lines().size(), kInf);
  for (const model::LineElement& el : model.elements())
    m_lineAxialStiffness[el.line] = std::min(m_lineAxialStiffness[el.line], el.type->axialStiffness);
  const auto& elements = model.elements();
  const int lines = static_cast<int>(model.lines().size());
  m_pointStiffness.resize(static_cast<std::size_t>(lines) * static_cast<std::size_t>(lines));
  const auto hasElements = [&](int l) { return model.lines()[static_cast<std::size_t>(l)].elementCount > 0; };
  for (int a = 0; a < lines; ++a)
    for (int b = 0; b < lines; ++b)
      m_pointStiffness[static_cast<std::size_t>(a * lines + b)] =
          hasElements(a) && hasElements(b) ? computePointStiffness(a, b) : std::nan("");
  m_nodeMass.resize(static_cast<std::size_t>(model.nodeCount()));
  for (int n = 0; n < model.nodeCount(); ++n) m_nodeMass[static_cast<std::size_t>(n)] = computeNodeMass(n);
  m_bent.assign(elements.size(), kNotBent);
  m_massPerLength.resize(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e)
    m_massPerLength[e] = computeMassPerLength(static_cast<int>(e));
}

double DistributedContact::radiusAt(int element, double t) const { return m_profile.at(element, t); }

std::array<double, 3> DistributedContact::radiusProfile(int element, double t) const {
  return m_profile.profile(element, t);
}

double DistributedContact::bentness(const model::State& state, int element, double radii) const {
  // The curvature of the C1 piece at five points (it is largest at a node of a folded cable; the pieces
  // of the neighbours meet it there with their own second derivative, so both are asked by their patches),
  // kappa R, mapped to [0, 1] by a smoothstep between kappa R = 1/4 (straight on the contact's scale) and
  // 1/2 (a fold or a wrap).
  double largest = 0.0;
  for (int i = 0; i <= 4; ++i)
    largest = std::max(
        largest,
        curvature(centrelineStencil(m_curves[static_cast<std::size_t>(element)], 0.25 * i), state.position) *
            radii);
  const double x = std::clamp((largest - 0.25) / 0.25, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

double DistributedContact::bentnessAt(const model::State& state, int element, double w, double radii) {
  const auto& elements = m_model->elements();
  const model::Line& line = m_model->lines()[elements[element].line];
  const auto bent = [&](int e) {
    if (e < line.firstElement || e >= line.firstElement + line.elementCount) return 0.0;
    double& known = m_bent[static_cast<std::size_t>(e)];
    if (known == kNotBent) {
      known = bentness(state, e, radii);
      m_bentElements.push_back(e);
    }
    return known;
  };
  const double own = bent(element);
  const double atNode1 = std::max(own, bent(element - 1)), atNode2 = std::max(own, bent(element + 1));
  const double t = std::clamp(w, 0.0, 1.0);
  return (1.0 - t) * atNode1 + t * atNode2;
}

double DistributedContact::pointStiffness(int lineA, int lineB) const {
  return m_pointStiffness[static_cast<std::size_t>(lineA) * m_model->lines().size() +
                          static_cast<std::size_t>(lineB)];
}

double DistributedContact::computePointStiffness(int lineA, int lineB) const {
  // Radii of the two lines' first elements (a line's contact diameter is one per section; the first is
  // representative and keeps the stiffness one number per pair of lines).
  const double rA = m_radius[m_model->lines()[lineA].firstElement],
               rB = m_radius[m_model->lines()[lineB].firstElement];
  return m_spec.stiffness > 0.0
             ? m_spec.stiffness
             : kAutoStiffnessFactor * std::min(m_lineAxialStiffness[lineA], m_lineAxialStiffness[lineB]) /
                   (kReferenceLengthFactor * (rA + rB));
}

double DistributedContact::lineStiffness(int lineA, int lineB) const {
  const double rA = m_radius[m_model->lines()[lineA].firstElement],
               rB = m_radius[m_model->lines()[lineB].firstElement];
  return pointStiffness(lineA, lineB) / contactScale(rA, rB);
}

BarrierPenalty DistributedContact::law(int elementA, int elementB) const {
  const auto& el = m_model->elements();
  return BarrierPenalty::forScale(lineStiffness(el[elementA].line, el[elementB].line),
                                  contactScale(m_radius[elementA], m_radius[elementB]));
}

double DistributedContact::computeNodeMass(int node) const {
  const model::DofMap& dofs = m_model->dofs();
  if (dofs.equation(dofs.firstDof(node)) < 0) return kInf;
  return m_model->nodeMass()[node];
}

double DistributedContact::computeMassPerLength(int element) const {
  const model::LineElement& x = m_model->elements()[element];
  if (std::isinf(nodeMass(x.node1)) && std::isinf(nodeMass(x.node2))) return kInf;
  return x.type->totalMassPerLength();
}

double DistributedContact::pairMassPerLength(int elementA, int elementB) const {
  return reducedMass(massPerLength(elementA), massPerLength(elementB));
}

double DistributedContact::restitutionSpeed(int elementA, int elementB) const {
  const auto& elements = m_model->elements();
  const double mass =
      pairMassPerLength(elementA, elementB) * kReferenceLengthFactor *
      (m_radius[static_cast<std::size_t>(elementA)] + m_radius[static_cast<std::size_t>(elementB)]);
  if (!std::isfinite(mass) || !(mass > 0.0)) return 0.0;
  const double stiffness = pointStiffness(elements[static_cast<std::size_t>(elementA)].line,
                                          elements[static_cast<std::size_t>(elementB)].line);
  return kRestitutionSpeedFraction * std::sqrt(stiffness / mass) * law(elementA, elementB).depth;
}

double DistributedContact::slipDistance(const ContactSample& smp) const {
  // The stick spring as stiff as the normal law's linear part: 2 mu f_n / u_s = k_line (the tangential
  // penalty equal to the normal one), and no less than a thousandth of the law's regularisation depth.
  const BarrierPenalty lawAB = law(smp.elementA, smp.elementB);
  return std::max(2.0 * m_spec.frictionCoefficient * smp.lineForce / lawAB.stiffness, 1e-3 * lawAB.depth);
}

double DistributedContact::arcOf(int element, double w) const {
  const model::Line& l = m_model->lines()[m_model->elements()[element].line];
  const int i = element - l.firstElement;
  w = std::clamp(w, 0.0, 1.0);
  return l.arcLength[i] + w * (l.arcLength[i + 1] - l.arcLength[i]);
}

CentrelineDistance DistributedContact::project(const model::State& state, int slave, double xi, int master,
                                               double t0) const {
  // Projected Newton on V(t) = |x - c(t)|^2 / 2 over t in [0, 1] exactly: the master line is then the union
  // of its elements' pieces, and where the projection passes a node from one element to the next both give
  // the node itself with the same weights (with ranges that overlap, the nearer of two slightly different
  // extrapolated cubics would take over a little off the node, and the force would jump between the two
  // stencils by about the overlap times the force: 105 N of 5 kN on a wire folded over another).
  CentrelineDistance r;
  r.s = xi;
  r.sFree = false;
  r.a = centrelineStencil(m_curves[static_cast<std::size_t>(slave)], xi);
  r.pointA = r.a.point(state.position);
  const double t = nearestParameter(state, r.pointA, master, t0);
  r.t = t;
  r.tFree = t > 0.0 && t < 1.0;
  r.b = centrelineStencil(m_curves[static_cast<std::size_t>(master)], t);
  r.pointB = r.b.point(state.position);
  r.distance = (r.pointA - r.pointB).norm();
  return r;
}

double DistributedContact::nearestParameter(const model::State& state, const Vec3& x, int master,
                                            double t0) const {
  // The piece in the power basis (centrelinePowerBasis), made once per call: each Newton iteration is then a
  // Horner evaluation of the point and its two derivatives (30 multiply-adds instead of three weight arrays
  // and three sums over the four nodes: 1.42 G instructions of drilling-riser-drift's run went here, 600 per
  // call). The iterate differs from the weights' by round-off; the stop (a move below 1e-13) is the same.
  const ElementCurve& curve = m_curves[static_cast<std::size_t>(master)];
  // x relative to the piece's first node: the point's offset is then O(element) and not O(coordinates).
  return nearestOnPiece(centrelinePowerBasis(curve, state.position), x - state.position[curve.node[1]], t0,
                        0.0, 1.0);
}

DistributedContact::Projection DistributedContact::projectPoint(const model::State& state, int slave,
                                                                double xi, int master, double t0,
                                                                bool slope) const {
  const ElementCurve& curveA = m_curves[static_cast<std::size_t>(slave)];
  Projection p;
  p.pointA = centrelinePoint(curveA, xi, state.position);
  p.t = nearestParameter(state, p.pointA, master, t0);
  p.pointB = centrelinePoint(m_curves[static_cast<std::size_t>(master)], p.t, state.position);
  p.distance = (p.pointA - p.pointB).norm();
  if (slope) p.tangentA = combineNodes(curveA.node, centrelineSlopeWeights(curveA, xi), state.position);
  return p;
}

double DistributedContact::chordBound(const model::State& state, int element) const {
  double& bound = m_chordBound[static_cast<std::size_t>(element)];
  if (std::isnan(bound))
    bound = chordDeviationBound(m_curves[static_cast<std::size_t>(element)], state.position);
  return bound;
}

bool DistributedContact::contactIntervals(const model::State& state, int slave, int master,
                                          std::vector<Interval>& intervals) const {
  const auto& elements = m_model->elements();
  const model::LineElement& ea = elements[slave];
  const model::LineElement& eb = elements[master];
  const Vec3 &a0 = state.position[ea.node1], &a1 = state.position[ea.node2];
  const Vec3 &b0 = state.position[eb.node1], &b1 = state.position[eb.node2];
  // The largest sum of the radii on the two pieces, for the bounds below; the gap uses the radii at its
  // points.
  const double radii = m_profile.largest(slave) + m_profile.largest(master);
  // Each piece of the C1 centreline (below): first with the gap between the chords' bounding boxes, which
  // the chords' distance is at least (most candidate pairs end here, without the distance).
  const double reach = radii + chordBound(state, slave) + chordBound(state, master);
  if (geometry::segmentBoxGap(a0, a1, b0, b1) >= reach) return false;
  const geometry::SegmentDistanceResult chords = geometry::segmentDistance(a0, a1, b0, b1);
  // Each piece of the C1 centreline (xi, t in [0, 1], the ranges the gap is measured on) lies within its
  // chordDeviationBound of its chord: pieces whose chords are farther apart than the radii and both bounds
  // cannot touch. (With a quarter of the element lengths as the bound, 158 000 of drilling-riser-drift's
  // 200 000 searches went on to the minimisation, 79 000 of them of pairs this bound leaves out.)
  if (chords.distance >= reach) return false;
  // (Not centrelineMinimum: its point along a valley's floor, where Brent's method stops within its
  // tolerance, moved the sample below from one Newton iterate to the next, and the forces with it; two random
  // sweeps, RandomSweepTest's seeds 36 and 49, stopped with Newton stalled at 6e-5 N and 17 N.)
  const CentrelineDistance closest = centrelineDistance(*m_model, state.position, slave, master, chords.s,
                                                        chords.t, false, false, true, &m_curves);
  // The slave's share of its line is xi in [0, 1] (its neighbours integrate the rest), and the master's is
  // t in [0, 1]: the gap is measured to the master's piece on its exact range (project).
  double tGuess = closest.t;
  const auto gap = [&](double xi) {
    const Projection p = projectPoint(state, slave, xi, master, tGuess, false);
    return p.distance - (radiusAt(slave, xi) + radiusAt(master, p.t));
  };
  // Points of the slave with their gaps on the master's exact range (the root brackets below need the
  // true value there). The joint minimisation above runs over the extended search ranges: where it ends
  // with t off [0, 1] (on the extrapolated piece past a node) its distance is not the gap, and nearly
  // parallel elements have a flat distance along their overlap, so it may stop anywhere on it (a rod
  // sliding down an incline: the incline's pass lost 3/4 of its length between two iterations and Newton
  // cycled at 44 N; a taut string on a support stalled). First candidates: its s; the slave's point nearest
  // the master's piece where t was clamped; the middle of the overlap of the master's chord projected on
  // the slave's.
  struct GapPoint {
    double xi, g;
    bool ridge = false;  ///< the gap's largest between two dips of one run (a cut)
  };
  std::vector<GapPoint> points;
  points.reserve(24);  // the samples below and their refinements: one allocation
  const auto sample = [&](double xi) {
    xi = std::clamp(xi, 0.0, 1.0);
    points.push_back({xi, gap(xi)});
    return points.back().g;
  };
  double gMin = sample(closest.s);
  if (!(closest.t >= 0.0 && closest.t <= 1.0)) {
    const double tEnd = std::clamp(closest.t, 0.0, 1.0);
    gMin = std::min(gMin, sample(centrelineDistance(*m_model, state.position, slave, master, closest.s, tEnd,
                                                    false, true, true, &m_curves)
                                     .s));
  }
  const double s0 = projectOnAxis(b0, a0, a1), s1 = projectOnAxis(b1, a0, a1);
  const double overlapLo = std::max(0.0, std::min(s0, s1)), overlapHi = std::min(1.0, std::max(s0, s1));
  if (overlapHi > overlapLo) gMin = std::min(gMin, sample(0.5 * (overlapLo + overlapHi)));
  // Then, with one of them in contact or the chords within twice the radii, the chords' closest point, the
  // ends and six points along the slave: a kinked or curved pair may touch in more than one place, and
  // each dip is an interval of its own. (The minimisation from the chords' closest points can end in
  // another local minimum: two wires crossing 13.5 mm deep went unseen for several steps until a step's
  // first iterate found them, at 1.5e10 N/m, and Newton cycled; a second dip of a kinked pair, 0.74 mm deep
  // beside the one found, appeared the same way: RandomSweepTest.)
  if (gMin >= 0.0 && chords.distance >= 2.0 * radii) return false;
  sample(chords.s);
  sample(0.0);
  sample(1.0);
  for (int k = 0; k < 6; ++k) sample((k + 0.5) / 6.0);
  std::sort(points.begin(), points.end(), [](const GapPoint& x, const GapPoint& y) { return x.xi < y.xi; });
  // Each local minimum of the sampled gaps near contact, refined to the gap's minimum between its
  // neighbours: a dip narrower than the samples' spacing is found wherever it lies between them, and the
  // deepest point of each dip is found to the same place from one iterate to the next. (A 12 mm crossing of
  // two wires, 0.12 mm deep, lay between two samples; one of them flickered 4 um in and out of contact
  // between Newton iterates, and the crossing was found in every second one: Newton cycled.)
  const std::size_t sampled = points.size();
  for (std::size_t i = 0; i < sampled; ++i) {
    const double g = points[i].g;
    const bool notAbovePrevious = i == 0 || g <= points[i - 1].g;
    const bool notAboveNext = i + 1 == sampled || g <= points[i + 1].g;
    if (!notAbovePrevious || !notAboveNext || g >= radii) continue;
    const double a = i == 0 ? points[i].xi : points[i - 1].xi;
    const double b = i + 1 == sampled ? points[i].xi : points[i + 1].xi;
    if (!(b > a)) continue;
    const auto [xi, gMinimum] = core::brentMinimum(gap, a, b, points[i].xi, g, kMinimumTolerance, 40);
    if (gMinimum < g) points.push_back({xi, gMinimum});
  }
  std::sort(points.begin(), points.end(), [](const GapPoint& x, const GapPoint& y) { return x.xi < y.xi; });
  // Each ridge between two dips whose sampled points are all in contact, refined to the gap's largest value
  // between its neighbours: a cut there (below), or, where the ridge is out of contact, two intervals. As a
  // ridge sinks into contact the two intervals' inner ends meet at its top, so the Gauss points move
  // continuously; a run that took both dips on one piece integrated two humps with four points, and the
  // force jumped by that rule's error when a sample on the ridge came into contact (two lazy waves lying
  // along each other 10-100 um deep: 9 N, and Newton cycled at 2-5 N against a tolerance of 1 N). The cut
  // is weighted by how deep the ridge lies (the weights below): a contact along a length has shallow
  // ridges of the mesh's scale everywhere, whose tops move far for small changes (two risers side by side,
  // cut at every ridge a tenth of the dips' depth high: 157 Newton iterations instead of 34; a taut string
  // settled on a support stalled at 2 N against 0.018 N).
  // The shallower of the deepest gaps on either side of point k within its run in contact (the sorted points
  // before `count`) [m]: the dip depth a ridge at k is measured against.
  const auto shallowerDip = [&points](std::size_t k, std::size_t count) {
    double leftDip = 0.0, rightDip = 0.0;
    for (std::size_t m = k; m-- > 0 && points[m].g < 0.0;) leftDip = std::min(leftDip, points[m].g);
    for (std::size_t m = k + 1; m < count && points[m].g < 0.0; ++m)
      rightDip = std::min(rightDip, points[m].g);
    return std::max(leftDip, rightDip);
  };
  const std::size_t refined = points.size();
  for (std::size_t i = 1; i + 1 < refined; ++i) {
    const double g = points[i].g, left = points[i - 1].g, right = points[i + 1].g;
    if (!(g < 0.0 && left < 0.0 && right < 0.0) || g < left || g < right) continue;
    // A ridge deeper than kRidgeDepths[1] of the shallower dip gets no cut (weights below).
    if (g <= kRidgeDepths[1] * shallowerDip(i, refined)) continue;
    const auto negated = [&](double xi) { return -gap(xi); };
    const auto [xi, top] = core::brentMinimum(negated, points[i - 1].xi, points[i + 1].xi, points[i].xi, -g,
                                              kMinimumTolerance, 40);
    GapPoint ridge{xi, -top, true};
    if (-top < g) ridge = {points[i].xi, g, true};  // the sample itself is the highest found
    if (ridge.xi == points[i].xi)
      points[i].ridge = true;
    else
      points.push_back(ridge);
  }
  std::sort(points.begin(), points.end(), [](const GapPoint& x, const GapPoint& y) { return x.xi < y.xi; });
  // The gap and its slope d gap / d xi = n . c_A'(xi) (n the unit normal from the projection to the point:
  // the projection's own motion is normal to n where it is free, and it does not move where it is held).
  const auto gapAndSlope = [&](double xi) {
    const Projection p = projectPoint(state, slave, xi, master, tGuess, true);
    const Vec3 u = p.pointA - p.pointB;
    const double slope = p.distance > 0.0 ? u.dot(p.tangentA) / p.distance : 0.0;
    return std::pair<double, double>{p.distance - (radiusAt(slave, xi) + radiusAt(master, p.t)), slope};
  };
  // The root of gap between x0 (gap >= 0) and x1 (gap < 0), bracketed: Newton's step from the last point
  // where it stays inside the bracket and shrinks the step at least by half, else the bracket's middle
  // (Press et al., Numerical Recipes, 3rd ed., sec. 9.4, rtsafe). Quadratic where the gap is smooth: about
  // 4 projections per end where the Illinois method, superlinear, took 13.
  // (Of gap + level = 0 in general: the regularisation depth and the barrier's start cut the interval.)
  const auto root = [&](double x0, double g0, double x1, double g1, double level = 0.0) {
    // The value at x0, x1 (true ones) and the best point found.
    double best = std::abs(g0) <= std::abs(g1) ? x0 : x1, bestValue = std::min(std::abs(g0), std::abs(g1));
    double x = x1 - g1 * (x1 - x0) / (g1 - g0);  // the secant's point first
    if (!(x > std::min(x0, x1) && x < std::max(x0, x1))) x = 0.5 * (x0 + x1);
    double previousStep = std::abs(x1 - x0);
    for (int i = 0; i < 100 && std::abs(x1 - x0) > kRootTolerance; ++i) {
      const auto [value, slope] = gapAndSlope(x);
      const double g = value + level;
      if (std::abs(g) < bestValue) {
        best = x;
        bestValue = std::abs(g);
      }
      if (g == 0.0) break;
      (g > 0.0 ? x0 : x1) = x;
      const double newton = slope != 0.0 ? x - g / slope : std::numeric_limits<double>::quiet_NaN();
      const double lo = std::min(x0, x1), hi = std::max(x0, x1);
      double next;
      if (newton > lo && newton < hi && std::abs(newton - x) <= 0.5 * previousStep) {
        // Within kNewtonRootStep of the root Newton's point is exact to round-off (the error squares); the
        // gap's own round-off, ~1e-16 m, would move further iterates at random by ~1e-14.
        if (std::abs(newton - x) <= kNewtonRootStep) return newton;
        next = newton;
      } else {
        next = 0.5 * (x0 + x1);
      }
      previousStep = std::abs(next - x);
      if (previousStep <= kRootTolerance || !(next > lo && next < hi)) break;  // round-off reached
      x = next;
    }
    return best;
  };
  const BarrierPenalty lawAB = law(slave, master);
  intervals.clear();
  // Each run of sampled points in contact, between points out of contact (or the ends), is one dip.
  for (std::size_t i = 0; i < points.size();) {
    if (points[i].g >= 0.0) {
      ++i;
      continue;
    }
    std::size_t last = i, deepest = i;
    while (last + 1 < points.size() && points[last + 1].g < 0.0) {
      ++last;
      if (points[last].g < points[deepest].g) deepest = last;
    }
    const GapPoint& first = points[i];
    const GapPoint& final = points[last];
    const GapPoint& dip = points[deepest];
    Interval iv;
    // Each ridge's weight from its depth over the shallower of the deepest points on either side in the run:
    // 1 (a cut) up to kRidgeDepths[0] of it, 0 from kRidgeDepths[1], a smoothstep between, so that a cut
    // comes in continuously.
    for (std::size_t k = i + 1; k < last; ++k) {
      if (!points[k].ridge) continue;
      const double ratio = points[k].g / shallowerDip(k, points.size());  // ridge depth / shallower dip's
      const double x = std::clamp((kRidgeDepths[1] - ratio) / (kRidgeDepths[1] - kRidgeDepths[0]), 0.0, 1.0);
      const double weight = x * x * (3.0 - 2.0 * x);
      if (weight >= 1.0)
        iv.cuts.push_back(points[k].xi);
      else if (weight > 0.0)
        iv.ridges.emplace_back(points[k].xi, weight);
    }
    // The slave's ends are always sampled: a run that does not start at xi = 0 has a point out of contact
    // before it.
    iv.lo = i == 0 ? first.xi : root(points[i - 1].xi, points[i - 1].g, first.xi, first.g);
    iv.hi = last + 1 == points.size() ? final.xi
                                      : root(points[last + 1].xi, points[last + 1].g, final.xi, final.g);
    const double gl = i == 0 ? first.g : 0.0, gh = last + 1 == points.size() ? final.g : 0.0;
    i = last + 1;
    if (!(iv.hi > iv.lo)) continue;
    // The shoulder ends (radiusProfile), where the radius's third derivative jumps: the slave's, fixed in xi,
    // and the master's, where the projection of the slave's point passes them (each change of side between
    // five points of the interval, refined to round-off: the cut moves smoothly with the nodes). Four Gauss
    // points on a piece across a shoulder's end left the tangent 1.5 % off at a crossing (before 2026-12-06
    // the slave's cuts were tested against the interval before its ends were set, and none was made).
    {
      for (const double end : m_profile.taperEnds(slave))
        if (end > iv.lo && end < iv.hi && end > 0.0 && end < 1.0) iv.cuts.push_back(end);
      for (const double end : m_profile.taperEnds(master)) {
        if (!(end > 0.0 && end < 1.0)) continue;
        const auto side = [&](double xi) {
          return projectPoint(state, slave, xi, master, tGuess, false).t - end;
        };
        constexpr int kSpans = 4;
        double x0 = iv.lo, h0 = side(x0);
        for (int k = 1; k <= kSpans; ++k) {
          const double x1 = k == kSpans ? iv.hi : iv.lo + (iv.hi - iv.lo) * k / kSpans;
          const double h1 = side(x1);
          if ((h0 < 0.0 && h1 > 0.0) || (h0 > 0.0 && h1 < 0.0))
            iv.cuts.push_back(signChange(side, x0, h0, x1, h1));
          x0 = x1;
          h0 = h1;
        }
      }
    }
    // Where the integrand is not smooth: where the penetration passes the law's regularisation depth and
    // the barrier's start (the law's second derivative jumps there). Gauss points on pieces between them
    // integrate smooth functions: the quadrature is then accurate, and so is its derivative, which the
    // tangent takes as that of the exact integral (the Gauss points move with the cuts). (A cut at the
    // integrand's peak, where it is smooth, moved the Gauss points of a flat parallel contact a long way
    // for a small change: the tangent of parallel contact was then 0.2 % off.)
    for (const double level : {lawAB.depth, lawAB.barrierStart}) {
      if (dip.g >= -level) continue;
      if (gl > -level && dip.xi > iv.lo)
        iv.cuts.push_back(root(iv.lo, gl + level, dip.xi, dip.g + level, level));
      if (gh > -level && dip.xi < iv.hi)
        iv.cuts.push_back(root(iv.hi, gh + level, dip.xi, dip.g + level, level));
    }
    intervals.push_back(std::move(iv));
  }
  return !intervals.empty();
}

void DistributedContact::addSample(const model::State& state, int slave, double xi, double weight,
                                   const std::vector<int>& masters, const std::vector<Vec3>& reference) {
  const auto& elements = m_model->elements();
  // The closest point on the master line: the nearest of the projections on its candidate elements (the
  // C1 centreline makes the distance to the line continuous across its nodes; the ranges of neighbouring
  // elements overlap a little, so a minimum at a node is free on one of them).
  CentrelineDistance best;
  best.distance = kInf;
  int bestMaster = -1;
  const Vec3 x = centrelinePoint(m_curves[static_cast<std::size_t>(slave)], xi, state.position);
  for (const int f : masters) {
    const model::LineElement& eb = elements[f];
    const Vec3 &b0 = state.position[eb.node1], &b1 = state.position[eb.node2];
    const double t0 = std::clamp(projectOnAxis(x, b0, b1), 0.0, 1.0);
    if (bestMaster >= 0) {
      // The piece lies within its chordDeviationBound of the chord: a piece whose chord is farther from x
      // than that and the best distance so far cannot be the better one below, and needs no projection (a
      // margin well above the tie's for round-off).
      const double tie = 1e-9 * std::max(1.0, best.distance);
      const double chordDistance = (x - (b0 + t0 * (b1 - b0))).norm();
      if (chordDistance - chordBound(state, f) > best.distance + tie) continue;
    }
    const CentrelineDistance p = project(state, slave, xi, f, t0);
    const double tie = 1e-12 * std::max(1.0, p.distance);
    const bool better = bestMaster < 0 || p.distance < best.distance - tie ||
                        (p.distance <= best.distance + tie && p.tFree && !best.tFree);
    if (better) {
      best = p;
      bestMaster = f;
    }
  }
  if (bestMaster < 0) return;
  const std::array<double, 3> masterRadius = radiusProfile(bestMaster, best.t);
  const double radii = radiusAt(slave, xi) + masterRadius[0];
  const double gap = best.distance - radii;
  if (gap >= 0.0 || best.distance <= 0.0) return;
  ContactSample smp;
  smp.lineA = elements[slave].line;
  smp.lineB = elements[bestMaster].line;
  smp.elementA = slave;
  smp.elementB = bestMaster;
  smp.xi = xi;
  smp.t = best.t;
  smp.curve = best;
  smp.normal = (best.pointA - best.pointB) / best.distance;
  smp.gap = gap;
  smp.radii = radii;
  smp.sine =
      best.a.tangent(state.position).normalized().cross(best.b.tangent(state.position).normalized()).norm();
  if (best.tFree) {  // at an end of its range the projection is held there: t does not move
    smp.radiusSlope = masterRadius[1];
    smp.radiusCurvature = masterRadius[2];
  }
  // The pass's share (header): 1/2 + (b_slave - b_master) / 2 with the bentness along each line at the
  // two points, so that the other line's pass at the same contact gets 1 - share. (Taken per element against
  // the largest bentness of the other line's candidate elements, the two shares need not sum to one: two
  // wires whose elements next to a crossing were bent both got ~0, and an iterate went 16 mm into the
  // barrier with no force: RandomSweepTest.)
  smp.share = std::clamp(
      0.5 + 0.5 * (bentnessAt(state, slave, xi, radii) - bentnessAt(state, bestMaster, best.t, radii)), 0.0,
      1.0);
  smp.fullLength = weight;
  smp.length = smp.share * weight;
  const Vec3 va = best.a.value(m_model->dofs(), state.velocity),
             vb = best.b.value(m_model->dofs(), state.velocity);
  smp.gapRate = smp.normal.dot(va - vb);
  if (state.acceleration.size() == state.velocity.size())
    smp.gapAcceleration = smp.normal.dot(best.a.value(m_model->dofs(), state.acceleration) -
                                         best.b.value(m_model->dofs(), state.acceleration));
  const BarrierPenalty lawAB = law(slave, bestMaster);
  const double p = -gap;
  smp.slope = lawAB.slope(p);
  smp.spring = lawAB.value(p);
  smp.arcA = arcOf(slave, xi);
  smp.arcB = arcOf(bestMaster, best.t);
  smp.pairMass = reducedMass(stencilMass(best.a), stencilMass(best.b));
  // The slip friction acts against (finishSamples): the committed slip of the contact at this point of A
  // plus the displacement of the two material points since the last converged state, in statics and in
  // dynamics alike (a velocity-regularised friction creeps under any tangential load: a rod held on a
  // 10 degree incline by mu = 0.3 crept 11 mm in 1 s).
  smp.slipRate = va - vb;
  smp.relative = committedSlip(smp.lineA, smp.lineB, smp.arcA, elements[slave].restLength) +
                 (best.pointA - best.a.point(reference)) - (best.pointB - best.b.point(reference));
  (smp.share > 0.0 ? m_samples : m_unshared).push_back(smp);
}

void DistributedContact::coverUnseen() {
  const auto lowered = [](const ContactSample& x) { return x.share < 0.5; };
  if (std::none_of(m_samples.begin(), m_samples.end(), lowered) && m_unshared.empty()) return;
  // The law's force integral of each pass (without the shares) near the sample's two elements: its own
  // pass's on the same elements (+-1) and the reverse pass's on the same elements seen from the other line.
  const auto near = [](int e, int f) { return e >= f - 1 && e <= f + 1; };
  const auto integrals = [&](const ContactSample& x) {
    double own = 0.0, reverse = 0.0;
    for (const std::vector<ContactSample>* set : {&m_samples, &m_unshared})
      for (const ContactSample& y : *set) {
        if (y.lineA == x.lineA && y.lineB == x.lineB && near(y.elementA, x.elementA) &&
            near(y.elementB, x.elementB))
          own += y.spring * y.fullLength;
        else if (y.lineA == x.lineB && y.lineB == x.lineA && near(y.elementA, x.elementB) &&
                 near(y.elementB, x.elementA))
          reverse += y.spring * y.fullLength;
      }
    return std::pair(own, reverse);
  };
  // The weight given back is (1 - s) d (1 - c), c = min(1, F_rev / F_own): where the favoured pass sees less
  // than this one, the pair carries this pass's integral, F_rev + (F_own - F_rev); where it sees as much or
  // more, what it did before. (A smoothstep S(r) on (1 - r), 1 up to r = 1/2 and 0 from 0.8, to leave the
  // passes' few per cent of disagreement alone, did worse: RandomSweepTest's seeds 19 and 42 stalled.)
  // The integrals depend only on the sample's two elements, and the samples of one pair of elements come
  // one after another (findSamples visits slave by slave): found once per run of them, not per sample.
  int lastA = -1, lastB = -1;
  double coverage = 1.0;
  const auto cover = [&](const ContactSample& x) {
    if (x.elementA != lastA || x.elementB != lastB) {
      lastA = x.elementA;
      lastB = x.elementB;
      const auto [own, reverse] = integrals(x);
      coverage = own > 0.0 ? std::min(1.0, reverse / own) : 1.0;
    }
    const double deficit = std::clamp(1.0 - 2.0 * x.share, 0.0, 1.0);
    return x.share + (1.0 - x.share) * deficit * (1.0 - coverage);
  };
  // Decided from the shares and forces as found (every sample's coverage before any share changes).
  std::vector<double> shares(m_samples.size() + m_unshared.size());
  for (std::size_t i = 0; i < m_samples.size(); ++i)
    shares[i] = lowered(m_samples[i]) ? cover(m_samples[i]) : m_samples[i].share;
  for (std::size_t i = 0; i < m_unshared.size(); ++i) shares[m_samples.size() + i] = cover(m_unshared[i]);
  const std::size_t seen = m_samples.size();
  for (std::size_t i = 0; i < seen; ++i) {
    m_samples[i].share = shares[i];
    m_samples[i].length = shares[i] * m_samples[i].fullLength;
  }
  for (std::size_t i = 0; i < m_unshared.size(); ++i) {
    ContactSample& x = m_unshared[i];
    if (!(shares[seen + i] > 0.0)) continue;
    x.share = shares[seen + i];
    x.length = x.share * x.fullLength;
    m_samples.push_back(x);
  }
}

void DistributedContact::findSamples(const model::State& state, const ContactCandidates& search, bool dynamic,
                                     bool relaxation, const std::vector<Vec3>& reference) {
  // The samples depend on these inputs and on what commitSamples, beginStep and setStepScale change
  // (they clear m_found): the same inputs give the same samples.
  if (search.candidates().empty()) {
    // No pair is near: no samples, whatever the state (the lines apart: no copies of the state kept).
    m_samples.clear();
    m_unshared.clear();
    ++m_samplesVersion;
    m_found.valid = false;
    return;
  }
  // Compared bit by bit: the same bits give the same samples (+0 against -0 only costs a search), and a
  // memcmp: the value-by-value comparison took 0.38 G instructions of drilling-riser-drift's run, nearly
  // all at hits (the step's check, rejectStep, and its commit ask again for the last assembly's state).
  if (m_found.valid && m_found.dynamic == dynamic && m_found.relaxation == relaxation &&
      core::sameBits(m_found.position, state.position) && core::sameBits(m_found.velocity, state.velocity) &&
      core::sameBits(m_found.acceleration, state.acceleration) &&
      core::sameBits(m_found.reference, reference) && m_found.candidates == search.candidates())
    return;
  m_found.valid = false;
  m_samples.clear();
  m_unshared.clear();
  ++m_samplesVersion;
  const auto& elements = m_model->elements();
  m_chordBound.assign(elements.size(), std::numeric_limits<double>::quiet_NaN());
  // Per patch (slave element, master line), in the order of their keys: the master's candidate elements
  // and the slave's contact intervals against them, in the candidates' order. (The visits grouped by a
  // stable sort, in kept work space: a map of patches and its vectors made afresh were 450 000 allocations
  // of drilling-riser-drift's run.)
  std::vector<PatchVisit>& visits = m_work.visits;
  visits.clear();
  for (const CandidatePair& cp : search.candidates()) {
    const int e = search.proxies()[cp.first].element, f = search.proxies()[cp.second].element;
    visits.push_back({e, elements[f].line, f});
    visits.push_back({f, elements[e].line, e});
  }
  std::stable_sort(visits.begin(), visits.end(), [](const PatchVisit& x, const PatchVisit& y) {
    return std::pair(x.slave, x.line) < std::pair(y.slave, y.line);
  });
  std::vector<int>& masters = m_work.masters;
  std::vector<Interval>& intervals = m_work.intervals;
  std::vector<Interval>& found = m_work.found;
  std::vector<Interval>& merged = m_work.merged;
  std::vector<std::pair<double, double>>& ridges = m_work.ridges;
  std::vector<double>& fixedEnds = m_work.fixedEnds;
  std::vector<double>& ends = m_work.ends;
  for (std::size_t first = 0, last = 0; first < visits.size(); first = last) {
    const int slave = visits[first].slave;
    masters.clear();
    intervals.clear();
    for (last = first;
         last < visits.size() && visits[last].slave == slave && visits[last].line == visits[first].line;
         ++last) {
      masters.push_back(visits[last].master);
      if (contactIntervals(state, slave, visits[last].master, found))
        intervals.insert(intervals.end(), found.begin(), found.end());
    }
    std::sort(masters.begin(), masters.end());
    masters.erase(std::unique(masters.begin(), masters.end()), masters.end());
    if (intervals.empty()) continue;
    // The union of the intervals found against each master element (where two meet, the integrand is zero
    // or both cover the same points: a merge changes the integral continuously).
    std::sort(intervals.begin(), intervals.end(),
              [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
    merged.clear();
    for (const Interval& iv : intervals) {
      if (!merged.empty() && iv.lo <= merged.back().hi) {
        Interval& joined = merged.back();
        joined.cuts.insert(joined.cuts.end(), iv.cuts.begin(), iv.cuts.end());
        joined.ridges.insert(joined.ridges.end(), iv.ridges.begin(), iv.ridges.end());
        joined.hi = std::max(joined.hi, iv.hi);
      } else {
        merged.push_back(iv);
      }
    }
    const double restLength = elements[slave].restLength;
    for (const Interval& iv : merged) {
      ridges.clear();
      for (const auto& r : iv.ridges)
        if (r.first > iv.lo && r.first < iv.hi) ridges.push_back(r);
      // Two rules per partly weighted ridge (with its cut and without), blended: every combination, weighted
      // by the product of its ridges' weights (at most three such ridges; of more, the three of largest
      // weight, the least deep: a ridge left out is not cut, which changes the blend by its weight).
      if (ridges.size() > 3) {
        std::sort(ridges.begin(), ridges.end(),
                  [](const auto& x, const auto& y) { return x.second > y.second; });
        ridges.resize(3);
      }
      fixedEnds.assign({iv.lo, iv.hi});
      for (const double c : iv.cuts)
        if (c > iv.lo && c < iv.hi) fixedEnds.push_back(c);
      for (unsigned mask = 0; mask < (1u << ridges.size()); ++mask) {
        double share = 1.0;
        ends = fixedEnds;
        for (std::size_t r = 0; r < ridges.size(); ++r) {
          const bool cut = (mask >> r) & 1u;
          share *= cut ? ridges[r].second : 1.0 - ridges[r].second;
          if (cut) ends.push_back(ridges[r].first);
        }
        std::sort(ends.begin(), ends.end());
        for (std::size_t piece = 0; piece + 1 < ends.size(); ++piece) {
          const double a = ends[piece], b = ends[piece + 1];
          if (!(b > a)) continue;
          for (int g = 0; g < kPoints; ++g) {
            const double xi = 0.5 * (a + b) + 0.5 * (b - a) * kGaussX[g];
            // Gauss weight x d(arc)/d(xi) on the piece (the pass's share is applied in addSample).
            const double weight = share * kGaussW[g] * 0.5 * (b - a) * restLength;
            addSample(state, slave, xi, weight, masters, reference);
          }
        }
      }
    }
  }
  coverUnseen();
  finishSamples(dynamic && !relaxation);
  m_found.valid = true;
  m_found.dynamic = dynamic;
  m_found.relaxation = relaxation;
  core::copyPoints(state.position, m_found.position);
  core::copyPoints(reference, m_found.reference);
  m_found.velocity = state.velocity;
  m_found.acceleration = state.acceleration;
  m_found.candidates = search.candidates();
}

void DistributedContact::finishSamples(bool dashpot) {
  ++m_samplesVersion;  // the forces change
  // Restitution by hysteresis (HystereticRestitution, ContactLaw.hpp): the spring's force times
  // psi(dp/dt) = 1 + a tanh(v / v_s), v_s per pair of elements (restitutionSpeed). (A clipped dashpot of
  // damping ratio zeta(e) per patch, before: its force at first touch is c v0, and at e = 0 (zeta 100) two
  // risers closing at 1 m/s peaked at 5.74 MN, 24 times the elastic 242 kN: RisersClosingTest.)
  const bool friction = m_spec.frictionCoefficient > 0.0;
  if (dashpot && m_hysteresis > 0.0) {
    for (ContactSample& x : m_samples) {
      // Widened by a twentieth of the sliding speed v_t: the tangent leaves out the rate's change with the
      // normal's turning as the lines slide (d v / d x ~ v_t / R, times f psi'(v), up to f a / v_s), which
      // at v_t / v_s ~ 100 dwarfed the stiffness it keeps (f' psi ~ f / p); Newton stalled at 0.066 N with
      // increments of 1e-11 m at the minimum step (RandomSweepTest, seed 2). Widened, the part left out is
      // at most f a / (R / 20), 20 a p / R of the kept one: a fraction at the law's working depths.
      const double base = restitutionSpeed(x.elementA, x.elementB);
      if (!(base > 0.0)) continue;
      const double sliding =
          kRestitutionSlidingFraction * (x.slipRate - x.normal * x.normal.dot(x.slipRate)).norm();
      // And by the change of the rate within a step, a |p''| kf / cf (the pair's largest committed relative
      // normal acceleration where it presses; kf / cf about dt / 2): a switch much narrower than what the
      // rate moves in a step made the Newton iteration of an impact step a tanh's, which overshoots from
      // side to side (a two-cycle between 4.1 and 6.8 kN at the minimum step: RandomSweepTest, seed 19).
      // (With the contact force over mass instead, F / M, a rod resting on an incline at dt 0.01 s had
      // v_s 0.047 m/s, too little damping left at rest, and was still breathing at 1 s: InclinedFriction.)
      const auto it = m_pairAcceleration.find(linePair(x));
      const double stepped = it == m_pairAcceleration.end() ? 0.0 : m_hysteresis * it->second * m_stepScale;
      const HystereticRestitution restitution{m_hysteresis,
                                              std::sqrt(base * base + sliding * sliding + stepped * stepped)};
      x.rateFactor = restitution.factor(-x.gapRate);
      x.rateSpeed = restitution.speed;
      x.damping = x.spring * restitution.derivative(-x.gapRate);
    }
  }
  for (ContactSample& smp : m_samples) smp.lineForce = smp.spring * smp.rateFactor;
  if (!friction) return;
  const std::vector<std::vector<int>> groups = dashpot ? patches() : std::vector<std::vector<int>>{};
  std::vector<double> masses(groups.size());  // the patches' (patchMass), for the stick's dashpot
  for (std::size_t g = 0; g < groups.size(); ++g) masses[g] = patchMass(groups[g]);
  for (ContactSample& smp : m_samples) smp.slipLimit = slipDistance(smp);
  // The stick spring's dashpot (dynamics): per patch, the delay tau = 2 zeta_t sqrt(M / K_t) with the
  // patch's stick stiffness K_t = sum k_line w_i and its mass M, critically damped (zeta_t = 1).
  // Without it the stick spring, as stiff as the normal law, rang at +-mu f_n for as long as the run (a rod
  // held on an incline: the friction swung between -0.3 and +0.3 of the normal force from step to step).
  // K_t is the stick springs' 2 mu f_n / u_s = k_line wherever u_s is not at its floor, taken over every
  // Gauss point of the patch: with the actual springs, a point whose normal force the dashpot clips to zero
  // (or brings under the floor) leaves K_t within a fraction of a nanometre, tau with it, and the friction
  // of a patch sliding at 0.33 m/s (mostly tau v_t) jumped by 4 % between Newton iterates, which cycled at
  // 2.6 N (RandomSweepTest, seed 16).
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::vector<int>& patch = groups[g];
    double stiffness = 0.0;
    for (const int i : patch) {
      const ContactSample& x = m_samples[static_cast<std::size_t>(i)];
      stiffness += law(x.elementA, x.elementB).stiffness * x.length;
    }
    const double mass = masses[g];
    const double delay =
        stiffness > 0.0 && std::isfinite(mass) ? 2.0 * kStickDampingRatio * std::sqrt(mass / stiffness) : 0.0;
    for (const int i : patch) m_samples[static_cast<std::size_t>(i)].slipDelay = delay;
  }
  for (ContactSample& smp : m_samples) {
    if (smp.lineForce <= 0.0) continue;
    // Elastic stick, then Coulomb slip, joined smoothly, on w = u_t + tau v_t (the slip and its rate):
    // f_t = -mu f_n phi(|w|) w / |w| with phi(r) = 2 r / u_s - (r / u_s)^2 up to the slip distance u_s and
    // 1 beyond (C1 at u_s, so the force reaches mu f_n exactly and the committed slip can be held at u_s
    // without changing it: commitSlip). d(phi w / r) / dw = (phi / r) P + (phi' - phi / r) w w^T / r^2,
    // symmetric (P = I - n n^T).
    const Mat3 projector = Mat3::Identity() - smp.normal * smp.normal.transpose();
    const double us = smp.slipLimit;
    const Vec3 w = projector * (smp.relative + smp.slipDelay * smp.slipRate);
    const double r = w.norm();
    const double mu = m_spec.frictionCoefficient * smp.lineForce;
    if (r < us) {
      const double phiOverR = 2.0 / us - r / (us * us);
      smp.friction = -mu * phiOverR * w;
      smp.frictionTangent =
          mu * (phiOverR * projector - (r > 0.0 ? Mat3(w * w.transpose() / (r * us * us)) : Mat3::Zero()));
    } else {
      smp.friction = -mu * w / r;
      smp.frictionTangent = mu / r * (projector - w * w.transpose() / (r * r));
    }
  }
}

Vec3 DistributedContact::committedSlip(int lineA, int lineB, double arcA, double reach) const {
  // Linear in arc length between the two committed points of the pair that bracket arcA, the nearer one's
  // beyond the ends; nothing farther than `reach` from every committed point (a contact that starts).
  const auto it = m_slip.find({lineA, lineB});
  if (it == m_slip.end() || it->second.empty()) return Vec3::Zero();
  const std::vector<SlipRecord>& records = it->second;
  const auto upper = std::lower_bound(records.begin(), records.end(), arcA,
                                      [](const SlipRecord& x, double arc) { return x.arc < arc; });
  if (upper == records.begin()) return upper->arc - arcA <= reach ? upper->slip : Vec3::Zero();
  const auto lower = std::prev(upper);
  if (upper == records.end()) return arcA - lower->arc <= reach ? lower->slip : Vec3::Zero();
  if (upper->arc - lower->arc > 2.0 * reach) {
    if (arcA - lower->arc <= reach) return lower->slip;
    return upper->arc - arcA <= reach ? upper->slip : Vec3::Zero();
  }
  const double w = upper->arc > lower->arc ? (arcA - lower->arc) / (upper->arc - lower->arc) : 0.0;
  return (1.0 - w) * lower->slip + w * upper->slip;
}

void DistributedContact::commitSamples(double dt) {
  m_found.valid = false;  // the committed slip and contacts enter the next samples
  // The pairs' largest relative normal acceleration where they press (finishSamples): pairMotions'.
  m_pairAcceleration.clear();
  for (const auto& [key, motion] : pairMotions()) m_pairAcceleration[key] = motion.acceleration;
  // The struck crossings (impactStepLimit): a new one when its approach is significant; one that lets go,
  // turns to separate or outlives three times its estimated duration is judged afresh. (Held through the
  // rebound as well, until it turned to approach again, the rigid bars' e = 0.5 came to +1.8 % instead of
  // +4.6 %, but wires chattering on each other were held through every rebound and the random sweeps took
  // 1.34 times their CPU: 473 s against 354 s for the eight seeds.)
  std::map<std::pair<int, int>, StruckCrossing> struck;
  if (dt > 0.0) {
    for (const auto& [key, motion] : pairMotions()) {
      const auto it = m_struck.find(key);
      if (it != m_struck.end() && !(motion.deepestRate > 0.0) && it->second.remaining > dt) {
        struck[key] = {it->second.remaining - dt, it->second.step};
        continue;
      }
      if (crossingApproach(motion)) {
        // Three times the whole impact: unloading at e < 1 is slower, by 1 / e on a linear law, so the
        // impact lasts about (1 + 1 / e) / 2 times its time at e = 1 (e taken at least 1/4).
        const double loading = crossingLoadingTime(motion);
        const double restitution = std::max(0.25, m_spec.restitution);
        struck[key] = {1.5 * (1.0 + 1.0 / restitution) * loading, loading / kImpactSteps};
      }
    }
  }
  m_struck = std::move(struck);
  // The points in contact, for crossedSinceCommit.
  m_committed.clear();
  for (const ContactSample& smp : m_samples)
    m_committed.push_back({smp.elementA, smp.elementB, smp.xi, smp.t, smp.normal});
  // The slip of every Gauss point in contact at the converged state, tangential, held at the slip distance
  // u_s where friction slides (the force is mu f_n there and beyond: the elastic stick part is what is
  // kept, the rest has slid).
  m_slip.clear();
  for (const ContactSample& smp : m_samples) {
    if (smp.lineForce <= 0.0 || m_spec.frictionCoefficient <= 0.0) continue;
    const Vec3 ut = (Mat3::Identity() - smp.normal * smp.normal.transpose()) * smp.relative;
    const double us = smp.slipLimit, r = ut.norm();
    m_slip[{smp.lineA, smp.lineB}].push_back({smp.arcA, r > us ? Vec3(ut * (us / r)) : ut});
  }
  for (auto& [key, records] : m_slip)
    std::sort(records.begin(), records.end(),
              [](const SlipRecord& x, const SlipRecord& y) { return x.arc < y.arc; });
}

namespace {

/// Gradient of the projection's parameter t with respect to the eight node positions of a sample's two
/// stencils (centrelineKinematics' slots: A's four, then B's four) [1/m]. t minimises |u|^2 / 2,
/// u = c_A(xi) - c_B(t), with xi held: V_t = -u . c_B' = 0, so dt/dx = -V_tx / V_tt with
/// V_tt = c_B' . c_B' - u . c_B'' and, per slot, V_tx = -N_k c_B' (A) and N_k c_B' - dN_k u (B).
std::array<Vec3, 8> projectionGradient(const std::vector<Vec3>& position, const CentrelineDistance& d) {
  std::array<Vec3, 8> g;
  g.fill(Vec3::Zero());
  const Vec3 u = d.pointA - d.pointB;
  const Vec3 cb = d.b.tangent(position), cbb = d.b.secondDerivative(position);
  const double vtt = cb.squaredNorm() - u.dot(cbb);
  if (!(vtt > 0.0)) return g;  // not a minimum: no smooth projection to differentiate
  for (int k = 0; k < 4; ++k) {
    g[k] = d.a.N[k] * cb / vtt;
    g[4 + k] = (d.b.dN[k] * u - d.b.N[k] * cb) / vtt;
  }
  return g;
}

/// Hessian of the projection's parameter t with respect to the eight slots' positions (projectionGradient's
/// slots) [1/m^2], from differentiating F(x, t(x)) = 0 twice, F = V_t = -u . c_B':
///     Hess t = -(F_xx + F_xt grad t^T + grad t F_xt^T + F_tt grad t grad t^T) / F_t,
/// F_t = V_tt = c_B' . c_B' - u . c_B'', F_xx(i, j) = -(U_i P_j + P_i U_j) I, F_xt(j) = 2 P_j c_B' - U_j
/// c_B''
/// - Q_j u and F_tt = 3 c_B' . c_B'' - u . c_B''', with the slots' weights in u (U: N_k on A, -N_k on B), in
/// c_B' (P: dN_k on B) and in c_B'' (Q: ddN_k on B). `third`: B's third-derivative weights.
Eigen::Matrix<double, 24, 24> projectionHessian(const std::vector<Vec3>& position,
                                                const CentrelineDistance& d,
                                                const std::array<double, 4>& third,
                                                const std::array<Vec3, 8>& gradT) {
  Eigen::Matrix<double, 24, 24> h = Eigen::Matrix<double, 24, 24>::Zero();
  const Vec3 u = d.pointA - d.pointB;
  const Vec3 cb = d.b.tangent(position), cbb = d.b.secondDerivative(position);
  Vec3 cbbb = Vec3::Zero();
  for (int k = 0; k < 4; ++k) cbbb += third[k] * position[d.b.node[k]];
  const double vtt = cb.squaredNorm() - u.dot(cbb);
  if (!(vtt > 0.0)) return h;  // not a minimum (projectionGradient)
  std::array<double, 8> weightU{}, weightP{}, weightQ{};
  for (int k = 0; k < 4; ++k) {
    weightU[k] = d.a.N[k];
    weightU[4 + k] = -d.b.N[k];
    weightP[4 + k] = d.b.dN[k];
    weightQ[4 + k] = d.b.ddN[k];
  }
  std::array<Vec3, 8> fxt;
  for (int j = 0; j < 8; ++j) fxt[j] = 2.0 * weightP[j] * cb - weightU[j] * cbb - weightQ[j] * u;
  const double ftt = 3.0 * cb.dot(cbb) - u.dot(cbbb);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      Mat3 b = fxt[i] * gradT[j].transpose() + gradT[i] * fxt[j].transpose() +
               ftt * gradT[i] * gradT[j].transpose();
      b.diagonal().array() -= weightU[i] * weightP[j] + weightP[i] * weightU[j];
      h.block<3, 3>(3 * i, 3 * j) = -b / vtt;
    }
  return h;
}

}  // namespace

void DistributedContact::addForces(const model::State& state, const solver::AssemblyRequest& request,
                                   VecX& force, solver::SystemMatrix* matrix) const {
  const model::DofMap& dofs = m_model->dofs();
  // The blocks of consecutive samples on the same eight slots (the Gauss points of one element against
  // one element of the other line) are summed here and enter the matrix once: one 3 x 3 block per slot
  // pair and group instead of per sample. examples/risers-in-contact, two risers pressed together along
  // 66 m: 3.1 M block calls were 0.79 G of its 4.6 G instructions. The group's calls are also the same
  // from one assembly to the next while samples come and go within it, so the matrix replays them.
  struct {
    bool open = false;
    CentrelineSlots slots;  // the group's nodes and used slots
    Eigen::Matrix<double, 24, 24> block;
  } pending;
  const auto flush = [&] {
    if (!pending.open) return;
    pending.open = false;
    addSlotBlocks(pending.slots, pending.block, Mat3::Zero(), dofs, *matrix);
  };
  for (const ContactSample& smp : m_samples) {
    if (smp.lineForce <= 0.0) continue;
    const Vec3 f = smp.length * (smp.lineForce * smp.normal + smp.friction);  // on A [N]
    // In a shoulder of line B the gap is d - r_A - r_B(t): grad gap = grad d - r_B' grad t, and the force
    // f grad gap has a part along grad t (the shoulder's slope pushes along the lines).
    const bool shoulder = smp.radiusSlope != 0.0;
    std::array<Vec3, 8> gradT;
    if (shoulder) {
      gradT = projectionGradient(state.position, smp.curve);
      const double scale = smp.length * smp.lineForce * smp.radiusSlope;
      for (int i = 0; i < 8; ++i) {
        const int node = i < 4 ? smp.curve.a.node[i] : smp.curve.b.node[i - 4];
        if (gradT[i].squaredNorm() > 0.0) force.segment<3>(dofs.firstDof(node)) += scale * gradT[i];
      }
    }
    if (!matrix) {
      // The force alone: its weights are the stencils' N_k on A and -N_k on B (centrelineKinematics' slots;
      // the kinematics, with its 24 x 24 Hessian zeroed and copied, was 0.3 G instructions of
      // drilling-riser-drift's run, where most assemblies want no matrix).
      for (int i = 0; i < 4; ++i)
        if (smp.curve.a.N[i] != 0.0)
          force.segment<3>(dofs.firstDof(smp.curve.a.node[i])) -= smp.curve.a.N[i] * f;
      for (int i = 0; i < 4; ++i) {
        const double weight = -smp.curve.b.N[i];
        if (weight != 0.0) force.segment<3>(dofs.firstDof(smp.curve.b.node[i])) -= weight * f;
      }
      continue;
    }
    // The slots alone, without the 24 x 24 Hessian, except in a shoulder: the blocks are assembled from its
    // factored form below.
    const CentrelineSlots kin = centrelineSlots(smp.curve, 1.0);
    for (int i = 0; i < 8; ++i)
      if (kin.weight[i] != 0.0) force.segment<3>(dofs.firstDof(kin.node[i])) -= kin.weight[i] * f;
    // Normal: k' grad d grad d^T - f Hess d (the Gauss point held, its projection free: envelope theorem,
    // SmoothCentreline.hpp), k' = f'(p) psi (the restitution's factor; finishSamples); f psi'(v) n n^T on
    // the velocities; friction on the displacements. (psi's change with the patch's v_s is not
    // linearised, as the patch's mass and stiffness are held.)
    const double normalSlope = smp.slope * smp.rateFactor;
    Mat3 pointBlock = request.cf * smp.length * smp.damping * smp.normal * smp.normal.transpose();
    pointBlock += (request.kf + smp.slipDelay * request.cf) * smp.length * smp.frictionTangent;
    if (shoulder) {
      // Hess gap = Hess d - r_B'' grad t grad t^T - r_B' Hess t (projectionHessian).
      const CentrelineKinematics full = centrelineKinematics(state.position, smp.curve, 1.0, true);
      Eigen::Matrix<double, 24, 1> gt, gradGap;
      for (int i = 0; i < 8; ++i) gt.segment<3>(3 * i) = gradT[i];
      gradGap = full.gradient - smp.radiusSlope * gt;
      const Eigen::Matrix<double, 24, 24> hessT =
          projectionHessian(state.position, smp.curve,
                            centrelineThirdWeights(m_curves[static_cast<std::size_t>(smp.elementB)]), gradT);
      const Eigen::Matrix<double, 24, 24> block =
          request.kf * smp.length *
          (normalSlope * gradGap * gradGap.transpose() - smp.lineForce * full.hessian +
           smp.lineForce * (smp.radiusCurvature * gt * gt.transpose() + smp.radiusSlope * hessT));
      flush();
      addSlotBlocks(full, block, pointBlock, dofs, *matrix);
      continue;
    }
    // Block (i, j) of kf L (k' grad d grad d^T - f Hess d) + w_i w_j pointBlock, with grad d = w (x) n and
    // Hess d in its factored form (distanceCurvature): w_i w_j C + sum_a b_ia e_ja^T, C = kf L (k' n n^T - f
    // / d (I - n n^T)) + pointBlock and e_ja = kf L f / d sum_b Vinv_ab b_jb.
    const Vec3& n = kin.normal;
    const Mat3 nn = n * n.transpose();
    const double scale = request.kf * smp.length;
    Mat3 common = pointBlock + scale * normalSlope * nn;
    const double dist = std::abs(kin.distance);
    DistanceCurvature curvature;
    std::array<std::array<Vec3, 2>, 8> e{};
    if (dist > 0.0) {
      const double fd = scale * smp.lineForce / dist;
      common -= fd * (Mat3::Identity() - nn);
      curvature = distanceCurvature(state.position, smp.curve, kin.weight);
      for (int j = 0; j < 8; ++j)
        for (int a = 0; a < curvature.free; ++a) {
          Vec3 sum = curvature.inverse(a, 0) * curvature.mixed[j][0];
          if (curvature.free == 2) sum += curvature.inverse(a, 1) * curvature.mixed[j][1];
          e[j][a] = fd * sum;
        }
    }
    if (!pending.open || pending.slots.node != kin.node || pending.slots.used != kin.used) {
      flush();
      pending.open = true;
      pending.slots = kin;
      pending.block.setZero();
    }
    for (int i = 0; i < 8; ++i) {
      if (!kin.used[i]) continue;
      for (int j = 0; j < 8; ++j) {
        if (!kin.used[j]) continue;
        auto bij = pending.block.block<3, 3>(3 * i, 3 * j);
        bij.noalias() += (kin.weight[i] * kin.weight[j]) * common;
        for (int a = 0; a < curvature.free; ++a) bij.noalias() += curvature.mixed[i][a] * e[j][a].transpose();
      }
    }
  }
  flush();  // (a group is open only when a matrix is assembled)
}

double DistributedContact::limitIncrement(const model::State& state, const std::vector<Vec3>& move,
                                          const ContactCandidates& search,
                                          const std::vector<CandidatePair>& pairs, bool strict) const {
  double alpha = 1.0;
  // The barrier, on the measure it acts on (the C1 centrelines; a kinked cable's chords lie deeper): at
  // every Gauss point of this iterate the change of the distance, linear in the increment (grad d = w_k n),
  // may close at most kBarrierFraction of what is left to the barrier's limit.
  for (const ContactSample& smp : m_samples) {
    double change = 0.0;
    for (int k = 0; k < 4; ++k) {
      change += smp.curve.a.N[k] * smp.normal.dot(move[smp.curve.a.node[k]]);
      change -= smp.curve.b.N[k] * smp.normal.dot(move[smp.curve.b.node[k]]);
    }
    if (change >= 0.0) continue;
    const double room = law(smp.elementA, smp.elementB).limit + smp.gap;  // pmax - p [m]
    if (room <= 0.0) continue;  // beyond: the cap's force pushes back, rejectSamples refuses the state
    alpha = std::min(alpha, kBarrierFraction * room / -change);
  }
  // Every pair: no passing through, and no closing by more than a quarter of the radii (a contact is made
  // over several iterates, so its Gauss points are there to filter the rest).
  const auto& elements = m_model->elements();
  const auto& proxies = search.proxies();
  for (const CandidatePair& cp : pairs) {
    const SegmentProxy& a = proxies[cp.first];
    const SegmentProxy& b = proxies[cp.second];
    const model::LineElement& ea = elements[a.element];
    const model::LineElement& eb = elements[b.element];
    const double radii = a.radius + b.radius;
    // A pair that the increment at alpha cannot bring within its allowance or turn through is admissible
    // unmeasured (the two distances below were 6-7 % of the random sweeps' CPU): with m the most any
    // point of either chord moves, the chords' distance is at least D0 - m, and their closest points'
    // separation u keeps u . u0 >= D0 (D0 - m) > 0 (the points a - b of two segments form a convex set, u0
    // its point nearest the origin, so q . u0 >= D0^2 for each of its points q, and u lies within m of one).
    // D0 is at least the gap between the chords' bounding boxes; half of each bound for round-off.
    const double reach = alpha * (std::max(move[ea.node1].norm(), move[ea.node2].norm()) +
                                  std::max(move[eb.node1].norm(), move[eb.node2].norm()));
    if (reach <= 0.5 * kClosingFraction * radii &&
        reach < 0.5 * geometry::segmentBoxGap(state.position[ea.node1], state.position[ea.node2],
                                              state.position[eb.node1], state.position[eb.node2]))
      continue;
    const geometry::SegmentDistanceResult before =
        geometry::segmentDistance(state.position[ea.node1], state.position[ea.node2],
                                  state.position[eb.node1], state.position[eb.node2]);
    const double allowed = std::max(radii - before.distance, 0.0) + kClosingFraction * radii;
    auto admissible = [&](double f) {
      const geometry::SegmentDistanceResult d = geometry::segmentDistance(
          state.position[ea.node1] + f * move[ea.node1], state.position[ea.node2] + f * move[ea.node2],
          state.position[eb.node1] + f * move[eb.node1], state.position[eb.node2] + f * move[eb.node2]);
      if (radii - d.distance > allowed) return false;
      // Passed through: the separation reversed with the closest points inside both segments (chords
      // already within the barrier's reach are a sharp fold's, which the smooth curve wraps: not judged).
      const bool inside = d.s > 0.0 && d.s < 1.0 && d.t > 0.0 && d.t < 1.0;
      const bool judged = before.distance > radii - law(a.element, b.element).limit;
      return !(inside && judged && (before.closest0 - before.closest1).dot(d.closest0 - d.closest1) < 0.0);
    };
    // In dynamics a chord test is a guard against tunnelling between Gauss points, not the barrier: one that
    // no short fraction satisfies (a chord degenerate against the other, a fold's chord near the line) is
    // left out rather than stopping the iteration with a zero correction. Statics' increments can be
    // thousands of times the radii (a cable's first Newton step): there it is halved as far as it takes.
    double trial = alpha;
    const int halvings = strict ? 40 : 10;
    for (int i = 0; i < halvings && !admissible(trial); ++i) trial *= 0.5;
    if (strict || admissible(trial)) alpha = trial;
  }
  return alpha;
}

std::string DistributedContact::rejectSamples() const {
  for (const ContactSample& smp : m_samples) {
    const BarrierPenalty lawAB = law(smp.elementA, smp.elementB);
    if (!lawAB.beyondCap(-smp.gap)) continue;
    const auto& lines = m_model->lines();
    return fmt::format(
        "lines '{}' and '{}' overlap by {:.4g} m at {:.3f} m along '{}' and {:.3f} m along '{}', beyond the "
        "contact barrier ({:.4g} m; it stops overlaps at half the smaller contact diameter, {:.4g} m): an "
        "iterate jumped past the barrier",
        lines[smp.lineA].name, lines[smp.lineB].name, -smp.gap, smp.arcA, lines[smp.lineA].name, smp.arcB,
        lines[smp.lineB].name, lawAB.cap(), std::min(m_radius[smp.elementA], m_radius[smp.elementB]));
  }
  return {};
}

std::string DistributedContact::crossedSinceCommit(const model::State& state) const {
  // Each point in contact at the last converged state, against the same piece of the other line (exact
  // range): its separation must not have reversed. (The chords' test of LineContact::rejectStep needs the
  // closest points inside both elements; a wire folded at a node over a node of another passed through
  // there with every element pair's closest points at element ends, and full Newton converged on the
  // other side.) The same piece, not the nearest one: a point of a straight line inside a fold has a
  // nearest point on either leg, with opposite normals.
  const auto& lines = m_model->lines();
  for (const CommittedContact& c : m_committed) {
    const Projection p = projectPoint(state, c.elementA, c.xi, c.elementB, c.t, false);
    if ((p.pointA - p.pointB).dot(c.normal) >= 0.0) continue;
    const model::LineElement& ea = m_model->elements()[c.elementA];
    const model::LineElement& eb = m_model->elements()[c.elementB];
    return fmt::format(
        "lines '{}' and '{}' have passed through each other at {:.3f} m along '{}' and {:.3f} m along '{}' "
        "(where they touched at the last converged state)",
        lines[ea.line].name, lines[eb.line].name, arcOf(c.elementA, c.xi), lines[ea.line].name,
        arcOf(c.elementB, p.t), lines[eb.line].name);
  }
  return {};
}

const std::map<std::pair<int, int>, DistributedContact::PairMotion>& DistributedContact::pairMotions() const {
  if (m_motionsVersion == m_samplesVersion) return m_motions;
  m_motionsVersion = m_samplesVersion;
  std::map<std::pair<int, int>, PairMotion>& motions = m_motions;
  motions.clear();
  for (const ContactSample& smp : m_samples) {
    if (smp.lineForce <= 0.0) continue;
    const auto [it, fresh] = motions.try_emplace(linePair(smp));
    PairMotion& m = it->second;
    if (fresh) {
      m.slowest = kInf;
      m.deepest = kInf;
    }
    m.stiffness += smp.slope * smp.length;
    m.speed = std::max(m.speed, std::abs(smp.gapRate));
    m.slowest = std::min(m.slowest, std::abs(smp.gapRate));
    m.acceleration = std::max(m.acceleration, std::abs(smp.gapAcceleration));
    m.rateSpeed = std::max(m.rateSpeed, smp.rateSpeed);
    if (smp.gap < m.deepest) {
      const BarrierPenalty lawAB = law(smp.elementA, smp.elementB);
      m.deepest = smp.gap;
      m.deepestRate = smp.gapRate;
      m.scale = lawAB.depth;
      m.lineStiffness = lawAB.stiffness;
      m.mass = smp.pairMass;
      m.sine = smp.sine;
      m.radii = smp.radii;
      m.limit = lawAB.limit;
    }
  }
  for (const std::vector<int>& group : this->patches()) {
    const auto it = motions.find(linePair(m_samples[static_cast<std::size_t>(group.front())]));
    if (it != motions.end()) it->second.patchMass = std::max(it->second.patchMass, patchMass(group));
  }
  return motions;
}

namespace {
/// The mass that judges whether a pair's normal motion is dynamically significant: the larger of the
/// deepest point's and the patch's (impactStepLimit) [kg].
double significanceMass(double pointMass, double patchMass) {
  return std::isfinite(patchMass) ? std::max(pointMass, patchMass) : pointMass;
}
}  // namespace

bool DistributedContact::crossingApproach(const PairMotion& m) const {
  // A crossing loads along its own law, (2 / sine) integral f(p - w^2 / (2 R)) dw (crossingForce), far
  // softer at first touch than the point stiffness says: its work to p0 is 4 % of 1/2 K p0^2 for two equal
  // lines at right angles. The approach is significant if its kinetic energy would carry the crossing a
  // further p0 deeper than it is, W(p + p0) - W(p) (regularisedCrossingWork; beyond a few p0 this exceeds
  // what K gives, and the test with K decides). The approach is the deepest point's: at the edges of a
  // crossing that slides, points enter and leave the contact at the sliding speed times the slope of the
  // gap, which is no impact (judged by the patch's fastest point, the random sweeps took 1.8x their CPU).
  // A contact along a length (sine -> 0) is stiff by this measure and keeps K's.
  if (!std::isfinite(m.mass) || !(m.mass > 0.0) || !(m.radii > 0.0)) return false;
  const double depth = std::max(0.0, -m.deepest), sine = std::max(m.sine, 1e-12);
  const double further = regularisedCrossingWork(m.lineStiffness, m.scale, m.radii, sine, depth + m.scale) -
                         regularisedCrossingWork(m.lineStiffness, m.scale, m.radii, sine, depth);
  return 0.5 * significanceMass(m.mass, m.patchMass) * m.deepestRate * m.deepestRate > further;
}

double DistributedContact::crossingLoadingTime(const PairMotion& m) const {
  // The deepest penetration p* where the crossing's work along its loading law (1 + a) f has taken the
  // approach's kinetic energy, (1 + a) (W(p*) - W(p)) = 1/2 M v^2 (bisection; at most the barrier's pmax),
  // and the time to get there and back at e = 1, pi (p* - p) / v: exact for a linear law (p* = v / omega);
  // a Hertzian p^(3/2) one, the crossing's, takes 2.94 (p* - p) / v (Johnson, Contact Mechanics, 1985,
  // eq. 11.24).
  const double speed = std::abs(m.deepestRate);
  if (!(speed > 0.0)) return 0.0;
  const double depth = std::max(0.0, -m.deepest), sine = std::max(m.sine, 1e-12);
  const auto work = [&](double p) {
    return (1.0 + m_hysteresis) * regularisedCrossingWork(m.lineStiffness, m.scale, m.radii, sine, p);
  };
  const double target = work(depth) + 0.5 * significanceMass(m.mass, m.patchMass) * speed * speed;
  double lo = depth, hi = std::max(m.limit, depth);
  if (work(hi) > target) {
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (work(mid) < target ? lo : hi) = mid;
    }
  }
  return kPi * (hi - depth) / speed;
}

double DistributedContact::impactStepLimit() const {
  // Per pair of lines in contact: the stiffness K = sum of the Gauss points' slopes x lengths and the
  // lumped pair mass M at the deepest point. A pair whose relative normal motion is dynamically significant
  // (|v| sqrt(M / K), the penetration of a rigid impact at that speed, above the law's regularisation depth
  // p0, a hundredth of the contact scale) has its period resolved with kImpactSteps steps. (A thousandth
  // kept resolving the slow normal motion of sustained contacts: the drilling-riser example took 136 000
  // steps and 78.7 s CPU against 20 200 steps and 6.7 s, with the same impact energy within 1 % and peak
  // force within 0.01 %. Per patch, with patchMass, the steps were longer: a wire folding over another on
  // 40 elements then overshot to the barrier's cap at the minimum step.)
  // Whether the motion is significant is judged with the larger mass of the pair's contact patches
  // (patchMass, the dashpot's): with the deepest point's lumped mass against the whole patch's stiffness,
  // two 20 m risers closing side by side at 1 m/s (1500 kg, p* = 7.6 mm) looked like a 3 mm impact,
  // below p0, got no limit, and took their 19 ms impact in 10 growing steps, rebounding at 1.057 m/s
  // (RisersClosingTest).
  double limit = kInf;
  for (const auto& [key, motion] : pairMotions()) {
    if (!std::isfinite(motion.mass) || motion.mass <= 0.0 || motion.stiffness <= 0.0) continue;
    // At least the pair's point stiffness k (a crossing's, halfway into the law's linear range): a patch
    // only just touching, in the regularised start of the law, is soft, and its period allowed steps that
    // carried a wire bouncing on a node of another 2 mm deep at 6 m/s in one step (a drape at e = 1: the
    // converged step threw the wire off the other).
    const double stiffness = std::max(motion.stiffness, pointStiffness(key.first, key.second));
    const double mass = significanceMass(motion.mass, motion.patchMass);
    const double step = impactDuration(stiffness, motion.mass) / kImpactSteps;
    // The reversal of an impact (restitution by hysteresis, finishSamples): the force turns from
    // (1 + a) f to (1 - a) f while the penetration rate passes through +-v_s, in a time 2 v_s / |p''|
    // far shorter than an impact step (two risers closing side by side at 1 m/s: v_s 0.035 m/s, p''
    // 320 m/s^2, 0.2 ms against 0.27 ms steps); taken in one step, the Eq. 5 mass of that impact was
    // 1.2 % (e = 0.5) to 2.6 % (e = 0) high. When the patch's normal acceleration is an impact's (its
    // dynamic penetration |p''| M / K above p0: a contact at rest has none, whatever its force) and its
    // rate is within reach of the switch, steps of v_s / |p''|, but not below an eighth of an impact step.
    const bool decelerating = motion.acceleration * mass / stiffness > motion.scale;
    if (motion.rateSpeed > 0.0 && decelerating &&
        motion.slowest < 3.0 * motion.rateSpeed + motion.acceleration * step)
      limit = std::min(limit, std::max(motion.rateSpeed / motion.acceleration, step / 8.0));
    // Significant by its speed, or by its acceleration near the deepest point, where the speed is gone: the
    // steps grew there, 25 % a step to 0.44 ms (1/24 of the impact), and the sampled peak of two risers
    // closing side by side at e = 0.5 was 1.3 % low.
    if (motion.speed * std::sqrt(mass / stiffness) > motion.scale || decelerating) {
      limit = std::min(limit, step);
      continue;
    }
    // Or a crossing struck harder than its soft start takes within p0 (crossingApproach), until it lets go,
    // turns to separate or outlives its time (m_struck, commitSamples), in steps of its own law's impact
    // (crossingLoadingTime), no shorter than K's. Judged with K alone, two rigid 0.2 m bars crossing at
    // 2 m/s (1.2 mm against p0 = 2 mm) got no limit, the steps grew 1.25-fold through the impact and the
    // bars left with 9.8 % more kinetic energy at e = 1; judged afresh at every step, the impact's last p0
    // looked insignificant again and they left with 7.2 % more; struck until they separate, +0.53 %. In
    // K's steps, wires chattering on each other at 0.1-0.3 m/s took the random sweeps 1.8 times their CPU.
    // (The patch's own secant stiffness, tried instead of the crossing's law, switched the limit on and off
    // as a patch grew, and random sweep seed 22 blew up: kinetic energy 866 kJ from 241 J.)
    const auto it = m_struck.find(key);
    if (it != m_struck.end())
      limit = std::min(limit, std::max(step, it->second.step));
    else if (crossingApproach(motion))
      limit = std::min(limit, std::max(step, crossingLoadingTime(motion) / kImpactSteps));
  }
  return limit;
}

double DistributedContact::impactDuration(double stiffness, double mass) const {
  // The loading half at the stiffness (1 + a) K, twice (the unloading half is longer, and at e = 0 there
  // is none to resolve).
  return contactDuration((1.0 + m_hysteresis) * stiffness, mass, 0.0);
}

std::vector<std::vector<int>> DistributedContact::patches() const {
  std::vector<int> order(m_samples.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto sample = [&](int i) -> const ContactSample& { return m_samples[static_cast<std::size_t>(i)]; };
  const auto lowArc = [&](int i) {
    return sample(i).lineA <= sample(i).lineB ? sample(i).arcA : sample(i).arcB;
  };
  const auto pairKey = [&](int i) { return linePair(sample(i)); };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return std::make_pair(pairKey(a), lowArc(a)) < std::make_pair(pairKey(b), lowArc(b));
  });
  std::vector<std::vector<int>> out;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool joins = k > 0 && pairKey(order[k]) == pairKey(order[k - 1]) &&
                       lowArc(order[k]) - lowArc(order[k - 1]) <= 4.0 * sample(order[k]).radii;
    if (!joins) out.emplace_back();
    out.back().push_back(order[k]);
  }
  return out;
}

double DistributedContact::patchMass(const std::vector<int>& patch) const {
  // The larger of two estimates (issue 43):
  // - the lumped pair mass where the patch presses (a crossing at a node engages the nodes there): the
  //   mean of the samples' lumped pair masses weighted by their spring forces, harmonic (of the mobilities
  //   1 / m, so that a held node's infinite mass counts as zero mobility). (The pair mass at the deepest
  //   point jumped between two Gauss points of equal depth from one Newton iteration to the next: the
  //   dashpot's force of 4 kN at a wire's first touch at 1.2 m/s changed by 0.4 N for a change of position
  //   of 1e-11 m, and Newton cycled 4 orders above its tolerance: RandomSweepTest.)
  // - the reduced mass of the two lengths of line in contact, m_X = (mass per length of X) x (length of X
  //   the patch covers: the intervals of X's own pass, sum of weight / share, or where that pass has no
  //   share the extent of the projections on X). A parallel contact of length L gives mu L; a short bar
  //   across a thick body its own mass, not the body's mass per length times the long interval the body's
  //   pass finds under it (the seed paper's free fall, section 6.2: that overdamped e = 0.9 to 0.57).
  const ContactSample& first = m_samples[static_cast<std::size_t>(patch.front())];
  const auto [lowLine, highLine] = linePair(first);
  const int lines[2] = {lowLine, highLine};
  double passLength[2] = {0.0, 0.0}, lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf},
         perLength[2] = {kInf, kInf};
  double deepest = kInf, deepestMass = kInf, weight = 0.0, mobility = 0.0;
  for (const int i : patch) {
    const ContactSample& x = m_samples[static_cast<std::size_t>(i)];
    if (x.gap < deepest) {
      deepest = x.gap;
      deepestMass = x.pairMass;
    }
    const double w = x.spring * x.length;
    weight += w;
    if (x.pairMass > 0.0) mobility += w / x.pairMass;
    for (int side = 0; side < 2; ++side) {
      const bool own = x.lineA == lines[side];
      if (!own && x.lineB != lines[side]) continue;
      const double arc = own ? x.arcA : x.arcB;
      lo[side] = std::min(lo[side], arc);
      hi[side] = std::max(hi[side], arc);
      perLength[side] = std::min(perLength[side], massPerLength(own ? x.elementA : x.elementB));
      if (own && x.share > 0.0 && lines[0] != lines[1]) passLength[side] += x.length / x.share;
    }
  }
  // No spring force yet (every sample at zero penetration): the deepest point's.
  const double lumped = weight > 0.0 ? (mobility > 0.0 ? weight / mobility : kInf) : deepestMass;
  double lengthMass = kInf;
  if (lines[0] != lines[1]) {
    const double m0 = perLength[0] * std::max(passLength[0], hi[0] - lo[0]);
    const double m1 = perLength[1] * std::max(passLength[1], hi[1] - lo[1]);
    lengthMass = reducedMass(m0, m1);
  } else {
    // Self contact: both sides on one line; the contact length times the reduced mass per length.
    double length = 0.0;
    for (const int i : patch) length += m_samples[static_cast<std::size_t>(i)].length;
    lengthMass = 0.5 * perLength[0] * length;
  }
  if (std::isinf(lumped)) return lengthMass;
  if (std::isinf(lengthMass)) return lumped;
  return std::max(lumped, lengthMass);
}

double DistributedContact::stencilMass(const CentrelineStencil& stencil) const {
  // 1/m = sum N_k^2 / M_k: the instantaneous mass of a point of the centreline.
  double inverse = 0.0;
  for (int k = 0; k < 4; ++k)
    if (stencil.N[k] != 0.0) inverse += stencil.N[k] * stencil.N[k] / nodeMass(stencil.node[k]);
  return inverse > 0.0 ? 1.0 / inverse : kInf;
}

std::vector<ContactSpot> DistributedContact::spots(const model::State& state, double dt, bool dynamic) const {
  std::vector<ContactSpot> out;
  const auto& elements = m_model->elements();
  for (const ContactSample& smp : m_samples) {
    if (smp.lineForce <= 0.0) continue;
    ContactSpot spot;
    // One event per pair of lines whichever line a Gauss point lies on: the lower index is line A.
    const bool swapped = smp.lineA > smp.lineB;
    spot.lineA = swapped ? smp.lineB : smp.lineA;
    spot.lineB = swapped ? smp.lineA : smp.lineB;
    spot.arcA = swapped ? smp.arcB : smp.arcA;
    spot.arcB = swapped ? smp.arcA : smp.arcB;
    spot.position = swapped ? smp.curve.pointB : smp.curve.pointA;
    spot.normal = swapped ? Vec3(-smp.normal) : smp.normal;
    spot.length = smp.length;
    spot.forcePerLength = smp.lineForce;
    spot.force = smp.lineForce * smp.length;
    spot.friction = (swapped ? -smp.length : smp.length) * smp.friction;  // on the lower-index line
    spot.velocityWeight = smp.spring * smp.length;
    // Approach speed before the step (trapezoidal change over the step, as the point formulation).
    const double accelerationRate =
        dynamic && state.acceleration.size() == state.velocity.size()
            ? smp.normal.dot(smp.curve.a.value(m_model->dofs(), state.acceleration) -
                             smp.curve.b.value(m_model->dofs(), state.acceleration))
            : 0.0;  // the rates are the same seen from either line
    spot.approachSpeed = std::max(0.0, -(smp.gapRate - 0.5 * dt * accelerationRate));
    spot.gap = smp.gap;
    spot.pairMass = pairMassPerLength(smp.elementA, smp.elementB) * smp.length;
    spot.stiffness = lineStiffness(smp.lineA, smp.lineB) * smp.length;
    spot.lumpedPairMass = smp.pairMass;
    spot.pointStiffness = pointStiffness(smp.lineA, smp.lineB);
    const Vec3 va = smp.curve.a.value(m_model->dofs(), state.velocity),
               vb = smp.curve.b.value(m_model->dofs(), state.velocity);
    spot.velocityBeforeA = spot.velocityA = swapped ? vb : va;
    spot.velocityBeforeB = spot.velocityB = swapped ? va : vb;
    spot.radii = smp.radii;
    spot.minRadius = std::min(m_radius[smp.elementA], m_radius[smp.elementB]);
    spot.elementLength = std::max(elements[smp.elementA].restLength, elements[smp.elementB].restLength);
    out.push_back(spot);
  }
  return out;
}

Vec3 DistributedContact::pairForce(int lineA, int lineB) const {
  Vec3 total = Vec3::Zero();
  for (const ContactSample& smp : m_samples) {
    const Vec3 f = smp.length * (smp.lineForce * smp.normal + smp.friction);
    if (smp.lineA == lineA && smp.lineB == lineB) total += f;
    if (smp.lineA == lineB && smp.lineB == lineA) total -= f;
  }
  return total;
}

}  // namespace tangle::contact
