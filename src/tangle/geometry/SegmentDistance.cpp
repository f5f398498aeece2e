#include "tangle/geometry/SegmentDistance.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tangle/core/Error.hpp"

// Round-off (eps = 2.2e-16, theta = angle between the segments, L = segment length):
// - Eberly's numerators b e - c d, b d - a e cancel to theta^2 L^4 from terms of size L^3 |D|, so
//   they carry absolute errors ~eps L^3 |D|; through Binet-Cauchy the cancellation happens once,
//   inside M0 x M1 (relative error ~eps/theta), and s^, t^ come out with relative errors ~eps/theta
//   (checked against long double and by the randomised tests).
// - In region 0 of a nearly parallel pair these errors, though small in (s,t), move the point
//   across the valley of Q, where Q is steep (curvature ~L^2): the distance error would be
//   ~eps L/theta. Recomputing t as the exact minimiser for the computed s puts the point back on
//   the line dQ/dt = 0, along which Q - Qmin = det/c (s - smin)^2 = theta^2 L0^2 (s - smin)^2, so
//   the error drops to ~eps L whatever theta is (the RandomNearlyParallel test fails without it).
// - Treating a pair with sin^2(theta) <= kParallelTolerance as parallel moves the answer along the
//   valley by at most the size of the square, where Q rises by lambda_min |dx|^2 <= 4 theta^2
//   min(L0, L1)^2 (lambda_min <= 2 det/(a + c)): a distance error below 2 theta min(L0, L1), i.e.
//   2e-12 of the segment length, and far less once the distance exceeds theta L.

namespace tangle::geometry {
namespace {

/// num/den clamped to [0, 1] for den >= 0, dividing only when 0 < num < den (Eberly's deferred
/// division; never divides by zero).
double clampedRatio(double num, double den) {
  if (num <= 0.0) return 0.0;
  if (num >= den) return 1.0;
  return num / den;
}

/// Point at parameter u of the segment from x0 to x1 (direction m = x1 - x0); the end points are
/// returned exactly for u = 0 and u = 1.
Vec3 pointAt(const Vec3& x0, const Vec3& x1, const Vec3& m, double u) {
  if (u == 0.0) return x0;
  if (u == 1.0) return x1;
  return x0 + u * m;
}

[[noreturn]] void throwNonFinite(const Vec3& p0, const Vec3& q0) {
  auto text = [](const Vec3& v) {
    return "(" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " + std::to_string(v.z()) + ")";
  };
  throw Error("segmentDistance: non-finite coordinate or overflow (segment 0 starting at " + text(p0) +
              ", segment 1 starting at " + text(q0) + ")");
}

/// The coefficients of Q(s,t) that the search needs (f is not needed: the distance is computed
/// from the closest points).
struct Quadratic {
  double a, b, c, d, e;
};

/// A candidate pair of parameters with its squared distance [m^2].
struct Candidate {
  double s, t, squaredDistance;
};

class Evaluator {
 public:
  Evaluator(const Vec3& p0, const Vec3& p1, const Vec3& m0, const Vec3& q0, const Vec3& q1, const Vec3& m1)
      : m_p0(p0), m_p1(p1), m_m0(m0), m_q0(q0), m_q1(q1), m_m1(m1) {}
  Candidate operator()(double s, double t) const {
    return {s, t, (pointAt(m_p0, m_p1, m_m0, s) - pointAt(m_q0, m_q1, m_m1, t)).squaredNorm()};
  }

 private:
  const Vec3& m_p0;
  const Vec3& m_p1;
  const Vec3& m_m0;
  const Vec3& m_q0;
  const Vec3& m_q1;
  const Vec3& m_m1;
};

/// Exact minimum of Q over the boundary of the unit square: the four edges, each a clamped 1D
/// minimisation (dQ/ds = 2(a s + b t + d), dQ/dt = 2(b s + c t + e)).
Candidate boundaryMinimum(const Quadratic& q, const Evaluator& eval) {
  Candidate best = eval(clampedRatio(-q.d, q.a), 0.0);  // edge t = 0
  const Candidate candidates[] = {
      eval(clampedRatio(-(q.b + q.d), q.a), 1.0),  // edge t = 1
      eval(0.0, clampedRatio(-q.e, q.c)),          // edge s = 0
      eval(1.0, clampedRatio(-(q.b + q.e), q.c)),  // edge s = 1
  };
  for (const Candidate& c : candidates) {
    if (c.squaredDistance < best.squaredDistance) best = c;
  }
  return best;
}

/// Parallel segments (det ~ 0) and zero-length segments. Q is then constant along the valley
/// a s + b t + d = 0 (Eberly 2005: "the gradient of Q is zero on an entire st-line"); in the
/// coordinate x along M0 (x = M0.(X - B0)) segment 0 covers [0, a] and segment 1 goes from
/// x = -d (t = 0) to x = -d - b (t = 1). The middle of the overlap of the two intervals is returned,
/// or the nearest end points when they do not overlap.
Candidate parallelMinimum(const Quadratic& q, const Evaluator& eval) {
  if (q.a == 0.0 && q.c == 0.0) return eval(0.0, 0.0);        // point - point
  if (q.a == 0.0) return eval(0.0, clampedRatio(-q.e, q.c));  // point - segment
  if (q.c == 0.0) return eval(clampedRatio(-q.d, q.a), 0.0);  // segment - point
  if (q.b == 0.0) return boundaryMinimum(q, eval);            // only on underflow of b^2 ~ a c
  const double x0 = -q.d;                                     // x of q0
  const double x1 = -q.d - q.b;                               // x of q1
  const double lo = std::max(0.0, std::min(x0, x1));
  const double hi = std::min(q.a, std::max(x0, x1));
  double x;  // x of the chosen pair on segment 0
  if (lo <= hi) {
    x = 0.5 * (lo + hi);
  } else if (lo > q.a) {  // segment 1 lies beyond the end p1 of segment 0
    x = q.a;
  } else {  // segment 1 lies before the start p0 of segment 0
    x = 0.0;
  }
  const double xOnSegment1 = std::clamp(x, std::min(x0, x1), std::max(x0, x1));
  const double s = std::clamp(x / q.a, 0.0, 1.0);
  const double t = std::clamp((xOnSegment1 - x0) / (x1 - x0), 0.0, 1.0);
  return eval(s, t);
}

}  // namespace

