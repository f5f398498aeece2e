#include "tangle/contact/LineContact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <tuple>

#include "tangle/contact/CentrelineBlocks.hpp"
#include "tangle/contact/ContactKinematics.hpp"
#include "tangle/contact/ContactLaw.hpp"
#include "tangle/contact/ReducedMass.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::contact {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Automatic contact stiffness: a tenth of the axial stiffness EA / L of the softest element of the
/// line. Penetration under a force F is then F L / (0.1 EA), i.e. ten times the elastic stretch of one
/// element under F: small against the diameters for any force the line itself can carry, while the
/// contact period stays well above typical time steps for chain and wire (see docs/theory.md).
constexpr double kAutoStiffnessFactor = 0.1;
/// Steps per impact duration: the step limiter resolves every dynamic impact with at least this many.
/// The error of the rebound velocity is second order in the step (energy error of the trapezoidal-like
/// step through the spring, about (pi / steps)^2 / 4 of the impact energy): 20 steps gave rebound
/// heights 0.6 to 0.8 % high in the paper's free-fall case (6.2), 40 steps below 0.15 %.
constexpr double kImpactSteps = 40.0;
/// Fraction of the approach speed the relative velocity must have changed by before Eq. 5 replaces the
/// lumped pair mass in the dashpot [-] (see LineContact::commitStep).
constexpr double kEq5UpdateFraction = 0.0005;
/// Largest ratio of the dashpot's Eq. 5 mass to the lumped pair mass at first contact [-]: the impact
/// masses measured in the validation cases are 1.5 (three-element bars) to 4.4 (a flexible landing on
/// another) times the lumped one; larger quotients come from steady loads, not inertia (commitStep).
constexpr double kDashpotMassGrowth = 10.0;
/// Upper bound of the mass an impact between two lines engages [kg]: the reduced mass of two free lines,
/// unbounded (+inf) when either is held (LineContact's constructor).
double pairMassBound(double a, double b) {
  return std::isinf(a) || std::isinf(b) ? std::numeric_limits<double>::infinity() : reducedMass(a, b);
}
/// Contact radius of every element of a model [m]: half its contact diameter.
std::vector<double> elementRadii(const model::Model& model) {
  std::vector<double> radius;
  radius.reserve(model.elements().size());
  for (const model::LineElement& el : model.elements()) radius.push_back(0.5 * el.type->contactDiameter);
  return radius;
}
}  // namespace

LineContact::LineContact(const model::Model& model, const model::ContactSpec& spec, double timeStep)
    : m_model(&model),
      m_spec(spec),
      m_timeStep(timeStep),
      m_zeta(dampingRatioForRestitution(spec.restitution)),
      m_radius(elementRadii(model)),
      m_profile(model, m_radius),
      m_search(model, spec, m_radius),
      m_eventTracker(spec.impactVelocityThreshold, spec.eventSeparationTime),
      m_debug(std::getenv("TANGLE_DEBUG_CONTACT") != nullptr) {
  const int nLines = static_cast<int>(model.lines().size());
  m_lineStiffness.assign(nLines, kInf);
  m_lineMassWithAdded.assign(nLines, 0.0);
  const double rho = model.environment().waterDensity;
  for (int l = 0; l < nLines; ++l) {
    const model::Line& line = model.lines()[l];
    for (int e = 0; e < line.elementCount; ++e) {
      const model::LineElement& el = model.elements()[line.firstElement + e];
      m_lineStiffness[l] =
          std::min(m_lineStiffness[l], kAutoStiffnessFactor * el.type->axialStiffness / el.restLength);
      // Normal added mass Can rho pi/4 D^2 per unit length over the whole line, submerged or not: the
      // upper bound of the mass an impact can engage (ContactEvents.hpp).
      m_lineMassWithAdded[l] += el.type->normalAddedMassPerLength(rho) * el.restLength;
    }
    for (int n = line.firstNode; n <= line.lastNode(); ++n) m_lineMassWithAdded[l] += model.nodeMass()[n];
  }
  for (const model::NodeAttachment& a : model.attachments())
    m_lineMassWithAdded[model.lineOfNode(a.node)] += a.spec.addedMass;
  // A line held at an end (anchored, fixed, pinned, on a vessel) passes impulse on to its support and
  // springs back from it: the mass an impact engages on a held line has no bound (a bar striking a lump on
  // a taut wire engages more than its own mass when the wire throws the lump back, ImpactEnergyTest).
  for (int l = 0; l < nLines; ++l) {
    const model::LineSpec& ls = *model.lines()[l].spec;
    if (ls.endA.kind != model::EndKind::Free || ls.endB.kind != model::EndKind::Free)
      m_lineMassWithAdded[l] = kInf;
  }
  if (spec.formulation == model::ContactFormulation::Distributed) {
    if (spec.model == model::ImpactModel::Impulse)
      throw std::invalid_argument(
          "contact: the velocity-jump (impulse) model belongs to the point formulation: set the "
          "formulation to point, or use the penalty model");
    m_distributed = std::make_unique<DistributedContact>(model, spec, m_radius);
  }
}

double LineContact::stiffness(int a, int b) const {
  return m_spec.stiffness > 0.0 ? m_spec.stiffness : std::min(m_lineStiffness[a], m_lineStiffness[b]);
}

double LineContact::pairStiffness(int a, int b) const {
  return m_distributed ? m_distributed->pointStiffness(a, b) : stiffness(a, b);
}

double LineContact::nodeTransverseMass(int node) const {
  const model::DofMap& dofs = m_model->dofs();
  if (dofs.equation(dofs.firstDof(node)) < 0) return kInf;  // held node: immovable
  return m_model->nodeMass()[node];
}

double LineContact::elementMass(int element) const {
  const model::LineElement& el = m_model->elements()[element];
  const bool held = std::isinf(nodeTransverseMass(el.node1)) && std::isinf(nodeTransverseMass(el.node2));
  return held ? kInf : el.type->totalMassPerLength() * el.restLength;
}

double LineContact::lumpedMass(int element, double w) const {
  // Instantaneous effective mass of the point at parameter w of an element with lumped node masses:
  // 1/m = (1-w)^2/M1 + w^2/M2 (the impulse I at the point changes the point's velocity by I/m).
  const model::LineElement& el = m_model->elements()[element];
  const double inv =
      (1.0 - w) * (1.0 - w) / nodeTransverseMass(el.node1) + w * w / nodeTransverseMass(el.node2);
  return inv > 0.0 ? 1.0 / inv : kInf;
}

Vec3 LineContact::pointValue(const VecX& field, int element, double w) const {
  const model::LineElement& el = m_model->elements()[element];
  const model::DofMap& dofs = m_model->dofs();
  return (1.0 - w) * field.segment<3>(dofs.firstDof(el.node1)) +
         w * field.segment<3>(dofs.firstDof(el.node2));
}

Vec3 LineContact::stencilValue(const VecX& field, const CentrelineStencil& stencil) const {
  return stencil.value(m_model->dofs(), field);
}

double LineContact::stencilMass(const CentrelineStencil& stencil) const {
  double inverse = 0.0;
  for (int k = 0; k < 4; ++k)
    if (stencil.N[k] != 0.0) inverse += stencil.N[k] * stencil.N[k] / nodeTransverseMass(stencil.node[k]);
  return inverse > 0.0 ? 1.0 / inverse : kInf;
}

double LineContact::arcOf(int line, int element, double w) const {
  const model::Line& l = m_model->lines()[line];
  const int i = element - l.firstElement;
  return l.arcLength[i] + w * (l.arcLength[i + 1] - l.arcLength[i]);
}

double LineContact::broadPhaseMargin(const model::State& state, bool dynamic) const {
  // What any node can move within a few nominal steps, plus the largest contact radius.
  double maxSpeed2 = 0.0;  // [m^2/s^2] (one root, not one per node)
  const model::DofMap& dofs = m_model->dofs();
  if (dynamic)
    for (int n = 0; n < m_model->nodeCount(); ++n)
      maxSpeed2 = std::max(maxSpeed2, state.velocity.segment<3>(dofs.firstDof(n)).squaredNorm());
  return m_search.maxRadius() + 4.0 * std::sqrt(maxSpeed2) * m_timeStep;
}

bool LineContact::markLoadedNodes(std::vector<char>& mark) const {
  // Every contact point and line-to-line sample comes from a candidate pair (findContacts' narrow phase).
  m_search.markLoadedNodes(mark);
  return true;
}

