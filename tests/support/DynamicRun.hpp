#pragma once
// The set-up every dynamic run of a test shares: the model on a Newton path, without plots or ParaView
// files, its statics solved; and the row of end tensions a test records at each output.

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "tangle/analysis/Simulation.hpp"

namespace tangle::test {

/// `spec` on the Newton path `solver` (dynamics.solver), plots and ParaView output off, with its statics
/// solved (a failure is recorded when they do not converge): ready for runDynamics.
inline std::unique_ptr<analysis::Simulation> simulationAfterStatics(model::ModelSpec spec,
                                                                    const model::DynamicSolverSpec& solver) {
  spec.dynamics.solver = solver;
  spec.output.vtk = false;
  spec.output.plots = false;
  auto sim = std::make_unique<analysis::Simulation>(std::move(spec));
  const solver::StaticResult statics = sim->solveStatics();
  EXPECT_TRUE(statics.converged) << statics.message;
  return sim;
}

/// Every line's effective tension at end A and end B, line after line [N], at the simulation's current state.
inline std::vector<double> endTensionRow(analysis::Simulation& sim) {
  std::vector<double> row;
  for (const solver::LineSnapshot& l : sim.snapshot(true)) {
    row.push_back(l.endTensionA);
    row.push_back(l.endTensionB);
  }
  return row;
}

}  // namespace tangle::test
