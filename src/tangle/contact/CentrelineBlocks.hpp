#pragma once
/// @file CentrelineBlocks.hpp
/// The scatter of one contact's tangent over the nodes of the two centreline stencils it couples
/// (CentrelineSlots, SmoothCentreline.hpp): the one loop the point contacts (LineContact) and the distributed
/// contact's shoulders (DistributedContact) share.

#include <Eigen/Dense>

#include "tangle/contact/SmoothCentreline.hpp"
#include "tangle/core/Types.hpp"
#include "tangle/model/DofMap.hpp"
#include "tangle/solver/SystemMatrix.hpp"

namespace tangle::contact {

/// Adds, for every pair (i, j) of the used slots, block (i, j) of `block` plus w_i w_j `pointBlock` to the
/// matrix at the translations of slot i's and slot j's nodes. `block` is the tangent over the 24 slot
/// coordinates (the normal law's k grad d grad d^T - f Hess d, times the integrator's weight) and
/// `pointBlock` a force that acts at the contact point alone (a dashpot along the normal, friction), so that
/// it reaches the nodes through the slots' weights w (CentrelineSlots::weight). Units: the matrix's [N/m] or
/// [N s/m], as both blocks are already weighted for it.
inline void addSlotBlocks(const CentrelineSlots& slots, const Eigen::Matrix<double, 24, 24>& block,
                          const Mat3& pointBlock, const model::DofMap& dofs, solver::SystemMatrix& matrix) {
  for (int i = 0; i < 8; ++i) {
    if (!slots.used[i]) continue;
    for (int j = 0; j < 8; ++j) {
      if (!slots.used[j]) continue;
      const Mat3 bij = block.block<3, 3>(3 * i, 3 * j) + slots.weight[i] * slots.weight[j] * pointBlock;
      matrix.add3x3(dofs.firstDof(slots.node[i]), dofs.firstDof(slots.node[j]), bij);
    }
  }
}

}  // namespace tangle::contact
