#pragma once
/// @file YamlPython.hpp
/// Model trees between YAML and Python: the Python module edits a model as nested dicts and lists, and
/// hands it back to the model reader as YAML text, so a model built in Python gets exactly the checks and
/// messages of a model file.
///
/// YAML -> Python: maps -> dict, lists -> list, plain scalars -> None (null, ~, empty), bool (true/false),
/// int, float, else str; quoted scalars stay str. Python -> YAML: dict (str keys), list, tuple and
/// numpy arrays (via tolist()), bool, int (also numpy integers), float (17 significant digits), None, str.

#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

#include <string>

namespace tangle::python {

pybind11::object toPython(const YAML::Node& node);
/// @param where the key path so far, for the TypeError of an unsupported value
YAML::Node toYaml(const pybind11::handle& value, const std::string& where = "");

}  // namespace tangle::python
