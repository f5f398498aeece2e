#include "tangle/seabed/SeabedSurface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/core/WordTable.hpp"

namespace tangle::seabed {

namespace {

/// Cell of `ticks` holding `v` and the fraction across it; beyond the ends, the end cell with the fraction
/// clamped to 0 or 1 (the height is held at the edge value) and `inside` false (no slope along this axis).
struct CellPosition {
  std::size_t cell = 0;
  double fraction = 0.0;
  double width = 1.0;
  bool inside = false;
};

CellPosition locate(const std::vector<double>& ticks, double v) {
  CellPosition c;
  if (ticks.size() < 2) return c;
  if (v <= ticks.front()) return c;
  if (v >= ticks.back()) {
    c.cell = ticks.size() - 2;
    c.fraction = 1.0;
    c.width = ticks.back() - ticks[c.cell];
    return c;
  }
  c.cell = static_cast<std::size_t>(std::upper_bound(ticks.begin(), ticks.end(), v) - ticks.begin()) - 1;
  c.width = ticks[c.cell + 1] - ticks[c.cell];
  c.fraction = (v - ticks[c.cell]) / c.width;
  c.inside = true;
  return c;
}

Vec3 normalFromGradient(double gx, double gy) { return Vec3(-gx, -gy, 1.0).normalized(); }

}  // namespace

SeabedSurface SeabedSurface::flat(double depth) {
  SeabedSurface s;
  s.m_kind = Kind::Flat;
  s.m_depth = depth;
  return s;
}

SeabedSurface SeabedSurface::plane(double depth, double slope, double azimuth) {
  if (!(slope >= 0.0 && slope < 0.5 * kPi))
    throw std::invalid_argument("seabed slope must be in [0, 90) degrees");
  if (slope == 0.0) return flat(depth);
  SeabedSurface s;
  s.m_kind = Kind::Plane;
  s.m_depth = depth;
  s.m_slope = slope;
  s.m_azimuth = azimuth;
  const double t = std::tan(slope);
  s.m_gradient = Vec2(t * std::cos(azimuth), t * std::sin(azimuth));
  return s;
}

SeabedSurface SeabedSurface::grid(std::vector<double> x, std::vector<double> y, std::vector<double> height,
                                  Interpolation interpolation) {
  if (x.empty() || y.empty())
    throw std::invalid_argument("a bathymetry grid needs at least one x and one y tick");
  for (const std::vector<double>* ticks : {&x, &y})
    for (std::size_t i = 1; i < ticks->size(); ++i)
      if (!((*ticks)[i] > (*ticks)[i - 1]))
        throw std::invalid_argument("the ticks of a bathymetry grid must increase strictly");
  if (height.size() != x.size() * y.size())
    throw std::invalid_argument(fmt::format("a bathymetry grid of {} x {} ticks needs {} heights, got {}",
                                            x.size(), y.size(), x.size() * y.size(), height.size()));
  SeabedSurface s;
  s.m_kind = Kind::Grid;
  s.m_x = std::move(x);
  s.m_y = std::move(y);
  s.m_height = std::move(height);
  s.m_depth = -*std::min_element(s.m_height.begin(), s.m_height.end());
  return s.interpolated(interpolation);
}

SeabedSurface SeabedSurface::interpolated(Interpolation interpolation) const {
  SeabedSurface s = *this;
  if (m_kind != Kind::Grid) return s;
  s.m_interpolation = interpolation;
  s.m_hx.clear();
  s.m_hy.clear();
  s.m_hxy.clear();
  if (interpolation == Interpolation::Cubic) s.computeNodeSlopes();
  return s;
}

namespace {

/// The derivative at each tick of the values v (stride `stride` from `first`, `count` of them) along
/// `ticks`: the parabola's through the tick and its two neighbours (uneven spacing), one-sided at the ends,
/// 0 for a single tick.
void tickDerivatives(const std::vector<double>& ticks, const std::vector<double>& v, std::size_t first,
                     std::size_t stride, std::vector<double>& out) {
  const std::size_t n = ticks.size();
  const auto at = [&](std::size_t i) { return v[first + i * stride]; };
  for (std::size_t i = 0; i < n; ++i) {
    double d = 0.0;
    if (n >= 2) {
      if (i == 0) {
        d = (at(1) - at(0)) / (ticks[1] - ticks[0]);
      } else if (i + 1 == n) {
        d = (at(n - 1) - at(n - 2)) / (ticks[n - 1] - ticks[n - 2]);
      } else {
        const double hl = ticks[i] - ticks[i - 1], hr = ticks[i + 1] - ticks[i];
        const double sl = (at(i) - at(i - 1)) / hl, sr = (at(i + 1) - at(i)) / hr;
        d = (sl * hr + sr * hl) / (hl + hr);
      }
    }
    out[first + i * stride] = d;
  }
}

/// Cubic Hermite basis on [0, 1]: values at u of the four functions (value at 0, value at 1, slope at 0,
/// slope at 1, the slopes per unit u) and their derivatives in u.
struct Hermite {
  double h00, h01, h10, h11, d00, d01, d10, d11;
  explicit Hermite(double u) {
    const double u2 = u * u, u3 = u2 * u;
    h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
    h01 = -2.0 * u3 + 3.0 * u2;
    h10 = u3 - 2.0 * u2 + u;
    h11 = u3 - u2;
    d00 = 6.0 * u2 - 6.0 * u;
    d01 = -6.0 * u2 + 6.0 * u;
    d10 = 3.0 * u2 - 4.0 * u + 1.0;
    d11 = 3.0 * u2 - 2.0 * u;
  }
};

}  // namespace

void SeabedSurface::computeNodeSlopes() {
  const std::size_t nx = m_x.size(), ny = m_y.size();
  m_hx.assign(m_height.size(), 0.0);
  m_hy.assign(m_height.size(), 0.0);
  m_hxy.assign(m_height.size(), 0.0);
  for (std::size_t j = 0; j < ny; ++j) tickDerivatives(m_x, m_height, j * nx, 1, m_hx);
  for (std::size_t i = 0; i < nx; ++i) tickDerivatives(m_y, m_height, i, nx, m_hy);
  for (std::size_t i = 0; i < nx; ++i) tickDerivatives(m_y, m_hx, i, nx, m_hxy);
}

SeabedPoint SeabedSurface::cubicAt(double x, double y) const {
  const std::size_t nx = m_x.size();
  const CellPosition cx = locate(m_x, x);
  const CellPosition cy = locate(m_y, y);
  const std::size_t i0 = cx.cell, i1 = nx > 1 ? cx.cell + 1 : 0;
  const std::size_t j0 = cy.cell, j1 = m_y.size() > 1 ? cy.cell + 1 : 0;
  // A single tick along an axis: no extent, the slopes along it are 0 and the width does not matter.
  const double wx = nx > 1 ? cx.width : 1.0, wy = m_y.size() > 1 ? cy.width : 1.0;
  const Hermite bx(cx.fraction), by(cy.fraction);
  const std::array<std::size_t, 4> node{j0 * nx + i0, j0 * nx + i1, j1 * nx + i0, j1 * nx + i1};
  // Corner k = (p, q): p along x (0: i0, 1: i1), q along y.
  const std::array<double, 2> ax{bx.h00, bx.h01}, sx{bx.h10 * wx, bx.h11 * wx};
  const std::array<double, 2> ay{by.h00, by.h01}, sy{by.h10 * wy, by.h11 * wy};
  const std::array<double, 2> dax{bx.d00 / wx, bx.d01 / wx}, dsx{bx.d10, bx.d11};
  const std::array<double, 2> day{by.d00 / wy, by.d01 / wy}, dsy{by.d10, by.d11};
  SeabedPoint out;
  double gx = 0.0, gy = 0.0;
  for (int q = 0; q < 2; ++q)
    for (int p = 0; p < 2; ++p) {
      const std::size_t k = node[static_cast<std::size_t>(2 * q + p)];
      const double h = m_height[k], hx = m_hx[k], hy = m_hy[k], hxy = m_hxy[k];
      out.height += ax[p] * ay[q] * h + sx[p] * ay[q] * hx + ax[p] * sy[q] * hy + sx[p] * sy[q] * hxy;
      gx += dax[p] * ay[q] * h + dsx[p] * ay[q] * hx + dax[p] * sy[q] * hy + dsx[p] * sy[q] * hxy;
      gy += ax[p] * day[q] * h + sx[p] * day[q] * hx + ax[p] * dsy[q] * hy + sx[p] * dsy[q] * hxy;
    }
  // Beyond the grid the height is held: no slope along that axis (as the bilinear surface).
  if (!cx.inside) gx = 0.0;
  if (!cy.inside) gy = 0.0;
  out.normal = normalFromGradient(gx, gy);
  return out;
}

double SeabedSurface::height(double x, double y) const {
  switch (m_kind) {
    case Kind::Flat:
      return -m_depth;
    case Kind::Plane:
      return -m_depth + m_gradient.x() * x + m_gradient.y() * y;
    case Kind::Grid:
      break;
  }
  return at(x, y).height;
}

SeabedPoint SeabedSurface::at(double x, double y) const {
  SeabedPoint p;
  switch (m_kind) {
    case Kind::Flat:
      p.height = -m_depth;
      return p;
    case Kind::Plane:
      p.height = -m_depth + m_gradient.x() * x + m_gradient.y() * y;
      p.normal = normalFromGradient(m_gradient.x(), m_gradient.y());
      return p;
    case Kind::Grid:
      break;
  }
  if (m_interpolation == Interpolation::Cubic) return cubicAt(x, y);
  const std::size_t nx = m_x.size();
  const CellPosition cx = locate(m_x, x);
  const CellPosition cy = locate(m_y, y);
  const std::size_t i1 = nx > 1 ? cx.cell + 1 : 0;
  const std::size_t j1 = m_y.size() > 1 ? cy.cell + 1 : 0;
  const double h00 = m_height[cy.cell * nx + cx.cell], h10 = m_height[cy.cell * nx + i1];
  const double h01 = m_height[j1 * nx + cx.cell], h11 = m_height[j1 * nx + i1];
  const double fx = cx.fraction, fy = cy.fraction;
  // Bilinear interpolation (as MoorDyn's interp2) and its gradient within the cell.
  p.height = (1.0 - fx) * (1.0 - fy) * h00 + fx * (1.0 - fy) * h10 + (1.0 - fx) * fy * h01 + fx * fy * h11;
  const double gx = cx.inside ? ((1.0 - fy) * (h10 - h00) + fy * (h11 - h01)) / cx.width : 0.0;
  const double gy = cy.inside ? ((1.0 - fx) * (h01 - h00) + fx * (h11 - h10)) / cy.width : 0.0;
  p.normal = normalFromGradient(gx, gy);
  return p;
}

double SeabedSurface::surfaceGap(const Vec3& position, double radius) const {
  const SeabedPoint s = at(position.x(), position.y());
  return (position.z() - s.height) * s.normal.z() - radius;
}

double SeabedSurface::restingZ(double x, double y, double radius, double penetration) const {
  if (m_kind == Kind::Flat) return -m_depth + radius - penetration;
  const SeabedPoint s = at(x, y);
  return s.height + (radius - penetration) / s.normal.z();
}

Vec2 SeabedSurface::footprint(const Vec3& position) const {
  if (m_kind == Kind::Flat) return Vec2(position.x(), position.y());
  const SeabedPoint s = at(position.x(), position.y());
  const double distance = (position.z() - s.height) * s.normal.z();
  return Vec2(position.x() - distance * s.normal.x(), position.y() - distance * s.normal.y());
}

double SeabedSurface::shallowestDepth(double extent) const {
  switch (m_kind) {
    case Kind::Flat:
      return m_depth;
    case Kind::Plane:
      return m_depth - std::tan(m_slope) * extent;
    case Kind::Grid:
      break;
  }
  return -*std::max_element(m_height.begin(), m_height.end());
}

double SeabedSurface::deepestDepth(double extent) const {
  switch (m_kind) {
    case Kind::Flat:
      return m_depth;
    case Kind::Plane:
      return m_depth + std::tan(m_slope) * extent;
    case Kind::Grid:
      break;
  }
  return m_depth;
}

std::string SeabedSurface::describe() const {
  switch (m_kind) {
    case Kind::Flat:
      return fmt::format("flat, {:g} m deep", m_depth);
    case Kind::Plane:
      return fmt::format("plane, {:g} m deep at the origin, rising {:g} deg towards azimuth {:g} deg",
                         m_depth, m_slope * 180.0 / kPi, m_azimuth * 180.0 / kPi);
    case Kind::Grid:
      break;
  }
  return fmt::format(
      "bathymetry grid {} x {} over x [{:g}, {:g}] m, y [{:g}, {:g}] m, {:g} to {:g} m deep at its "
      "nodes, {} between them",
      m_x.size(), m_y.size(), m_x.front(), m_x.back(), m_y.front(), m_y.back(), shallowestDepth(0.0), m_depth,
      m_interpolation == Interpolation::Cubic ? "bicubic" : "bilinear");
}

SeabedSurface readSeafloorFile(const std::string& path) {
  const core::WordTable table(path, "SeafloorFile");
  if (table.size() < 4)
    throw InputError(path, 0, "SeafloorFile",
                     "at least 4 lines: 'nx ny', the x ticks, the y ticks and one 'x y z' row per grid node");
  if (table.rows()[0].words.size() < 2)
    throw InputError(path, table.rows()[0].line, "nx ny", "two counts on the first line");
  const std::size_t nx = table.count(0, 0, "nx", 1.0, 100000.0), ny = table.count(0, 1, "ny", 1.0, 100000.0);
  if (nx * ny > 4000000)
    throw InputError(path, table.rows()[0].line, "nx ny", "at most 4 000 000 grid nodes");
  std::vector<double> x = table.ticks(1, nx, "x ticks"), y = table.ticks(2, ny, "y ticks");
  // MoorDyn's calcInsertIndex: the first tick above the value, less one (the tick at or below it).
  auto snap = [](const std::vector<double>& t, double v) {
    const auto above = std::upper_bound(t.begin(), t.end(), v);
    return above == t.begin() ? std::size_t{0} : static_cast<std::size_t>(above - t.begin()) - 1;
  };
  std::vector<double> height(nx * ny, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t r = 3; r < table.size(); ++r) {
    const core::WordRow& row = table.rows()[r];
    if (row.words.size() != 3)
      throw InputError(path, row.line, "x y z", fmt::format("3 numbers (x, y, z), got {}", row.words.size()));
    const double z = table.number(r, 2, "z");
    if (z > 0.0)
      throw InputError(path, row.line, "z",
                       fmt::format("the seabed's z <= 0 (below still water), got {}", z));
    height[snap(y, table.number(r, 1, "y")) * nx + snap(x, table.number(r, 0, "x"))] = z;
  }
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i)
      if (std::isnan(height[j * nx + i]))
        throw InputError(path, 0, "x y z",
                         fmt::format("a row for every grid node; none for x = {}, y = {}", x[i], y[j]));
  return SeabedSurface::grid(std::move(x), std::move(y), std::move(height));
}

}  // namespace tangle::seabed
