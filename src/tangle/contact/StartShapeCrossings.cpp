#include "tangle/contact/StartShapeCrossings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace tangle::contact {
namespace {

/// Clearance at which the surfaces of a laid-over start shape stand apart [-] of the sum of the radii.
constexpr double kLiftClearance = 0.05;
/// Overlap that counts as crossed [-] of the sum of the radii (below it the contact's own side is clear).
constexpr double kCrossedOverlap = 0.01;
/// Sine of the angle between the axes below which two lines lie along each other rather than cross [-].
constexpr double kAlongSine = 0.2;

/// The element of `line` holding unstretched arc length `arc` [m] (local index) and the fraction along it.
std::pair<int, double> elementAt(const model::Line& line, double arc) {
  const auto& s = line.arcLength;
  const auto it = std::upper_bound(s.begin(), s.end(), arc);
  const int i = std::clamp(static_cast<int>(it - s.begin()) - 1, 0, line.nodeCount - 2);
  const double length = s[static_cast<std::size_t>(i) + 1] - s[static_cast<std::size_t>(i)];
  return {i, length > 0.0 ? std::clamp((arc - s[static_cast<std::size_t>(i)]) / length, 0.0, 1.0) : 0.0};
}

/// Point [m] and unit chord direction of `line` at arc length `arc`, on its chords.
std::pair<Vec3, Vec3> pointAt(const model::Line& line, const model::State& state, double arc) {
  const auto [i, f] = elementAt(line, arc);
  const Vec3& x0 = state.position[line.firstNode + i];
  const Vec3& x1 = state.position[line.firstNode + i + 1];
  const Vec3 chord = x1 - x0;
  const double length = chord.norm();
  return {x0 + f * chord, length > 0.0 ? Vec3(chord / length) : Vec3(Vec3::UnitX())};
}

/// Distance [m] from point x to the chords of `line`.
double distanceToLine(const model::Line& line, const model::State& state, const Vec3& x) {
  double best = std::numeric_limits<double>::infinity();
  for (int e = 0; e < line.elementCount; ++e)
    best = std::min(best, geometry::segmentDistance(x, x, state.position[line.firstNode + e],
                                                    state.position[line.firstNode + e + 1])
                              .distance);
  return best;
}

/// The direction in which the upper line is moved off the lower one at a crossing (file comment).
Vec3 liftDirection(const Vec3& lowerTangent, const Vec3& upperTangent, const Vec3& lowerPoint,
                   const Vec3& upperPoint) {
  const Vec3 apart = upperPoint - lowerPoint;
  const Vec3 normal = lowerTangent.cross(upperTangent);
  const double sine = normal.norm();
  if (sine > kAlongSine) {
    Vec3 d = normal / sine;
    // Upwards where the crossing's normal has a vertical part; else (the two axes in a vertical plane) to
    // the side the upper line already is on.
    if (std::abs(d.z()) >= 0.1 ? d.z() < 0.0 : apart.dot(d) < 0.0) d = -d;
    return d;
  }
  // Along each other: upwards square to the lower line; for vertical lines, away from it.
  Vec3 d = Vec3::UnitZ() - lowerTangent.z() * lowerTangent;
  if (d.norm() < 0.1) d = apart - apart.dot(lowerTangent) * lowerTangent;
  if (d.norm() < 1e-9) d = lowerTangent.unitOrthogonal();
  return d.normalized();
}

}  // namespace

std::string StartShapeLift::describe(const model::Model& model) const {
  const std::string& lower = model.lines()[static_cast<std::size_t>(lowerLine)].name;
  const std::string& upper = model.lines()[static_cast<std::size_t>(upperLine)].name;
  return fmt::format(
      "start shapes: line '{}' laid over line '{}' at {:.2f} m along '{}' and {:.2f} m along '{}' (their "
      "catenaries passed {:.3f} m through each other; moved up to {:.3f} m towards ({:.2f}, {:.2f}, "
      "{:.2f})): a "
      "line listed later is laid over one listed earlier; to choose otherwise, list them the other way "
      "round or give lines[{}].start_shape",
      upper, lower, arcUpper, upper, arcLower, lower, overlap, lift, direction.x(), direction.y(),
      direction.z(), upper);
}

