/// @file ImpactContinuum.cpp
/// LineContact's mesh-free estimate of an impact's participating mass (ContinuumImpactMass.hpp,
/// docs/theory.md 9.10): the lines at the first contact as their waves see them, the contact law as a
/// crossing loads it, and the checks of where the estimate holds.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/contact/ContinuumImpactMass.hpp"
#include "tangle/contact/DistributedContact.hpp"
#include "tangle/contact/LineContact.hpp"
#include "tangle/core/Units.hpp"

namespace tangle::contact {

namespace {
/// Largest patch half-length of a point impact as a fraction of the shorter participating length [-]: the
/// impedance is that of a point force; a crossing's patch spreads the force over +-u*, which leaves the
/// point's answer nearly unchanged while u* is short beside the length whose mass takes part. Against
/// meshes that resolve the impact (docs/theory.md 9.10: tensioned pipes crossing at 90 to 1 deg, flexible
/// risers at 16 deg): -15 % to +13 % up to a ratio of 0.28, -19 % at 0.56, -60 % at 1.1, where a mesh
/// that does not resolve the impact was off by +74 to +210 %.
constexpr double kPointPatchFraction = 0.6;
/// Longest element that resolves an impact, as a fraction of the participating length [-] (see below).
constexpr double kResolvingFraction = 1.0 / 3.0;
}  // namespace

void LineContact::estimateContinuum(const model::State& state, ContactEvent& e) const {
  const auto& elements = m_model->elements();
  const model::DofMap& dofs = m_model->dofs();
  const auto held = [&](int node) { return dofs.equation(dofs.firstDof(node)) < 0; };
  const int ea = pointAtArc(e.lineA, e.arcAStart).first, eb = pointAtArc(e.lineB, e.arcBStart).first;
  const double rho = m_model->environment().waterDensity;
  // A line at the point: its element's axial force, its mass per length with contents and (submerged)
  // normal added mass, its bending stiffness.
  const auto atPoint = [&](int element) {
    const model::LineElement& el = elements[static_cast<std::size_t>(element)];
    const Vec3& x1 = state.position[static_cast<std::size_t>(el.node1)];
    const Vec3& x2 = state.position[static_cast<std::size_t>(el.node2)];
    LineAtPoint p;
    p.tension = el.bar ? el.bar->axialForce(x1, x2)
                       : el.beam
                             ->sectionForces(x1, state.triad[static_cast<std::size_t>(el.node1)], x2,
                                             state.triad[static_cast<std::size_t>(el.node2)])
                             .axialForce;
    const bool submerged = 0.5 * (x1.z() + x2.z()) < 0.0;
    p.massPerLength =
        el.type->totalMassPerLength() + (submerged ? el.type->normalAddedMassPerLength(rho) : 0.0);
    p.bendingStiffness = el.type->bendingStiffness;
    p.held = held(el.node1) && held(el.node2);
    return p;
  };
  const LineAtPoint a = atPoint(ea), b = atPoint(eb);
  const auto tangent = [&](int element) {
    const model::LineElement& el = elements[static_cast<std::size_t>(element)];
    return (state.position[static_cast<std::size_t>(el.node2)] -
            state.position[static_cast<std::size_t>(el.node1)])
        .normalized();
  };
  const double sine = tangent(ea).cross(tangent(eb)).norm();
  const double radii = m_radius[static_cast<std::size_t>(ea)] + m_radius[static_cast<std::size_t>(eb)];
  PenetrationForce force;
  if (m_distributed) {
    // The distributed law loads along (1 + a) f (restitution by hysteresis), integrated over the crossing.
    const BarrierPenalty law = m_distributed->law(ea, eb);
    const double loading = 1.0 + m_distributed->hysteresis();
    force = [law, loading, radii, sine](double p) {
      return crossingForce([&](double q) { return loading * law.value(q); }, radii, std::max(sine, 1e-3), p);
    };
  } else {
    const double k = stiffness(e.lineA, e.lineB);  // the point formulation's spring (its dashpot aside)
    force = [k](double p) { return k * p; };
  }
  const ContinuumImpact c = continuumImpact(a, b, force, e.impactVelocity);
  if (!c.defined) {
    e.continuumNote = "no estimate: a slack line at the point (no tension or bending to carry waves)";
    return;
  }
  e.continuumMass = c.pairMass;
  e.continuumEnergy = c.energy;
  e.continuumLengthA = c.lengthA;
  e.continuumLengthB = c.lengthB;
  e.continuumDuration = c.duration;
  e.continuumPeakForce = c.peakForce;
  e.continuumNote.clear();
  const double patch = std::sqrt(2.0 * radii * c.penetration) / std::max(sine, 1e-12);
  double shorter = std::numeric_limits<double>::infinity();
  if (!a.held) shorter = std::min(shorter, c.lengthA);
  if (!b.held) shorter = std::min(shorter, c.lengthB);
  // Where the estimate does not hold the impact energy is the mesh's, which is only as good as its
  // elements near the point: the mesh's Eq. 5 mass was within 3 % of the converged one where they were at
  // most a third of the participating length, 2 to 23 % off at 0.4 to 0.85 (docs/theory.md 9.10).
  const double around = std::max(shorter, patch);
  const std::string refine =
      fmt::format("; elements of at most {:.3g} m within {:.3g} m of the point would resolve it",
                  kResolvingFraction * shorter, around);
  // A point: the crossing's patch short beside the lengths whose mass takes part.
  if (patch > kPointPatchFraction * shorter) {
    e.continuumNote = fmt::format(
        "a contact along a length, not a point: crossing at {:.3g} deg, patch half-length {:.3g} m against "
        "a participating length of {:.3g} m{}",
        radToDeg(std::asin(std::min(1.0, sine))), patch, shorter, refine);
    return;
  }
  // An infinite line: its waves must not meet an end, a support, a lump or a change of section within the
  // impact, pi / omega at the group speed (a reflection would come back within it).
  const auto reach = [&](int lineIndex, int element, double arc, const LineAtPoint& p) -> std::string {
    if (p.held) return {};
    const model::Line& line = m_model->lines()[static_cast<std::size_t>(lineIndex)];
    const double travel = groupSpeed(p, c.omega) * c.duration;
    const double lo = arc - travel, hi = arc + travel;
    const section::LineType* type = elements[static_cast<std::size_t>(element)].type;
    std::string what;
    if (lo < line.arcLength.front() || hi > line.arcLength.back()) what = "an end";
    for (int i = 0; what.empty() && i < line.nodeCount; ++i) {
      const double s = line.arcLength[static_cast<std::size_t>(i)];
      if (s < lo || s > hi) continue;
      const int node = line.firstNode + i;
      if (held(node)) what = "a support";
      for (const model::NodeAttachment& at : m_model->attachments())
        if (at.node == node && what.empty()) what = "a lump";
    }
    for (int i = 0; what.empty() && i < line.elementCount; ++i) {
      if (line.arcLength[static_cast<std::size_t>(i) + 1] < lo ||
          line.arcLength[static_cast<std::size_t>(i)] > hi)
        continue;
      if (elements[static_cast<std::size_t>(line.firstElement + i)].type != type)
        what = "a change of section";
    }
    if (what.empty()) return {};
    return fmt::format(
        "line '{}': its waves reach {} within the impact ({:.3g} m at {:.3g} m/s in {:.3g} s){}", line.name,
        what, travel, groupSpeed(p, c.omega), c.duration, refine);
  };
  std::string why = reach(e.lineA, ea, e.arcAStart, a);
  if (why.empty()) why = reach(e.lineB, eb, e.arcBStart, b);
  e.continuumNote = why;
}

}  // namespace tangle::contact
