#include "tangle/element/CorotationalBeam.hpp"

#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "tangle/core/Error.hpp"
#include "tangle/element/Jet.hpp"
#include "tangle/element/RotationLogFactor.hpp"

namespace tangle::element {

namespace {

// Independent variables of the energy (N = 9): d = x2 - x1 (0..2), spatial rotation increment of
// triad 1 (3..5) and of triad 2 (6..8). Q_i(dtheta) = exp(dtheta) Q_i.
constexpr int kNumVars = 9;
constexpr int kTheta1 = 3;
constexpr int kTheta2 = 6;
using ForceJet = Jet<kNumVars, 1>;
using TangentJet = Jet<kNumVars, 2>;

// Limits that make the element undefined: coincident nodes, the mean second material axis
// parallel to the chord (the co-rotated frame has no direction), a local rotation of pi.
constexpr double kMinRelativeLength = 1e-12;
constexpr double kMinFrameSine = 1e-10;
constexpr double kMinCosine = -1.0 + 1e-10;

template <class T>
using V3 = std::array<T, 3>;

template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
V3<T> scaled(const V3<T>& a, const T& s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}

/// Deformational quantities in the co-rotated frame (Battini & Pacoste 2002, sec. 2-3).
template <class T>
struct Local {
  T u;                         // axial extension l - L0 [m]
  V3<T> phi1;                  // local rotation vector of node 1, co-rotated components [rad]
  V3<T> phi2;                  // local rotation vector of node 2 [rad]
  std::array<V3<T>, 3> frame;  // e1, e2, e3 (global components)
};

// The triads enter as exp(dtheta_i) Q_i with dtheta_i = variables offset..offset+2 of the jet; the
// expansion exp(S) = I + S + S^2 / 2 + O(3) is exact to second order at dtheta = 0, all a Hessian at 0
// needs. With T = double the triad is used as is (offset ignored).

/// Column c of exp(dtheta) Q as a jet: value c, first derivatives S(e_k) c = e_k x c, second
/// derivatives (S_k S_l + S_l S_k) c / 2 with (S_k S_l c)_r = delta_rl c_k - delta_kl c_r.
template <class T>
V3<T> rotatedColumn(const Vec3& c, int offset) {
  if constexpr (std::is_same_v<T, double>) {
    (void)offset;
    return {c.x(), c.y(), c.z()};
  } else {
    V3<T> col;
    for (int r = 0; r < 3; ++r) {
      T entry(c[r]);
      for (int k = 0; k < 3; ++k) entry.grad(offset + k) = Vec3::Unit(k).cross(c)[r];
      if constexpr (T::kPacked > 0) {
        for (int k = 0; k < 3; ++k) {
          for (int l = k; l < 3; ++l) {
            double h = 0.5 * ((r == l ? c[k] : 0.0) + (r == k ? c[l] : 0.0));
            if (k == l) h -= c[r];
            entry.addHess(offset + k, offset + l, h);
          }
        }
      }
      col[r] = entry;
    }
    return col;
  }
}

/// f = e . (exp(dtheta) c) for a general jet vector e and a constant column c, without forming the
/// jets of exp(dtheta) c (3 fused scalings instead of 3 jet products). At dtheta = 0 (product rule):
///   df/dx_j         = de/dx_j . c + [j = off+k] (c x e)_k
///   d2f/dx_j dx_l   = d2e/dx_j dx_l . c + [l = off+k] (c x de/dx_j)_k + [j = off+k] (c x de/dx_l)_k
///                     + [j = off+k, l = off+m] ((e_m c_k + e_k c_m) / 2 - delta_km e . c).
template <class T>
T dotRotated(const V3<T>& e, const Vec3& c, int offset) {
  if constexpr (std::is_same_v<T, double>) {
    (void)offset;
    return e[0] * c.x() + e[1] * c.y() + e[2] * c.z();
  } else {
    T f = e[0] * c.x();
    f.addScaled(e[1], c.y());
    f.addScaled(e[2], c.z());
    const Vec3 ev(e[0].value(), e[1].value(), e[2].value());
    const Vec3 cxe = c.cross(ev);
    for (int k = 0; k < 3; ++k) f.grad(offset + k) += cxe[k];
    if constexpr (T::kPacked > 0) {
      for (int j = 0; j < T::kSize; ++j) {
        const Vec3 m = c.cross(Vec3(e[0].grad(j), e[1].grad(j), e[2].grad(j)));
        for (int k = 0; k < 3; ++k) {
          // Both mixed terms land on the pair (j, off+k); on the diagonal they are the same entry twice.
          f.addHess(j, offset + k, j == offset + k ? 2.0 * m[k] : m[k]);
        }
      }
      const double ec = ev.dot(c);
      for (int k = 0; k < 3; ++k) {
        for (int l = k; l < 3; ++l) {
          f.addHess(offset + k, offset + l, 0.5 * (ev[l] * c[k] + ev[k] * c[l]) - (k == l ? ec : 0.0));
        }
      }
    }
    return f;
  }
}

/// Local rotation vector log(Rr^T Q) from the co-rotated frame e and the triad exp(dtheta) Q, with the
/// log written as g(c)/2 v (RotationLogFactor.hpp) so that it is smooth at zero rotation.
template <class T>
V3<T> localRotation(const std::array<V3<T>, 3>& e, const Mat3& q, int offset) {
  // R = Rr^T Q, R_ab = e_a . q_b
  const auto r = [&](int a, int b) { return dotRotated(e[a], Vec3(q.col(b)), offset); };
  const V3<T> v{r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1)};
  const T c = (r(0, 0) + r(1, 1) + r(2, 2) - 1.0) * 0.5;
  const double cv = valueOf(c);
  if (!(cv > kMinCosine)) {
    throw Error(
        "CorotationalBeam: local (deformational) rotation reached pi; the element is folded back "
        "on itself (mesh too coarse or load step too large)");
  }
  // The series branch of thetaOverSin is also valid for c slightly above 1 (round-off), so no clamp.
  if constexpr (std::is_same_v<T, double>) {
    return scaled(v, 0.5 * thetaOverSinValue(cv));
  } else {
    const ThetaOverSin g = thetaOverSin(cv);
    const T half = chainRule(c, 0.5 * g.value, 0.5 * g.first, 0.5 * g.second);
    return scaled(v, half);
  }
}

/// Co-rotated frame and local deformations (Crisfield 1990; Battini & Pacoste 2002, eqs. 3-9):
/// e1 = d / l, q = (Q1 e2 + Q2 e2) / 2, e3 = e1 x q / |e1 x q|, e2 = e3 x e1, phi_i = log(Rr^T Q_i),
/// as functions of d and of the rotation increments of the triads (variables 3..5 and 6..8).
template <class T>
Local<T> localDeformation(const V3<T>& d, const Mat3& q1, const Mat3& q2, double l0) {
  Local<T> loc;
  using std::sqrt;
  const T l = sqrt(dot(d, d));
  if (!(valueOf(l) > kMinRelativeLength * l0)) throw Error("CorotationalBeam: the two nodes coincide");
  loc.u = l - l0;
  auto& e = loc.frame;
  e[0] = scaled(d, reciprocal(l));
  const V3<T> q1y = rotatedColumn<T>(q1.col(1), kTheta1);
  const V3<T> q2y = rotatedColumn<T>(q2.col(1), kTheta2);
  const V3<T> q{(q1y[0] + q2y[0]) * 0.5, (q1y[1] + q2y[1]) * 0.5, (q1y[2] + q2y[2]) * 0.5};
  const V3<T> w = cross(e[0], q);
  const T wNorm = sqrt(dot(w, w));
  if (!(valueOf(wNorm) > kMinFrameSine)) {
    throw Error(
        "CorotationalBeam: the mean second triad axis is parallel to the chord; the co-rotated "
        "frame is undefined (local rotation of 90 degrees about a transverse axis)");
  }
  e[2] = scaled(w, reciprocal(wNorm));
  e[1] = cross(e[2], e[0]);
  loc.phi1 = localRotation(e, q1, kTheta1);
  loc.phi2 = localRotation(e, q2, kTheta2);
  return loc;
}

/// Strain energy of the co-rotational Euler-Bernoulli beam (Battini & Pacoste 2002, eq. 12 with the
/// linear local element of Przemieniecki 1968, shear deformation neglected).
template <class T>
T energyOf(const Local<T>& loc, const BeamProperties& p, double l0) {
  const T twist = loc.phi2[0] - loc.phi1[0];
  T bending = loc.phi1[1] * loc.phi1[1] + loc.phi1[1] * loc.phi2[1] + loc.phi2[1] * loc.phi2[1];
  bending += loc.phi1[2] * loc.phi1[2] + loc.phi1[2] * loc.phi2[2] + loc.phi2[2] * loc.phi2[2];
  T energy = loc.u * loc.u * (0.5 * p.axialStiffness / l0);
  energy += twist * twist * (0.5 * p.torsionalStiffness / l0);
  energy += bending * (2.0 * p.bendingStiffness / l0);
  return energy;
}

V3<double> toArray(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

template <class J>
J energyJet(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2, const BeamProperties& p,
            double l0) {
  const Vec3 dv = x2 - x1;
  const V3<J> d{J::variable(dv.x(), 0), J::variable(dv.y(), 1), J::variable(dv.z(), 2)};
  const Local<J> loc = localDeformation(d, q1, q2, l0);
  return energyOf(loc, p, l0);
}

/// Variable of the energy and sign for each of the 12 element DOF [u1, theta1, u2, theta2]
/// (d = x2 - x1, so d d / d u1 = -I and d d / d u2 = +I).
constexpr std::array<int, 12> kVarOfDof{0, 1, 2, 3, 4, 5, 0, 1, 2, 6, 7, 8};
constexpr std::array<double, 12> kSignOfDof{-1, -1, -1, 1, 1, 1, 1, 1, 1, 1, 1, 1};

/// Coefficient of S(phi)^2 in the inverse left Jacobian of SO(3),
/// J_l^-1(phi) = I - S(phi) / 2 + a(theta) S(phi)^2,  a = 1 / theta^2 - (1 + cos theta) / (2 theta sin theta)
/// (e.g. Chirikjian 2011, "Stochastic models, information theory and Lie groups", vol. 2, sec. 10.6), by
/// its Taylor series 1/12 + theta^2/720 + theta^4/30240 below theta = 0.05 (next term theta^6/1209600, under
/// 2e-14 relative there), where the closed form loses digits to cancellation.
double inverseJacobianFactor(double theta) {
  if (theta < 0.05) {
    const double t2 = theta * theta;
    return 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 / 30240.0);
  }
  return 1.0 / (theta * theta) - (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
}

/// d a / d(theta^2) of inverseJacobianFactor (a as a function of s = theta^2, smooth at 0): by the series
/// 1/720 + 2 s / 30240 below theta = 0.05, else a'(theta) / (2 theta) with, since (1 + cos) / sin =
/// cot(theta / 2), a'(theta) = -2 / theta^3 + (theta / sin^2(theta / 2) + 2 cot(theta / 2)) / (4 theta^2).
/// (Near 0.05 the closed form loses ~5 digits to cancellation; the term it scales is of order theta^3
/// against the tangent's O(1) ones.)
double inverseJacobianFactorSlope(double theta) {
  if (theta < 0.05) return 1.0 / 720.0 + 2.0 * theta * theta / 30240.0;
  const double half = 0.5 * theta;
  const double sinHalf = std::sin(half);
  const double slope = -2.0 / (theta * theta * theta) +
                       (theta / (sinHalf * sinHalf) + 2.0 * std::cos(half) / sinHalf) / (4.0 * theta * theta);
  return slope / (2.0 * theta);
}

/// a(|phi|) of inverseJacobianFactor for a plain vector.
double inverseJacobianFactorOf(const V3<double>& phi) {
  return inverseJacobianFactor(std::sqrt(dot(phi, phi)));
}

/// a(|phi|) as a jet, through s = phi . phi (so that it stays differentiable at phi = 0).
template <int N, int Order>
Jet<N, Order> inverseJacobianFactorOf(const V3<Jet<N, Order>>& phi) {
  static_assert(Order == 1, "the force's jets are first order");
  const Jet<N, Order> s = dot(phi, phi);
  const double theta = std::sqrt(s.value());
  return s.chain(inverseJacobianFactor(theta), inverseJacobianFactorSlope(theta), 0.0);
}

/// a / b for plain numbers; a * (1 / b) for jets.
inline double divided(double a, double b) { return a / b; }
template <int N, int Order>
Jet<N, Order> divided(const Jet<N, Order>& a, const Jet<N, Order>& b) {
  return a * reciprocal(b);
}
template <int N, int Order>
Jet<N, Order> divided(const Jet<N, Order>& a, double b) {
  return a * (1.0 / b);
}

/// The internal force as the three vectors dE/dd, dE/dtheta1, dE/dtheta2 (global components).
template <class T>
struct ForceTerms {
  V3<T> d, theta1, theta2;
};

/// Internal force by the closed-form gradient of the energy (Battini & Pacoste 2002, sec. 3, in spatial
/// rotation increments). With the local end loads n = EA u / L0 and m_i = dE/dphi_i, and the variations
///   du = e1 . dd,   dphi_i = J_l^-1(phi_i) Rr^T (dtheta_i - domega_r),
/// where domega_r is the spin of the co-rotated frame Rr = [e1 e2 e3] (q = (Q1 e2 + Q2 e2) / 2,
/// q_a = q . e_a, l the chord length):
///   domega_r = w1 e1 + w2 e2 + w3 e3,  w2 = -e3 . dd / l,  w3 = e2 . dd / l,
///   w1 = (-(q_1 / l) e3 . dd + ((Q1 e2) x e3) . dtheta1 / 2 + ((Q2 e2) x e3) . dtheta2 / 2) / q_2,
/// the force is, with the spatial end moments M_i = Rr J_l^-T(phi_i) m_i and M = M1 + M2,
///   dE/dd = n e1 + (M . e1) (q_1 / (l q_2)) e3 + (M . e2) e3 / l - (M . e3) e2 / l,
///   dE/dtheta_i = M_i - (M . e1) ((Q_i e2) x e3) / (2 q_2).
/// Checked against the automatic derivative of the same energy to round-off (CorotationalBeamTest).
/// T = double: the force. T = a first-order jet in d and the rotation increments (variables 0..8, as the
/// energy's): the force and its derivative, whose symmetric part is the energy's Hessian (see compute).
template <class T>
ForceTerms<T> forceTerms(const V3<T>& d, const Mat3& q1, const Mat3& q2, const BeamProperties& p, double l0) {
  using std::sqrt;
  const Local<T> loc = localDeformation(d, q1, q2, l0);
  const V3<T>& e1 = loc.frame[0];
  const V3<T>& e2 = loc.frame[1];
  const V3<T>& e3 = loc.frame[2];
  const T l = sqrt(dot(d, d));
  const V3<T>& phi1 = loc.phi1;
  const V3<T>& phi2 = loc.phi2;
  const double kt = p.torsionalStiffness / l0, kb = 2.0 * p.bendingStiffness / l0;
  const T twist = phi2[0] - phi1[0];
  const V3<T> m1{-kt * twist, kb * (2.0 * phi1[1] + phi2[1]), kb * (2.0 * phi1[2] + phi2[2])};
  const V3<T> m2{kt * twist, kb * (phi1[1] + 2.0 * phi2[1]), kb * (phi1[2] + 2.0 * phi2[2])};
  // Rr J_l^-T(phi) m = Rr (m + phi x m / 2 + a(theta) phi x (phi x m))   (S^T = -S, (S^2)^T = S^2)
  const auto spatialMoment = [&](const V3<T>& phi, const V3<T>& m) {
    const V3<T> pm = cross(phi, m);
    const V3<T> ppm = cross(phi, pm);
    const T a = inverseJacobianFactorOf(phi);
    V3<T> local;
    for (int k = 0; k < 3; ++k) local[k] = m[k] + 0.5 * pm[k] + a * ppm[k];
    V3<T> out;
    for (int k = 0; k < 3; ++k) out[k] = e1[k] * local[0] + e2[k] * local[1] + e3[k] * local[2];
    return out;
  };
  const V3<T> bigM1 = spatialMoment(phi1, m1);
  const V3<T> bigM2 = spatialMoment(phi2, m2);
  V3<T> bigM;
  for (int k = 0; k < 3; ++k) bigM[k] = bigM1[k] + bigM2[k];
  const V3<T> q1y = rotatedColumn<T>(q1.col(1), kTheta1);
  const V3<T> q2y = rotatedColumn<T>(q2.col(1), kTheta2);
  V3<T> q;
  for (int k = 0; k < 3; ++k) q[k] = 0.5 * (q1y[k] + q2y[k]);
  const T qa = dot(q, e1), qb = dot(q, e2);
  const T n = divided(T(p.axialStiffness * loc.u), l0);
  const T mAxial = dot(bigM, e1);
  const T c3 = divided(T(mAxial * qa), T(l * qb));
  const T c3b = divided(dot(bigM, e2), l);
  const T c2 = divided(dot(bigM, e3), l);
  const T spin = divided(mAxial, T(2.0 * qb));
  const V3<T> r1 = cross(q1y, e3), r2 = cross(q2y, e3);
  ForceTerms<T> f;
  for (int k = 0; k < 3; ++k) {
    f.d[k] = n * e1[k] + c3 * e3[k] + c3b * e3[k] - c2 * e2[k];
    f.theta1[k] = bigM1[k] - spin * r1[k];
    f.theta2[k] = bigM2[k] - spin * r2[k];
  }
  return f;
}

void analyticForce(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2, const BeamProperties& p,
                   double l0, Vec12& f) {
  const ForceTerms<double> t = forceTerms(toArray(x2 - x1), q1, q2, p, l0);
  for (int k = 0; k < 3; ++k) {
    f[k] = -t.d[k];
    f[3 + k] = t.theta1[k];
    f[6 + k] = t.d[k];
    f[9 + k] = t.theta2[k];
  }
}

}  // namespace

CorotationalBeam::CorotationalBeam(const BeamProperties& properties, double restLength)
    : m_props(properties), m_l0(restLength) {
  if (!(properties.axialStiffness > 0.0)) {
    throw Error("CorotationalBeam: axial stiffness EA must be > 0 (got " +
                std::to_string(properties.axialStiffness) + " N)");
  }
  if (!(properties.bendingStiffness > 0.0)) {
    throw Error("CorotationalBeam: bending stiffness EI must be > 0 (got " +
                std::to_string(properties.bendingStiffness) + " N m^2)");
  }
  if (!(properties.torsionalStiffness > 0.0)) {
    throw Error("CorotationalBeam: torsional stiffness GJ must be > 0 (got " +
                std::to_string(properties.torsionalStiffness) + " N m^2)");
  }
  if (!(restLength > 0.0)) {
    throw Error("CorotationalBeam: rest length L0 must be > 0 (got " + std::to_string(restLength) + " m)");
  }
}

void CorotationalBeam::compute(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2,
                               Vec12& internalForce, Mat12* tangent) const {
  if (tangent == nullptr) {
    analyticForce(x1, q1, x2, q2, m_props, m_l0, internalForce);
    return;
  }
  // The closed-form force in first-order jets of the energy's 9 variables: its derivative J. By the
  // Baker-Campbell-Hausdorff formula J = H + (skew terms in the moments), so the Hessian H (the tangent) is
  // the symmetric part of J (the skew part is -S(M_i)/2 on each node's rotation block; see the header).
  // A quarter of the work of the energy's second-order jets (referenceTangent), the beam's
  // largest cost when the matrix is refreshed often (docs/performance.md).
  const Vec3 dv = x2 - x1;
  const V3<ForceJet> d{ForceJet::variable(dv.x(), 0), ForceJet::variable(dv.y(), 1),
                       ForceJet::variable(dv.z(), 2)};
  const ForceTerms<ForceJet> t = forceTerms(d, q1, q2, m_props, m_l0);
  // Force (and its jet) of each energy variable: dE/dd, dE/dtheta1, dE/dtheta2.
  const std::array<const ForceJet*, kNumVars> byVariable{&t.d[0],      &t.d[1],      &t.d[2],
                                                         &t.theta1[0], &t.theta1[1], &t.theta1[2],
                                                         &t.theta2[0], &t.theta2[1], &t.theta2[2]};
  for (int i = 0; i < 12; ++i) {
    const ForceJet& fi = *byVariable[static_cast<std::size_t>(kVarOfDof[i])];
    internalForce[i] = kSignOfDof[i] * fi.value();
    for (int j = i; j < 12; ++j) {
      const ForceJet& fj = *byVariable[static_cast<std::size_t>(kVarOfDof[j])];
      const double k = 0.5 * kSignOfDof[i] * kSignOfDof[j] * (fi.grad(kVarOfDof[j]) + fj.grad(kVarOfDof[i]));
      (*tangent)(i, j) = k;
      (*tangent)(j, i) = k;
    }
  }
}

void CorotationalBeam::referenceTangent(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2,
                                        Vec12& internalForce, Mat12& tangent) const {
  const TangentJet e = energyJet<TangentJet>(x1, q1, x2, q2, m_props, m_l0);
  for (int i = 0; i < 12; ++i) {
    internalForce[i] = kSignOfDof[i] * e.grad(kVarOfDof[i]);
    for (int j = i; j < 12; ++j) {
      const double k = kSignOfDof[i] * kSignOfDof[j] * e.hess(kVarOfDof[i], kVarOfDof[j]);
      tangent(i, j) = k;
      tangent(j, i) = k;
    }
  }
}

BeamSectionForces CorotationalBeam::sectionForces(const Vec3& x1, const Mat3& q1, const Vec3& x2,
                                                  const Mat3& q2) const {
  const Local<double> loc = localDeformation(toArray(x2 - x1), q1, q2, m_l0);
  const double k = m_props.bendingStiffness / m_l0;
  // End moments exerted on the element (gradient of the energy with respect to the local rotations).
  const double m1y = k * (4.0 * loc.phi1[1] + 2.0 * loc.phi2[1]);
  const double m1z = k * (4.0 * loc.phi1[2] + 2.0 * loc.phi2[2]);
  const double m2y = k * (2.0 * loc.phi1[1] + 4.0 * loc.phi2[1]);
  const double m2z = k * (2.0 * loc.phi1[2] + 4.0 * loc.phi2[2]);
  const Vec3 e2(loc.frame[1][0], loc.frame[1][1], loc.frame[1][2]);
  const Vec3 e3(loc.frame[2][0], loc.frame[2][1], loc.frame[2][2]);
  BeamSectionForces f;
  f.axialForce = m_props.axialStiffness * loc.u / m_l0;
  f.torque = m_props.torsionalStiffness / m_l0 * (loc.phi2[0] - loc.phi1[0]);
  // Section moments (exerted by the node-2 side of the line on the node-1 side): the end moment at
  // node 2 and minus the end moment at node 1.
  f.moment1 = -(m1y * e2 + m1z * e3);
  f.moment2 = m2y * e2 + m2z * e3;
  return f;
}

double CorotationalBeam::strainEnergy(const Vec3& x1, const Mat3& q1, const Vec3& x2, const Mat3& q2) const {
  return energyOf(localDeformation(toArray(x2 - x1), q1, q2, m_l0), m_props, m_l0);
}

}  // namespace tangle::element
