/// @file CurrentProfile.cpp
/// Piecewise-linear current profile (see CurrentProfile.hpp).

#include "tangle/hydro/CurrentProfile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"

namespace tangle::hydro {

namespace {

[[noreturn]] void fail(std::size_t index, const std::string& what, double value) {
  std::ostringstream os;
  os.precision(17);
  os << "CurrentProfile: level " << index << ": " << what << " (got " << value << ")";
  throw Error(os.str());
}

/// Angle difference b - a wrapped to (-pi, pi] [rad].
double shorterArc(double a, double b) {
  double d = std::remainder(b - a, 2.0 * kPi);  // in [-pi, pi]
  if (d <= -kPi) d += 2.0 * kPi;
  return d;
}

}  // namespace

CurrentProfile::CurrentProfile(std::vector<CurrentLevel> levels) : m_levels(std::move(levels)) {
  if (m_levels.empty()) throw Error("CurrentProfile: at least one level is required");
  for (std::size_t i = 0; i < m_levels.size(); ++i) {
    const CurrentLevel& level = m_levels[i];
    if (!std::isfinite(level.z)) fail(i, "z [m] must be finite", level.z);
    if (level.z > 0.0)
      fail(i, "z [m] must be <= 0 (z is the global level, 0 at still water, negative below)", level.z);
    if (!std::isfinite(level.speed) || level.speed < 0.0)
      fail(i, "speed [m/s] must be finite and >= 0", level.speed);
    if (!std::isfinite(level.azimuth)) fail(i, "azimuth [rad] must be finite", level.azimuth);
  }
  std::stable_sort(m_levels.begin(), m_levels.end(),
                   [](const CurrentLevel& a, const CurrentLevel& b) { return a.z < b.z; });
  for (std::size_t i = 1; i < m_levels.size(); ++i) {
    if (m_levels[i].z == m_levels[i - 1].z) {
      fail(i, "two levels share the same z [m] (after sorting by z)", m_levels[i].z);
    }
  }
  m_unwrappedAzimuth.resize(m_levels.size());
  m_unwrappedAzimuth[0] = m_levels[0].azimuth;
  for (std::size_t i = 1; i < m_levels.size(); ++i) {
    m_unwrappedAzimuth[i] =
        m_unwrappedAzimuth[i - 1] + shorterArc(m_unwrappedAzimuth[i - 1], m_levels[i].azimuth);
  }
  // Directions at the levels, computed once: velocity() is called for every element at every assembly,
  // and between two levels of equal azimuth (the common case) the direction is exactly that of the level.
  m_unwrappedDirection.resize(m_levels.size());
  for (std::size_t i = 0; i < m_levels.size(); ++i)
    m_unwrappedDirection[i] = Vec2(std::cos(m_unwrappedAzimuth[i]), std::sin(m_unwrappedAzimuth[i]));
  m_frontDirection = Vec2(std::cos(m_levels.front().azimuth), std::sin(m_levels.front().azimuth));
  m_backDirection = Vec2(std::cos(m_levels.back().azimuth), std::sin(m_levels.back().azimuth));
}

CurrentProfile CurrentProfile::uniform(double speed, double azimuth) {
  return CurrentProfile({CurrentLevel{0.0, speed, azimuth}});
}

Vec3 CurrentProfile::profileVelocity(double z) const {
  if (z <= m_levels.front().z) {
    const double speed = m_levels.front().speed;
    return Vec3(speed * m_frontDirection.x(), speed * m_frontDirection.y(), 0.0);
  }
  if (z >= m_levels.back().z) {
    const double speed = m_levels.back().speed;
    return Vec3(speed * m_backDirection.x(), speed * m_backDirection.y(), 0.0);
  }
  // First level strictly above z; its predecessor is at or below z.
  const auto above = std::upper_bound(m_levels.begin(), m_levels.end(), z,
                                      [](double value, const CurrentLevel& level) { return value < level.z; });
  const auto i = static_cast<std::size_t>(above - m_levels.begin());
  const CurrentLevel& lo = m_levels[i - 1];
  const CurrentLevel& hi = m_levels[i];
  const double s = (z - lo.z) / (hi.z - lo.z);
  const double speed = lo.speed + s * (hi.speed - lo.speed);
  const double turn = m_unwrappedAzimuth[i] - m_unwrappedAzimuth[i - 1];
  if (turn == 0.0) return Vec3(speed * m_unwrappedDirection[i - 1].x(), speed * m_unwrappedDirection[i - 1].y(), 0.0);
  const double azimuth = m_unwrappedAzimuth[i - 1] + s * turn;
  return Vec3(speed * std::cos(azimuth), speed * std::sin(azimuth), 0.0);
}

CurrentProfile CurrentProfile::withGrid(std::shared_ptr<const CurrentGrid> grid) {
  if (!grid) throw Error("current grid: none given");
  CurrentProfile out;
  out.m_grid = std::move(grid);
  return out;
}

bool CurrentProfile::isZero() const {
  if (m_grid) return m_grid->isZero();
  if (!m_snapshots.empty())
    return std::all_of(m_snapshots.begin(), m_snapshots.end(),
                       [](const CurrentProfile& p) { return p.isZero(); });
  return std::all_of(m_levels.begin(), m_levels.end(), [](const CurrentLevel& l) { return l.speed == 0.0; });
}

Vec3 CurrentProfile::historyVelocity(double z, double t) const {
  if (t <= m_times.front()) return m_snapshots.front().velocity(z);
  if (t >= m_times.back()) return m_snapshots.back().velocity(z);
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(m_times.begin(), m_times.end(), t) - m_times.begin()) - 1;
  const double f = (t - m_times[k]) / (m_times[k + 1] - m_times[k]);
  return (1.0 - f) * m_snapshots[k].velocity(z) + f * m_snapshots[k + 1].velocity(z);
}

CurrentProfile CurrentProfile::withHistory(std::vector<double> times, std::vector<CurrentProfile> profiles) {
  if (times.empty() || times.size() != profiles.size())
    throw Error(fmt::format("current history: {} times and {} profiles (at least one of each, as many)",
                            times.size(), profiles.size()));
  for (std::size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1]))
      throw Error(fmt::format("current history: time {} s does not follow {} s", times[k], times[k - 1]));
  CurrentProfile out = profiles.front();
  out.m_times = std::move(times);
  out.m_snapshots = std::move(profiles);
  return out;
}

}  // namespace tangle::hydro
