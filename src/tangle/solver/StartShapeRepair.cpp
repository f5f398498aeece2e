#include "tangle/solver/StartShapeRepair.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tangle/geometry/Rotation.hpp"
#include "tangle/seabed/SeabedSurface.hpp"

namespace tangle::solver {

std::vector<int> slackSuspendedBars(const model::Model& model, const model::State& state) {
  // Cable elements carry no compression (Assembler: a slack bar keeps 1e-6 EA), so a suspended bar that
  // is shorter than its unstretched length by more than 1e-4 is slack: its line is not held in tension
  // there (an unstable or indifferent branch). Laid elements may be slack: the seabed holds them.
  std::vector<int> out;
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const model::LineElement& el = model.elements()[e];
    if (!el.bar) continue;
    const double strain = (state.position[el.node2] - state.position[el.node1]).norm() / el.restLength - 1.0;
    if (strain >= -1e-4) continue;
    // Suspended: neither node on the seabed (a touchdown element may be slack, its chord cuts the corner).
    const seabed::SeabedSurface& bed = model.seabedSurface();
    const bool touches =
        bed.gap(state.position[el.node1], 0.5 * model.nodeContactDiameter()[el.node1]) <= 1e-3 ||
        bed.gap(state.position[el.node2], 0.5 * model.nodeContactDiameter()[el.node2]) <= 1e-3;
    if (!touches) out.push_back(static_cast<int>(e));
  }
  return out;
}

void bulgeSlackRuns(const model::Model& model, model::State& state, const std::vector<int>& elements) {
  const auto& env = model.environment();
  const model::DofMap& dofs = model.dofs();
  // Group consecutive elements of a line into runs; bulge each run's free nodes by a half sine whose
  // arc length takes up the run's unstretched length: A = (2 c / pi) sqrt(L / c - 1) for a chord c.
  std::size_t i = 0;
  while (i < elements.size()) {
    std::size_t j = i;
    while (j + 1 < elements.size() && elements[j + 1] == elements[j] + 1 &&
           model.elements()[elements[j + 1]].line == model.elements()[elements[i]].line)
      ++j;
    const auto& first = model.elements()[elements[i]];
    const auto& last = model.elements()[elements[j]];
    double restLength = 0.0, weight = 0.0;
    for (std::size_t k = i; k <= j; ++k) {
      const auto& el = model.elements()[elements[k]];
      restLength += el.restLength;
      weight += el.type->submergedWeight(env.waterDensity, env.gravity) * el.restLength;
    }
    const Vec3 a = state.position[first.node1];
    const Vec3 b = state.position[last.node2];
    const double chord = (b - a).norm();
    const double amplitude = chord < restLength
                                 ? 2.0 * chord / std::numbers::pi * std::sqrt(restLength / chord - 1.0)
                                 : 0.05 * chord;
    // The load direction: down for a heavy run, up for a buoyant one; perpendicular to a vertical chord
    // it falls back to a horizontal direction.
    Vec3 dir = weight >= 0.0 ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitZ());
    const Vec3 axis = (b - a).normalized();
    dir -= dir.dot(axis) * axis;
    if (dir.norm() < 1e-6) dir = axis.unitOrthogonal();
    dir.normalize();
    for (int n = first.node1 + 1; n < last.node2; ++n) {
      const int d = dofs.firstDof(n);
      bool free = false;
      for (int c = 0; c < 3; ++c) free = free || dofs.equation(d + c) >= 0;
      if (!free) continue;
      const double f = static_cast<double>(n - first.node1) / static_cast<double>(last.node2 - first.node1);
      state.position[n] = a + f * (b - a) + amplitude * std::sin(std::numbers::pi * f) * dir;
    }
    i = j + 1;
  }
}