SegmentDistanceResult segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 m0 = p1 - p0;
  const Vec3 m1 = q1 - q0;
  const Vec3 diff = p0 - q0;  // D = B0 - B1
  const Quadratic q{m0.dot(m0), -m0.dot(m1), m1.dot(m1), m0.dot(diff), -m1.dot(diff)};
  const Evaluator eval(p0, p1, m0, q0, q1, m1);
  // a (c) is not finite iff p0 or p1 (q0 or q1) has a non-finite coordinate or |M0|^2 overflows.
  if (!std::isfinite(q.a) || !std::isfinite(q.c)) throwNonFinite(p0, q0);

  // Binet-Cauchy: a c - b^2 = |M0 x M1|^2, b e - c d = n.(M1 x D), b d - a e = n.(M0 x D).
  const Vec3 n = m0.cross(m1);
  const double det = n.squaredNorm();
  const double ac = q.a * q.c;

  Candidate result{0.0, 0.0, 0.0};
  int region = -1;
  bool parallel = false;
  if (det <= kParallelTolerance * ac) {
    parallel = true;
    result = parallelMinimum(q, eval);
  } else {
    const double sNum = n.dot(m1.cross(diff));  // s^ * det
    const double tNum = n.dot(m0.cross(diff));  // t^ * det
    // Region of (s^, t^), tested as (sNum, tNum) against [0, det]^2 to defer the division.
    if (sNum >= 0.0) {
      if (sNum <= det) {
        region = tNum >= 0.0 ? (tNum <= det ? 0 : 3) : 7;
      } else {
        region = tNum >= 0.0 ? (tNum <= det ? 1 : 2) : 8;
      }
    } else {
      region = tNum >= 0.0 ? (tNum <= det ? 5 : 4) : 6;
    }
    const bool nearlyParallel = det <= kNearlyParallel * ac;
    double s = 0.0;
    double t = 0.0;
    switch (region) {
      case 0: {  // interior: (s^, t^) itself
        const double invDet = 1.0 / det;
        s = sNum * invDet;
        t = nearlyParallel ? clampedRatio(-(q.b * s + q.e), q.c) : tNum * invDet;
        break;
      }
      case 1:  // edge s = 1: F(t) = Q(1,t), F'(t)/2 = (b + e) + c t
        s = 1.0;
        t = clampedRatio(-(q.b + q.e), q.c);
        break;
      case 3:  // edge t = 1: F(s) = Q(s,1), F'(s)/2 = (b + d) + a s
        s = clampedRatio(-(q.b + q.d), q.a);
        t = 1.0;
        break;
      case 5:  // edge s = 0: F(t) = Q(0,t), F'(t)/2 = e + c t
        t = clampedRatio(-q.e, q.c);
        break;
      case 7:  // edge t = 0: F(s) = Q(s,0), F'(s)/2 = d + a s
        s = clampedRatio(-q.d, q.a);
        break;
      case 2:  // corner (1,1): Qs(1,1)/2 = a + b + d > 0 -> minimum on edge t = 1, else on s = 1
        if (q.a + q.b + q.d > 0.0) {
          s = clampedRatio(-(q.b + q.d), q.a);
          t = 1.0;
        } else {
          s = 1.0;
          t = clampedRatio(-(q.b + q.e), q.c);
        }
        break;
      case 4:  // corner (0,1): Qs(0,1)/2 = b + d < 0 -> minimum on edge t = 1, else on s = 0
        if (q.b + q.d < 0.0) {
          s = clampedRatio(-(q.b + q.d), q.a);
          t = 1.0;
        } else {
          t = clampedRatio(-q.e, q.c);
        }
        break;
      case 6:  // corner (0,0): Qs(0,0)/2 = d < 0 -> minimum on edge t = 0, else on s = 0
        if (q.d < 0.0) {
          s = clampedRatio(-q.d, q.a);
        } else {
          t = clampedRatio(-q.e, q.c);
        }
        break;
      default:  // 8, corner (1,0): Qs(1,0)/2 = a + d > 0 -> minimum on edge t = 0, else on s = 1
        if (q.a + q.d > 0.0) {
          s = clampedRatio(-q.d, q.a);
        } else {
          s = 1.0;
          t = clampedRatio(-(q.b + q.e), q.c);
        }
        break;
    }
    result = eval(s, t);
  }

  if (!std::isfinite(result.squaredDistance)) throwNonFinite(p0, q0);
  SegmentDistanceResult out;
  out.s = result.s;
  out.t = result.t;
  out.closest0 = pointAt(p0, p1, m0, result.s);
  out.closest1 = pointAt(q0, q1, m1, result.t);
  out.squaredDistance = result.squaredDistance;
  out.distance = std::sqrt(result.squaredDistance);
  out.region = region;
  out.parallel = parallel;
  return out;
}

}  // namespace tangle::geometry
