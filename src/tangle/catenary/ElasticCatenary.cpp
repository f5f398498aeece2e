/// @file ElasticCatenary.cpp
/// Elastic catenary (Jonkman 2007; Irvine 1981) solved by Newton's method on (H, V), and the
/// initial-shape generator built on it. Equations: docs/theory.md (section 4).

#include "tangle/catenary/ElasticCatenary.hpp"
#include "tangle/catenary/MultiSectionCatenary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

#include "tangle/core/Error.hpp"

namespace tangle::catenary {
namespace {

/// Backtracking halvings of a Newton step before the step is taken anyway.
constexpr int kMaxHalvings = 40;
/// A Newton step may shrink H (and, on an anchored line, V) by at most this factor.
constexpr double kMaxShrink = 0.1;
/// Arc lengths within this fraction of L from an end return that end exactly (initialLineShape).
constexpr double kEndSnap = 1e-12;
/// Residual accepted at the round-off floor when the Newton step no longer changes (H, V),
/// relative to max(L, X, |Z|).
constexpr double kRoundOffTolerance = 1e-9;

std::string describe(const CatenaryInput& in) {
  std::ostringstream os;
  os.precision(10);
  os << "X = " << in.span << " m, Z = " << in.height << " m, L = " << in.length << " m, w = " << in.weight
     << " N/m, EA = " << in.axialStiffness << " N";
  return os.str();
}

/// Axial compliance 1/EA [1/N]; 0 for an inextensible line (EA = +infinity).
double complianceOf(const CatenaryInput& in) {
  return std::isinf(in.axialStiffness) ? 0.0 : 1.0 / in.axialStiffness;
}

void validate(const CatenaryInput& in, const CatenaryOptions& options, const char* who) {
  if (options.maxIterations < 0 || !(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
    throw Error(std::string(who) + ": CatenaryOptions need maxIterations >= 0 and a finite tolerance > 0");
  }
  const auto fail = [&](const std::string& what) {
    throw Error(std::string(who) + ": " + what + " (" + describe(in) + ")");
  };
  if (!std::isfinite(in.span) || in.span < 0.0) fail("span X must be finite and >= 0");
  if (!std::isfinite(in.height)) fail("height Z must be finite");
  if (!std::isfinite(in.length) || in.length <= 0.0) fail("length L must be finite and > 0");
  if (!std::isfinite(in.weight) || in.weight <= 0.0) fail("submerged weight w must be finite and > 0");
  if (std::isnan(in.axialStiffness) || in.axialStiffness <= 0.0) fail("axial stiffness EA must be > 0");
}

/// asinh(a) - asinh(b) without cancellation, from sinh(p - q) = sinh p cosh q - cosh p sinh q.
/// d = a - b is passed separately because callers know it accurately (w L / H), while a and b may
/// be huge and nearly equal on a taut line.
double asinhDifference(double a, double b, double d) {
  const double ra = std::hypot(1.0, a);
  const double rb = std::hypot(1.0, b);
  if (a * b <= 0.0) return std::asinh(a * rb - b * ra);
  return std::asinh(d * (a + b) / (a * rb + b * ra));
}

/// sqrt(1 + a^2) - sqrt(1 + b^2) without cancellation, d = a - b (see asinhDifference).
double rootDifference(double a, double b, double d) {
  return d * (a + b) / (std::hypot(1.0, a) + std::hypot(1.0, b));
}

/// a / sqrt(1 + a^2) - b / sqrt(1 + b^2) without cancellation, d = a - b.
double sineDifference(double a, double b, double d) {
  const double ra = std::hypot(1.0, a);
  const double rb = std::hypot(1.0, b);
  if (a * b <= 0.0) return a / ra - b / rb;
  // (a rb - b ra) / (ra rb) with a rb - b ra = d (a + b) / (a rb + b ra).
  return d * (a + b) / ((a * rb + b * ra) * ra * rb);
}

/// 1 / sqrt(1 + a^2) - 1 / sqrt(1 + b^2) without cancellation, d = a - b.
double cosineDifference(double a, double b, double d) {
  const double ra = std::hypot(1.0, a);
  const double rb = std::hypot(1.0, b);
  return -d * (a + b) / (ra * rb * (ra + rb));
}

/// End-B position (x, z) relative to end A for given (H, V), and its Jacobian.
struct EndEvaluation {
  double x = 0.0;
  double z = 0.0;
  double dxdH = 0.0;
  double dxdV = 0.0;
  double dzdH = 0.0;
  double dzdV = 0.0;
};

/// Fully suspended elastic catenary (Jonkman 2007; Irvine 1981 eqs. for the elastic catenary):
///   X = H/w [asinh(V/H) - asinh((V - wL)/H)] + H L / EA
///   Z = H/w [sqrt(1 + (V/H)^2) - sqrt(1 + ((V - wL)/H)^2)] + (V L - w L^2 / 2) / EA
EndEvaluation evaluateSuspended(double h, double v, double length, double w, double c) {
  const double a = v / h;
  const double b = (v - w * length) / h;
  const double d = w * length / h;  // a - b, accurate even when a and b are huge
  const double asinhDiff = asinhDifference(a, b, d);
  const double sineDiff = sineDifference(a, b, d);
  EndEvaluation e;
  e.x = h / w * asinhDiff + h * c * length;
  e.z = h / w * rootDifference(a, b, d) + c * (v * length - 0.5 * w * length * length);
  e.dxdH = (asinhDiff - sineDiff) / w + c * length;
  e.dxdV = cosineDifference(a, b, d) / w;
  e.dzdH = e.dxdV;
  e.dzdV = sineDiff / w + c * length;
  return e;
}

/// Elastic catenary with a grounded portion Lb = L - V/w on a frictionless seabed (Jonkman 2007, CB = 0):
///   X = L - V/w + H/w asinh(V/H) + H L / EA
///   Z = H/w [sqrt(1 + (V/H)^2) - 1] + V^2 / (2 w EA)
EndEvaluation evaluateGrounded(double h, double v, double length, double w, double c) {
  const double a = v / h;
  const double ra = std::hypot(1.0, a);
  EndEvaluation e;
  e.x = length - v / w + h / w * std::asinh(a) + h * c * length;
  e.z = h / w * a * a / (ra + 1.0) + c * v * v / (2.0 * w);
  e.dxdH = (std::asinh(a) - a / ra) / w + c * length;
  e.dxdV = -a * a / (ra * (ra + 1.0)) / w;  // (1/ra - 1)/w
  e.dzdH = e.dxdV;
  e.dzdV = a / (ra * w) + c * v / w;
  return e;
}

/// Anchored line: grounded equations while V < wL, suspended ones beyond (both agree, with their
/// first derivatives, at V = wL, so Newton may cross the switch).
EndEvaluation evaluateAnchored(double h, double v, double length, double w, double c) {
  return v < w * length ? evaluateGrounded(h, v, length, w, c) : evaluateSuspended(h, v, length, w, c);
}

struct NewtonResult {
  double h = 0.0;
  double v = 0.0;
  int iterations = 0;
};

/// Newton iteration on (H, V) with the analytic Jacobian, from the Peyrot & Goulois (1979)
/// initial guess (as in FAST v7 / MoorDyn / MAP), keeping H > 0 (and V > 0 when anchored), with a
/// backtracking line search on the residual norm.
NewtonResult solveNewton(const CatenaryInput& in, bool anchored, const CatenaryOptions& options,
                         const char* who) {
  const double x = in.span;
  const double z = in.height;
  const double length = in.length;
  const double w = in.weight;
  const double c = complianceOf(in);
  const auto evaluate = [&](double h, double v) {
    return anchored ? evaluateAnchored(h, v, length, w, c) : evaluateSuspended(h, v, length, w, c);
  };

  // Peyrot & Goulois (1979) initial guess.
  const double chord = std::hypot(x, z);
  const double lambda0 = length <= chord ? 0.2 : std::sqrt(3.0 * ((length * length - z * z) / (x * x) - 1.0));
  double h = std::max(std::abs(0.5 * w * x / lambda0), 1e-12 * w * length);
  double v = 0.5 * w * (z / std::tanh(lambda0) + length);
  if (anchored && v <= 0.0) v = 0.5 * w * length;

  const double scale = std::max({length, x, std::abs(z)});
  const double tolerance = options.tolerance * scale;
  double residual = std::numeric_limits<double>::infinity();
  const char* reason = "the iteration limit was reached";
  for (int iteration = 0; iteration <= options.maxIterations; ++iteration) {
    const EndEvaluation e = evaluate(h, v);
    const double rx = e.x - x;
    const double rz = e.z - z;
    residual = std::max(std::abs(rx), std::abs(rz));
    if (residual <= tolerance) return {h, v, iteration};
    if (!std::isfinite(residual)) {
      reason = "the residual is not finite";
      break;
    }
    if (iteration == options.maxIterations) break;

    const double det = e.dxdH * e.dzdV - e.dxdV * e.dzdH;
    if (!std::isfinite(det) || det == 0.0) {
      reason = "the Jacobian is singular";
      break;
    }
    const double dh = -(e.dzdV * rx - e.dxdV * rz) / det;
    const double dv = -(-e.dzdH * rx + e.dxdH * rz) / det;

    // Keep H (and V for an anchored line) positive: shrink by at most kMaxShrink per step.
    double alpha = 1.0;
    if (h + dh < kMaxShrink * h) alpha = std::min(alpha, (1.0 - kMaxShrink) * h / -dh);
    if (anchored && v + dv < kMaxShrink * v) alpha = std::min(alpha, (1.0 - kMaxShrink) * v / -dv);

    // Backtracking on the Euclidean residual norm (Newton's direction is a descent direction for it).
    const double norm = std::hypot(rx, rz);
    double hNew = h + alpha * dh;
    double vNew = v + alpha * dv;
    for (int k = 0; k < kMaxHalvings; ++k) {
      const EndEvaluation en = evaluate(hNew, vNew);
      const double normNew = std::hypot(en.x - x, en.z - z);
      if (std::isfinite(normNew) && normNew < norm) break;
      alpha *= 0.5;
      hNew = h + alpha * dh;
      vNew = v + alpha * dv;
    }
    const bool stalled =
        std::abs(hNew - h) <= 4.0 * std::numeric_limits<double>::epsilon() * h &&
        std::abs(vNew - v) <= 4.0 * std::numeric_limits<double>::epsilon() * (std::abs(v) + w * length);
    h = hNew;
    v = vNew;
    if (stalled && residual <= kRoundOffTolerance * scale) return {h, v, iteration + 1};
  }
  std::ostringstream os;
  os.precision(10);
  os << who << ": Newton iteration on (H, V) did not converge (" << reason << ", at most "
     << options.maxIterations << " iterations; " << describe(in) << "); last H = " << h << " N, V = " << v
     << " N, residual = " << residual << " m, tolerance = " << tolerance << " m";
  throw ConvergenceError(os.str());
}

/// Fills the tensions of a solution whose regime, H, V and grounded length are set.
void finish(CatenarySolution& sol) {
  const double h = sol.horizontalTension;
  const double v = sol.verticalTension;
  const double wl = sol.input.weight * sol.input.length;
  sol.fairleadTension = std::hypot(h, v);
  switch (sol.regime) {
    case CatenaryRegime::Grounded:
    case CatenaryRegime::SlackGrounded:
      sol.anchorTension = h;
      break;
    case CatenaryRegime::Suspended:
    case CatenaryRegime::Vertical:
      sol.anchorTension = std::hypot(h, v - wl);
      break;
  }
}

/// Vertical line (X = 0, H = 0) between two points: with q(s) = V - w (L - s), the height is
///   z(s) = (|q(s)| - |q(0)|)/w + (q(s)^2 - q(0)^2) / (2 w EA)     (H -> 0 limit of the suspended form).
/// Solved in closed form for V: a U-shaped fold when 0 <= V <= wL, else taut upward or downward.
double verticalTension(const CatenaryInput& in, const char* who) {
  const double z = in.height;
  const double length = in.length;
  const double w = in.weight;
  const double c = complianceOf(in);
  const double fold = 0.5 * w * (length + z / (1.0 + 0.5 * c * w * length));
  if (fold >= 0.0 && fold <= w * length) return fold;
  if (c == 0.0) {
    throw Error(std::string(who) +
                ": inextensible vertical line shorter than the distance between its ends (" + describe(in) +
                ")");
  }
  // Taut upward (V > wL): Z = L + (2V - wL) L c / 2; downward (V < 0): Z = -L + (2V - wL) L c / 2.
  const double straight = z > 0.0 ? z - length : z + length;
  return straight / (c * length) + 0.5 * w * length;
}

/// Point at arc length s along a circular arc of length `arc` lying in a horizontal plane from
/// (0, 0) to (chord, 0), chord <= arc; returns (x along the chord, y to its left). The half-angle
/// phi in (0, pi] solves sin(phi)/phi = chord/arc (bisection: sin(phi)/phi is decreasing there);
/// chord = 0 gives a full circle. Used to lay a slack grounded part on the seabed without strain.
std::pair<double, double> seabedArc(double chord, double arc, double s) {
  if (chord >= arc * (1.0 - 1e-12)) return {s * chord / arc, 0.0};
  const double ratio = chord / arc;
  double lo = 0.0;
  double hi = std::numbers::pi;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::sin(mid) > ratio * mid ? lo : hi) = mid;
  }
  const double phi = 0.5 * (lo + hi);
  const double radius = arc / (2.0 * phi);
  const double angle = 0.5 * std::numbers::pi + phi - s / radius;  // clockwise from (0, 0)
  return {0.5 * chord + radius * std::cos(angle), radius * (std::sin(angle) - std::cos(phi))};
}

}  // namespace

