/// @file PyCoupledRun.cpp
/// Co-simulation from Python (see PyCoupledRun.hpp).

#include "tangle/python/PyCoupledRun.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

#include "tangle/core/Error.hpp"
#include "tangle/io/ModelReader.hpp"
#include "tangle/io/MoorDynCoupling.hpp"
#include "tangle/io/MoorDynDeck.hpp"

namespace py = pybind11;

namespace tangle::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The coupled points given as lists of "line_name:a" / "line_name:b", or as ["vessel:name"] for a pinned
/// vessel's reference point (points named point1, point2, ...).
std::vector<analysis::CoupledPointSpec> parsePoints(const std::vector<std::vector<std::string>>& points,
                                                    const std::string& path) {
  std::vector<analysis::CoupledPointSpec> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    analysis::CoupledPointSpec p;
    p.name = fmt::format("point{}", i + 1);
    if (points[i].empty())
      throw InputError(
          path, 0, fmt::format("points[{}]", i),
          "a list of at least one line end ('line_name:a'), or ['vessel:name'] for a pinned vessel");
    if (points[i].size() == 1 && points[i][0].rfind("vessel:", 0) == 0) {
      p.vessel = points[i][0].substr(7);  // CoupledRun checks that it names a pinned free vessel
      out.push_back(std::move(p));
      continue;
    }
    for (std::size_t j = 0; j < points[i].size(); ++j) {
      const std::string& text = points[i][j];
      const std::size_t colon = text.rfind(':');
      std::string end = colon == std::string::npos ? std::string() : text.substr(colon + 1);
      std::transform(end.begin(), end.end(), end.begin(), [](unsigned char c) { return std::tolower(c); });
      if (colon == 0 || (end != "a" && end != "b"))
        throw InputError(path, 0, fmt::format("points[{}][{}]", i, j),
                         fmt::format("a line end as 'line_name:a' or 'line_name:b', not '{}'", text));
      p.ends.emplace_back(text.substr(0, colon), end == "a" ? 0 : 1);
    }
    out.push_back(std::move(p));
  }
  return out;
}

Array flatArray(const std::vector<double>& data) {
  Array a(static_cast<py::ssize_t>(data.size()));
  std::copy(data.begin(), data.end(), a.mutable_data());
  return a;
}

}  // namespace

PyCoupledRun::PyCoupledRun(const std::string& path,
                           const std::optional<std::vector<std::vector<std::string>>>& points) {
  model::ModelSpec spec;
  if (io::isMoorDynDeck(path)) {
    io::DeckCoupling deck = io::loadMoorDynCoupling(path);
    spec = std::move(deck.spec);
    m_points = points ? parsePoints(*points, path) : std::move(deck.points);
  } else {
    spec = io::readModelFile(path);  // first: a missing or bad file is the first thing to report
    if (!points)
      throw InputError(
          path, 0, "points",
          "the coupled points of a tangle model, e.g. points=[['mooring1:b']] (a list of line ends "
          "per point; only a MoorDyn deck has default points)");
    m_points = parsePoints(*points, path);
  }
  m_run = std::make_unique<analysis::CoupledRun>(std::move(spec), m_points);
}

std::vector<std::vector<std::string>> PyCoupledRun::pointEnds() const {
  std::vector<std::vector<std::string>> out;
  for (const analysis::CoupledPointSpec& p : m_points) {
    std::vector<std::string> ends;
    if (!p.vessel.empty()) ends.push_back("vessel:" + p.vessel);
    for (const auto& [line, end] : p.ends) ends.push_back(line + (end == 0 ? ":a" : ":b"));
    out.push_back(std::move(ends));
  }
  return out;
}

py::array_t<double> PyCoupledRun::modelPositions() const {
  if (!m_run->initialized()) return flatArray(m_run->modelPositions());
  std::vector<double> positions;
  for (int p = 0; p < pointCount(); ++p) {
    const Vec3 x = m_run->pointPosition(p);
    positions.insert(positions.end(), {x.x(), x.y(), x.z()});
  }
  return flatArray(positions);
}