void LineContact::findContacts(const model::State& state, bool dynamic, bool refreshBroadPhase, bool trial) {
  if (refreshBroadPhase) refreshCandidates(state);
  const auto& elements = m_model->elements();
  // Narrow phase on every candidate, at the current positions.
  struct Raw {
    int proxyA = 0, proxyB = 0;
    geometry::SegmentDistanceResult d;      // closest points of the chords
    double weight = 0.0;                    // point-to-point weight of the ABC blending
    bool endContact = false;                // chords meet at their ends, one of them a free line end
    CentrelineDistance curve;               // closest points of the smooth centrelines (if weight > 0)
    double distance = 0.0;                  // curve.distance if weight > 0, else d.distance [m]
    bool smoothA = false, smoothB = false;  // measured on the smooth centreline (beams), else the polyline
  };
  const auto atLineEnd = [&](int element, double w) {
    const model::Line& l = m_model->lines()[elements[element].line];
    return (element == l.firstElement && w <= 0.0) ||
           (element == l.firstElement + l.elementCount - 1 && w >= 1.0);
  };
  const auto atSegmentEnd = [](double w) { return w <= 0.0 || w >= 1.0; };
  std::vector<Raw> raw;
  for (const CandidatePair& c : m_search.candidates()) {
    int pa = c.first, pb = c.second;
    if (m_search.proxies()[pa].line > m_search.proxies()[pb].line ||
        (m_search.proxies()[pa].line == m_search.proxies()[pb].line &&
         m_search.proxies()[pa].element > m_search.proxies()[pb].element))
      std::swap(pa, pb);
    const model::LineElement& ea = elements[m_search.proxies()[pa].element];
    const model::LineElement& eb = elements[m_search.proxies()[pb].element];
    const Vec3 &a0 = state.position[ea.node1], &a1 = state.position[ea.node2];
    const Vec3 &b0 = state.position[eb.node1], &b1 = state.position[eb.node2];
    Raw r;
    r.proxyA = pa;
    r.proxyB = pb;
    r.d = geometry::segmentDistance(a0, a1, b0, b1);
    // Candidates a little beyond touching (for a beam, the smooth centreline lies off the chord by up
    // to about (kink angle) L / 8 at a kinked node: a quarter of the element length bounds that) and
    // every pair of the active set.
    r.smoothA = hasSmoothCentreline(*m_model, m_search.proxies()[pa].element);
    r.smoothB = hasSmoothCentreline(*m_model, m_search.proxies()[pb].element);
    const double radii = m_search.proxies()[pa].radius + m_search.proxies()[pb].radius;
    const double bulge = 0.25 * std::max(r.smoothA ? ea.restLength : 0.0, r.smoothB ? eb.restLength : 0.0);
    const bool sticky =
        inNeighbourhood({m_search.proxies()[pa].element, m_search.proxies()[pb].element}, m_sticky);
    if (!sticky && r.d.distance >= (1.0 + 0.05) * radii + bulge) continue;
    // Point-to-point weight of the ABC blending (docs/theory.md 9.3): by the crossing angle of the two
    // elements; 1 for an end contact that the line-to-line part cannot see (both closest points at
    // segment ends, one of them a free line end: lines meeting end to end or end to node).
    r.endContact = atSegmentEnd(r.d.s) && atSegmentEnd(r.d.t) &&
                   (atLineEnd(m_search.proxies()[pa].element, r.d.s) ||
                    atLineEnd(m_search.proxies()[pb].element, r.d.t));
    r.weight =
        r.endContact ? 1.0 : pointToPointWeight(crossingAngle(a0, a1, b0, b1), kBlendLower, kBlendUpper);
    r.distance = r.d.distance;
    if (r.weight > 0.0 && (r.smoothA || r.smoothB)) {
      // The point-to-point part is measured between the smooth centrelines (SmoothCentreline.hpp): a
      // polyline corner would act like a sphere and make Newton cycle between the elements at a node.
      r.curve = centrelineDistance(*m_model, state.position, m_search.proxies()[pa].element,
                                   m_search.proxies()[pb].element, r.d.s, r.d.t);
      r.distance = r.curve.distance;
    }
    raw.push_back(std::move(r));
  }
  if (m_debug)
    std::cerr << fmt::format("      findContacts: {} candidates, {} raw, trial {}, sticky {}\n",
                             m_search.candidates().size(), raw.size(), trial, m_sticky.size());
  // The polyline closest points of two cables (segment parameters; free when inside the segment).
  for (Raw& r : raw) {
    if (r.weight <= 0.0 || r.smoothA || r.smoothB) continue;
    r.curve.s = r.d.s;
    r.curve.t = r.d.t;
    r.curve.sFree = !atSegmentEnd(r.d.s);
    r.curve.tFree = !atSegmentEnd(r.d.t);
    r.curve.a = centrelineStencil(*m_model, m_search.proxies()[r.proxyA].element, r.d.s);
    r.curve.b = centrelineStencil(*m_model, m_search.proxies()[r.proxyB].element, r.d.t);
    r.curve.pointA = r.d.closest0;
    r.curve.pointB = r.d.closest1;
    r.curve.distance = r.distance = r.d.distance;
  }
  // A cable bent at a node towards the other line (a convex kink: a line draped over another, a cable
  // pressed by a line across it) has an interior closest point on each of the two elements at the
  // node, one on each side, about (rA + rB) times the kink angle away from it. They are one physical
  // contact at the fold: both are moved to the node (where the smooth line's closest point is), with
  // the closest point on the other line recomputed. Only when both are at the contact (within the
  // search distance of 1.05 radii) and closer to each other than the sum of the radii (one contact
  // patch): a kinked line near but not at a contact keeps its true closest point. (A beam's smooth
  // centreline has no fold.)
  {
    auto interior = [](double w) { return w > 1e-9 && w < 1.0 - 1e-9; };
    std::vector<int> snapA(raw.size(), -1), snapB(raw.size(), -1);  // -1: keep; 0 / 1: move to that end
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i].weight <= 0.0) continue;
      const SegmentProxy& a = m_search.proxies()[raw[i].proxyA];
      const SegmentProxy& b = m_search.proxies()[raw[i].proxyB];
      const double radii = a.radius + b.radius;
      if (raw[i].distance >= 1.05 * radii) continue;
      const CentrelineDistance& ci = raw[i].curve;
      for (std::size_t j = 0; j < raw.size(); ++j) {
        if (j == i || raw[j].weight <= 0.0) continue;
        const SegmentProxy& a2 = m_search.proxies()[raw[j].proxyA];
        const SegmentProxy& b2 = m_search.proxies()[raw[j].proxyB];
        if (a2.line != a.line || b2.line != b.line) continue;
        if (raw[j].distance >= 1.05 * (a2.radius + b2.radius)) continue;
        const CentrelineDistance& cj = raw[j].curve;
        if (!raw[i].smoothB && b2.element == b.element + 1 &&
            elements[b.element].node2 == elements[b2.element].node1 &&
            std::abs(a2.element - a.element) <= 1 && interior(ci.t) && interior(cj.t) &&
            (ci.pointB - cj.pointB).norm() < radii) {
          snapB[i] = 1;
          snapB[j] = 0;
        }
        if (!raw[i].smoothA && a2.element == a.element + 1 &&
            elements[a.element].node2 == elements[a2.element].node1 &&
            std::abs(b2.element - b.element) <= 1 && interior(ci.s) && interior(cj.s) &&
            (ci.pointA - cj.pointA).norm() < radii) {
          snapA[i] = 1;
          snapA[j] = 0;
        }
      }
    }
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (snapA[i] < 0 && snapB[i] < 0) continue;
      const int elementA = m_search.proxies()[raw[i].proxyA].element,
                elementB = m_search.proxies()[raw[i].proxyB].element;
      const CentrelineDistance& old = raw[i].curve;
      const double s0 = snapA[i] >= 0 ? snapA[i] : old.s, t0 = snapB[i] >= 0 ? snapB[i] : old.t;
      raw[i].curve = centrelineDistance(*m_model, state.position, elementA, elementB, s0, t0, snapA[i] >= 0,
                                        snapB[i] >= 0);
      raw[i].distance = raw[i].curve.distance;
      if (m_debug)
        std::cerr << fmt::format("        kink: e{}-e{} moved to s {:.6f} t {:.6f}\n", elementA, elementB,
                                 raw[i].curve.s, raw[i].curve.t);
    }
  }
  // One contact per local minimum of the distance between the centrelines, among the pairs of the
  // same two lines that are neighbours along both:
  // - two cables (polylines): a minimum at a node is reported by both elements there, and a pair whose
  //   closest point is held at a segment end next to a pair with a smaller distance is not a minimum;
  //   the first pair in a strict total order (distance, then element indices) is kept (a tolerance on
  //   "equal" distances would not be transitive and could drop every pair around a node);
  // - a beam side (smooth centreline): a pair whose closest point is held at the widened end of its
  //   range has its minimum on the neighbouring element, whose pair finds it: dropped. The ranges of
  //   neighbouring elements overlap (kParameterOverlap), so a minimum near a node is found by both
  //   pairs at the same point: of pairs whose closest points are within a hundredth of the radii on
  //   both lines the first in the order is kept; distinct minima on neighbouring elements (a line
  //   draped over another, one foot each side of a bent node) are kept both. A cable side of such a
  //   pair held at a segment end next to a pair with a smaller distance is dropped as above.
  const auto heldAtOverlap = [&](const Raw& r) {
    const double s = r.curve.s, t = r.curve.t;
    const bool sHeld = !r.curve.sFree && (s < 0.0 || s > 1.0);
    const bool tHeld = !r.curve.tFree && (t < 0.0 || t > 1.0);
    return sHeld || tHeld;
  };
  m_trial.clear();
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const SegmentProxy& a = m_search.proxies()[raw[i].proxyA];
    const SegmentProxy& b = m_search.proxies()[raw[i].proxyB];
    if (raw[i].weight <= 0.0 || heldAtOverlap(raw[i])) continue;
    bool keep = true;
    const double same = 0.01 * (a.radius + b.radius);
    for (std::size_t j = 0; j < raw.size() && keep; ++j) {
      if (j == i || raw[j].weight <= 0.0 || heldAtOverlap(raw[j])) continue;
      const SegmentProxy& a2 = m_search.proxies()[raw[j].proxyA];
      const SegmentProxy& b2 = m_search.proxies()[raw[j].proxyB];
      if (a2.line != a.line || b2.line != b.line) continue;
      if (std::abs(a2.element - a.element) > 1 || std::abs(b2.element - b.element) > 1) continue;
      const bool before = std::make_tuple(raw[j].distance, a2.element, b2.element) <
                          std::make_tuple(raw[i].distance, a.element, b.element);
      if (!before) continue;
      const bool samePoint = (raw[j].curve.pointA - raw[i].curve.pointA).norm() <= same &&
                             (raw[j].curve.pointB - raw[i].curve.pointB).norm() <= same;
      // A cable side held at a segment end is not a minimum when the pair across that node (the same
      // element on the other line) is closer: the minimum is there. A closer pair on another element of
      // the other line is a distinct minimum (the two legs of a cable folded over a wire's node).
      const bool heldA = !raw[i].smoothA && !raw[i].curve.sFree;
      const bool heldB = !raw[i].smoothB && !raw[i].curve.tFree;
      const bool acrossHeldNode = (heldA && b2.element == b.element) || (heldB && a2.element == a.element);
      if (samePoint || acrossHeldNode) keep = false;
    }
    if (!keep) continue;
    const CentrelineDistance& d = raw[i].curve;
    ContactPoint c;
    c.lineA = a.line;
    c.lineB = b.line;
    c.elementA = a.element;
    c.elementB = b.element;
    c.curve = d;
    c.s = d.s;
    c.t = d.t;
    c.pointA = d.pointA;
    c.pointB = d.pointB;
    c.sFree = d.sFree;
    c.tFree = d.tFree;
    c.weight = raw[i].weight;
    c.arcA = arcOf(c.lineA, c.elementA, c.s);
    c.arcB = arcOf(c.lineB, c.elementB, c.t);
    // Normal: the direction of the true closest points (never an approximate normal built from
    // smoothed tangents, which is not the closest-point direction on curved lines and gave phantom
    // forces at positive gaps). Its sign is -1 when this element pair has passed through each other
    // since the last committed state (a Newton iterate that overshot), so that the lines are pushed back
    // to the side they came from. Committed states are never crossed (rejectStep, rejectState), so the
    // pair's own chords at that state tell the side. (Comparing with the normal of a contact tracked
    // nearby along the lines is wrong where the normal turns legitimately: the two legs of a cable
    // folded over a wire touch it from sides 90-180 deg apart, and a foot passing from one leg to the
    // other read as a crossing: a gap of minus the distance minus the radii, 80 kN on a 1.6 kg/m wire.)
    const Vec3 diff = c.pointA - c.pointB;
    c.sign = 1.0;
    if (!m_reference.empty()) {
      const model::LineElement& ea = elements[c.elementA];
      const model::LineElement& eb = elements[c.elementB];
      const geometry::SegmentDistanceResult before = geometry::segmentDistance(
          m_reference[ea.node1], m_reference[ea.node2], m_reference[eb.node1], m_reference[eb.node2]);
      // raw[i].d: the same chords' closest points at this state.
      if (before.distance > 1e-12 && passedThrough(c.elementA, c.elementB, before, raw[i].d)) c.sign = -1.0;
    }
    c.normal = diff.norm() > 1e-12 ? Vec3(c.sign * diff.normalized()) : Vec3(Vec3::UnitZ());
    c.gap = c.sign * diff.norm() - a.radius - b.radius;
    const Vec3 va = stencilValue(state.velocity, d.a);
    const Vec3 vb = stencilValue(state.velocity, d.b);
    c.gapRate = c.normal.dot(va - vb);
    c.lumpedMassA = stencilMass(d.a);
    c.lumpedMassB = stencilMass(d.b);
    // Match with a committed contact: same lines, close along both.
    const double reach = 2.0 * (elements[c.elementA].restLength + elements[c.elementB].restLength);
    double best = kInf;
    for (int k = 0; k < static_cast<int>(m_tracked.size()); ++k) {
      const TrackedContact& tr = m_tracked[k];
      if (tr.lineA != c.lineA || tr.lineB != c.lineB) continue;
      const double dist = std::abs(tr.arcA - c.arcA) + std::abs(tr.arcB - c.arcB);
      if (dist < reach && dist < best) {
        best = dist;
        c.track = k;
      }
    }
    if (c.track >= 0 && m_tracked[c.track].pairMass > 0.0) {
      c.pairMass = m_tracked[c.track].pairMass;
    } else if (std::isinf(c.lumpedMassA)) {
      c.pairMass = c.lumpedMassB;
    } else if (std::isinf(c.lumpedMassB)) {
      c.pairMass = c.lumpedMassA;
    } else {
      c.pairMass = c.lumpedMassA * c.lumpedMassB / (c.lumpedMassA + c.lumpedMassB);
    }
    c.stiffness = c.weight * stiffness(c.lineA, c.lineB);
    const bool dashpot = dynamic && m_spec.model == model::ImpactModel::Penalty && std::isfinite(c.pairMass);
    c.damping = dashpot ? c.weight * 2.0 * m_zeta * std::sqrt(stiffness(c.lineA, c.lineB) * c.pairMass) : 0.0;
    // Active set (Wriggers 2006, sec. 6.1): a pair that touches becomes active and stays active for the
    // rest of the step's Newton iterations, with a linear spring even if it pulls, so Newton does not
    // cycle between "in contact" and "free"; at convergence, active pairs that pull are released
    // (updateActiveSet) and the step iterates on. A released pair comes back only if it penetrates
    // clearly (1 % of the radii) and its spring and dashpot push: a pair still overlapping while it
    // separates faster than its spring pushes is past the end of its impact, and letting it back would
    // make it pull again until the release rounds run out and then pull for the whole step.
    // The point slides from pair to pair across nodes, so membership is by neighbourhood.
    const std::pair<int, int> key{c.elementA, c.elementB};
    const double radii = a.radius + b.radius;
    const bool sticky = sameContact(key, c.pointA, c.pointB, radii, m_sticky);
    const bool released = sameContact(key, c.pointA, c.pointB, radii, m_released);
    const bool pushes = c.stiffness * -c.gap + c.damping * -c.gapRate > 0.0;
    const bool touching = c.gap < 0.0 && (!released || (pushes && c.gap < -0.01 * radii));
    if (m_debug)
      std::cerr << fmt::format(
          "        raw e{}-e{} s {:.6f} t {:.6f} dist-r {:.4e} gap {:.4e} sticky {} released {}\n",
          c.elementA, c.elementB, c.s, c.t, d.distance - radii, c.gap, sticky, released);
    if (!sticky && !touching) continue;
    if (trial) m_sticky[key] = ActiveMark{c.pointA, c.pointB};
    c.normalForce = c.stiffness * -c.gap + c.damping * -c.gapRate;  // may be < 0 until released
    if (dynamic && m_spec.frictionCoefficient > 0.0 && c.normalForce > 0.0) {
      const Vec3 vrel = va - vb;
      const Vec3 vt = vrel - c.normal.dot(vrel) * c.normal;
      const double speed = vt.norm();
      c.frictionForce =
          -m_spec.frictionCoefficient * c.normalForce * vt / std::max(speed, m_spec.frictionVelocity);
    }
    m_trial.push_back(c);
  }
}

