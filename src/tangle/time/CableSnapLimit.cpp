#include "tangle/time/CableSnapLimit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tangle::time {

double cableSnapStepLimit(const model::Model& model, const model::State& state, double maxStrainStep,
                          double horizon) {
  double limit = std::numeric_limits<double>::infinity();
  if (maxStrainStep <= 0.0) return limit;
  const model::DofMap& dofs = model.dofs();
  // Per step over every bar: the square root and the division only for the few bars that qualify
  // (lengthening, and within maxStrainStep of their kink)(docs/performance.md).
  for (const model::LineElement& el : model.elements()) {
    if (!el.bar) continue;
    const Vec3 chord = state.position[el.node2] - state.position[el.node1];
    const Vec3 dv = state.velocity.segment<3>(dofs.firstDof(el.node2)) -
                    state.velocity.segment<3>(dofs.firstDof(el.node1));
    const double lengthening = chord.dot(dv);  // length * d(length)/dt [m^2/s]
    // Only a bar at its kink can snap: one stretched beyond maxStrainStep is on its linear branch. Bars
    // just taut (0 <= strain < maxStrainStep) stay limited: left free, the 40 s snap run of
    // docs/theory.md 8.3 reached 2.95e5 N at the anchor instead of 2.1e5 N.
    const double linearFrom =
        el.restLength * (1.0 + maxStrainStep);  // length where strain = maxStrainStep [m]
    const double length2 = chord.squaredNorm();
    if ((lengthening < 0.0) & (length2 > el.restLength * el.restLength)) {
      // A taut bar going slack (the unloading half of a snap). Predicted to reach its kink within
      // `horizon`, it approaches it in steps that end at maxStrainStep / 2 while it is stretched beyond
      // maxStrainStep, then crosses it overshooting by at most maxStrainStep: the step across the kink
      // then starts at a force of at most EA maxStrainStep. One long step from deep tension across the
      // kink releases the work of the start force over the whole shortening (trapezoidal), more than
      // the strain energy stored: whipping free cable ends gained energy unload after unload, with the
      // loading half resolved by the rule below and this one not (a short wire draped over another, in
      // air, e = 1: 3847 J -> 7e8 J in 3.5 s; docs/theory.md 8.3).
      // Without a square root: time to the kink (L^2 - L0^2) / (-2 L L') ~ (L - L0) / (-L') to O(strain).
      const double toKink = (length2 - el.restLength * el.restLength) / (-2.0 * lengthening);
      if (toKink >= horizon) continue;
      const double length = std::sqrt(length2);
      const double rate = -lengthening / (length * el.restLength);  // shortening rate [1/s]
      const double strain = length / el.restLength - 1.0;
      const double target = strain > maxStrainStep ? 0.5 * maxStrainStep : -maxStrainStep;
      limit = std::min(limit, (strain - target) / rate);
      continue;
    }
    // Both tests in one branch, rarely taken: a branch on the lengthening's sign alone (about as often
    // negative as positive) was mispredicted every other bar.
    if (!((lengthening > 0.0) & (length2 < linearFrom * linearFrom))) continue;
    const double length = chord.norm();
    const double rate = lengthening / (length * el.restLength);  // [1/s]
    const double strain = length / el.restLength - 1.0;
    limit = std::min(limit, (maxStrainStep + std::max(-strain, 0.0)) / rate);
  }
  return limit;
}

double cableUnloadStepFraction(const model::Model& model, const model::State& before,
                               const model::State& after, double maxStrainStep) {
  double fraction = 1.0;
  if (maxStrainStep <= 0.0) return fraction;
  for (const model::LineElement& el : model.elements()) {
    if (!el.bar) continue;
    // On squared lengths first: most bars are not at their kink at the step's end.
    const double rest2 = el.restLength * el.restLength;
    const double slackBelow = (1.0 - maxStrainStep) * el.restLength;
    const double after2 = (after.position[el.node2] - after.position[el.node1]).squaredNorm();
    if (after2 >= slackBelow * slackBelow) continue;
    const double tautAbove = (1.0 + maxStrainStep) * el.restLength;
    const double before2 = (before.position[el.node2] - before.position[el.node1]).squaredNorm();
    if (before2 <= tautAbove * tautAbove || !(rest2 > 0.0)) continue;
    const double start = std::sqrt(before2) / el.restLength - 1.0;  // [-]
    const double end = std::sqrt(after2) / el.restLength - 1.0;     // [-]
    fraction = std::min(fraction, (start - 0.5 * maxStrainStep) / (start - end));
  }
  return fraction;
}

}  // namespace tangle::time
