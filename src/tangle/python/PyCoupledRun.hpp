#pragma once
/// @file PyCoupledRun.hpp
/// analysis::CoupledRun driven from Python: the compiled class `tangle._tangle.CoupledRun`, which
/// python/tangle/coupling.py wraps as `tangle.Coupling` (docs/moordyn.md, "C API and Python coupling").
/// The model is a MoorDyn deck (read as the C API reads it, io::loadMoorDynCoupling) or a tangle model file;
/// the coupled points are lists of line ends named "line_name:a" / "line_name:b". Arrays are flat here
/// (x, y, z per point); the Python layer shapes them (n, 3). The GIL is released while the model solves.
/// Units: SI (m, m/s, N, s).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tangle/analysis/CoupledRun.hpp"

namespace tangle::python {

class PyCoupledRun {
 public:
  /// Reads the model at `path` (a MoorDyn deck when io::isMoorDynDeck, else a tangle YAML model). `points`:
  /// the line ends held by each coupled point; required for a YAML model, by default for a deck its Coupled
  /// points in deck order. @throws InputError (tangle.ModelError) for a bad file, bad end names, ends
  /// CoupledRun refuses, or a YAML model without points
  PyCoupledRun(const std::string& path, const std::optional<std::vector<std::vector<std::string>>>& points);

  int pointCount() const { return m_run->pointCount(); }
  /// The line ends of each point as "line_name:a" / "line_name:b".
  std::vector<std::vector<std::string>> pointEnds() const;
  /// Positions of the points, flat [m]: before initialize the model's (CoupledRun::modelPositions), then
  /// where the host has them at the current time (CoupledRun::pointPosition).
  pybind11::array_t<double> modelPositions() const;
  /// CoupledRun::initialize (x [m], xd [m/s], 3 values per point; xd None: zero), without the GIL.
  void initialize(const pybind11::array_t<double>& x, const std::optional<pybind11::array_t<double>>& xd);
  /// CoupledRun::step over dt [s] without the GIL; returns the forces, flat [N].
  pybind11::array_t<double> step(const pybind11::array_t<double>& x, const pybind11::array_t<double>& xd,
                                 double dt);
  /// Simulated time [s] (0 before the first step).
  double time() const;
  /// The forces on the points at the current state, flat [N] (zero before initialize).
  pybind11::array_t<double> forces() const;
  /// Effective tension per node of every line at the current state [N], by line name.
  pybind11::dict lineTensions() const;
  bool initialized() const { return m_run->initialized(); }

 private:
  /// The values of `a` (3 per point). @throws std::invalid_argument (ValueError) for another size
  std::vector<double> values(const pybind11::array_t<double>& a, const char* name) const;

  std::vector<analysis::CoupledPointSpec> m_points;
  std::unique_ptr<analysis::CoupledRun> m_run;
};

/// Adds `CoupledRun` to the module.
void bindCoupledRun(pybind11::module_& m);

}  // namespace tangle::python