void LineContact::addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                            solver::SystemMatrix* matrix) {
  const bool refresh = !request.dynamic || !(request.time == m_candidateTime);
  if (refresh) {
    m_margin = broadPhaseMargin(state, request.dynamic);
    m_candidateTime = request.dynamic ? request.time : std::numeric_limits<double>::quiet_NaN();
  }
  m_lastDynamic = request.dynamic && !request.relaxation;
  if (m_distributed) {
    if (refresh) refreshCandidates(state);
    addDistributedForces(state, request, force, matrix);
    return;
  }
  findContacts(state, request.dynamic, refresh, true);
  if (m_debug)
    for (const ContactPoint& c : m_trial)
      std::cerr << fmt::format(
          "      contact e{}-e{} s {:.6f} t {:.6f} gap {:.4e} rate {:.4e} F {:.6e} n "
          "({:.3e},{:.3e},{:.3e})\n",
          c.elementA, c.elementB, c.s, c.t, c.gap, c.gapRate, c.normalForce, c.normal.x(), c.normal.y(),
          c.normal.z());
  const model::DofMap& dofs = m_model->dofs();
  for (const ContactPoint& c : m_trial) {
    // Consistent tangent: the spring k grad(d) grad(d)^T plus the rotation of the normal and the sliding
    // of the closest points, -F Hess(d) (SmoothCentreline.hpp; exact for the free projection
    // parameters); the dashpot c n n^T on the velocities; the friction damping.
    const CentrelineKinematics kin = centrelineKinematics(state.position, c.curve, c.sign, matrix != nullptr);
    const Vec3 f = c.normalForce * c.normal + c.frictionForce;  // force on line A
    for (int i = 0; i < 8; ++i)
      if (kin.weight[i] != 0.0) force.segment<3>(dofs.firstDof(kin.node[i])) -= kin.weight[i] * f;
    if (!matrix) continue;
    const Mat3 nn = c.normal * c.normal.transpose();
    const Eigen::Matrix<double, 24, 24> block =
        request.kf * (c.stiffness * kin.gradient * kin.gradient.transpose() - c.normalForce * kin.hessian);
    Mat3 cBlock = request.cf * c.damping * nn;
    if (c.frictionForce.squaredNorm() > 0.0 && request.cf != 0.0) {
      cBlock += request.cf * m_spec.frictionCoefficient * c.normalForce / m_spec.frictionVelocity *
                (Mat3::Identity() - nn);
    }
    addSlotBlocks(kin, block, cBlock, dofs, *matrix);
  }
  addLineToLineForces(state, request, force, matrix);
  addPointFriction(state, request, force, matrix);
}

