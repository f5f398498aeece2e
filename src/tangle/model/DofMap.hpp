#pragma once
/// @file DofMap.hpp
/// Numbering of the degrees of freedom: every node owns 3 (bar nodes: translations) or 6 (beam
/// nodes: translations then rotations) consecutive "full" DOFs; each full DOF is either free (it has
/// an equation number) or constrained (its value is prescribed and it has no equation).

#include <cstddef>
#include <vector>

namespace tangle::model {

/// Maps node DOFs to full DOF indices and free DOFs to equation numbers.
class DofMap {
 public:
  /// Adds a node with `dofCount` (3 or 6) DOFs; returns its first full DOF index.
  int addNode(int dofCount);
  /// Marks full DOF `dof` as constrained (no equation). Call before finalize().
  void constrain(int dof);
  /// Numbers the free DOFs. Must be called once, after all addNode/constrain calls.
  void finalize();

  int nodeCount() const { return static_cast<int>(m_firstDof.size()); }  ///< number of nodes
  int fullDofCount() const { return static_cast<int>(m_equation.size()); } ///< all DOFs
  int equationCount() const { return m_equationCount; }                   ///< free DOFs
  int firstDof(int node) const { return m_firstDof[node]; }                ///< first full DOF of a node
  int dofCount(int node) const { return m_dofCount[node]; }                ///< 3 or 6
  bool hasRotations(int node) const { return m_dofCount[node] == 6; }      ///< beam node
  /// Equation number of full DOF `dof`, or -1 when constrained.
  int equation(int dof) const { return m_equation[dof]; }
  /// Node owning full DOF `dof`.
  int nodeOf(int dof) const { return m_dofNode[dof]; }
  /// Full DOF of each equation.
  const std::vector<int>& equationDofs() const { return m_equationDof; }
  /// First equation of node `node` (0 <= node <= nodeCount()): the equations are numbered in node order, so
  /// the node's are [firstEquation(node), firstEquation(node + 1)), empty for a node held in every DOF.
  int firstEquation(int node) const { return m_firstEquation[static_cast<std::size_t>(node)]; }

 private:
  std::vector<int> m_firstDof;
  std::vector<int> m_dofCount;
  std::vector<int> m_equation;  // -1 constrained, -2 free before finalize
  std::vector<int> m_equationDof;
  std::vector<int> m_dofNode;
  std::vector<int> m_firstEquation;  // per node, then the equation count (finalize)
  int m_equationCount = 0;
};

}  // namespace tangle::model
