/// @file LineToLine.cpp
/// The line-to-line (Gauss-point-to-segment) part of the contact (Meier, Popp & Wall 2016; blended with
/// the point-to-point part by the crossing angle as in Meier, Wall & Popp 2017): for every candidate pair
/// of a slave element (line A) and a master element (line B), the interval of the slave element whose
/// points project orthogonally into the master element and lie closer than the sum of the radii to its
/// axis is found exactly (ContactKinematics.hpp); kGaussPoints Gauss points on that interval carry the
/// regularised penalty line load f(p) (ContactLaw.hpp) along the true closest-point normal. Because the
/// load and its slope vanish at the ends of the interval, the interval bounds need no linearisation.
/// See docs/theory.md, section 9.3.

#include <algorithm>
#include <cmath>
#include <limits>

#include "tangle/contact/ContactKinematics.hpp"
#include "tangle/contact/ContactLaw.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/contact/ReducedMass.hpp"

namespace tangle::contact {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Gauss-Legendre points and weights on [-1, 1].
constexpr double kGaussX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double kGaussW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
static_assert(kGaussPoints == 4);
}  // namespace

double LineContact::lineStiffness(int eA, int eB) const {
  // A parallel contact along one element length is as stiff as one point contact: k_line = k_point / L,
  // L the mean element length of the two.
  const auto& el = m_model->elements();
  const double length = 0.5 * (el[eA].restLength + el[eB].restLength);
  return stiffness(el[eA].line, el[eB].line) / length;
}

double LineContact::lineDamping(int eA, int eB) const {
  // Dashpot per unit length from a fixed per-pair mass per unit length (series of the two lines' masses
  // per length; an immovable line contributes none): c = 2 zeta sqrt(k_line m_pair). It never grows with
  // the contact's history, so a resting contact stays as damped as the impact was (docs/theory.md 9.6).
  const auto& el = m_model->elements();
  const model::Line& la = m_model->lines()[el[eA].line];
  const model::Line& lb = m_model->lines()[el[eB].line];
  auto massPerLength = [&](int e, const model::Line& line) {
    const model::LineElement& x = el[e];
    const double m1 = nodeTransverseMass(x.node1), m2 = nodeTransverseMass(x.node2);
    if (std::isinf(m1) && std::isinf(m2)) return kInfinity;
    (void)line;
    return x.type->totalMassPerLength();
  };
  const double ma = massPerLength(eA, la), mb = massPerLength(eB, lb);
  const double m = reducedMass(ma, mb);
  if (!std::isfinite(m) || m <= 0.0) return 0.0;
  return 2.0 * m_zeta * std::sqrt(lineStiffness(eA, eB) * m);
}

std::pair<int, double> LineContact::pointAtArc(int line, double arc) const {
  const model::Line& l = m_model->lines()[line];
  arc = std::clamp(arc, 0.0, l.length);
  const auto it = std::upper_bound(l.arcLength.begin(), l.arcLength.end(), arc);
  int i = static_cast<int>(it - l.arcLength.begin()) - 1;
  i = std::clamp(i, 0, l.elementCount - 1);
  const double len = l.arcLength[i + 1] - l.arcLength[i];
  return {l.firstElement + i, len > 0.0 ? std::clamp((arc - l.arcLength[i]) / len, 0.0, 1.0) : 0.0};
}

