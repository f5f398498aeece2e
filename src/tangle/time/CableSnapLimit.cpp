#include "tangle/time/CableSnapLimit.hpp"

#include <algorithm>
#include <limits>

namespace tangle::time {

double cableSnapStepLimit(const model::Model& model, const model::State& state, double maxStrainStep) {
  double limit = std::numeric_limits<double>::infinity();
  if (maxStrainStep <= 0.0) return limit;
  const model::DofMap& dofs = model.dofs();
  // Per step over every bar: the square root and the division only for the few bars that qualify
  // (lengthening, and within maxStrainStep of their kink); it was 1.3 % of the mooring example's run.
  for (const model::LineElement& el : model.elements()) {
    if (!el.bar) continue;
    const Vec3 chord = state.position[el.node2] - state.position[el.node1];
    const Vec3 dv = state.velocity.segment<3>(dofs.firstDof(el.node2)) - state.velocity.segment<3>(dofs.firstDof(el.node1));
    const double lengthening = chord.dot(dv);  // length * d(length)/dt [m^2/s]
    // Only a bar at its kink can snap: one stretched beyond maxStrainStep is on its linear branch. Bars
    // just taut (0 <= strain < maxStrainStep) stay limited: left free, the 40 s snap run of
    // docs/theory.md 8.3 reached 2.95e5 N at the anchor instead of 2.1e5 N.
    const double linearFrom =
        el.restLength * (1.0 + maxStrainStep);  // length where strain = maxStrainStep [m]
    // Both tests in one branch, rarely taken: a branch on the lengthening's sign alone (about as often
    // negative as positive) was mispredicted every other bar.
    if (!((lengthening > 0.0) & (chord.squaredNorm() < linearFrom * linearFrom))) continue;
    const double length = chord.norm();
    const double rate = lengthening / (length * el.restLength);  // [1/s]
    const double strain = length / el.restLength - 1.0;
    limit = std::min(limit, (maxStrainStep + std::max(-strain, 0.0)) / rate);
  }
  return limit;
}

}  // namespace tangle::time
