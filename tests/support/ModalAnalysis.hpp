#pragma once
/// @file ModalAnalysis.hpp
/// Natural frequencies of a model at a state for verification tests: the dense generalized eigenvalue
/// problem K phi = omega^2 M phi of the assembled tangent and mass (small models only).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/SystemMatrix.hpp"

namespace tangle::test {

/// Eigenfrequencies [Hz] (ascending) and mass-normalised modes (columns over the free equations).
struct ModalResult {
  VecX frequency;  ///< [Hz]
  MatX modes;      ///< columns over equations
};

/// K phi = omega^2 M phi with K the assembled static tangent (kf = 1) and M the assembled mass (mf = 1) at
/// `state`.
inline ModalResult modalAnalysis(solver::Assembler& assembler, const model::State& state) {
  const model::DofMap& dofs = assembler.model().dofs();
  solver::SystemMatrix k(dofs), m(dofs);
  solver::AssemblyRequest request;
  request.kf = 1.0;
  request.cf = 0.0;
  request.dynamic = false;
  request.wantMatrix = true;
  VecX force;
  assembler.assemble(state, request, force, &k);
  assembler.addMass(state, 1.0, &m, nullptr, nullptr);
  SparseMatrix ks, ms;
  k.build(ks);
  m.build(ms);
  MatX kd = MatX(ks);
  kd = 0.5 * (kd + kd.transpose()).eval();  // symmetric by construction; remove round-off asymmetry
  const MatX md = MatX(ms);
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> solver(kd, md);
  EXPECT_EQ(solver.info(), Eigen::Success);
  ModalResult r;
  r.frequency = solver.eigenvalues().unaryExpr(
      [](double l) { return std::sqrt(std::max(l, 0.0)) / (2.0 * 3.141592653589793); });
  r.modes = solver.eigenvectors();
  return r;
}

}  // namespace tangle::test
