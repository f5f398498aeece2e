#include "tangle/solver/IncrementLimits.hpp"

#include <algorithm>

#include "tangle/solver/Assembler.hpp"

namespace tangle::solver {

double translationCap(const model::Model& model) {
  double lref = 1.0;
  double minElement = 1e30;
  for (const auto& line : model.lines()) lref = std::max(lref, line.length);
  for (const auto& el : model.elements()) minElement = std::min(minElement, el.restLength);
  if (model.elements().empty()) minElement = lref;
  double maxElement = 0.0;
  for (const auto& el : model.elements()) maxElement = std::max(maxElement, el.restLength);
  return std::max(std::min(0.05 * lref, std::max(10.0, 5.0 * maxElement)), 2.0 * minElement);
}

double strainStepRatio(const model::Model& model, const Assembler& assembler, const model::State& state,
                       const VecX& full) {
  const model::DofMap& dofs = model.dofs();
  double worst = 0.0;
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const model::LineElement& el = elements[e];
    if (!el.bar) continue;
    const int d1 = dofs.firstDof(el.node1), d2 = dofs.firstDof(el.node2);
    const Vec3 a = state.position[el.node1], b = state.position[el.node2];
    const Vec3 da(full[d1], full[d1 + 1], full[d1 + 2]), db(full[d2], full[d2 + 1], full[d2 + 2]);
    const double l0 = assembler.restLengthOf(e);
    const double now = std::max((b - a).norm() / l0 - 1.0, 0.0);
    const double next = (b + db - a - da).norm() / l0 - 1.0;
    worst = std::max(worst, (next - now) / kMaxStrainStep);
  }
  return worst;
}

}  // namespace tangle::solver
