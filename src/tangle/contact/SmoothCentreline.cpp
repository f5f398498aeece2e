#include "tangle/contact/SmoothCentreline.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "tangle/core/BrentMinimum.hpp"

namespace tangle::contact {

Vec3 CentrelineStencil::value(const model::DofMap& dofs, const VecX& field) const {
  Vec3 v = Vec3::Zero();
  for (int k = 0; k < 4; ++k)
    if (N[k] != 0.0) v += N[k] * field.segment<3>(dofs.firstDof(node[k]));
  return v;
}

bool hasSmoothCentreline(const model::Model& model, int element, bool smoothCables) {
  return smoothCables || model.elements()[element].type->isBeam();
}

ElementCurve elementCurve(const model::Model& model, int element, bool smoothCables) {
  const auto& elements = model.elements();
  const model::LineElement& el = elements[element];
  ElementCurve c;
  c.smooth = hasSmoothCentreline(model, element, smoothCables);
  if (!c.smooth) {
    // A cable's centreline is its polyline (see the header).
    c.node = {el.node1, el.node1, el.node2, el.node2};
    return c;
  }
  const model::Line& line = model.lines()[el.line];
  const int index = element - line.firstElement;
  // A parted neighbour (lines[].failure, at any time) is no neighbour: this element's node there is an end.
  const model::PartedElements& parted = model.parted();
  const auto intact = [&](int e) {
    return !parted.parted(static_cast<std::size_t>(e), std::numeric_limits<double>::infinity());
  };
  const bool hasPrevious = index > 0 && intact(element - 1),
             hasNext = index < line.elementCount - 1 && intact(element + 1);
  const double l1 = el.restLength;
  // Nodal tangents in units of this element's parameter: m1 = a0 x0 + a1 x1 + a2 x2, m2 = b1 x1 + b2 x2 + b3
  // x3 (three-point difference on the rest arc lengths; the chord at a line end). See the header.
  if (hasPrevious) {
    const double l0 = elements[element - 1].restLength;
    const double alpha = l1 / (l0 + l1), beta = l0 / (l0 + l1);
    c.a0 = -alpha * l1 / l0;
    c.a1 = alpha * l1 / l0 - beta;
    c.a2 = beta;
  }
  if (hasNext) {
    const double l2 = elements[element + 1].restLength;
    const double gamma = l2 / (l1 + l2), delta = l1 / (l1 + l2);
    c.b1 = -gamma;
    c.b2 = gamma - delta * l1 / l2;
    c.b3 = delta * l1 / l2;
  }
  c.node = {hasPrevious ? elements[element - 1].node1 : el.node1, el.node1, el.node2,
            hasNext ? elements[element + 1].node2 : el.node2};
  return c;
}

std::vector<ElementCurve> elementCurves(const model::Model& model, bool smoothCables) {
  std::vector<ElementCurve> out;
  out.reserve(model.elements().size());
  for (int e = 0; e < static_cast<int>(model.elements().size()); ++e)
    out.push_back(elementCurve(model, e, smoothCables));
  return out;
}

double chordDeviationBound(const ElementCurve& c, const std::vector<Vec3>& x) {
  if (!c.smooth) return 0.0;
  const Vec3 d = x[c.node[2]] - x[c.node[1]];
  const Vec3 m1 = c.a0 * x[c.node[0]] + c.a1 * x[c.node[1]] + c.a2 * x[c.node[2]];
  const Vec3 m2 = c.b1 * x[c.node[1]] + c.b2 * x[c.node[2]] + c.b3 * x[c.node[3]];
  return 4.0 / 27.0 * ((m1 - d).norm() + (m2 - d).norm());
}

double searchRangeDeviationBound(const ElementCurve& c, const std::vector<Vec3>& x) {
  if (!c.smooth) return 0.0;
  return chordDeviationBound(c, x) + kParameterOverlap * (x[c.node[2]] - x[c.node[1]]).norm();
}

double centrelineWeightBound(const ElementCurve& c) {
  if (!c.smooth) return 1.0;
  return 1.0 + 4.0 / 27.0 *
                   (std::abs(c.a0) + std::abs(c.a1) + std::abs(c.a2) + std::abs(c.b1) + std::abs(c.b2) +
                    std::abs(c.b3));
}

CentrelineStencil centrelineStencil(const model::Model& model, int element, double s, bool smoothCables) {
  return centrelineStencil(elementCurve(model, element, smoothCables), s);
}

namespace {
/// Search range of an element's parameter (widened at interior nodes, see kParameterOverlap): a smooth
/// piece with a neighbour (its outer stencil node is not its own end node) on that side.
std::pair<double, double> parameterRange(const ElementCurve& c) {
  if (!c.smooth) return {0.0, 1.0};
  return {c.node[0] != c.node[1] ? -kParameterOverlap : 0.0,
          c.node[3] != c.node[2] ? 1.0 + kParameterOverlap : 1.0};
}
}  // namespace

namespace {
/// Where searchPieces ends.
struct PieceSearch {
  double s = 0.0, t = 0.0;  ///< [-]
  /// Stopped where V's Hessian is not positive definite and V is flat or falls along its valley
  /// (stopInValley): nearly parallel pieces, whose minimum along the valley the caller finds.
  bool valley = false;
};

/// centrelineDistance's projected Newton method on two pieces (its comment); with stopInValley it returns
/// where it first finds itself in a valley instead of descending along it.
PieceSearch searchPieces(const ElementCurve& curveA, const ElementCurve& curveB,
                         const std::vector<Vec3>& position, double s0, double t0, bool holdS, bool holdT,
                         bool stopInValley) {
  const auto [sLo, sHi] = parameterRange(curveA);
  const auto [tLo, tHi] = parameterRange(curveB);
  const double lo[2] = {sLo, tLo}, hi[2] = {sHi, tHi};
  PieceSearch out;
  double p[2] = {holdS ? s0 : std::clamp(s0, sLo, sHi), holdT ? t0 : std::clamp(t0, tLo, tHi)};
  auto value = [&](const double q[2]) {
    return 0.5 *
           (centrelineStencil(curveA, q[0]).point(position) - centrelineStencil(curveB, q[1]).point(position))
               .squaredNorm();
  };
  auto gradientNorm = [&](const double q[2]) {
    const CentrelineStencil a = centrelineStencil(curveA, q[0]);
    const CentrelineStencil b = centrelineStencil(curveB, q[1]);
    const Vec3 u = a.point(position) - b.point(position);
    double gs = u.dot(a.tangent(position)), gt = -u.dot(b.tangent(position));
    if (holdS || (q[0] <= lo[0] && gs > 0.0) || (q[0] >= hi[0] && gs < 0.0)) gs = 0.0;
    if (holdT || (q[1] <= lo[1] && gt > 0.0) || (q[1] >= hi[1] && gt < 0.0)) gt = 0.0;
    return std::hypot(gs, gt);
  };
  // Projected Newton on V(s, t) = |c_A(s) - c_B(t)|^2 / 2 with bound constraints (Bertsekas 1982): a
  // parameter at a bound whose gradient points out of the range is held; the others take a Newton step
  // (a scaled gradient step where the reduced Hessian is not positive definite), projected on the range,
  // halved until V decreases.
  for (int iteration = 0; iteration < 40; ++iteration) {
    const CentrelineStencil a = centrelineStencil(curveA, p[0]);
    const CentrelineStencil b = centrelineStencil(curveB, p[1]);
    const Vec3 u = a.point(position) - b.point(position);
    const Vec3 ca = a.tangent(position), cb = b.tangent(position);
    const Vec3 caa = a.secondDerivative(position), cbb = b.secondDerivative(position);
    const double g[2] = {u.dot(ca), -u.dot(cb)};
    Eigen::Matrix2d h;
    h << ca.dot(ca) + u.dot(caa), -ca.dot(cb), -ca.dot(cb), cb.dot(cb) - u.dot(cbb);
    bool held[2];
    for (int k = 0; k < 2; ++k)
      held[k] = (k == 0 ? holdS : holdT) || (p[k] <= lo[k] && g[k] > 0.0) || (p[k] >= hi[k] && g[k] < 0.0);
    double step[2] = {0.0, 0.0};
    if (!held[0] && !held[1]) {
      const Eigen::Vector2d gv(g[0], g[1]);
      if (h(0, 0) > 0.0 && h.determinant() > 1e-12 * h(0, 0) * h(1, 1)) {
        const Eigen::Vector2d d = -h.ldlt().solve(gv);
        step[0] = d(0);
        step[1] = d(1);
      } else {
        // Not positive definite: two nearly parallel centrelines, V flat or falling along the valley where
        // s and t move together (curved pieces side by side). Across the valley (h's directions of curvature
        // above 1e-8 of the largest) the Newton step, to its floor; along it (the rest) the step scaled by
        // each parameter's |c'|^2, a descent that drifts down the valley as before (the step limit and the
        // gap's first sample take that lower point: not moving along the valley at all, a wire dropped
        // across a taut wire stopped with a missed impact, DrapeDynamicsTest). The scaled step in both
        // directions ignored the coupling -c_A'.c_B' (as large as the diagonal there): it overshot across
        // the valley twofold and bounced between its walls, 40 iterations for 26 000 of the 107 000 searches
        // of examples/risers-in-contact (30 % of its instructions) without reaching the floor.
        // h's eigenvalues m +- r and the unit eigenvector of the larger in closed form (the iterative
        // solver for a 2 x 2 was 16 % of that run's CPU); the other eigenvector is its normal.
        const double mean = 0.5 * (h(0, 0) + h(1, 1)), half = 0.5 * (h(0, 0) - h(1, 1));
        const double radius = std::hypot(half, h(0, 1));
        const double largest = mean + radius;
        if (stopInValley && !(mean - radius > 1e-8 * largest)) {
          out.valley = true;
          break;
        }
        Eigen::Vector2d across =
            half >= 0.0 ? Eigen::Vector2d(radius + half, h(0, 1)) : Eigen::Vector2d(h(0, 1), radius - half);
        const double acrossNorm = across.norm();
        across = acrossNorm > 0.0 ? Eigen::Vector2d(across / acrossNorm) : Eigen::Vector2d(1.0, 0.0);
        const Eigen::Vector2d along(-across(1), across(0));
        const Eigen::Vector2d scaled(-g[0] / std::max(ca.squaredNorm(), 1e-300),
                                     -g[1] / std::max(cb.squaredNorm(), 1e-300));
        Eigen::Vector2d d = Eigen::Vector2d::Zero();
        const std::array<std::pair<double, Eigen::Vector2d>, 2> directions{
            {{largest, across}, {mean - radius, along}}};
        for (const auto& [curvature, direction] : directions) {
          if (curvature > 1e-8 * largest)
            d -= direction * (direction.dot(gv) / curvature);
          else
            d += direction * direction.dot(scaled);
        }
        step[0] = d(0);
        step[1] = d(1);
      }
    } else {
      for (int k = 0; k < 2; ++k) {
        if (held[k]) continue;
        const double scale = k == 0 ? ca.squaredNorm() : cb.squaredNorm();
        step[k] = -g[k] / (h(k, k) > 0.0 ? h(k, k) : std::max(scale, 1e-300));
      }
    }
    if (std::abs(step[0]) + std::abs(step[1]) < 1e-13) break;
    const double v0 = 0.5 * u.squaredNorm();
    // Converged when the step's predicted decrease of V, -g.step / 2 (the quadratic model's for a Newton
    // step), is below V's round-off: the step is taken, the parameters' error then its square's order, and
    // the search ends. Without this test the iterations went on at the round-off floor while the gradient's
    // noise (eps |x| |c'|, x the coordinates) over a small determinant (nearly parallel pieces) gave steps of
    // 1e-11, each ended by a line search of up to 40 halvings: 6-18 iterations where 4 had converged.
    const double predicted = -0.5 * (g[0] * step[0] + g[1] * step[1]);  // [m^2]
    if (predicted >= 0.0 && predicted <= 16.0 * std::numeric_limits<double>::epsilon() * v0) {
      for (int k = 0; k < 2; ++k) p[k] = std::clamp(p[k] + step[k], lo[k], hi[k]);
      break;
    }
    // Accept a step that lowers V, or (near the minimum, where V changes below its round-off) one
    // that lowers the gradient: the Newton step there converges quadratically.
    const double g0 = std::hypot(held[0] ? 0.0 : g[0], held[1] ? 0.0 : g[1]);
    double lambda = 1.0;
    double q[2];
    bool improved = false;
    // A step that leaves the range is first tried cut where it meets the bound, in its own direction (the
    // parameter there then held at the next iteration). Clamped instead, the step turns off its direction;
    // along a valley (nearly parallel pieces, s and t moving together) that is uphill, and the halvings
    // approached the bound by half the distance per iteration: 10-20 iterations.
    double reach = 1.0;
    int meets = -1;  // the parameter whose bound the step meets first
    for (int k = 0; k < 2; ++k) {
      const double bound = step[k] < 0.0 ? lo[k] : hi[k];
      if (step[k] != 0.0 && (bound - p[k]) / step[k] < reach) {
        reach = (bound - p[k]) / step[k];
        meets = k;
      }
    }
    if (meets >= 0 && reach > 0.0) {
      for (int k = 0; k < 2; ++k) q[k] = std::clamp(p[k] + reach * step[k], lo[k], hi[k]);
      q[meets] = step[meets] < 0.0 ? lo[meets] : hi[meets];
      improved = value(q) < v0;
    }
    for (int halving = 0; halving < 40 && !improved; ++halving, lambda *= 0.5) {
      for (int k = 0; k < 2; ++k) q[k] = std::clamp(p[k] + lambda * step[k], lo[k], hi[k]);
      if (value(q) < v0 || (halving == 0 && gradientNorm(q) < 0.5 * g0)) {
        improved = true;
        break;
      }
    }
    if (!improved) break;
    const double moved = std::abs(q[0] - p[0]) + std::abs(q[1] - p[1]);
    p[0] = q[0];
    p[1] = q[1];
    if (moved < 1e-13) break;
  }
  out.s = p[0];
  out.t = p[1];
  return out;
}

/// The closest points' record of parameters s and t of the two pieces.
CentrelineDistance distanceAt(const ElementCurve& curveA, const ElementCurve& curveB,
                              const std::vector<Vec3>& position, double s, double t, bool holdS, bool holdT) {
  const auto [sLo, sHi] = parameterRange(curveA);
  const auto [tLo, tHi] = parameterRange(curveB);
  CentrelineDistance r;
  r.s = s;
  r.t = t;
  r.sFree = !holdS && s > sLo && s < sHi;
  r.tFree = !holdT && t > tLo && t < tHi;
  r.a = centrelineStencil(curveA, r.s);
  r.b = centrelineStencil(curveB, r.t);
  r.pointA = r.a.point(position);
  r.pointB = r.b.point(position);
  r.distance = (r.pointA - r.pointB).norm();
  return r;
}

/// An element's piece: from the given curves if there are, else made from the model.
ElementCurve curveOf(const model::Model& model, int element, bool smoothCables,
                     const std::vector<ElementCurve>* curves) {
  return curves ? (*curves)[static_cast<std::size_t>(element)] : elementCurve(model, element, smoothCables);
}
}  // namespace

CentrelineDistance centrelineDistance(const model::Model& model, const std::vector<Vec3>& position,
                                      int elementA, int elementB, double s0, double t0, bool holdS,
                                      bool holdT, bool smoothCables,
                                      const std::vector<ElementCurve>* curves) {
  const ElementCurve curveA = curveOf(model, elementA, smoothCables, curves);
  const ElementCurve curveB = curveOf(model, elementB, smoothCables, curves);
  const PieceSearch found = searchPieces(curveA, curveB, position, s0, t0, holdS, holdT, false);
  return distanceAt(curveA, curveB, position, found.s, found.t, holdS, holdT);
}

CentrelineDistance centrelineMinimum(const model::Model& model, const std::vector<Vec3>& position,
                                     int elementA, int elementB, double s0, double t0, bool smoothCables,
                                     const std::vector<ElementCurve>* curves) {
  const ElementCurve curveA = curveOf(model, elementA, smoothCables, curves);
  const ElementCurve curveB = curveOf(model, elementB, smoothCables, curves);
  const PieceSearch found = searchPieces(curveA, curveB, position, s0, t0, false, false, true);
  if (!found.valley) return distanceAt(curveA, curveB, position, found.s, found.t, false, false);
  // Nearly parallel pieces: V is flat or falls along a valley in which s and t move together, and its
  // minimum lies along the valley's floor, often at an end of a range. Along the floor V is
  // f(s) = min over t of V(s, t) (each s's nearest point of B), a function of s alone: its samples at five
  // points of s's range and where the search stopped, then Brent's method between the lowest one's
  // neighbours. (Descending the valley by scaled gradient steps crept towards the minimum and stopped at the
  // iteration cap: 22 910 of examples/risers-in-contact's 107 000 searches, up to 21 cm above the minimum.)
  const auto [sLo, sHi] = parameterRange(curveA);
  const auto [tLo, tHi] = parameterRange(curveB);
  // Both pieces in the power basis about their first nodes (centrelinePowerBasis): c_A(s) - x_B1 and the
  // B piece's offset from x_B1 are then of the elements' size, not the coordinates'.
  const CentrelinePowerBasis pa = centrelinePowerBasis(curveA, position);
  const CentrelinePowerBasis pb = centrelinePowerBasis(curveB, position);
  const Vec3 offset = position[curveA.node[1]] - position[curveB.node[1]];
  double t = found.t;  // the projections' start: the last projection's result
  const auto floor = [&](double s) {
    const Vec3 x = offset + s * (pa.q1 + s * (pa.q2 + s * pa.q3));
    t = nearestOnPiece(pb, x, t, tLo, tHi);
    return 0.5 * (x - t * (pb.q1 + t * (pb.q2 + t * pb.q3))).squaredNorm();
  };
  constexpr int kSamples = 5;
  std::array<std::pair<double, double>, kSamples + 1> samples{};  // (s, f(s)), ascending in s
  for (int k = 0; k < kSamples; ++k)
    samples[static_cast<std::size_t>(k)].first = sLo + (sHi - sLo) * k / (kSamples - 1);
  samples[kSamples].first = found.s;
  std::sort(samples.begin(), samples.end());
  for (auto& [sk, fk] : samples) fk = floor(sk);
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < samples.size(); ++k)
    if (samples[k].second < samples[lowest].second) lowest = k;
  const double a = samples[lowest == 0 ? 0 : lowest - 1].first;
  const double b = samples[std::min(lowest + 1, samples.size() - 1)].first;
  double sBest = samples[lowest].first;
  if (b > a) sBest = core::brentMinimum(floor, a, b, sBest, samples[lowest].second, 1e-9, 40).first;
  floor(sBest);  // its t
  return distanceAt(curveA, curveB, position, sBest, t, false, false);
}

