/// @file RadiusProfile.cpp
/// Contact radius along the lines (definition in RadiusProfile.hpp).

#include "tangle/contact/RadiusProfile.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tangle::contact {

RadiusProfile::RadiusProfile(const model::Model& model, std::vector<double> elementRadius)
    : m_radius(std::move(elementRadius)) {
  const auto& elements = model.elements();
  m_shoulders.resize(elements.size());
  m_nodeRadius.assign(static_cast<std::size_t>(model.nodeCount()), 0.0);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    Shoulder& sh = m_shoulders[e];
    const double r = m_radius[e];
    sh.startRadius = sh.endRadius = sh.largest = r;
    const double length = std::max(elements[e].restLength, 1e-12);
    auto taper = [&](std::size_t neighbour, double& atNode, double& extent) {
      const double other = m_radius[neighbour];
      if (other == r) return;
      atNode = 0.5 * (r + other);
      extent = std::min(0.5, 0.5 * std::abs(other - r) / length);
      sh.largest = std::max(sh.largest, atNode);
    };
    if (e > 0 && elements[e - 1].line == elements[e].line) taper(e - 1, sh.startRadius, sh.startLength);
    if (e + 1 < elements.size() && elements[e + 1].line == elements[e].line)
      taper(e + 1, sh.endRadius, sh.endLength);
    // Both elements at a node give it the same radius (the mean at a change, else the section's).
    m_nodeRadius[static_cast<std::size_t>(elements[e].node1)] = sh.startRadius;
    m_nodeRadius[static_cast<std::size_t>(elements[e].node2)] = sh.endRadius;
  }
}

namespace {
std::vector<double> halfContactDiameters(const model::Model& model) {
  std::vector<double> radius;
  radius.reserve(model.elements().size());
  for (const model::LineElement& el : model.elements()) radius.push_back(0.5 * el.type->contactDiameter);
  return radius;
}
}  // namespace

RadiusProfile::RadiusProfile(const model::Model& model) : RadiusProfile(model, halfContactDiameters(model)) {}

std::array<double, 3> RadiusProfile::profile(int element, double t) const {
  // In a taper the radius follows the smootherstep S(u) = u^3 (10 - 15 u + 6 u^2) of the whole taper, u from
  // 0 at its far end in the neighbour to 1/2 at the node and 1 where this element's own radius is reached: C2
  // along the line (a linear taper's kinks at its two ends were steps of the contact force's slope).
  const Shoulder& sh = m_shoulders[static_cast<std::size_t>(element)];
  const double r = m_radius[static_cast<std::size_t>(element)];
  t = std::clamp(t, 0.0, 1.0);
  auto shoulder = [&](double atNode, double extent, double fromNode, double sign) -> std::array<double, 3> {
    const double other = 2.0 * atNode - r;  // the neighbour's radius
    const double u = 0.5 + 0.5 * fromNode / extent, du = 0.5 / extent;
    const double value = other + (r - other) * u * u * u * (10.0 + u * (6.0 * u - 15.0));
    const double slope = (r - other) * 30.0 * u * u * (1.0 - u) * (1.0 - u) * du;
    const double curvature = (r - other) * 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) * du * du;
    return {value, sign * slope, curvature};
  };
  if (t < sh.startLength) return shoulder(sh.startRadius, sh.startLength, t, 1.0);
  if (1.0 - t < sh.endLength) return shoulder(sh.endRadius, sh.endLength, 1.0 - t, -1.0);
  return {r, 0.0, 0.0};
}

std::array<double, 2> RadiusProfile::taperEnds(int element) const {
  const Shoulder& sh = m_shoulders[static_cast<std::size_t>(element)];
  return {sh.startLength, 1.0 - sh.endLength};
}

}  // namespace tangle::contact
