#pragma once
/// @file RadiusProfile.hpp
/// The contact radius along each line of a model: its section's, tapered where the line changes section.
///
/// Contact, the clearance envelope and the clash report measure a line's surface with this one profile, so
/// that a clearance and a contact's gap agree at a section change (a node's radius was the larger section's
/// in the clearances: a line striking another at the thin side of its change of section reported -0.147 m
/// where the contact pressed 3.3 cm deep).

#include <array>
#include <vector>

#include "tangle/model/Model.hpp"

namespace tangle::contact {

/// Contact radius along the lines (docs/theory.md 9.11, "Radius along a line"). Each element has its
/// section's contact radius r, except where its line changes section: there the radius runs from one
/// section's to the other's over |r1 - r2| of arc centred on the node (at most half of either element) along
/// the smootherstep S(u) = u^3 (10 - 15 u + 6 u^2): C2 along the line, the mean of the two at the node, 62
/// degrees at the node as the end of a buoyancy module.
class RadiusProfile {
 public:
  /// @param elementRadius contact radius of every element of `model` (half its contact diameter) [m]
  RadiusProfile(const model::Model& model, std::vector<double> elementRadius);
  /// With each element's section radius half its line type's contact diameter (every caller's).
  explicit RadiusProfile(const model::Model& model);

  /// The radius of element e at parameter t of its piece (clamped to [0, 1]) and its first two derivatives in
  /// t: (r [m], dr/dt [m], d2r/dt2 [m]).
  std::array<double, 3> profile(int element, double t) const;
  /// The radius of element e at parameter t [m]. Inline for an element without a taper (nearly all: the
  /// clearance envelope asks at every segment it measures), the same value as profile()'s.
  double at(int element, double t) const {
    const Shoulder& sh = m_shoulders[static_cast<std::size_t>(element)];
    if (sh.startLength == 0.0 && sh.endLength == 0.0) return m_radius[static_cast<std::size_t>(element)];
    return profile(element, t)[0];
  }
  /// The elements' own (their sections') radii, by element [m].
  const std::vector<double>& sectionRadii() const { return m_radius; }
  /// The largest radius anywhere on element e [m]: a bound for every point of it.
  double largest(int element) const { return m_shoulders[static_cast<std::size_t>(element)].largest; }
  /// Where element e's tapers end, in its parameter: (end of the taper from node1, start of the taper to
  /// node2); 0 and 1 when there is none [-]. The radius's third derivative jumps there.
  std::array<double, 2> taperEnds(int element) const;
  /// The radius at every node of the model, by global node: the profile at the node (the mean of the two
  /// sections' at a change of section); 0 at a node of no element [m].
  const std::vector<double>& nodeRadius() const { return m_nodeRadius; }

 private:
  struct Shoulder {
    double startRadius = 0.0;  ///< radius at node1: the mean of the two sections' at a change [m]
    double startLength = 0.0;  ///< extent of the taper in the element from node1, in its parameter [-]
    double endRadius = 0.0;    ///< radius at node2 [m]
    double endLength = 0.0;    ///< extent from node2 [-]
    double largest = 0.0;      ///< largest radius on the element's piece [m]
  };
  std::vector<double> m_radius;  ///< each element's section radius [m]
  std::vector<Shoulder> m_shoulders;
  std::vector<double> m_nodeRadius;
};

}  // namespace tangle::contact