bool LineContact::neighbours(const std::pair<int, int>& a, const std::pair<int, int>& b) const {
  const auto& el = m_model->elements();
  return el[a.first].line == el[b.first].line && el[a.second].line == el[b.second].line &&
         std::abs(a.first - b.first) <= 1 && std::abs(a.second - b.second) <= 1;
}

bool LineContact::inNeighbourhood(const std::pair<int, int>& key, const ActiveSet& set) const {
  for (const auto& entry : set)
    if (neighbours(entry.first, key)) return true;
  return false;
}

bool LineContact::sameContact(const std::pair<int, int>& key, const Vec3& pA, const Vec3& pB, double radii,
                              const ActiveSet::value_type& member) const {
  return neighbours(member.first, key) && (member.second.pointA - pA).norm() < 0.5 * radii &&
         (member.second.pointB - pB).norm() < 0.5 * radii;
}

bool LineContact::sameContact(const std::pair<int, int>& key, const Vec3& pA, const Vec3& pB, double radii,
                              const ActiveSet& set) const {
  for (const auto& member : set)
    if (sameContact(key, pA, pB, radii, member)) return true;
  return false;
}

void LineContact::beginStep() {
  if (m_distributed) m_distributed->beginStep();
  m_pendingAnchors.clear();
  m_pendingPointAnchors.clear();
  m_sticky.clear();
  m_released.clear();
  m_releaseRounds = 0;
}

bool LineContact::updateActiveSet() {
  // Release the active pairs that pull (the spring-dashpot never pulls lines together) or no longer
  // overlap. After a few rounds in one step the set is accepted as it is (the remaining pulls are
  // reported as zero force).
  if (m_distributed) return false;  // a smooth law: no active set
  if (++m_releaseRounds > 8) return false;
  bool changed = false;
  for (const ContactPoint& c : m_trial) {
    // Released: a pair that pulls, and a pair whose surfaces have parted (its dashpot would push across
    // the gap while they approach: a force with no overlap, 1.1 kN on a flexible landing on another).
    if (c.normalForce >= 0.0 && c.gap <= 0.0) continue;
    const std::pair<int, int> key{c.elementA, c.elementB};
    const double radii = m_radius[c.elementA] + m_radius[c.elementB];
    for (auto it = m_sticky.begin(); it != m_sticky.end();)
      it = sameContact(key, c.pointA, c.pointB, radii, *it) ? m_sticky.erase(it) : std::next(it);
    m_released[key] = ActiveMark{c.pointA, c.pointB};
    changed = true;
  }
  return changed;
}

bool LineContact::beyondReach(const model::State& state, int elementA, int elementB, double chordGap,
                              double engaged, double step) const {
  const std::vector<ElementCurve>* all = curves();
  if (!all) return false;  // the point formulation's curves are built per query: measured
  const ElementCurve& ca = (*all)[static_cast<std::size_t>(elementA)];
  const ElementCurve& cb = (*all)[static_cast<std::size_t>(elementB)];
  // The curves' gap is at least the chords' less how far each curve strays from its chord; within the
  // smaller radius the pair engages the 1.25-fold growth (m_engaged): measured.
  const double gap = chordGap - searchRangeDeviationBound(ca, state.position) -
                     searchRangeDeviationBound(cb, state.position);
  if (!(gap >= engaged) || !(step > 0.0)) return false;
  // Bounds of the closing speed and acceleration at any pair of the curves' points: each piece's weight bound
  // times the largest of its nodes' values.
  const model::DofMap& dofs = m_model->dofs();
  const bool hasAcceleration = state.acceleration.size() == state.velocity.size();
  double speed = 0.0, acceleration = 0.0;  // [m/s], [m/s^2]
  for (const ElementCurve* c : {&ca, &cb}) {
    double v = 0.0, acc = 0.0;
    for (const int node : c->node) {
      v = std::max(v, state.velocity.segment<3>(dofs.firstDof(node)).norm());
      if (hasAcceleration) acc = std::max(acc, state.acceleration.segment<3>(dofs.firstDof(node)).norm());
    }
    const double w = centrelineWeightBound(*c);
    speed += w * v;
    acceleration += w * acc;
  }
  // The least time to close `gap` at those bounds: speed t + acceleration t^2 / 2 = gap.
  const double fastest = acceleration > 0.0
                             ? 2.0 * gap / (speed + std::sqrt(speed * speed + 2.0 * acceleration * gap))
                         : speed > 0.0 ? gap / speed
                                       : kInf;
  return fastest >= 2.0 * step;
}

double LineContact::limitStep(const model::State& state, double step) {
  double limit = kInf;
  const auto& elements = m_model->elements();
  // Look ahead: candidates within the motion of one nominal step.
  m_margin = broadPhaseMargin(state, true);
  refreshCandidates(state);
  m_candidateTime = std::numeric_limits<double>::quiet_NaN();  // force a refresh at the next assembly
  m_engaged = m_distributed && m_distributed->pressing();
  for (const CandidatePair& cp : m_search.candidates()) {
    const SegmentProxy& a = m_search.proxies()[cp.first];
    const SegmentProxy& b = m_search.proxies()[cp.second];
    const geometry::SegmentDistanceResult d = geometry::segmentDistance(a.a, a.b, b.a, b.b);
    const double radii = a.radius + b.radius;
    double gap = d.distance - radii;
    Vec3 n = d.closest0 - d.closest1;
    Vec3 relativeVelocity = Vec3::Zero(), relativeAcceleration = Vec3::Zero();
    const bool hasAcceleration = state.acceleration.size() == state.velocity.size();
    const bool smoothCables = m_distributed != nullptr;
    if (hasSmoothCentreline(*m_model, a.element, smoothCables) ||
        hasSmoothCentreline(*m_model, b.element, smoothCables)) {
      // The curves' closest points are a minimisation (8-9 % of the random sweeps' CPU went to it here):
      // skipped for a pair that cannot close to touching within twice the step, whose limits below (half
      // the time to touch at the least) are then all at least the step (beyondReach).
      if (beyondReach(state, a.element, b.element, d.distance - radii, std::min(a.radius, b.radius), step))
        continue;
      // A beam's contact is measured on its smooth centreline, which lies off the chord by up to
      // kappa L^2 / 8 (6 cm for a flexible riser of 10 m elements near its touchdown): the chords' gap
      // would see a touch that late and let a nominal step run into it (an unresolved impact, its
      // force applied over the whole step).
      // (Not centrelineMinimum: the least gap of nearly parallel pieces, instead of where the search stops on
      // the valley's floor, halved this call's cost (risers-in-contact: 0.49 -> 0.26 G instructions) but
      // moved the steps of the random sweeps, and three of 60 that ran through stopped (RandomSweepTest's
      // seeds 39, 43 and 9 with 1e-9 faster launches; docs/performance.md).)
      const CentrelineDistance cd = centrelineDistance(*m_model, state.position, a.element, b.element, d.s,
                                                       d.t, false, false, smoothCables, curves());
      gap = cd.distance - radii;
      n = cd.pointA - cd.pointB;
      relativeVelocity = stencilValue(state.velocity, cd.a) - stencilValue(state.velocity, cd.b);
      if (hasAcceleration)
        relativeAcceleration =
            stencilValue(state.acceleration, cd.a) - stencilValue(state.acceleration, cd.b);
    } else {
      relativeVelocity =
          pointValue(state.velocity, a.element, d.s) - pointValue(state.velocity, b.element, d.t);
      if (hasAcceleration)
        relativeAcceleration =
            pointValue(state.acceleration, a.element, d.s) - pointValue(state.acceleration, b.element, d.t);
    }
    if (gap < std::min(a.radius, b.radius)) m_engaged = true;
    if (n.norm() < 1e-12) continue;
    n.normalize();
    // Closing speed and acceleration along the normal: a line at the top of a bounce, or released at rest,
    // is not approaching yet but falls onto the other within the step (a flexible at the apex of its
    // rebound fell 6 mm in a nominal step of 0.1 s and touched at 0.11 m/s, unresolved).
    const double closing = -n.dot(relativeVelocity);                  // [m/s]
    const double closingAcceleration = -n.dot(relativeAcceleration);  // [m/s^2]
    if (closing <= 0.0 && closingAcceleration <= 0.0) continue;
    // Earliest t > 0 with closing t + 1/2 closingAcceleration t^2 = distance (+inf if never) [s].
    const auto timeToClose = [&](double distance) {
      if (distance <= 0.0) return 0.0;
      const double v = closing, acc = closingAcceleration;
      if (std::abs(acc) * distance < 1e-12 * std::max(v * v, 1e-300)) return v > 0.0 ? distance / v : kInf;
      const double discriminant = v * v + 2.0 * acc * distance;
      if (discriminant < 0.0) return kInf;  // stops approaching before it gets there
      const double t = (-v + std::sqrt(discriminant)) / acc;
      return t > 0.0 ? t : kInf;
    };
    limit = std::min(limit, timeToClose(std::max(gap, 0.0) + 0.2 * radii));
    // A dynamic impact about to start (same criterion as below, with the lumped pair mass): the step
    // that reaches it must end where the lines touch, so that the impact starts with a step as short as
    // the ones that resolve it, at its beginning. A step ending in contact would apply the contact
    // force over the whole step (a step of the nominal length swallows an impact that lasts far less,
    // and stops the line); a touch inside an impact step would start the dashpot force c v0 (which
    // jumps at first touch) at the wrong time, an error of order zeta pi / steps in the restitution.
    // Far away (more than two impact steps), half the time to touch (room for accelerations within
    // the step); then up to half a first contact step before the touch at the approach speed (the
    // acceleration error is second order in a step this short). The step in which the lines touch is a
    // sixteenth of an impact step: the dashpot force jumps from 0 to c v0 at the touch, which the integrator
    // sees only at the end of that step (its start force is the one before the touch), an error proportional
    // to the length of that step. The steps that follow grow back twofold per step (DynamicAnalysis).
    if (gap > 0.0) {
      const double toTouch = timeToClose(gap);
      if (!std::isfinite(toTouch)) continue;
      const double touchSpeed = closing + closingAcceleration * toTouch;  // [m/s]
      const double ma = lumpedMass(a.element, d.s), mb = lumpedMass(b.element, d.t);
      // The lumped pair mass and the point stiffness (distributed: a crossing's stiffness at the law's
      // reference penetration, DistributedContact::pointStiffness).
      const double m = reducedMass(ma, mb);
      const double k =
          m_distributed ? m_distributed->pointStiffness(a.line, b.line) : stiffness(a.line, b.line);
      if (std::isfinite(m) && touchSpeed * std::sqrt(m / k) > 1e-3 * std::min(a.radius, b.radius)) {
        const double impactStep =
            (m_distributed ? m_distributed->impactDuration(k, m) : contactDuration(k, m, m_zeta)) /
            kImpactSteps;
        const double firstStep = impactStep / 16.0;
        limit = std::min(limit, toTouch > 2.0 * impactStep ? 0.5 * toTouch
                                : toTouch > firstStep      ? toTouch - 0.5 * firstStep
                                                           : firstStep);
      }
    }
  }
  // Resolve every impact with at least kImpactSteps (40) steps while it lasts. An impact is dynamic when the
  // rigid impact penetration v0 sqrt(m / k) is not negligible (> 1e-3 of the smaller contact radius: a thin
  // line hitting a thick one is judged by its own size); a quasi-static touch needs no resolution in
  // time and keeps the nominal step.
  for (const TrackedContact& tr : m_tracked) {
    if (!(tr.pairMass > 0.0) || std::isinf(tr.pairMass)) continue;
    const double k = stiffness(tr.lineA, tr.lineB);
    const double duration = contactDuration(k, tr.pairMass, m_zeta);
    const double radius = std::min(m_radius[m_model->lines()[tr.lineA].firstElement],
                                   m_radius[m_model->lines()[tr.lineB].firstElement]);
    const bool dynamicImpact = tr.impactVelocity * std::sqrt(tr.pairMass / k) > 1e-3 * radius;
    if (dynamicImpact && state.time - tr.startTime < 2.0 * duration)
      limit = std::min(limit, duration / kImpactSteps);
  }
  (void)elements;
  if (m_distributed) limit = std::min(limit, m_distributed->impactStepLimit());
  if (m_debug) std::cerr << fmt::format("    limitStep: t {:.6e} limit {:.6e}\n", state.time, limit);
  return limit;
}

