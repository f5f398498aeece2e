/// @file YamlPython.cpp
/// YAML <-> Python conversion (see YamlPython.hpp).

#include "tangle/python/YamlPython.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <regex>

namespace py = pybind11;

namespace tangle::python {

namespace {

/// YAML 1.2 core schema forms of the plain scalars the reader accepts as numbers.
const std::regex& intPattern() {
  static const std::regex r("[-+]?[0-9]+");
  return r;
}
const std::regex& floatPattern() {
  static const std::regex r("[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?|[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|NAN)");
  return r;
}

py::object scalar(const YAML::Node& node) {
  const std::string& s = node.Scalar();
  if (node.Tag() == "!") return py::str(s);  // quoted: a string whatever it looks like
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return py::none();
  if (s == "true" || s == "True" || s == "TRUE") return py::bool_(true);
  if (s == "false" || s == "False" || s == "FALSE") return py::bool_(false);
  if (std::regex_match(s, intPattern())) {
    errno = 0;
    const long long v = std::strtoll(s.c_str(), nullptr, 10);
    if (errno == 0) return py::int_(v);
  }
  if (std::regex_match(s, floatPattern())) return py::float_(node.as<double>());
  return py::str(s);
}

}  // namespace

py::object toPython(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict d;
      for (const auto& kv : node) d[py::str(kv.first.Scalar())] = toPython(kv.second);
      return d;
    }
    case YAML::NodeType::Sequence: {
      py::list l;
      for (const auto& item : node) l.append(toPython(item));
      return l;
    }
    case YAML::NodeType::Scalar: return scalar(node);
    default: return py::none();
  }
}

YAML::Node toYaml(const py::handle& value, const std::string& where) {
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return YAML::Node(value.cast<long long>());
  if (py::isinstance<py::float_>(value)) {
    YAML::Emitter e;
    e.SetDoublePrecision(17);
    e << value.cast<double>();
    return YAML::Node(std::string(e.c_str()));
  }
  if (py::isinstance<py::str>(value)) {
    return YAML::Node(value.cast<std::string>());  // the reader reads names and words as text anyway
  }
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& kv : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(kv.first))
        throw py::type_error(fmt::format("model key {}: keys must be str, got {}", where.empty() ? "(top)" : where,
                                         py::repr(kv.first).cast<std::string>()));
      const std::string key = kv.first.cast<std::string>();
      map[key] = toYaml(kv.second, where.empty() ? key : where + "." + key);
    }
    return map;
  }
  if (py::hasattr(value, "tolist") && !py::isinstance<py::list>(value)) return toYaml(value.attr("tolist")(), where);
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node seq(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const auto& item : value) seq.push_back(toYaml(item, fmt::format("{}[{}]", where, i++)));
    return seq;
  }
  if (py::hasattr(value, "__index__")) return YAML::Node(value.attr("__index__")().cast<long long>());
  if (py::hasattr(value, "__float__")) return toYaml(py::float_(value.attr("__float__")()), where);
  throw py::type_error(fmt::format("model key {}: cannot store a {} in a model (numbers, str, bool, None, lists "
                                   "and dicts are)",
                                   where.empty() ? "(top)" : where,
                                   py::str(value.get_type().attr("__name__")).cast<std::string>()));
}

}  // namespace tangle::python
