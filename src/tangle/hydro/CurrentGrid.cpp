/// @file CurrentGrid.cpp
#include "tangle/hydro/CurrentGrid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/core/Error.hpp"
#include "tangle/core/WordTable.hpp"

namespace tangle::hydro {

namespace {
/// The cell of `ticks` that holds v and the fraction of the way across it, v clamped to the ticks.
struct Bracket {
  std::size_t lower;
  double fraction;
};
Bracket bracket(const std::vector<double>& ticks, double v) {
  if (ticks.size() == 1 || !(v > ticks.front())) return {0, 0.0};
  if (v >= ticks.back()) return {ticks.size() - 2, 1.0};
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(ticks.begin(), ticks.end(), v) - ticks.begin()) - 1;
  return {k, (v - ticks[k]) / (ticks[k + 1] - ticks[k])};
}
}  // namespace

CurrentGrid::CurrentGrid(std::array<std::vector<double>, 4> ticks, std::vector<Vec3> velocity)
    : m_ticks(std::move(ticks)), m_velocity(std::move(velocity)) {
  static const char* const kNames[4] = {"x", "y", "z", "t"};
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < 4; ++a) {
    const std::vector<double>& t = m_ticks[a];
    if (t.empty()) throw Error(fmt::format("current grid: no {} ticks", kNames[a]));
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (!std::isfinite(t[i]))
        throw Error(fmt::format("current grid: {} tick {} is not finite", kNames[a], i));
      if (i > 0 && !(t[i] > t[i - 1]))
        throw Error(
            fmt::format("current grid: {} ticks must increase; {} follows {}", kNames[a], t[i], t[i - 1]));
    }
    nodes *= t.size();
  }
  if (m_velocity.size() != nodes)
    throw Error(fmt::format("current grid: {} velocities for {} nodes", m_velocity.size(), nodes));
  for (const Vec3& v : m_velocity)
    if (!v.allFinite()) throw Error("current grid: a velocity is not finite");
}

Vec3 CurrentGrid::velocity(const Vec3& position, double t) const {
  const Bracket b[4] = {bracket(m_ticks[0], position.x()), bracket(m_ticks[1], position.y()),
                        bracket(m_ticks[2], position.z()), bracket(m_ticks[3], t)};
  const std::size_t n[4] = {m_ticks[0].size(), m_ticks[1].size(), m_ticks[2].size(), m_ticks[3].size()};
  Vec3 out = Vec3::Zero();
  // The 16 corners of the cell (fewer distinct ones along an axis of one tick: its weight is all on corner
  // 0).
  for (int corner = 0; corner < 16; ++corner) {
    double weight = 1.0;
    std::size_t index = 0;
    for (int a = 0; a < 4; ++a) {
      const bool upper = (corner >> a) & 1;
      const double w = upper ? b[a].fraction : 1.0 - b[a].fraction;
      if (w == 0.0) {
        weight = 0.0;
        break;
      }
      weight *= w;
      index = index * n[a] + b[a].lower + (upper ? 1 : 0);
    }
    if (weight != 0.0) out += weight * m_velocity[index];
  }
  return out;
}

bool CurrentGrid::isZero() const {
  return std::all_of(m_velocity.begin(), m_velocity.end(), [](const Vec3& v) { return v.isZero(0.0); });
}

CurrentGrid readCurrentGridFile(const std::string& path) {
  const core::WordTable table(path, "current grid");
  if (table.size() < 5 || table.rows()[0].words.size() != 4)
    throw InputError(path, table.size() > 0 ? table.rows()[0].line : 0, "nx ny nz nt",
                     "a first line 'nx ny nz nt', the x, y, z and t ticks on one line each, then one row "
                     "'x y z t ux uy uz' per grid node");
  std::array<std::size_t, 4> n{};
  static const char* const kCounts[4] = {"nx", "ny", "nz", "nt"};
  for (std::size_t a = 0; a < 4; ++a) n[a] = table.count(0, a, kCounts[a], 1.0, 1.0e6);
  const double nodes = double(n[0]) * double(n[1]) * double(n[2]) * double(n[3]);
  if (nodes > 1.0e7)
    throw InputError(path, table.rows()[0].line, "nx ny nz nt",
                     fmt::format("at most 10 000 000 grid nodes, got {}", nodes));
  static const char* const kTicks[4] = {"x ticks", "y ticks", "z ticks", "t ticks"};
  std::array<std::vector<double>, 4> ticks;
  for (std::size_t a = 0; a < 4; ++a) ticks[a] = table.ticks(1 + a, n[a], kTicks[a]);
  if (table.size() - 5 != static_cast<std::size_t>(nodes))
    throw InputError(path, 0, "x y z t ux uy uz",
                     fmt::format("one row per grid node: {} rows, got {}", static_cast<std::size_t>(nodes),
                                 table.size() - 5));
  std::vector<Vec3> velocity(static_cast<std::size_t>(nodes), Vec3::Constant(std::nan("")));
  static const char* const kCoordinates[4] = {"x", "y", "z", "t"};
  for (std::size_t r = 5; r < table.size(); ++r) {
    const core::WordRow& row = table.rows()[r];
    if (row.words.size() != 7)
      throw InputError(path, row.line, "x y z t ux uy uz",
                       fmt::format("7 numbers, got {}", row.words.size()));
    std::size_t index = 0;
    for (std::size_t a = 0; a < 4; ++a) {
      const double v = table.number(r, a, kCoordinates[a]);
      const std::vector<double>& t = ticks[a];
      const auto at = std::lower_bound(t.begin(), t.end(), v);
      // A row's coordinate is one of the ticks (to the round-off of writing it in text).
      const double tol = 1e-9 * std::max(1.0, std::abs(v));
      std::size_t k = static_cast<std::size_t>(at - t.begin());
      if (k > 0 && (k == t.size() || std::abs(t[k - 1] - v) < std::abs(t[k] - v))) --k;
      if (std::abs(t[k] - v) > tol)
        throw InputError(path, row.line, kCoordinates[a],
                         fmt::format("one of the {} ticks, got {}", kCoordinates[a], row.words[a]));
      index = index * n[a] + k;
    }
    if (!std::isnan(velocity[index].x()))
      throw InputError(path, row.line, "x y z t", "one row per grid node; this node was given before");
    velocity[index] = Vec3(table.number(r, 4, "ux"), table.number(r, 5, "uy"), table.number(r, 6, "uz"));
  }
  return CurrentGrid(std::move(ticks), std::move(velocity));
}

}  // namespace tangle::hydro