void LineContact::applyImpulse(model::State& state, const ContactPoint& c, double impulse) const {
  // Through the stencil weights: sum_k M_k dv_k = sum_k w_k I n = I n (momentum conserved, sum N_k = 1),
  // and the point's velocity changes by sum_k N_k^2 I / M_k = I / m (stencilMass).
  const model::DofMap& dofs = m_model->dofs();
  for (int side = 0; side < 2; ++side) {
    const CentrelineStencil& st = side == 0 ? c.curve.a : c.curve.b;
    const double sideSign = side == 0 ? 1.0 : -1.0;
    for (int k = 0; k < 4; ++k) {
      const double m = nodeTransverseMass(st.node[k]);
      if (!std::isfinite(m) || st.N[k] == 0.0) continue;
      state.velocity.segment<3>(dofs.firstDof(st.node[k])) += sideSign * st.N[k] * impulse / m * c.normal;
    }
  }
}

std::string LineContact::rejectStep(const model::State& before, const model::State& after) {
  const auto& elements = m_model->elements();
  if (m_distributed) {
    // At `after` itself (the last assembly may have been of a trial the solver did not keep).
    m_distributed->findSamples(after, m_search, m_lastDynamic, false,
                               m_reference.size() == after.position.size() ? m_reference : after.position);
    if (std::string why = m_distributed->rejectSamples(); !why.empty()) return why;
    if (std::string why = m_distributed->crossedSinceCommit(after); !why.empty()) return why;
  }
  for (const CandidatePair& cp : m_search.candidates()) {
    const SegmentProxy& a = m_search.proxies()[cp.first];
    const SegmentProxy& b = m_search.proxies()[cp.second];
    const model::LineElement& ea = elements[a.element];
    const model::LineElement& eb = elements[b.element];
    const geometry::SegmentDistanceResult d0 =
        geometry::segmentDistance(before.position[ea.node1], before.position[ea.node2],
                                  before.position[eb.node1], before.position[eb.node2]);
    const geometry::SegmentDistanceResult d1 =
        geometry::segmentDistance(after.position[ea.node1], after.position[ea.node2],
                                  after.position[eb.node1], after.position[eb.node2]);
    const double radii = a.radius + b.radius;
    // Far too deep: the step was too long (the distributed formulation's barrier bounds the depth of its
    // own measure, the C1 centrelines, checked above; a kinked cable's chord may lie deeper than that).
    const bool tooDeep = !m_distributed && d1.distance - radii < -0.5 * radii;
    // Tunnelling: the centrelines crossed (the separation vector reversed) within both segments, from a
    // separated state or from one in contact (every committed state is uncrossed: findContacts tells the
    // side of a pair from its chords at the last committed state).
    bool crossed = !tooDeep && d0.distance > 1e-12 && passedThrough(a.element, b.element, d0, d1);
    if (crossed && m_distributed) {
      // The distributed formulation measures the C1 centrelines: a chord of a sharply folded cable can
      // cut through a line the smooth curve wraps. Crossed only if the smooth curves' separation reversed
      // too, at a stationary point inside both.
      const CentrelineDistance c0 = centrelineDistance(*m_model, before.position, a.element, b.element, d0.s,
                                                       d0.t, false, false, true, curves());
      const CentrelineDistance c1 = centrelineDistance(*m_model, after.position, a.element, b.element, d1.s,
                                                       d1.t, false, false, true, curves());
      crossed = c1.sFree && c1.tFree && (c0.pointA - c0.pointB).dot(c1.pointA - c1.pointB) < 0.0;
    }
    if (!tooDeep && !crossed) continue;
    const model::Line& la = m_model->lines()[ea.line];
    const model::Line& lb = m_model->lines()[eb.line];
    const Vec3 where = d1.closest0;
    return fmt::format(
        "lines '{}' and '{}' {} at {:.3f} m along '{}' and {:.3f} m along '{}' (x, y, z = {:.3f}, {:.3f}, "
        "{:.3f} m; surface gap {:.4g} m, sum of contact radii {:.4g} m, change of distance {:.3g} m/s). "
        "Remedies: a larger contact.stiffness (now {:.4g} N/m), larger contact diameters, finer elements "
        "where they touch, or a smaller dynamics.min_time_step",
        la.name, lb.name,
        tooDeep ? "overlap by more than half their contact radii" : "pass through each other",
        arcOf(ea.line, a.element, d1.s), la.name, arcOf(eb.line, b.element, d1.t), lb.name, where.x(),
        where.y(), where.z(), d1.distance - radii, radii,
        (d1.distance - d0.distance) / std::max(after.time - before.time, 1e-300),
        stiffness(ea.line, eb.line));
  }
  return {};
}

