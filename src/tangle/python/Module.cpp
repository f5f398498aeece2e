/// @file Module.cpp
/// The compiled part of the Python package `tangle` (module `tangle._tangle`); python/tangle/__init__.py
/// builds the user-facing classes on it. See docs/python.md.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "tangle/core/Error.hpp"
#include "tangle/io/ModelDocument.hpp"
#include "tangle/io/ModelReader.hpp"
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

  py::class_<tangle::python::PySimulation>(m, "Simulation", "One analysis of one model (compiled core).")
      .def(py::init<const std::string&, const std::string&>(), py::arg("text"), py::arg("source"))
      .def("lines", &tangle::python::PySimulation::lines)
      .def("statics", &tangle::python::PySimulation::statics)
      .def("profiles", &tangle::python::PySimulation::profiles)
      .def("dynamics", &tangle::python::PySimulation::dynamics, py::arg("progress") = py::none());
}
