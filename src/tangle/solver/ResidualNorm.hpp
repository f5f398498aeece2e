#pragma once
/// @file ResidualNorm.hpp
/// The convergence measure of the Newton solvers: the largest out-of-balance force over the free DOFs,
/// with moments made comparable to forces by dividing by a length at their node (Model::momentScale).

#include "tangle/core/Types.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::solver {

/// How a residual vector is indexed.
enum class ResidualIndexing {
  FullDofs,   ///< one entry per full DOF (constrained DOFs are skipped)
  Equations   ///< one entry per equation
};

/// Lever [m] that turns a nodal moment residual of a line node into a force for the statics' convergence
/// test (StaticSolver, ArcLengthContinuation): a fixed length, not the element length, so that the test does
/// not tighten as the mesh is refined.
inline constexpr double kStaticMomentLever = 1.0;

/// Largest |residual| over the free DOFs [N] (moments divided by the node's moment scale); NaN if any entry
/// is NaN. `worstNode` (optional) receives the node where it occurs. `lineMomentLever` [m], when > 0,
/// replaces the moment scale of line nodes (statics compares moments over a fixed lever, so that the test
/// does not tighten as elements get shorter); vessel nodes keep theirs.
double residualNorm(const model::Model& model, const VecX& residual, ResidualIndexing indexing, int* worstNode,
                    double lineMomentLever = 0.0);

}  // namespace tangle::solver