void LineContact::commitStep(model::State& state, double dt) {
  if (m_distributed) {
    commitDistributed(state, dt);
    return;
  }
  m_time = state.time;
  m_reference = state.position;
  commitFriction();
  const bool dynamic = dt > 0.0;
  findContacts(state, dynamic, false, false);
  findLineSamples(state, dynamic);
  std::vector<bool> seen(m_tracked.size(), false);
  std::vector<TrackedContact> next;
  std::vector<ContactSpot> spots;
  const auto& elements = m_model->elements();
  for (const ContactPoint& c : m_trial) {
    if (c.normalForce <= 0.0) continue;
    const Vec3 va = stencilValue(state.velocity, c.curve.a);
    const Vec3 vb = stencilValue(state.velocity, c.curve.b);
    ContactSpot spot;
    spot.lineA = c.lineA;
    spot.lineB = c.lineB;
    spot.arcA = c.arcA;
    spot.arcB = c.arcB;
    spot.position = c.pointA;
    spot.normal = c.normal;
    spot.force = c.normalForce;
    spot.approachSpeed = std::max(0.0, -c.gapRate);
    spot.gap = c.gap;
    spot.pairMass = c.pairMass;
    spot.stiffness = stiffness(c.lineA, c.lineB);
    spot.velocityBeforeA = spot.velocityA = va;
    spot.velocityBeforeB = spot.velocityB = vb;
    spot.radii = m_radius[c.elementA] + m_radius[c.elementB];
    spot.minRadius = std::min(m_radius[c.elementA], m_radius[c.elementB]);
    spot.elementLength = std::max(elements[c.elementA].restLength, elements[c.elementB].restLength);
    spot.elementPairMass = reducedMass(elementMass(c.elementA), elementMass(c.elementB));
    spot.linePairMass = pairMassBound(m_lineMassWithAdded[c.lineA], m_lineMassWithAdded[c.lineB]);
    if (c.track >= 0 && !seen[c.track]) {
      seen[c.track] = true;
      TrackedContact tr = m_tracked[c.track];
      tr.impulse += 0.5 * (tr.lastForce + c.normalForce) * dt;
      tr.peakForce = std::max(tr.peakForce, c.normalForce);
      tr.lastForce = c.normalForce;
      tr.lastGapRate = c.gapRate;
      tr.arcA = c.arcA;
      tr.arcB = c.arcB;
      tr.lastVelocityA = va;
      tr.lastVelocityB = vb;
      tr.minGap = std::min(tr.minGap, c.gap);
      tr.path.push_back({state.time, c.arcA, c.arcB});
      // Paper Eq. 5: m_eff = integral F dt / change of the relative normal velocity; used for the
      // dashpot as soon as the impact has slowed the pair measurably (0.05 %; before, the lumped
      // estimate holds). The participating mass of a line is larger than the lumped mass of the
      // nodes at the contact point once the line responds as a whole (a short body hit at its middle
      // node: the whole mass against half of it); the sooner it is used, the closer the restitution.
      // At most kDashpotMassGrowth times the lumped pair mass at first contact: a line landing slowly
      // under its weight (a flexible on another at 0.05 m/s) is first sped up by its weight against the
      // young contact force, and its impulse over a velocity change of a fraction of a percent read as
      // 420 t (the measured impact masses of that landing are 1.4 to 4.4 times the lumped one): a
      // dashpot of 1.2e6 N s/m and a force of 37 kN where the spring carried 4 kN.
      // Only during the impact (two impact durations, as the step limiter): in a contact that lasts
      // (a line pushed along by another) the impulse keeps growing while the velocity does not change,
      // and the quotient, hence the dashpot, would grow without bound.
      const double dv = c.gapRate + tr.impactVelocity;
      const bool impact =
          std::isfinite(tr.pairMass) && tr.pairMass > 0.0 &&
          state.time - tr.startTime <= 2.0 * contactDuration(c.stiffness, tr.pairMass, m_zeta);
      if (impact && tr.impactVelocity > 0.0 && dv > kEq5UpdateFraction * tr.impactVelocity &&
          tr.impulse + tr.jumpImpulse > 0.0)
        tr.pairMass = std::min((tr.impulse + tr.jumpImpulse) / dv, kDashpotMassGrowth * tr.firstPairMass);
      next.push_back(std::move(tr));
    } else {
      TrackedContact tr;
      tr.impactVelocity = std::max(0.0, -c.gapRate);
      if (m_spec.model == model::ImpactModel::Penalty && dt > 0.0) {
        // The approach speed before the step in which the lines touched: the step's change of the
        // relative normal velocity is taken as dt times the mean of the accelerations at its ends, the
        // one before the touch being negligible against the contact's. The same trapezoidal rule gives
        // the impulse of that step below (0.5 F dt), so Eq. 5 is consistent from the first step on.
        const double accelerationRate = c.normal.dot(stencilValue(state.acceleration, c.curve.a) -
                                                     stencilValue(state.acceleration, c.curve.b));
        tr.impactVelocity = std::max(0.0, -(c.gapRate - 0.5 * dt * accelerationRate));
      }
      if (m_spec.model == model::ImpactModel::Impulse && dt > 0.0 && c.gapRate < 0.0 &&
          std::isfinite(c.pairMass)) {
        // The paper's impulse model (Eq. 6-7 with restitution): the relative normal velocity jumps from
        // -v0 to e v0; the impulse I = (1 + e) v0 m_pair goes to the nodes through the shape functions,
        // which conserves momentum exactly for the lumped masses.
        const double impulse = (1.0 + m_spec.restitution) * tr.impactVelocity * c.pairMass;
        applyImpulse(state, c, impulse);
        tr.jumpImpulse = impulse;
      }
      const Vec3 va0 = stencilValue(state.velocity, c.curve.a);
      const Vec3 vb0 = stencilValue(state.velocity, c.curve.b);
      tr.lineA = c.lineA;
      tr.lineB = c.lineB;
      tr.arcA = c.arcA;
      tr.arcB = c.arcB;
      tr.startTime = state.time;
      tr.impulse = 0.5 * c.normalForce * dt;
      tr.pairMass = c.pairMass;
      tr.firstPairMass = c.pairMass;
      tr.peakForce = c.normalForce;
      tr.lastForce = c.normalForce;
      tr.lastGapRate = c.gapRate;
      tr.startVelocityA = va;
      tr.startVelocityB = vb;
      tr.lastVelocityA = va0;
      tr.lastVelocityB = vb0;
      tr.normal = c.normal;
      tr.lumpedMassA = c.lumpedMassA;
      tr.lumpedMassB = c.lumpedMassB;
      tr.minGap = c.gap;
      tr.path.push_back({state.time, c.arcA, c.arcB});
      spot.approachSpeed = tr.impactVelocity;
      spot.jumpImpulse = tr.jumpImpulse;
      spot.velocityA = va0;
      spot.velocityB = vb0;
      next.push_back(std::move(tr));
    }
    spots.push_back(spot);
  }
  m_tracked = std::move(next);
  // Line-to-line Gauss points.
  for (const LineSample& smp : m_samples) {
    if (smp.lineForce <= 0.0) continue;
    ContactSpot spot;
    spot.lineA = smp.lineA;
    spot.lineB = smp.lineB;
    spot.arcA = smp.arcA;
    spot.arcB = smp.arcB;
    const model::LineElement& ea = elements[smp.elementA];
    spot.position = (1.0 - smp.xi) * state.position[ea.node1] + smp.xi * state.position[ea.node2];
    spot.normal = smp.normal;
    spot.length = smp.length;
    spot.forcePerLength = smp.lineForce;
    spot.force = smp.lineForce * smp.length;
    // Approach speed before the step, as for point contacts (trapezoidal change over the step).
    const double accelerationRate =
        dynamic ? smp.normal.dot(pointValue(state.acceleration, smp.elementA, smp.xi) -
                                 pointValue(state.acceleration, smp.elementB, smp.t))
                : 0.0;
    spot.approachSpeed = std::max(0.0, -(smp.gapRate - 0.5 * dt * accelerationRate));
    spot.gap = smp.gap;
    // Reduced mass per unit length of the two lines times the length the point stands for.
    const double muA = lumpedMass(smp.elementA, smp.xi) / elements[smp.elementA].restLength;
    const double muB = lumpedMass(smp.elementB, smp.t) / elements[smp.elementB].restLength;
    const double mu = std::isinf(muA) ? muB : std::isinf(muB) ? muA : muA * muB / (muA + muB);
    spot.pairMass = mu * smp.length;
    spot.stiffness = lineStiffness(smp.elementA, smp.elementB) * smp.length;
    spot.velocityBeforeA = spot.velocityA = pointValue(state.velocity, smp.elementA, smp.xi);
    spot.velocityBeforeB = spot.velocityB = pointValue(state.velocity, smp.elementB, smp.t);
    spot.radii = m_radius[smp.elementA] + m_radius[smp.elementB];
    spot.minRadius = std::min(m_radius[smp.elementA], m_radius[smp.elementB]);
    spot.elementLength = std::max(elements[smp.elementA].restLength, elements[smp.elementB].restLength);
    spot.elementPairMass = reducedMass(elementMass(smp.elementA), elementMass(smp.elementB));
    spot.linePairMass = pairMassBound(m_lineMassWithAdded[smp.lineA], m_lineMassWithAdded[smp.lineB]);
    spots.push_back(spot);
  }
  m_eventTracker.update(
      state.time, dt, dynamic, spots,
      [&](int a, int b, double a0, double a1, double b0, double b1) {
        return gapBetween(state, a, b, a0, a1, b0, b1);
      },
      [&](ContactEvent& e) { estimateContinuum(state, e); });
}

double LineContact::gapBetween(const model::State& state, int lineA, int lineB, double a0, double a1,
                               double b0, double b1) const {
  const model::Line& la = m_model->lines()[lineA];
  const model::Line& lb = m_model->lines()[lineB];
  const auto& elements = m_model->elements();
  double best = kInf;
  for (int i = 0; i < la.elementCount; ++i) {
    if (la.arcLength[i + 1] < a0 || la.arcLength[i] > a1) continue;
    const model::LineElement& ea = elements[la.firstElement + i];
    for (int j = 0; j < lb.elementCount; ++j) {
      if (lb.arcLength[j + 1] < b0 || lb.arcLength[j] > b1) continue;
      if (lineA == lineB && std::abs(i - j) <= 1) continue;
      const model::LineElement& eb = elements[lb.firstElement + j];
      const geometry::SegmentDistanceResult d =
          geometry::segmentDistance(state.position[ea.node1], state.position[ea.node2],
                                    state.position[eb.node1], state.position[eb.node2]);
      best = std::min(
          best, d.distance - m_profile.at(la.firstElement + i, d.s) - m_profile.at(lb.firstElement + j, d.t));
    }
  }
  return best;
}

