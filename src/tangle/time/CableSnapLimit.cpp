#include "tangle/time/CableSnapLimit.hpp"

#include <algorithm>
#include <limits>

namespace tangle::time {

double cableSnapStepLimit(const model::Model& model, const model::State& state, double maxStrainStep) {
  double limit = std::numeric_limits<double>::infinity();
  if (maxStrainStep <= 0.0) return limit;
  const model::DofMap& dofs = model.dofs();
  for (const model::LineElement& el : model.elements()) {
    if (!el.bar) continue;
    const Vec3 chord = state.position[el.node2] - state.position[el.node1];
    const double length = chord.norm();
    if (length <= 0.0) continue;
    const Vec3 dv = state.velocity.segment<3>(dofs.firstDof(el.node2)) - state.velocity.segment<3>(dofs.firstDof(el.node1));
    const double rate = chord.dot(dv) / (length * el.restLength);  // [1/s]
    if (rate <= 0.0) continue;
    const double strain = length / el.restLength - 1.0;
    // Only a bar at its kink can snap: one stretched beyond maxStrainStep is on its linear branch. Bars
    // just taut (0 <= strain < maxStrainStep) stay limited: left free, the 40 s snap run of
    // docs/theory.md 8.3 reached 2.95e5 N at the anchor instead of 2.1e5 N.
    if (strain >= maxStrainStep) continue;
    limit = std::min(limit, (maxStrainStep + std::max(-strain, 0.0)) / rate);
  }
  return limit;
}

}  // namespace tangle::time