CatenaryPoint CatenarySolution::position(double s) const {
  const double length = input.length;
  if (!(s >= -1e-12 * length && s <= length * (1.0 + 1e-12))) {
    std::ostringstream os;
    os.precision(10);
    os << "CatenarySolution::position: arc length s = " << s << " m outside [0, L = " << length << " m]";
    throw Error(os.str());
  }
  s = std::clamp(s, 0.0, length);
  const double w = input.weight;
  const double c = complianceOf(input);
  const double h = horizontalTension;
  const double v = verticalTension;
  const double lb = groundedLength;
  switch (regime) {
    case CatenaryRegime::Grounded: {
      // Jonkman (2007), CB = 0: x = s (1 + H/EA) on the seabed; above it, with u = s - Lb,
      // x = Lb + H/w asinh(w u / H) + H s / EA, z = H/w [sqrt(1 + (w u / H)^2) - 1] + w u^2 / (2 EA).
      if (s <= lb) return {s * (1.0 + c * h), 0.0};
      const double u = s - lb;
      if (h <= 0.0) return {lb, u + 0.5 * c * w * u * u};
      const double a = w * u / h;
      return {lb + h / w * std::asinh(a) + c * h * s,
              h / w * a * a / (std::hypot(1.0, a) + 1.0) + 0.5 * c * w * u * u};
    }
    case CatenaryRegime::Suspended: {
      // Jonkman (2007), suspended: with VA = V - wL,
      // x = H/w [asinh((VA + w s)/H) - asinh(VA/H)] + H s / EA,
      // z = H/w [sqrt(1 + ((VA + w s)/H)^2) - sqrt(1 + (VA/H)^2)] + (VA s + w s^2 / 2) / EA.
      const double q0 = v - w * length;
      const double a = (q0 + w * s) / h;
      const double b = q0 / h;
      const double d = w * s / h;
      return {h / w * asinhDifference(a, b, d) + c * h * s,
              h / w * rootDifference(a, b, d) + c * (q0 * s + 0.5 * w * s * s)};
    }
    case CatenaryRegime::SlackGrounded: {
      if (s <= lb) return {lb > 0.0 ? s * input.span / lb : 0.0, 0.0};
      const double u = s - lb;
      return {input.span, u + 0.5 * c * w * u * u};
    }
    case CatenaryRegime::Vertical: {
      const double q0 = v - w * length;
      const double qs = q0 + w * s;
      return {input.span, (std::abs(qs) - std::abs(q0)) / w + 0.5 * c * (qs - q0) * (qs + q0) / w};
    }
  }
  return {};
}