void LineContact::findLineSamples(const model::State& state, bool dynamic) {
  m_samples.clear();
  const auto& elements = m_model->elements();
  for (const CandidatePair& cp : m_search.candidates()) {
    int pa = cp.first, pb = cp.second;
    if (m_search.proxies()[pa].line > m_search.proxies()[pb].line ||
        (m_search.proxies()[pa].line == m_search.proxies()[pb].line && m_search.proxies()[pa].element > m_search.proxies()[pb].element))
      std::swap(pa, pb);
    const SegmentProxy& A = m_search.proxies()[pa];
    const SegmentProxy& B = m_search.proxies()[pb];
    const model::LineElement& ea = elements[A.element];
    const model::LineElement& eb = elements[B.element];
    const Vec3 &a0 = state.position[ea.node1], &a1 = state.position[ea.node2];
    const Vec3 &b0 = state.position[eb.node1], &b1 = state.position[eb.node2];
    const double radii = A.radius + B.radius;
    const double blend = 1.0 - pointToPointWeight(crossingAngle(a0, a1, b0, b1), kBlendLower, kBlendUpper);
    if (blend <= 0.0) continue;
    double xi0 = 0.0, xi1 = 0.0;
    if (!contactInterval(a0, a1, b0, b1, radii, xi0, xi1)) continue;
    const RegularisedPenalty law{lineStiffness(A.element, B.element), kRegularisationFraction * radii};
    const double damping = dynamic && m_spec.model == model::ImpactModel::Penalty ? lineDamping(A.element, B.element) : 0.0;
    // Split the interval where the penetration reaches the regularisation depth p0 (the law's slope has
    // a kink there): Gauss quadrature is then applied to smooth integrands only.
    double cuts[4] = {xi0, xi0, xi1, xi1};
    int nCuts = 2;
    double in0 = 0.0, in1 = 0.0;
    if (contactInterval(a0, a1, b0, b1, radii - law.depth, in0, in1)) {
      cuts[1] = std::max(in0, xi0);
      cuts[2] = std::min(in1, xi1);
      cuts[3] = xi1;
      nCuts = 4;
    } else {
      cuts[1] = xi1;
    }
    for (int piece = 0; piece + 1 < nCuts; ++piece) {
    const double lo = cuts[piece], hi = cuts[piece + 1];
    if (hi <= lo) continue;
    const double jacobian = 0.5 * (hi - lo) * ea.restLength;
    for (int g = 0; g < kGaussPoints; ++g) {
      LineSample smp;
      smp.xi = 0.5 * (lo + hi) + 0.5 * (hi - lo) * kGaussX[g];
      const Vec3 xa = (1.0 - smp.xi) * a0 + smp.xi * a1;
      smp.t = std::clamp(projectOnAxis(xa, b0, b1), 0.0, 1.0);
      const Vec3 diff = xa - ((1.0 - smp.t) * b0 + smp.t * b1);
      const double dist = diff.norm();
      smp.gap = dist - radii;
      if (smp.gap >= 0.0 || dist <= 0.0) continue;
      smp.lineA = A.line;
      smp.lineB = B.line;
      smp.elementA = A.element;
      smp.elementB = B.element;
      smp.normal = diff / dist;
      smp.length = kGaussW[g] * jacobian * blend;
      const double p = -smp.gap;
      const Vec3 va = pointValue(state.velocity, A.element, smp.xi), vb = pointValue(state.velocity, B.element, smp.t);
      smp.gapRate = smp.normal.dot(va - vb);
      smp.damping = damping * law.dampingFraction(p);
      smp.slope = law.slope(p);
      smp.lineForce = std::max(0.0, law.value(p) - smp.damping * smp.gapRate);
      smp.arcA = arcOf(A.line, A.element, smp.xi);
      smp.arcB = arcOf(B.line, B.element, smp.t);
      m_samples.push_back(smp);
    }
    }
  }
}

void LineContact::addLineToLineForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                                      solver::SystemMatrix* matrix) {
  findLineSamples(state, request.dynamic);
  const auto& elements = m_model->elements();
  const model::DofMap& dofs = m_model->dofs();
  for (const LineSample& smp : m_samples) {
    if (smp.lineForce <= 0.0) continue;
    const model::LineElement& ea = elements[smp.elementA];
    const model::LineElement& eb = elements[smp.elementB];
    const int node[4] = {ea.node1, ea.node2, eb.node1, eb.node2};
    const double w[4] = {1.0 - smp.xi, smp.xi, -(1.0 - smp.t), -smp.t};
    const double f = smp.lineForce * smp.length;  // [N]
    for (int i = 0; i < 4; ++i) force.segment<3>(dofs.firstDof(node[i])) -= w[i] * f * smp.normal;
    if (!matrix) continue;
    // Energy-consistent tangent of f(p) along grad(d): k' grad d grad d^T - f Hess d (the slave point is
    // fixed, the master projection t free); the dashpot c n n^T on the velocities.
    const DistanceKinematics kin = distanceKinematics(state.position[ea.node1], state.position[ea.node2],
                                                      state.position[eb.node1], state.position[eb.node2], smp.xi,
                                                      smp.t, false, smp.t > 0.0 && smp.t < 1.0, 1.0, true);
    const Mat12 block = request.kf * smp.length * (smp.slope * kin.gradient * kin.gradient.transpose() - smp.lineForce * kin.hessian);
    const Mat3 cBlock = request.cf * smp.length * smp.damping * smp.normal * smp.normal.transpose();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const Mat3 bij = block.block<3, 3>(3 * i, 3 * j) + w[i] * w[j] * cBlock;
        matrix->add3x3(dofs.firstDof(node[i]), dofs.firstDof(node[j]), bij);
      }
  }
  addFriction(state, request, force, matrix);
}

Vec3 LineContact::pairForce(int lineA, int lineB) const {
  if (m_distributed) return m_distributed->pairForce(lineA, lineB);
  // Each part stores the force on its line A; the force on its line B is the opposite.
  Vec3 total = Vec3::Zero();
  const auto add = [&](int a, int b, const Vec3& onA) {
    if (a == lineA && b == lineB) total += onA;
    if (a == lineB && b == lineA && a != b) total -= onA;
  };
  for (const ContactPoint& c : m_trial)
    add(c.lineA, c.lineB, std::max(0.0, c.normalForce) * c.normal + c.frictionForce);
  for (const LineSample& s : m_samples) add(s.lineA, s.lineB, s.lineForce * s.length * s.normal);
  for (const FrictionPatch& p : m_patches) add(p.lineA, p.lineB, p.force);
  return total;
}

}  // namespace tangle::contact