bool hangFreeLines(const model::Model& model, model::State& state) {
  const auto& env = model.environment();
  bool any = false;
  for (const model::Line& line : model.lines()) {
    const bool freeA = line.spec->endA.kind == model::EndKind::Free;
    const bool freeB = line.spec->endB.kind == model::EndKind::Free;
    if (freeA == freeB || line.nodeCount < 3) continue;
    // Weight per length: submerged below the water, in air above it (the held end decides).
    const int held = freeB ? line.firstNode : line.lastNode();
    const bool wet = state.position[held].z() < 0.0;
    double weight = 0.0, bending = 0.0;
    for (int e = 0; e < line.elementCount; ++e) {
      const model::LineElement& el = model.elements()[static_cast<std::size_t>(line.firstElement + e)];
      weight += (wet ? el.type->submergedWeight(env.waterDensity, env.gravity)
                     : el.type->totalMassPerLength() * env.gravity) *
                el.restLength;
      bending = std::max(bending, el.type->bendingStiffness);
    }
    for (const model::NodeAttachment& a : model.attachments())
      if (model.lineOfNode(a.node) == static_cast<int>(&line - model.lines().data()))
        weight += (a.spec.mass - (wet ? env.waterDensity * a.spec.volume : 0.0)) * env.gravity;
    if (weight == 0.0) continue;
    const Vec3 g = weight > 0.0 ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitZ());
    const double elementLength = line.length / static_cast<double>(line.elementCount);
    const double bendLength =
        std::min(0.25 * line.length,
                 std::max(2.0 * elementLength,
                          3.0 * std::sqrt(bending / (std::abs(weight) / line.length) / line.length)));
    // Walk from the held end: step k runs from node order[k] to order[k + 1].
    std::vector<int> order(static_cast<std::size_t>(line.nodeCount));
    for (int i = 0; i < line.nodeCount; ++i)
      order[static_cast<std::size_t>(i)] = freeB ? line.firstNode + i : line.lastNode() - i;
    Vec3 d0 = state.position[order[1]] - state.position[order[0]];
    if (d0.norm() <= 0.0) continue;
    d0.normalize();
    Vec3 axis = d0.cross(g);
    const double angle = std::atan2(axis.norm(), d0.dot(g));
    if (axis.norm() < 1e-9) axis = d0.unitOrthogonal();
    axis.normalize();
    Vec3 horizontal(d0.x(), d0.y(), 0.0);
    horizontal = horizontal.norm() > 1e-9 ? Vec3(horizontal.normalized()) : Vec3(Vec3::UnitX());
    const seabed::SeabedSurface& bed = model.seabedSurface();
    const double heldRadius = 0.5 * model.nodeContactDiameter()[static_cast<std::size_t>(held)];
    double s = 0.0;
    Vec3 x = state.position[order[0]];
    std::vector<Vec3> tangent(order.size(), g);
    for (std::size_t k = 0; k + 1 < order.size(); ++k) {
      const double length = std::abs(line.arcLength[static_cast<std::size_t>(order[k + 1] - line.firstNode)] -
                                     line.arcLength[static_cast<std::size_t>(order[k] - line.firstNode)]);
      const double mid = std::min(1.0, (s + 0.5 * length) / bendLength);
      Vec3 t = Eigen::AngleAxisd(mid * angle, axis) * d0;
      if (bed.isFlat()) {
        const double bottom = -env.waterDepth + heldRadius;
        if (x.z() <= bottom + 1e-9 && t.z() < 0.0) t = horizontal;  // laid along the seabed
        x += length * t;
        if (x.z() < bottom) x.z() = bottom;
      } else {
        // Laid along the seabed's tangent plane, in the vertical plane of the line's first chord.
        if (bed.gap(x, heldRadius) <= 1e-9 && t.z() < 0.0) {
          const Vec3 n = bed.at(x.x(), x.y()).normal;
          const Vec3 along =
              horizontal - horizontal.dot(n) / n.z() * Vec3::UnitZ();  // on the plane, above it
          t = along.normalized();
        }
        x += length * t;
        if (bed.gap(x, heldRadius) < 0.0) x.z() = bed.restingZ(x.x(), x.y(), heldRadius, 0.0);
      }
      s += length;
      state.position[order[k + 1]] = x;
      tangent[k] = t;
    }
    // Triads: the held end keeps its own; the others follow by parallel transport of the tangents.
    Vec3 previous = d0;
    Mat3 q = state.triad[order[0]];
    for (std::size_t k = 1; k < order.size(); ++k) {
      const Vec3 t = k + 1 < order.size() ? Vec3((tangent[k - 1] + tangent[k]).normalized()) : tangent[k - 1];
      q = geometry::rotationBetween(previous, t) * q;
      state.triad[order[k]] = q;
      previous = t;
    }
    any = true;
  }
  return any;
}

}  // namespace tangle::solver