double CatenarySolution::tension(double s) const {
  const double length = input.length;
  if (!(s >= -1e-12 * length && s <= length * (1.0 + 1e-12))) {
    std::ostringstream os;
    os.precision(10);
    os << "CatenarySolution::tension: arc length s = " << s << " m outside [0, L = " << length << " m]";
    throw Error(os.str());
  }
  s = std::clamp(s, 0.0, length);
  const double vertical = verticalTension - input.weight * (length - s);
  switch (regime) {
    case CatenaryRegime::Grounded:
    case CatenaryRegime::SlackGrounded:
      if (s <= groundedLength) return horizontalTension;
      return std::hypot(horizontalTension, std::max(vertical, 0.0));
    case CatenaryRegime::Suspended:
    case CatenaryRegime::Vertical:
      return std::hypot(horizontalTension, vertical);
  }
  return 0.0;
}

CatenarySolution solveAnchoredCatenary(const CatenaryInput& input, const CatenaryOptions& options) {
  constexpr const char* kWho = "solveAnchoredCatenary";
  validate(input, options, kWho);
  if (input.height < 0.0) {
    throw Error(std::string(kWho) + ": the fairlead (end B) is below the anchor on the seabed (" +
                describe(input) + ")");
  }
  const double x = input.span;
  const double z = input.height;
  const double length = input.length;
  const double w = input.weight;
  const double c = complianceOf(input);

  CatenarySolution sol;
  sol.input = input;

  // Unstretched length hanging vertically over height Z: Z = Ls + w Ls^2 / (2 EA).
  const double hanging = 2.0 * z / (1.0 + std::sqrt(1.0 + 2.0 * w * z * c));
  if (x <= length - hanging) {
    // Too long to be tensioned: H = 0, vertical hanging part, slack grounded part (H -> 0 limit).
    sol.regime = CatenaryRegime::SlackGrounded;
    sol.verticalTension = w * hanging;
    sol.groundedLength = length - hanging;
    sol.touchdownDistance = x;
    finish(sol);
    return sol;
  }
  if (x == 0.0) {
    // Vertical and taut: Z = L + (2V - wL) L / (2 EA).
    sol.regime = CatenaryRegime::Vertical;
    sol.verticalTension = verticalTension(input, kWho);
    finish(sol);
    return sol;
  }
  if (z == 0.0) {
    // Stretched straight along the seabed: X = L (1 + H / EA), V = 0.
    if (c == 0.0) {
      throw Error(std::string(kWho) + ": inextensible line shorter than the anchor-fairlead distance (" +
                  describe(input) + ")");
    }
    sol.regime = CatenaryRegime::Grounded;
    sol.horizontalTension = (x - length) / (c * length);
    sol.groundedLength = length;
    sol.touchdownDistance = x;
    finish(sol);
    return sol;
  }
  if (c == 0.0 && std::hypot(x, z) >= length) {
    throw Error(std::string(kWho) +
                ": inextensible line not longer than the anchor-fairlead chord: no catenary (" +
                describe(input) + ")");
  }
  const NewtonResult r = solveNewton(input, true, options, kWho);
  sol.horizontalTension = r.h;
  sol.verticalTension = r.v;
  sol.iterations = r.iterations;
  if (r.v < w * length) {
    sol.regime = CatenaryRegime::Grounded;
    sol.groundedLength = length - r.v / w;
    sol.touchdownDistance = sol.groundedLength * (1.0 + c * r.h);
  } else {
    sol.regime = CatenaryRegime::Suspended;
  }
  finish(sol);
  return sol;
}