DistanceCurvature distanceCurvature(const std::vector<Vec3>& position, const CentrelineDistance& d,
                                    const std::array<double, 8>& weight) {
  // Mixed derivatives V_xp for the free parameters: column for p is, per slot i, w_i du/dp + (dw_i/dp) u.
  DistanceCurvature c;
  const Vec3 u = d.pointA - d.pointB;
  Vec3 m[2];
  double curvatureTerm[2];
  int nFree = 0;
  if (d.sFree) {
    m[nFree] = d.a.tangent(position);
    curvatureTerm[nFree] = u.dot(d.a.secondDerivative(position));
    for (int i = 0; i < 8; ++i) c.mixed[i][nFree] = weight[i] * m[nFree] + (i < 4 ? d.a.dN[i] : 0.0) * u;
    ++nFree;
  }
  if (d.tFree) {
    m[nFree] = -d.b.tangent(position);
    curvatureTerm[nFree] = -u.dot(d.b.secondDerivative(position));
    for (int i = 0; i < 8; ++i) c.mixed[i][nFree] = weight[i] * m[nFree] + (i < 4 ? 0.0 : -d.b.dN[i - 4]) * u;
    ++nFree;
  }
  if (nFree == 1) {
    const double vpp = m[0].squaredNorm() + curvatureTerm[0];
    if (vpp > 0.0) {
      c.free = 1;
      c.inverse(0, 0) = 1.0 / vpp;
    }
  } else if (nFree == 2) {
    Eigen::Matrix2d vpp;
    vpp << m[0].dot(m[0]) + curvatureTerm[0], m[0].dot(m[1]), m[1].dot(m[0]),
        m[1].dot(m[1]) + curvatureTerm[1];
    const double det = vpp.determinant();
    if (det > 1e-12 * std::abs(vpp(0, 0) * vpp(1, 1))) {
      c.free = 2;
      c.inverse = vpp.inverse();
    }
  }
  return c;
}

