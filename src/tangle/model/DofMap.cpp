#include "tangle/model/DofMap.hpp"

#include "tangle/core/Error.hpp"

namespace tangle::model {

int DofMap::addNode(int dofCount) {
  if (dofCount != 3 && dofCount != 6) throw Error("DofMap: a node has 3 or 6 DOFs");
  const int first = fullDofCount();
  m_firstDof.push_back(first);
  m_dofCount.push_back(dofCount);
  m_equation.insert(m_equation.end(), dofCount, -2);
  m_dofNode.insert(m_dofNode.end(), dofCount, nodeCount() - 1);
  return first;
}

void DofMap::constrain(int dof) { m_equation.at(dof) = -1; }

void DofMap::finalize() {
  m_equationCount = 0;
  m_equationDof.clear();
  m_firstEquation.assign(m_firstDof.size() + 1, 0);
  for (int dof = 0; dof < fullDofCount(); ++dof) {
    if (m_equation[dof] != -1) {
      m_equation[dof] = m_equationCount++;
      m_equationDof.push_back(dof);
    }
    m_firstEquation[static_cast<std::size_t>(m_dofNode[dof]) + 1] = m_equationCount;
  }
}

}  // namespace tangle::model