void LineContact::finish(double time) {
  m_eventTracker.finish(time);
  m_tracked.clear();
}

LineContact::ClearanceBlocks LineContact::clearanceBlocks(const model::State& state, int lineIndex) const {
  const model::Line& line = m_model->lines()[static_cast<std::size_t>(lineIndex)];
  const auto& elements = m_model->elements();
  constexpr int kBlock = kClearanceBlock;
  const std::size_t count = static_cast<std::size_t>((line.elementCount + kBlock - 1) / kBlock);
  ClearanceBlocks b;
  b.lo.resize(count);
  b.hi.resize(count);
  b.radius.assign(count, 0.0);
  for (int j = 0; j < line.elementCount; ++j) {
    const model::LineElement& e = elements[static_cast<std::size_t>(line.firstElement + j)];
    const std::size_t k = static_cast<std::size_t>(j / kBlock);
    const Vec3 lo = state.position[e.node1].cwiseMin(state.position[e.node2]);
    const Vec3 hi = state.position[e.node1].cwiseMax(state.position[e.node2]);
    b.lo[k] = j % kBlock == 0 ? lo : Vec3(b.lo[k].cwiseMin(lo));
    b.hi[k] = j % kBlock == 0 ? hi : Vec3(b.hi[k].cwiseMax(hi));
    b.radius[k] = std::max(b.radius[k], m_profile.largest(line.firstElement + j));
  }
  const std::size_t groups = (count + kBlock - 1) / kBlock;
  b.groupLo.resize(groups);
  b.groupHi.resize(groups);
  b.groupRadius.assign(groups, 0.0);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t g = k / kBlock;
    b.groupLo[g] = k % kBlock == 0 ? b.lo[k] : Vec3(b.groupLo[g].cwiseMin(b.lo[k]));
    b.groupHi[g] = k % kBlock == 0 ? b.hi[k] : Vec3(b.groupHi[g].cwiseMax(b.hi[k]));
    b.groupRadius[g] = std::max(b.groupRadius[g], b.radius[k]);
  }
  // How far the curves clearance() measures lie off the chords.
  const bool smoothCables = m_distributed != nullptr;
  if (!curves() && m_clearanceCurves.empty()) m_clearanceCurves = elementCurves(*m_model, smoothCables);
  const std::vector<ElementCurve>& curveSet = curves() ? *curves() : m_clearanceCurves;
  b.deviation.assign(static_cast<std::size_t>(line.elementCount), 0.0);
  for (int j = 0; j < line.elementCount; ++j) {
    const int e = line.firstElement + j;
    if (!hasSmoothCentreline(*m_model, e, smoothCables)) continue;
    b.deviation[static_cast<std::size_t>(j)] =
        chordDeviationBound(curveSet[static_cast<std::size_t>(e)], state.position);
    b.largestDeviation = std::max(b.largestDeviation, b.deviation[static_cast<std::size_t>(j)]);
  }
  return b;
}

std::array<double, 3> LineContact::clearance(const model::State& state, int lineA, int lineB) const {
  return clearance(state, lineA, lineB, clearanceBlocks(state, lineA), clearanceBlocks(state, lineB));
}

std::vector<std::array<double, 3>> LineContact::clearances(const model::State& state,
                                                           const std::vector<std::array<int, 2>>& pairs) const {
  std::map<int, ClearanceBlocks> blocks;
  const auto of = [&](int line) -> const ClearanceBlocks& {
    auto it = blocks.find(line);
    if (it == blocks.end()) it = blocks.emplace(line, clearanceBlocks(state, line)).first;
    return it->second;
  };
  std::vector<std::array<double, 3>> out;
  out.reserve(pairs.size());
  for (const std::array<int, 2>& p : pairs) {
    const ClearanceBlocks& a = of(p[0]);
    out.push_back(clearance(state, p[0], p[1], a, of(p[1])));
  }
  return out;
}