CatenarySolution solveSuspendedCatenary(const CatenaryInput& input, const CatenaryOptions& options) {
  constexpr const char* kWho = "solveSuspendedCatenary";
  validate(input, options, kWho);
  CatenarySolution sol;
  sol.input = input;
  if (input.span == 0.0) {
    sol.regime = CatenaryRegime::Vertical;
    sol.verticalTension = verticalTension(input, kWho);
    finish(sol);
    return sol;
  }
  if (complianceOf(input) == 0.0 && std::hypot(input.span, input.height) >= input.length) {
    throw Error(std::string(kWho) + ": inextensible line not longer than the chord: no catenary (" +
                describe(input) + ")");
  }
  const NewtonResult r = solveNewton(input, false, options, kWho);
  sol.regime = CatenaryRegime::Suspended;
  sol.horizontalTension = r.h;
  sol.verticalTension = r.v;
  sol.iterations = r.iterations;
  finish(sol);
  return sol;
}

InitialShape initialLineShape(const Vec3& endA, const Vec3& endB,
                              const std::vector<CatenarySection>& sections, double seabedDepth,
                              const std::vector<double>& arcLengths, const CatenaryOptions& options) {
  constexpr const char* kWho = "initialLineShape";
  if (sections.empty()) throw Error(std::string(kWho) + ": the line has no sections");
  if (!endA.allFinite() || !endB.allFinite() || !std::isfinite(seabedDepth)) {
    throw Error(std::string(kWho) + ": end positions and seabed depth must be finite");
  }
  double length = 0.0;
  double totalWeight = 0.0;
  double flexibility = 0.0;  // sum L_i / EA_i [m/N]
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const CatenarySection& sec = sections[i];
    if (!std::isfinite(sec.length) || sec.length <= 0.0 || !std::isfinite(sec.weight) ||
        !std::isfinite(sec.axialStiffness) || sec.axialStiffness <= 0.0) {
      std::ostringstream os;
      os.precision(10);
      os << kWho << ": section " << i
         << " needs a finite length > 0, finite weight and finite EA > 0 (length = " << sec.length
         << " m, w = " << sec.weight << " N/m, EA = " << sec.axialStiffness << " N)";
      throw Error(os.str());
    }
    length += sec.length;
    totalWeight += sec.weight * sec.length;
    flexibility += sec.length / sec.axialStiffness;
  }
  for (double s : arcLengths) {
    if (!(s >= -1e-9 * length && s <= length * (1.0 + 1e-9))) {
      std::ostringstream os;
      os.precision(10);
      os << kWho << ": arc length " << s << " m outside the line [0, " << length << " m]";
      throw Error(os.str());
    }
  }
  const double meanWeight = totalWeight / length;
  const double equivalentStiffness = length / flexibility;
  const Vec3 chord = endB - endA;
  const double chordLength = chord.norm();
  const double seabedZ = -seabedDepth;

  InitialShape shape;
  shape.positions.reserve(arcLengths.size());
  // Shape before the end-point correction, as a function of s in [0, L].
  std::vector<Vec3> raw;
  raw.reserve(arcLengths.size() + 2);

  const auto straightShortened = [&](double s) -> Vec3 { return endA + chord * (s / length); };
  std::vector<double> samples;
  samples.reserve(arcLengths.size() + 2);
  samples.push_back(0.0);
  samples.push_back(length);
  for (double s : arcLengths) samples.push_back(std::clamp(s, 0.0, length));

  if (chordLength >= length) {
    // Taut: straight, uniform tension T = (chord - L) / sum(L_i / EA_i); section i stretched by T L_i / EA_i.
    shape.kind = InitialShapeKind::Taut;
    const double tension = (chordLength - length) / flexibility;
    shape.horizontalTension = tension;
    for (double s : samples) {
      double stretched = 0.0;
      double start = 0.0;
      for (const CatenarySection& sec : sections) {
        const double part = std::clamp(s - start, 0.0, sec.length);
        stretched += part * (1.0 + tension / sec.axialStiffness);
        start += sec.length;
      }
      raw.push_back(endA + chord * (stretched / chordLength));
    }
  } else if (meanWeight <= 0.0) {
    // Buoyant (or weightless) overall: no hanging catenary; straight chord, uniformly shortened.
    shape.kind = InitialShapeKind::Straight;
    for (double s : samples) raw.push_back(straightShortened(s));
  } else {
    const double tolZ = 1e-6 * std::max(1.0, length);
    const bool onA = endA.z() <= seabedZ + tolZ;
    const bool onB = endB.z() <= seabedZ + tolZ;
    const bool anchoredAtA = onA && (!onB || endA.z() <= endB.z());
    const bool anchored = onA || onB;
    const Vec3& origin = anchored && !anchoredAtA ? endB : endA;
    const Vec3& other = anchored && !anchoredAtA ? endA : endB;
    Vec3 horizontal = other - origin;
    horizontal.z() = 0.0;
    double span = horizontal.norm();
    Vec3 direction = Vec3::UnitX();
    if (span > 1e-9 * length) {
      direction = horizontal / span;
    } else {
      span = 0.0;  // vertical: any horizontal direction; the end-point correction absorbs the rest
    }
    const double height = anchored ? std::max(0.0, other.z() - origin.z()) : other.z() - origin.z();
    const CatenaryInput input{span, height, length, meanWeight, equivalentStiffness};
    try {
      const CatenarySolution sol =
          anchored ? solveAnchoredCatenary(input, options) : solveSuspendedCatenary(input, options);
      shape.kind = anchored ? InitialShapeKind::Anchored : InitialShapeKind::Suspended;
      shape.horizontalTension = sol.horizontalTension;
      const Vec3 lateral = kUp.cross(direction);
      // A line with buoyant sections (lazy or steep wave) from an anchor: its sections' own weights shape
      // it (the hump of the buoyancy section), and the equivalent uniform catenary is far from equilibrium
      // (the static solver stalled from it on beam lazy waves). Solved from the equivalent one's H and
      // grounded length; kept only when it converges.
      const bool buoyantSection = std::any_of(sections.begin(), sections.end(),
                                              [](const CatenarySection& c) { return c.weight <= 0.0; });
      if (buoyantSection && span > 0.0) {
        MultiSectionCatenary multi(sections, anchored);
        const bool fromA = !anchored || anchoredAtA;  // `origin` is end A
        if (!fromA) std::reverse(multi.sections.begin(), multi.sections.end());
        const double guessU = sol.groundedLength > 0.0 ? sol.groundedLength / length : -1e-3;
        const bool ok =
            multi.solve(span, height, std::max(sol.horizontalTension, 1e-3 * multi.weightScale), guessU);
        if (std::getenv("TANGLE_DEBUG_SHAPE"))
          std::fprintf(
              stderr,
              "multi-section catenary: %s H %g grounded %g Vanchor %g (equivalent H %g grounded %g)\n",
              ok ? "ok" : "FAILED", multi.horizontal, multi.grounded, multi.anchorVertical,
              sol.horizontalTension, sol.groundedLength);
        if (ok) {
          shape.horizontalTension = multi.horizontal;
          for (double s : samples) {
            const auto [x, z] = multi.at(fromA ? s : length - s);
            raw.push_back(origin + direction * x + kUp * z);
          }
        }
      }
      for (double s : samples) {
        if (raw.size() == samples.size()) break;  // the multi-section shape above
        const double local = anchored && !anchoredAtA ? length - s : s;
        if (sol.regime == CatenaryRegime::SlackGrounded && local < sol.groundedLength) {
          // Slack grounded part: strain-free arc on the seabed instead of the shortened straight
          // layout of CatenarySolution::position (any layout is an equilibrium when H = 0).
          const auto [x, y] = seabedArc(span, sol.groundedLength, local);
          raw.push_back(origin + direction * x + lateral * y);
        } else {
          const CatenaryPoint p = sol.position(local);
          raw.push_back(origin + direction * p.x + kUp * p.z);
        }
      }
    } catch (const ConvergenceError&) {
      shape.kind = InitialShapeKind::Fallback;
      shape.horizontalTension = 0.0;
      raw.clear();
      for (double s : samples) raw.push_back(straightShortened(s));
    }
  }

  bool finite = std::all_of(raw.begin(), raw.end(), [](const Vec3& p) { return p.allFinite(); });
  if (!finite) {  // defensive: never hand NaN to the static solver
    shape.kind = InitialShapeKind::Fallback;
    shape.horizontalTension = 0.0;
    raw.clear();
    for (double s : samples) raw.push_back(straightShortened(s));
  }

  // Make the end points exact: distribute the (round-off) end mismatch linearly in s.
  const Vec3 errorA = endA - raw[0];
  const Vec3 errorB = endB - raw[1];
  for (std::size_t i = 0; i < arcLengths.size(); ++i) {
    const double s = samples[i + 2];
    Vec3 p;
    if (s <= kEndSnap * length) {
      p = endA;
    } else if (s >= (1.0 - kEndSnap) * length) {
      p = endB;
    } else {
      const double t = s / length;
      p = raw[i + 2] + errorA * (1.0 - t) + errorB * t;
      p.z() = std::max(p.z(), seabedZ);
    }
    shape.positions.push_back(p);
  }
  return shape;
}

}  // namespace tangle::catenary