std::vector<double> PyCoupledRun::values(const py::array_t<double>& a, const char* name) const {
  const Array flat = Array::ensure(a);
  if (!flat) throw std::invalid_argument(fmt::format("{} must be an array of numbers", name));
  const auto n = static_cast<py::ssize_t>(3 * pointCount());
  if (flat.size() != n)
    throw std::invalid_argument(fmt::format("{} has {} values; {} expected (x, y, z of {} points)", name,
                                            flat.size(), n, pointCount()));
  return std::vector<double>(flat.data(), flat.data() + n);
}

void PyCoupledRun::initialize(const py::array_t<double>& x, const std::optional<py::array_t<double>>& xd) {
  const std::vector<double> position = values(x, "x");
  const std::vector<double> velocity =
      xd ? values(*xd, "xd") : std::vector<double>(static_cast<std::size_t>(3 * pointCount()), 0.0);
  if (m_run->initialized()) throw std::runtime_error("init() was already called on this coupling");
  py::gil_scoped_release release;
  m_run->initialize(position, velocity);
}

py::array_t<double> PyCoupledRun::step(const py::array_t<double>& x, const py::array_t<double>& xd,
                                       double dt) {
  if (!m_run->initialized()) throw std::runtime_error("call init() before step()");
  if (!(dt > 0.0)) throw std::invalid_argument(fmt::format("dt must be > 0, not {}", dt));
  const std::vector<double> position = values(x, "x");
  const std::vector<double> velocity = values(xd, "xd");
  {
    py::gil_scoped_release release;
    m_run->step(position, velocity, dt);
  }
  return flatArray(m_run->forces());
}

double PyCoupledRun::time() const { return m_run->initialized() ? m_run->time() : 0.0; }

py::array_t<double> PyCoupledRun::forces() const {
  const auto n = static_cast<std::size_t>(3 * pointCount());
  if (!m_run->initialized() || m_run->forces().size() != n) return flatArray(std::vector<double>(n, 0.0));
  return flatArray(m_run->forces());
}

py::dict PyCoupledRun::lineTensions() const {
  if (!m_run->initialized()) throw std::runtime_error("call init() first: there are no results yet");
  py::dict out;
  for (const solver::LineSnapshot& s : m_run->lineResults()) out[py::str(s.name)] = flatArray(s.tension);
  return out;
}

void bindCoupledRun(py::module_& m) {
  py::class_<PyCoupledRun>(
      m, "CoupledRun",
      "A model driven step by step by a host (analysis::CoupledRun; tangle.Coupling wraps it).")
      .def(py::init<const std::string&, const std::optional<std::vector<std::vector<std::string>>>&>(),
           py::arg("path"), py::arg("points") = py::none())
      .def_property_readonly("point_count", &PyCoupledRun::pointCount)
      .def_property_readonly("point_ends", &PyCoupledRun::pointEnds)
      .def_property_readonly("initialized", &PyCoupledRun::initialized)
      .def("model_positions", &PyCoupledRun::modelPositions,
           "Positions of the points in the model, flat [m].")
      .def("initialize", &PyCoupledRun::initialize, py::arg("x"), py::arg("xd") = py::none(),
           "Puts the points at x [m] (flat) and solves the statics there; xd [m/s] or None.")
      .def("step", &PyCoupledRun::step, py::arg("x"), py::arg("xd"), py::arg("dt"),
           "Advances by dt [s] with the points moving from x [m] at xd [m/s]; returns the forces, flat [N].")
      .def_property_readonly("time", &PyCoupledRun::time)
      .def("forces", &PyCoupledRun::forces, "Forces the lines exert on the points, flat [N].")
      .def("line_tensions", &PyCoupledRun::lineTensions, "Effective tension per node of every line [N].");
}

}  // namespace tangle::python