std::array<double, 3> LineContact::clearance(const model::State& state, int lineA, int lineB,
                                             const ClearanceBlocks& blocksA, const ClearanceBlocks& blocksB) const {
  const model::Line& la = m_model->lines()[lineA];
  const model::Line& lb = m_model->lines()[lineB];
  const auto& elements = m_model->elements();
  std::array<double, 3> best{kInf, 0.0, 0.0};
  int i0 = 0, j0 = 0;  // elements of the nearest pair along each line
  // The gap of the nearest pair at the last call (the lines move little between steps) bounds the minimum:
  // pairs whose boxes are farther apart are culled from the start. Every pair that may attain the minimum is
  // still measured, in the same order: the same result as without it.
  // Element i of A and j of B are measured unless neighbours on one line or across an exclusion
  // (contact.exclude, exclusion_zones, a shared connection: lines at one fairlead or at one point touch there
  // by construction; the clearance is the contact's, which skips them too).
  // Nor a parted element (lines[].failure): its nodes are the ends of two pieces, and the segment between
  // them, hundreds of metres long once the pieces have fallen apart, is no line (the envelope's rule).
  const model::PartedElements& parted = m_model->parted();
  const auto measured = [&](int i, int j) {
    return !(lineA == lineB && std::abs(i - j) <= 1) &&
           m_search.elementPairAllowed(la.firstElement + i, lb.firstElement + j) &&
           !parted.parted(static_cast<std::size_t>(la.firstElement + i), state.time) &&
           !parted.parted(static_cast<std::size_t>(lb.firstElement + j), state.time);
  };
  double seed = kInf;
  std::pair<int, int>& hint = m_clearanceHint[{lineA, lineB}];
  if (hint.first < la.elementCount && hint.second < lb.elementCount && measured(hint.first, hint.second)) {
    const model::LineElement& ea = elements[la.firstElement + hint.first];
    const model::LineElement& eb = elements[lb.firstElement + hint.second];
    const geometry::SegmentDistanceResult d =
        geometry::segmentDistance(state.position[ea.node1], state.position[ea.node2],
                                  state.position[eb.node1], state.position[eb.node2]);
    seed = d.distance - m_profile.at(la.firstElement + hint.first, d.s) -
           m_profile.at(lb.firstElement + hint.second, d.t);
  }
  // Line B's elements in blocks (clearanceBlocks): a box and the largest radius per block, whose distance
  // bound to an element of A culls the whole block at once (a bound below each of its pairs' bounds: the same
  // result). And line A's elements in blocks too: at the start of each, the blocks of B whose boxes are beyond
  // the threshold from its box (then from each of its elements' boxes, and the threshold only falls) are
  // marked and skipped for all its elements at once, first by groups of blocks (a group's box holds its
  // blocks', so its bound is below each of theirs: the same marks); a block of A with every block of B marked
  // is skipped whole. Element by element each block of B cost a box test per element of A: 5 000 per pair of
  // 200-element lines, a tenth of the run of 12 lines apart with contact on all 66 pairs (at each output
  // time, ClashReport::recordClearance). The same pairs are measured in the same order.
  constexpr int kBlock = kClearanceBlock;
  const std::vector<Vec3>&blockLo = blocksB.lo, &blockHi = blocksB.hi;
  const std::vector<double>& blockRadius = blocksB.radius;
  std::vector<char>& blockFar = m_clearanceFar;
  blockFar.assign(blockLo.size(), 0);
  for (int i = 0; i < la.elementCount; ++i) {
    if (i % kBlock == 0) {
      const std::size_t m = static_cast<std::size_t>(i / kBlock);
      const double threshold = std::min({best[0], m_spec.clearanceMargin, seed});
      bool anyNear = false;
      for (std::size_t g = 0; g < blocksB.groupLo.size(); ++g) {
        const std::size_t k0 = g * kBlock, k1 = std::min(k0 + kBlock, blockFar.size());
        if (geometry::boxGap(blocksA.lo[m], blocksA.hi[m], blocksB.groupLo[g], blocksB.groupHi[g]) -
                blocksA.radius[m] - blocksB.groupRadius[g] >
            threshold) {
          std::fill(blockFar.begin() + static_cast<std::ptrdiff_t>(k0),
                    blockFar.begin() + static_cast<std::ptrdiff_t>(k1), 1);
          continue;
        }
        for (std::size_t k = k0; k < k1; ++k) {
          blockFar[k] = geometry::boxGap(blocksA.lo[m], blocksA.hi[m], blockLo[k], blockHi[k]) -
                                    blocksA.radius[m] - blockRadius[k] >
                                threshold
                            ? 1
                            : 0;
          anyNear = anyNear || !blockFar[k];
        }
      }
      if (!anyNear) {
        i += kBlock - 1;
        continue;
      }
    }
    const model::LineElement& ea = elements[la.firstElement + i];
    const Vec3& a0 = state.position[ea.node1];
    const Vec3& a1 = state.position[ea.node2];
    const Vec3 lo = a0.cwiseMin(a1), hi = a0.cwiseMax(a1);
    const double ra = m_profile.largest(la.firstElement + i);
    for (int j = 0; j < lb.elementCount; ++j) {
      if (j % kBlock == 0) {
        const std::size_t k = static_cast<std::size_t>(j / kBlock);
        if (blockFar[k] || geometry::boxGap(lo, hi, blockLo[k], blockHi[k]) - ra - blockRadius[k] >
                               std::min({best[0], m_spec.clearanceMargin, seed})) {
          j += kBlock - 1;
          continue;
        }
      }
      if (!measured(i, j)) continue;
      const model::LineElement& eb = elements[lb.firstElement + j];
      const Vec3& b0 = state.position[eb.node1];
      const Vec3& b1 = state.position[eb.node2];
      const double rb = m_profile.largest(lb.firstElement + j);
      // Box distance lower bound (with the elements' largest radii): skip pairs that cannot beat the best
      // (or the margin).
      const double bound = geometry::boxGap(lo, hi, b0.cwiseMin(b1), b0.cwiseMax(b1)) - ra - rb;
      if (bound > std::min({best[0], m_spec.clearanceMargin, seed})) continue;
      const geometry::SegmentDistanceResult d = geometry::segmentDistance(a0, a1, b0, b1);
      // The surfaces at the closest points (the radius along the lines, as the contact measures it).
      const double gap =
          d.distance - m_profile.at(la.firstElement + i, d.s) - m_profile.at(lb.firstElement + j, d.t);
      if (gap < best[0]) {
        best = {gap, la.arcLength[i] + d.s * (la.arcLength[i + 1] - la.arcLength[i]),
                lb.arcLength[j] + d.t * (lb.arcLength[j + 1] - lb.arcLength[j])};
        i0 = i;
        j0 = j;
      }
    }
  }
  if (std::isfinite(best[0])) hint = {i0, j0};
  // Beams (and with the distributed formulation, cables too) are measured on their smooth centrelines, as
  // contact measures them: the chords' gap is off by up to kappa L^2 / 8 (4 cm for a flexible of 10 m
  // elements near its touchdown, an overlap where the contact saw 1 mm; a wire of 6 m bars kinked over a
  // 0.46 m riser reported a clearance of -0.107 m where the distributed contact pressed 11.5 mm deep).
  // Where the chords are nearer than both lines' largest distance of a piece from its chord (the envelope's
  // bulgeBound, ClearanceEnvelope::onCurves: farther apart both measure the chords), the nearest pair of
  // chords first; then every pair whose chords, less both pieces' distance from them (chordDeviationBound,
  // on their own parts: ownPartsDistance), may come nearer than the best on the curves so far.
  // Where lines lie along each other the nearest chords need not be near the nearest curves: a rope wrapped
  // round a bollard on 0.1 m elements read -1.71 mm from the nearest chords and their neighbours alone where
  // its curves came to -2.36 mm, 0.16 m along it (2026-12-07).
  if (std::isfinite(best[0])) {
    const bool smoothCables = m_distributed != nullptr;
    const std::vector<ElementCurve>& curveSet = curves() ? *curves() : m_clearanceCurves;
    const std::vector<double>&deviationA = blocksA.deviation, &deviationB = blocksB.deviation;
    const double largestA = blocksA.largestDeviation, largestB = blocksB.largestDeviation;
    if (largestA + largestB > 0.0 && best[0] < largestA + largestB) {
      double refined = kInf;
      std::array<double, 3> at = best;
      const auto onCurves = [&](int i, int j, const geometry::SegmentDistanceResult& d) {
        const int ea = la.firstElement + i, eb = lb.firstElement + j;
        const CentrelineDistance c =
            centrelineMinimum(*m_model, state.position, ea, eb, d.s, d.t, smoothCables, &curveSet);
        const double s = std::clamp(c.s, 0.0, 1.0), t = std::clamp(c.t, 0.0, 1.0);
        const double gap = ownPartsDistance(c, curveSet[static_cast<std::size_t>(ea)],
                                            curveSet[static_cast<std::size_t>(eb)], state.position) -
                           m_profile.at(ea, s) - m_profile.at(eb, t);
        if (gap < refined) {
          refined = gap;
          at = {gap, la.arcLength[i] + s * (la.arcLength[i + 1] - la.arcLength[i]),
                lb.arcLength[j] + t * (lb.arcLength[j + 1] - lb.arcLength[j])};
        }
      };
      const auto chords = [&](int i, int j) {
        const model::LineElement& ea = elements[la.firstElement + i];
        const model::LineElement& eb = elements[lb.firstElement + j];
        return geometry::segmentDistance(state.position[ea.node1], state.position[ea.node2],
                                         state.position[eb.node1], state.position[eb.node2]);
      };
      onCurves(i0, j0, chords(i0, j0));
      // The rest, by groups of blocks and blocks of both lines (a box and largest radius bound the chords in
      // it).
      const std::size_t countA = blocksA.lo.size(), countB = blocksB.lo.size();
      const auto beyond = [&](const Vec3& loA, const Vec3& hiA, double rA, const Vec3& loB, const Vec3& hiB,
                              double rB) {
        return geometry::boxGap(loA, hiA, loB, hiB) - rA - rB - largestA - largestB >= refined;
      };
      for (std::size_t ka = 0; ka < countA; ++ka)
        for (std::size_t kb = 0; kb < countB; ++kb) {
          const std::size_t ga = ka / kBlock, gb = kb / kBlock;
          if (kb % kBlock == 0 && beyond(blocksA.groupLo[ga], blocksA.groupHi[ga], blocksA.groupRadius[ga],
                                         blocksB.groupLo[gb], blocksB.groupHi[gb], blocksB.groupRadius[gb])) {
            kb += kBlock - 1;
            continue;
          }
          if (beyond(blocksA.lo[ka], blocksA.hi[ka], blocksA.radius[ka], blocksB.lo[kb], blocksB.hi[kb],
                     blocksB.radius[kb]))
            continue;
          const int iEnd = std::min(static_cast<int>(ka + 1) * kBlock, la.elementCount);
          const int jEnd = std::min(static_cast<int>(kb + 1) * kBlock, lb.elementCount);
          for (int i = static_cast<int>(ka) * kBlock; i < iEnd; ++i)
            for (int j = static_cast<int>(kb) * kBlock; j < jEnd; ++j) {
              if (i == i0 && j == j0) continue;  // measured above
              if (!measured(i, j)) continue;
              const geometry::SegmentDistanceResult d = chords(i, j);
              const double lower = d.distance - m_profile.largest(la.firstElement + i) -
                                   m_profile.largest(lb.firstElement + j) -
                                   deviationA[static_cast<std::size_t>(i)] -
                                   deviationB[static_cast<std::size_t>(j)];
              if (lower < refined) onCurves(i, j, d);
            }
        }
      if (std::isfinite(refined)) best = at;
    }
  }
  if (best[0] > m_spec.clearanceMargin) best[0] = kInf;
  return best;
}

void LineContact::addDistributedForces(const model::State& state, const solver::AssemblyRequest& request,
                                       VecX& force, solver::SystemMatrix* matrix) {
  if (m_reference.size() != state.position.size()) m_reference = state.position;
  m_distributed->setStepScale(request.dynamic && request.cf > 0.0 ? request.kf / request.cf : 0.0);
  m_distributed->findSamples(state, m_search, request.dynamic, request.relaxation, m_reference);
  if (m_debug)
    for (const ContactSample& x : m_distributed->samples())
      std::cerr << fmt::format(
          "      sample e{}-e{} xi {:.9f} t {:.9f} gap {:.6e} rate {:.4e} w {:.6e} f {:.6e} damp {:.4e} fr "
          "({:.4e},{:.4e},{:.4e})\n",
          x.elementA, x.elementB, x.xi, x.t, x.gap, x.gapRate, x.length, x.lineForce, x.damping,
          x.friction.x(), x.friction.y(), x.friction.z());
  m_distributed->addForces(state, request, force, matrix);
}

void LineContact::commitDistributed(const model::State& state, double dt) {
  m_time = state.time;
  const bool dynamic = dt > 0.0;
  if (m_reference.size() != state.position.size()) m_reference = state.position;
  m_distributed->findSamples(state, m_search, dynamic, false, m_reference);
  m_distributed->commitSamples(dynamic ? dt : 0.0);
  m_reference = state.position;
  std::vector<ContactSpot> spots = m_distributed->spots(state, dt, dynamic);
  for (ContactSpot& spot : spots) {
    // The element of each line nearest the spot: the mass bounds of the event (ContactEvents.hpp).
    const auto [ea, wa] = pointAtArc(spot.lineA, spot.arcA);
    const auto [eb, wb] = pointAtArc(spot.lineB, spot.arcB);
    (void)wa;
    (void)wb;
    spot.elementPairMass = reducedMass(elementMass(ea), elementMass(eb));
    spot.linePairMass = pairMassBound(m_lineMassWithAdded[spot.lineA], m_lineMassWithAdded[spot.lineB]);
  }
  m_eventTracker.update(
      state.time, dt, dynamic, spots,
      [&](int a, int b, double a0, double a1, double b0, double b1) {
        return gapBetween(state, a, b, a0, a1, b0, b1);
      },
      [&](ContactEvent& e) { estimateContinuum(state, e); });
}

}  // namespace tangle::contact