CentrelineSlots centrelineSlots(const CentrelineDistance& d, double sign) {
  CentrelineSlots k;
  for (int i = 0; i < 4; ++i) {
    k.node[i] = d.a.node[i];
    k.weight[i] = d.a.N[i];
    k.node[4 + i] = d.b.node[i];
    k.weight[4 + i] = -d.b.N[i];
    k.used[i] = d.a.N[i] != 0.0 || d.a.dN[i] != 0.0 || d.a.ddN[i] != 0.0;
    k.used[4 + i] = d.b.N[i] != 0.0 || d.b.dN[i] != 0.0 || d.b.ddN[i] != 0.0;
  }
  const Vec3 u = d.pointA - d.pointB;
  const double dist = u.norm();
  k.distance = sign * dist;
  k.normal = dist > 0.0 ? Vec3(sign * u / dist) : Vec3(Vec3::UnitZ());
  return k;
}

CentrelineKinematics centrelineKinematics(const std::vector<Vec3>& position, const CentrelineDistance& d,
                                          double sign, bool wantHessian) {
  CentrelineKinematics k;
  static_cast<CentrelineSlots&>(k) = centrelineSlots(d, sign);
  const double dist = std::abs(k.distance);
  for (int i = 0; i < 8; ++i) k.gradient.segment<3>(3 * i) = k.weight[i] * k.normal;
  if (!wantHessian || dist <= 0.0) return k;
  using Mat24 = Eigen::Matrix<double, 24, 24>;
  Mat24 hv = Mat24::Zero();
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) hv.block<3, 3>(3 * i, 3 * j) = k.weight[i] * k.weight[j] * Mat3::Identity();
  const DistanceCurvature c = distanceCurvature(position, d, k.weight);
  if (c.free > 0) {
    Eigen::Matrix<double, 24, 2> bxp = Eigen::Matrix<double, 24, 2>::Zero();
    for (int i = 0; i < 8; ++i)
      for (int a = 0; a < c.free; ++a) bxp.block<3, 1>(3 * i, a) = c.mixed[i][a];
    hv -= bxp.leftCols(c.free) * c.inverse.topLeftCorner(c.free, c.free) * bxp.leftCols(c.free).transpose();
  }
  const Eigen::Matrix<double, 24, 1> g = sign * k.gradient;  // gradient of the unsigned distance
  k.hessian = sign * (hv - g * g.transpose()) / dist;
  return k;
}

}  // namespace tangle::contact

namespace tangle::contact {

double ownPartsDistance(const CentrelineDistance& c, const ElementCurve& a, const ElementCurve& b,
                        const std::vector<Vec3>& position) {
  const double s = std::clamp(c.s, 0.0, 1.0), t = std::clamp(c.t, 0.0, 1.0);
  if (s == c.s && t == c.t) return c.distance;
  return (centrelinePoint(a, s, position) - centrelinePoint(b, t, position)).norm();
}

}  // namespace tangle::contact
