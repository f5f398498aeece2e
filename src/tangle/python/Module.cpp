/// @file Module.cpp
/// The compiled part of the Python package `tangle` (module `tangle._tangle`); python/tangle/__init__.py
/// builds the user-facing classes on it. See docs/python.md.

#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "tangle/analysis/ExtremeStatistics.hpp"
#include "tangle/analysis/Rainflow.hpp"
#include "tangle/analysis/SnCurve.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/io/ModelDocument.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/MoorDynConversion.hpp"
#include "tangle/python/PyCoupledRun.hpp"
#include "tangle/python/PySimulation.hpp"
#include "tangle/python/YamlPython.hpp"

namespace py = pybind11;

namespace {

/// The model text of a Python model tree.
std::string yamlText(const py::object& tree) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << tangle::python::toYaml(tree);
  return std::string(out.c_str()) + "\n";
}

}  // namespace

PYBIND11_MODULE(_tangle, m) {
  m.doc() = "tangle: nonlinear statics and dynamics of offshore lines with line-to-line contact (compiled core)";
  m.attr("__version__") = TANGLE_VERSION;
  // The reader's InputError (file, line, key, what was expected) as tangle.ModelError (a ValueError).
  static py::exception<tangle::InputError> modelError(m, "ModelError", PyExc_ValueError);
  static py::exception<tangle::ConvergenceError> convergenceError(m, "ConvergenceError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const tangle::InputError& e) {
      modelError(e.what());
    } catch (const tangle::ConvergenceError& e) {
      convergenceError(e.what());
    }
  });

  m.def(
      "load_yaml",
      [](const std::string& text, const std::string& source) {
        return tangle::python::toPython(tangle::io::ModelDocument::fromText(text, source).root());
      },
      py::arg("text"), py::arg("source"), "YAML model text -> nested dicts and lists (syntax only).");
  m.def("dump_yaml", &yamlText, py::arg("tree"), "Nested dicts and lists -> YAML text.");
  m.def("is_moordyn_deck", &tangle::io::isMoorDynDeck, py::arg("path"),
        "True when the file reads as a MoorDyn v2 input file (docs/moordyn.md).");
  m.def(
      "convert_moordyn",
      [](const std::string& path) {
        const tangle::io::MoorDynConversion c = tangle::io::convertMoorDynDeck(tangle::io::readMoorDynDeck(path));
        return py::make_tuple(c.yaml, c.notes);
      },
      py::arg("path"), "MoorDyn v2 deck -> (tangle model YAML text, notes); raises ModelError naming the deck line.");
  m.def(
      "check",
      [](const std::string& text, const std::string& source) { tangle::io::readModelString(text, source); },
      py::arg("text"), py::arg("source"),
      "Checks model text with the model reader; raises ModelError with the reader's message.");
  m.def(
      "get_path",
      [](const py::object& tree, const std::string& path, const std::string& source) {
        const auto doc = tangle::io::ModelDocument::fromNode(tangle::python::toYaml(tree), source);
        return tangle::python::toPython(doc.get(path));
      },
      py::arg("tree"), py::arg("path"), py::arg("source"), "The value at a key path such as lines[riser].length.");
  m.def(
      "set_path",
      [](const py::object& tree, const std::string& path, const py::object& value, const std::string& source) {
        auto doc = tangle::io::ModelDocument::fromNode(tangle::python::toYaml(tree), source);
        doc.set(path, tangle::python::toYaml(value, path));
        return tangle::python::toPython(doc.root());
      },
      py::arg("tree"), py::arg("path"), py::arg("value"), py::arg("source"),
      "A copy of the tree with the value at a key path set (missing map keys are created).");

  m.def("run_to_folder", &tangle::python::runToFolder, py::arg("text"), py::arg("source"), py::arg("folder"),
        py::arg("overwrite"), py::arg("statics_only"), py::arg("report"), py::arg("plots"), py::arg("quiet"),
        "Runs the model into a results folder as `tangle run` does; returns (exit code, status).");

  // Design statistics (issue 32): numpy arrays in, numpy arrays and dicts out; units those of the input.
  m.def(
      "rainflow",
      [](const std::vector<double>& values) {
        const std::vector<tangle::analysis::RainflowCycle> cycles = tangle::analysis::rainflow(values);
        py::array_t<double> out({static_cast<py::ssize_t>(cycles.size()), static_cast<py::ssize_t>(3)});
        auto o = out.mutable_unchecked<2>();
        for (std::size_t i = 0; i < cycles.size(); ++i) {
          o(static_cast<py::ssize_t>(i), 0) = cycles[i].range;
          o(static_cast<py::ssize_t>(i), 1) = cycles[i].mean;
          o(static_cast<py::ssize_t>(i), 2) = cycles[i].count;
        }
        return out;
      },
      py::arg("values"),
      "Rainflow cycles (ASTM E1049-85 5.4.4) of a series: an array [cycle, (range, mean, count)], count 1 or 0.5.");
  // Cycles as rainflow returns them: rows (range, mean, count).
  const auto toCycles = [](const py::array_t<double>& rows) {
    const auto r = rows.unchecked<2>();
    if (r.ndim() != 2 || r.shape(1) != 3) throw py::value_error("cycles: an array of rows (range, mean, count)");
    std::vector<tangle::analysis::RainflowCycle> cycles;
    for (py::ssize_t i = 0; i < r.shape(0); ++i) cycles.push_back({r(i, 0), r(i, 1), r(i, 2)});
    return cycles;
  };
  const auto snCurve = [](double m1, double logA1, double m2, double logA2, double kneeCycles, double k,
                          double referenceThickness, double thickness) {
    tangle::analysis::SnCurve c;
    c.m1 = m1;
    c.logA1 = logA1;
    c.m2 = m2;
    c.logA2 = logA2;
    c.kneeCycles = kneeCycles;
    c.thicknessExponent = k;
    c.referenceThickness = referenceThickness;
    c.thickness = thickness;
    return c;
  };
  m.def(
      "sn_cycles_to_failure",
      [snCurve](double range, double m1, double logA1, double m2, double logA2, double kneeCycles, double k,
                double referenceThickness, double thickness) {
        return snCurve(m1, logA1, m2, logA2, kneeCycles, k, referenceThickness, thickness).cyclesToFailure(range);
      },
      py::arg("range"), py::arg("m1"), py::arg("log_a1"), py::arg("m2"), py::arg("log_a2"), py::arg("knee_cycles"),
      py::arg("k"), py::arg("reference_thickness"), py::arg("thickness"));
  m.def(
      "sn_preset",
      [](const std::string& name) {
        const std::optional<tangle::analysis::SnCurve> c = tangle::analysis::SnCurve::preset(name);
        if (!c) {
          std::string known;
          for (const std::string& n : tangle::analysis::SnCurve::presetNames()) known += (known.empty() ? "" : ", ") + n;
          throw py::value_error("unknown S-N curve preset '" + name + "'; expected one of " + known);
        }
        return py::make_tuple(c->m1, c->logA1, c->m2, c->logA2, c->kneeCycles, c->thicknessExponent,
                              c->referenceThickness);
      },
      py::arg("name"),
      "The constants (m1, log_a1, m2, log_a2, knee_cycles, k, reference_thickness) of a DNV-RP-C203 preset.");
  m.def(
      "sn_damage",
      [snCurve, toCycles](const py::array_t<double>& cycles, double m1, double logA1, double m2, double logA2,
                          double kneeCycles, double k, double referenceThickness, double thickness) {
        return tangle::analysis::minerDamage(
            toCycles(cycles), snCurve(m1, logA1, m2, logA2, kneeCycles, k, referenceThickness, thickness));
      },
      py::arg("cycles"), py::arg("m1"), py::arg("log_a1"), py::arg("m2"), py::arg("log_a2"), py::arg("knee_cycles"),
      py::arg("k"), py::arg("reference_thickness"), py::arg("thickness"),
      "Miner's sum of rainflow cycles [Pa] against a two-slope S-N curve (analysis/SnCurve).");
  m.def(
      "tn_damage",
      [toCycles](const py::array_t<double>& cycles, double breakingStrength, double slope, double aD) {
        return tangle::analysis::minerDamage(toCycles(cycles), tangle::analysis::TnCurve{slope, aD, breakingStrength});
      },
      py::arg("cycles"), py::arg("breaking_strength"), py::arg("m"), py::arg("a_d"),
      "Miner's sum of rainflow cycles of tension [N] against a chain T-N curve.");
  m.def(
      "peaks",
      [](const std::vector<double>& times, const std::vector<double>& values) {
        const tangle::analysis::PeakSet p = tangle::analysis::findPeaks(times, values);
        py::dict d;
        d["peaks"] = p.peaks;
        d["mean"] = p.mean;
        d["standard_deviation"] = p.standardDeviation;
        d["upcrossing_period_s"] = p.upcrossingPeriod;
        return d;
      },
      py::arg("times"), py::arg("values"));
  m.def(
      "fit_peaks",
      [](const std::vector<double>& peaks, double mean, const std::string& distribution, double count) {
        tangle::analysis::PeakSet p;
        p.peaks = peaks;
        p.mean = mean;
        const tangle::analysis::PeakFit f = distribution == "weibull" ? tangle::analysis::fitWeibull(p)
                                                                      : tangle::analysis::fitRayleigh(p);
        return py::make_tuple(f.scale, f.shape, f.mostProbableMaximum(mean, count));
      },
      py::arg("peaks"), py::arg("mean"), py::arg("distribution"), py::arg("count"),
      "(alpha, beta, most probable maximum of `count` peaks) of the fit of the peaks' excess over `mean`.");
  m.def(
      "fit_gumbel",
      [](const std::vector<double>& maxima) {
        const tangle::analysis::GumbelFit g = tangle::analysis::fitGumbel(maxima);
        return py::make_tuple(g.mean, g.standardDeviation, g.scale, g.mode);
      },
      py::arg("maxima"));

  py::class_<tangle::python::PySimulation>(m, "Simulation", "One analysis of one model (compiled core).")
      .def(py::init<const std::string&, const std::string&>(), py::arg("text"), py::arg("source"))
      .def("lines", &tangle::python::PySimulation::lines)
      .def("statics", &tangle::python::PySimulation::statics)
      .def("profiles", &tangle::python::PySimulation::profiles)
      .def("dynamics", &tangle::python::PySimulation::dynamics, py::arg("progress") = py::none());

  // Co-simulation (tangle.Coupling, python/tangle/coupling.py): analysis::CoupledRun stepped by a host.
  tangle::python::bindCoupledRun(m);
}
