#include "tangle/catenary/MultiSectionCatenary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tangle::catenary {

MultiSectionCatenary::MultiSectionCatenary(std::vector<CatenarySection> lineSections, bool groundable)
    : sections(std::move(lineSections)), canGround(groundable) {
  for (const CatenarySection& c : sections) {
    length += c.length;
    weightScale += std::abs(c.weight) * c.length;
  }
}

void MultiSectionCatenary::setUnknowns(double logH, double u) {
  horizontal = std::exp(logH);
  grounded = canGround ? std::clamp(u, 0.0, 1.0 - 1e-9) * length : 0.0;
  anchorVertical = canGround ? std::max(-u, 0.0) * weightScale : -u * weightScale;
}

std::pair<double, double> MultiSectionCatenary::at(double s) const {
  const double h = horizontal;
  double x = 0.0, z = 0.0, v = grounded > 0.0 ? 0.0 : anchorVertical, start = 0.0;
  for (const CatenarySection& sec : sections) {
    const double end = std::min(start + sec.length, s);
    if (end <= start) break;
    const double lg = std::max(0.0, std::min(end, grounded) - start);
    x += lg * (1.0 + h / sec.axialStiffness);
    const double l = end - std::max(start, grounded);
    if (l > 0.0) {
      const double w = sec.weight, v1 = v + w * l;
      if (std::abs(w) * l > 1e-9 * std::max(h, std::abs(v))) {
        x += h / w * (std::asinh(v1 / h) - std::asinh(v / h)) + h * l / sec.axialStiffness;
        z += h / w * (std::hypot(1.0, v1 / h) - std::hypot(1.0, v / h)) +
             (v * l + 0.5 * w * l * l) / sec.axialStiffness;
      } else {
        const double t = std::hypot(h, v);
        x += l * h / t * (1.0 + t / sec.axialStiffness);
        z += l * v / t * (1.0 + t / sec.axialStiffness);
      }
      v = v1;
    }
    start += sec.length;
  }
  return {x, z};
}

bool MultiSectionCatenary::groundedHeavy() const {
  // Every section with a grounded part must be heavy: a buoyant one cannot rest on the seabed (it would
  // rise). (Checking only the section at the touchdown let a lazy wave start with its buoyancy section laid
  // flat under a grounded riser section: 16 158 Newton iterations of continuation, issue 44.)
  double start = 0.0;
  for (const CatenarySection& sec : sections) {
    if (start >= grounded) break;
    if (sec.weight <= 0.0) return false;
    start += sec.length;
  }
  return true;
}

double MultiSectionCatenary::farEndVertical() const {
  double v = grounded > 0.0 ? 0.0 : anchorVertical, start = 0.0;
  for (const CatenarySection& sec : sections) {
    v += sec.weight * std::max(0.0, start + sec.length - std::max(start, grounded));
    start += sec.length;
  }
  return v;
}

bool MultiSectionCatenary::solve(double span, double height, double guessH, double guessU) {
  // Start from the best point of a coarse grid (H from 1e-4 to 1 of the total weight, u from an anchor
  // lifted by half the weight to 95 % grounded) as well as the guess: with a buoyancy hump the
  // equivalent line's (H, grounded length) can lie in another basin (touchdown inside the buoyant part).
  double p[2] = {std::log(std::max(guessH, 1e-6 * weightScale)), guessU};
  {
    double bestNorm = std::numeric_limits<double>::infinity();
    const auto consider = [&](double logH, double u) {
      setUnknowns(logH, u);
      if (!groundedHeavy()) return;
      const auto [x, z] = at(length);
      const double n = std::hypot(x - span, z - height);
      if (std::isfinite(n) && n < bestNorm) {
        bestNorm = n;
        p[0] = logH;
        p[1] = u;
      }
    };
    consider(p[0], p[1]);
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j)
        consider(std::log(weightScale) + std::log(1e-4) * (1.0 - i / 40.0),
                 canGround ? -0.5 + 1.45 * j / 40.0 : -1.0 + 2.0 * j / 40.0);
  }
  const auto residual = [&](const double* q, double* r) {
    setUnknowns(q[0], q[1]);
    const auto [x, z] = at(length);
    r[0] = (x - span) / length;
    r[1] = (z - height) / length;
    return std::hypot(r[0], r[1]);
  };
  double r[2];
  double norm = residual(p, r);
  for (int it = 0; it < 200 && norm > 1e-10; ++it) {
    double jac[2][2];
    for (int k = 0; k < 2; ++k) {
      double q[2] = {p[0], p[1]}, rk[2];
      const double step = 1e-7 * std::max(1.0, std::abs(p[k]));
      q[k] += step;
      residual(q, rk);
      jac[0][k] = (rk[0] - r[0]) / step;
      jac[1][k] = (rk[1] - r[1]) / step;
    }
    const double det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
    if (!std::isfinite(det) || std::abs(det) < 1e-300) return false;
    double d[2] = {-(jac[1][1] * r[0] - jac[0][1] * r[1]) / det,
                   -(-jac[1][0] * r[0] + jac[0][0] * r[1]) / det};
    // Steps of at most a factor e in H and 0.2 in u; halved until the residual falls.
    const double scale =
        std::min({1.0, 1.0 / std::max(std::abs(d[0]), 1e-300), 0.2 / std::max(std::abs(d[1]), 1e-300)});
    double lambda = scale;
    bool improved = false;
    for (int ls = 0; ls < 40 && !improved; ++ls, lambda *= 0.5) {
      double q[2] = {p[0] + lambda * d[0],
                     canGround ? std::min(p[1] + lambda * d[1], 1.0 - 1e-9) : p[1] + lambda * d[1]},
             rq[2];
      const double nq = residual(q, rq);
      if (std::isfinite(nq) && nq < norm) {
        p[0] = q[0];
        p[1] = q[1];
        r[0] = rq[0];
        r[1] = rq[1];
        norm = nq;
        improved = true;
      }
    }
    if (!improved) break;
  }
  setUnknowns(p[0], p[1]);
  return norm <= 1e-9 && std::isfinite(horizontal) && groundedHeavy();
}

}  // namespace tangle::catenary
