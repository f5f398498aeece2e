#include "tangle/solver/JunctionTies.hpp"

#include <algorithm>
#include <limits>

namespace tangle::solver {

JunctionTies::JunctionTies(const model::Model& model) : m_model(&model) {}

void JunctionTies::addForces(const model::State& state, const AssemblyRequest& request, VecX& force,
                             SystemMatrix* matrix) {
  addTies(state, request.kf, force, matrix);
}

void JunctionTies::addTies(const model::State& state, double kf, VecX& force, SystemMatrix* matrix) const {
  const model::DofMap& dofs = m_model->dofs();
  for (const model::NodeTie& tie : m_model->ties()) {
    const int dn = dofs.firstDof(tie.node), dc = dofs.firstDof(tie.carrier);
    // Out-of-balance sign: the spring's pull on the tied node, -k g, is an external load on it.
    const Vec3 f = tie.stiffness * (state.position[static_cast<std::size_t>(tie.node)] -
                                    state.position[static_cast<std::size_t>(tie.carrier)]);
    force.segment<3>(dn) += f;
    force.segment<3>(dc) -= f;
    if (!matrix) continue;
    const double k = tie.stiffness * kf;
    matrix->addDiagonal3(dn, k);
    matrix->addDiagonal3(dc, k);
    matrix->add3x3(dn, dc, Mat3::Identity(), -k);
    matrix->add3x3(dc, dn, Mat3::Identity(), -k);
  }
}

bool JunctionTies::markLoadedNodes(std::vector<char>& mark) const {
  for (const model::NodeTie& tie : m_model->ties()) {
    mark[static_cast<std::size_t>(tie.node)] = 1;
    mark[static_cast<std::size_t>(tie.carrier)] = 1;
  }
  return true;
}

VecX JunctionTies::tieForces(const model::State& state) const {
  VecX force = VecX::Zero(m_model->dofs().fullDofCount());
  addTies(state, 1.0, force, nullptr);
  return force;
}

void JunctionTies::raiseRoundoffFloor(const model::State& state, std::vector<double>& floor) const {
  for (const model::NodeTie& t : m_model->ties()) {
    const double x = std::max(state.position[static_cast<std::size_t>(t.node)].cwiseAbs().maxCoeff(),
                              state.position[static_cast<std::size_t>(t.carrier)].cwiseAbs().maxCoeff());
    const double f = 16.0 * std::numeric_limits<double>::epsilon() * t.stiffness * x;
    for (const int n : {t.node, t.carrier})
      floor[static_cast<std::size_t>(n)] = std::max(floor[static_cast<std::size_t>(n)], f);
  }
}

}  // namespace tangle::solver
