#include "tangle/solver/ResidualNorm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tangle::solver {

double residualNorm(const model::Model& model, const VecX& residual, ResidualIndexing indexing, int* worstNode,
                    double lineMomentLever) {
  const model::DofMap& dofs = model.dofs();
  double worst = 0.0;
  int node = -1;
  for (int n = 0; n < dofs.nodeCount(); ++n) {
    const int d = dofs.firstDof(n);
    const double lref = lineMomentLever > 0.0 && model.lineOfNode(n) >= 0 ? lineMomentLever
                                                                           : std::max(model.momentScale(n), 1e-6);
    for (int k = 0; k < dofs.dofCount(n); ++k) {
      const int eq = dofs.equation(d + k);
      if (eq < 0) continue;
      const double r = indexing == ResidualIndexing::FullDofs ? residual[d + k] : residual[eq];
      const double v = std::abs(r) / (k < 3 ? 1.0 : lref);
      if (!(v <= worst)) {  // also catches NaN
        worst = std::isnan(v) ? std::numeric_limits<double>::quiet_NaN() : v;
        node = n;
        if (std::isnan(v)) {
          if (worstNode) *worstNode = node;
          return worst;
        }
      }
    }
  }
  if (worstNode) *worstNode = node;
  return worst;
}

}  // namespace tangle::solver
