#pragma once
/// @file PySimulation.hpp
/// One analysis driven from Python: statics and dynamics of analysis::Simulation with the results
/// collected in memory and returned as numpy arrays (the same quantities the CLI writes, computed by the
/// same code: solver::LineSnapshot at every output time, ranges over every accepted step, contact events,
/// clearance envelopes). The GIL is released while the solvers run.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <utility>

#include "tangle/analysis/Simulation.hpp"

namespace tangle::python {

/// Runs the model `yaml` (named `sourceName` in messages) into the results folder `folder`, as `tangle run`
/// does: every file of the run, results.h5 and report.html included (results::RunOutputs). Returns the exit
/// code (0, or 2 when the statics did not converge or the dynamics stopped: the folder holds what was
/// computed; 130 when Ctrl-C stopped the dynamics at the next step) and the folder's status.
/// @throws InputError (tangle.ModelError) on bad input or a folder that may not be used
std::pair<int, std::string> runToFolder(const std::string& yaml, const std::string& sourceName, const std::string& folder,
                                        bool overwrite, bool staticsOnly, bool report, bool plots, bool quiet);

class PySimulation {
 public:
  /// Reads the model text (the model reader's checks; InputError -> tangle.ModelError) and meshes it.
  PySimulation(const std::string& yaml, const std::string& sourceName);

  /// Static equilibrium. Returns {converged, iterations, load_fraction, max_out_of_balance_N, message,
  /// warnings}; the Python layer raises when it did not converge.
  pybind11::dict statics();
  /// Results along every line at the current state: a list of dicts of numpy arrays (units in the keys).
  pybind11::list profiles();
  /// The dynamic run from the static equilibrium. `progress(time_s, duration_s)` (or None) is called at
  /// every output time with the GIL held; when it raises, or Ctrl-C reaches Python, the run stops at the
  /// next step and the dict holds everything up to then with `interrupted` True and `error` the exception.
  pybind11::dict dynamics(const pybind11::object& progress);
  /// The lines of the model: [{name, nodes, elements, length_m, mass_kg, arc_length_m}].
  pybind11::list lines();

 private:
  std::unique_ptr<analysis::Simulation> m_sim;
  bool m_staticsConverged = false;
};

}  // namespace tangle::python
