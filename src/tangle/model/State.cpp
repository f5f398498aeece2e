#include "tangle/model/State.hpp"

#include "tangle/geometry/Rotation.hpp"

namespace tangle::model {

void State::applyIncrement(const DofMap& dofs, const VecX& fullIncrement, bool orthonormalise) {
  for (int n = 0; n < dofs.nodeCount(); ++n) {
    const int d = dofs.firstDof(n);
    position[n] += fullIncrement.segment<3>(d);
    if (dofs.hasRotations(n)) {
      const Vec3 dtheta = fullIncrement.segment<3>(d + 3);
      if (dtheta.squaredNorm() > 0.0) {
        triad[n] = geometry::expMap(dtheta) * triad[n];
        if (orthonormalise) {
          // Re-orthonormalise to stop round-off drift over many steps.
          const Eigen::Quaterniond q(triad[n]);
          triad[n] = q.normalized().toRotationMatrix();
        }
      }
    }
  }
}

void State::orthonormaliseTriads(const DofMap& dofs) {
  for (int n = 0; n < dofs.nodeCount(); ++n)
    if (dofs.hasRotations(n)) triad[n] = Eigen::Quaterniond(triad[n]).normalized().toRotationMatrix();
}

}  // namespace tangle::model