std::vector<StartShapeLift> liftCrossedStartShapes(const model::Model& model, const LineContact& contact,
                                                   model::State& state) {
  std::vector<StartShapeLift> lifts;
  const auto& lines = model.lines();
  const model::DofMap& dofs = model.dofs();
  // A node the upper line may move: not an end (fixed by the user, or tied to a vessel or a point) and
  // free in its translations.
  const auto movable = [&](const model::Line& line, int i) {
    if (i <= 0 || i >= line.nodeCount - 1) return false;
    const int first = dofs.firstDof(line.firstNode + i);
    for (int k = 0; k < 3; ++k)
      if (dofs.equation(first + k) < 0) return false;
    return true;
  };
  for (const auto& [a, b] : contact.assessedPairs(state)) {
    if (a == b) continue;
    const model::Line& lower = lines[static_cast<std::size_t>(a)];
    const model::Line& upper = lines[static_cast<std::size_t>(b)];
    if (!lower.spec->startShape.empty() || !upper.spec->startShape.empty()) continue;
    const double radii = lower.contactRadius + upper.contactRadius;
    double previousOverlap = std::numeric_limits<double>::infinity();
    for (int attempt = 0; attempt < kMaxLiftsPerPair; ++attempt) {
      const std::array<double, 3> c = contact.clearance(state, a, b);
      const double overlap = -c[0];
      // Done when clear, and given up when a move did not reduce the overlap (nodes held near it).
      if (!(overlap > kCrossedOverlap * radii) || !(overlap < previousOverlap)) break;
      previousOverlap = overlap;
      const auto [pa, ta] = pointAt(lower, state, c[1]);
      const auto [pb, tb] = pointAt(upper, state, c[2]);
      const Vec3 d = liftDirection(ta, tb, pa, pb);
      const double lift = (1.0 + kLiftClearance) * radii - (pb - pa).dot(d);
      if (!(lift > 0.0)) break;
      // The stretch moved whole: the upper line's nodes within an element's length of the crossing (both
      // nodes of its element, or a node at the crossing and its two neighbours), and on either side those
      // that lie near the lower line (a lay along it); then a cosine taper over at least two elements and
      // twenty times the move, so the shape stays smooth.
      const auto& s = upper.arcLength;
      const int element = elementAt(upper, c[2]).first;
      const double elementLength =
          s[static_cast<std::size_t>(element) + 1] - s[static_cast<std::size_t>(element)];
      int first = element, last = element + 1;
      while (first > 0 && c[2] - s[static_cast<std::size_t>(first) - 1] <= elementLength) --first;
      while (last < upper.nodeCount - 1 && s[static_cast<std::size_t>(last) + 1] - c[2] <= elementLength)
        ++last;
      const double near = radii + lift;
      while (first > 0 && distanceToLine(lower, state, state.position[upper.firstNode + first - 1]) < near)
        --first;
      while (last < upper.nodeCount - 1 &&
             distanceToLine(lower, state, state.position[upper.firstNode + last + 1]) < near)
        ++last;
      const double lo = s[static_cast<std::size_t>(first)], hi = s[static_cast<std::size_t>(last)];
      const double taper = std::max(2.0 * elementLength, 20.0 * lift);
      double moved = 0.0;
      for (int i = 0; i < upper.nodeCount; ++i) {
        const double outside =
            std::max({lo - s[static_cast<std::size_t>(i)], s[static_cast<std::size_t>(i)] - hi, 0.0});
        if (outside >= taper || !movable(upper, i)) continue;
        const double weight = 0.5 * (1.0 + std::cos(kPi * outside / taper));
        state.position[upper.firstNode + i] += weight * lift * d;
        moved = std::max(moved, weight * lift);
      }
      if (moved == 0.0) break;
      model.setLineTriads(b, state);
      if (attempt == 0 || lifts.empty() || lifts.back().upperLine != b || lifts.back().lowerLine != a ||
          std::abs(lifts.back().arcUpper - c[2]) > taper) {
        lifts.push_back({a, b, c[1], c[2], overlap, moved, d});
      } else {
        lifts.back().lift += moved;  // the same crossing again (the curves between the chords' nodes)
      }
    }
  }
  return lifts;
}

}  // namespace tangle::contact
