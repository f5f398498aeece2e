#include "tangle/model/State.hpp"

#include "tangle/geometry/Rotation.hpp"

namespace tangle::model {

namespace {
/// The rotation nearest to a triad that round-off has moved off SO(3) (through the unit quaternion).
Mat3 orthonormalised(const Mat3& triad) { return Eigen::Quaterniond(triad).normalized().toRotationMatrix(); }
}  // namespace

void State::applyIncrement(const DofMap& dofs, const VecX& fullIncrement, bool orthonormalise) {
  setIncremented(*this, dofs, fullIncrement);
  if (!orthonormalise) return;
  // Re-orthonormalise the updated triads to stop round-off drift over many steps.
  for (int n = 0; n < dofs.nodeCount(); ++n)
    if (dofs.hasRotations(n) && fullIncrement.segment<3>(dofs.firstDof(n) + 3).squaredNorm() > 0.0)
      triad[n] = orthonormalised(triad[n]);
}

void State::setIncremented(const State& from, const DofMap& dofs, const VecX& fullIncrement) {
  time = from.time;
  if (&from != this) viscoelastic = from.viscoelastic;
  const int nodes = dofs.nodeCount();
  position.resize(static_cast<std::size_t>(nodes));
  // Nodes without rotations keep the identity triad in every state (the struct's contract): copied only
  // when this state has none yet.
  if (triad.size() != from.triad.size()) triad = from.triad;
  for (int n = 0; n < nodes; ++n) {
    const int d = dofs.firstDof(n);
    position[n] = from.position[n] + fullIncrement.segment<3>(d);
    if (dofs.hasRotations(n)) {
      const Vec3 dtheta = fullIncrement.segment<3>(d + 3);
      // The product is evaluated before it is assigned, so `from` may be this state (applyIncrement).
      triad[n] = dtheta.squaredNorm() > 0.0 ? Mat3(geometry::expMap(dtheta) * from.triad[n]) : from.triad[n];
    }
  }
}

void State::assignFrom(const State& from, const DofMap& dofs) {
  time = from.time;
  position = from.position;
  velocity = from.velocity;
  acceleration = from.acceleration;
  viscoelastic = from.viscoelastic;
  if (triad.size() != from.triad.size()) {
    triad = from.triad;
    return;
  }
  for (int n = 0; n < dofs.nodeCount(); ++n)
    if (dofs.hasRotations(n)) triad[n] = from.triad[n];
}

void State::orthonormaliseTriads(const DofMap& dofs) {
  for (int n = 0; n < dofs.nodeCount(); ++n)
    if (dofs.hasRotations(n)) triad[n] = orthonormalised(triad[n]);
}

}  // namespace tangle::model
