#pragma once
// A rope wrapped half round a bollard, for the clearance checks on smooth centrelines where two lines lie
// along each other (LineClearanceTest, ClearanceEnvelopeTest): a bollard (a beam along y, radius 0.5 m,
// 0.5 m elements) and a rope (radius 0.02 m, 76 elements of 0.1 m) hanging 3 m down either side of it with
// the half circle between, its wrapped nodes 1 mm into the bollard and moved at random by up to 1 mm more.
// A rope's chord lies up to L^2 / (8 R) = 2.4 mm inside its curve, so the nearest chords need not be where
// the curves are nearest. The reference is the minimum over every element pair of the curves' distance
// (centrelineDistance from the chords' closest points, on the pieces' own parts: ownPartsDistance) less the
// radii.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "tangle/contact/SmoothCentreline.hpp"
#include "tangle/geometry/SegmentDistance.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::test {

/// The model (distributed contact: the rope measured on its smooth centreline): line 0 the bollard, 1 the
/// rope.
inline std::string wrappedRopeYaml() {
  return R"(environment:
  water_depth: 100
line_types:
  - {name: bollard, outer_diameter: 1.0, mass_per_length: 800, axial_stiffness: 1.0e10, bending_stiffness: 1.0e10}
  - {name: rope, outer_diameter: 0.04, mass_per_length: 6.0, axial_stiffness: 8.0e7}
lines:
  - name: bollard
    end_a: {type: fixed, position: [0, -2, -10]}
    end_b: {type: fixed, position: [0, 2, -10]}
    sections: [{type: bollard, length: 4, elements: 8}]
  - name: rope
    end_a: {type: pinned, position: [-0.519, 0.1, -13]}
    end_b: {type: pinned, position: [0.519, 0.1, -13]}
    sections: [{type: rope, length: 7.6, elements: 76}]
contact: {friction_coefficient: 0.5}
)";
}

/// Lays the rope of `m` round the bollard in `state`, its wrapped nodes at 0.519 m from the bollard's axis
/// less up to 1 mm (drawn from `random`).
inline void wrapRope(const model::Model& m, model::State& state, std::mt19937& random) {
  const model::Line& rope = m.lines()[1];
  const double wrap = 0.519, length = 7.6, pi = 3.141592653589793;
  const double straight = 0.5 * (length - pi * wrap);  // each hanging leg [m]
  std::uniform_real_distribution<double> move(-0.001, 0.0);
  for (int i = 0; i < rope.nodeCount; ++i) {
    const double s = rope.arcLength[static_cast<std::size_t>(i)];
    Vec3 x;
    if (s < straight) {
      x = Vec3(-wrap, 0.1, -10.0 - (straight - s));
    } else if (s > length - straight) {
      x = Vec3(wrap, 0.1, -10.0 - (s - (length - straight)));
    } else {
      const double angle = pi - (s - straight) / wrap;  // from -x over the top to +x
      const double radius = wrap + move(random);
      x = Vec3(radius * std::cos(angle), 0.1, -10.0 + radius * std::sin(angle));
    }
    state.position[static_cast<std::size_t>(rope.firstNode + i)] = x;
  }
}

/// The smallest surface gap between the bollard's and the rope's smooth centrelines over every element pair
/// [m].
inline double wrappedRopeClearance(const model::Model& m, const model::State& state) {
  const std::vector<contact::ElementCurve> curves = contact::elementCurves(m, true);
  const model::Line& bollard = m.lines()[0];
  const model::Line& rope = m.lines()[1];
  double exact = std::numeric_limits<double>::infinity();
  for (int i = 0; i < bollard.elementCount; ++i)
    for (int j = 0; j < rope.elementCount; ++j) {
      const int ea = bollard.firstElement + i, eb = rope.firstElement + j;
      const model::LineElement& a = m.elements()[static_cast<std::size_t>(ea)];
      const model::LineElement& b = m.elements()[static_cast<std::size_t>(eb)];
      const geometry::SegmentDistanceResult d = geometry::segmentDistance(
          state.position[a.node1], state.position[a.node2], state.position[b.node1], state.position[b.node2]);
      const contact::CentrelineDistance c =
          contact::centrelineDistance(m, state.position, ea, eb, d.s, d.t, false, false, true, &curves);
      exact =
          std::min(exact, contact::ownPartsDistance(c, curves[static_cast<std::size_t>(ea)],
                                                    curves[static_cast<std::size_t>(eb)], state.position) -
                              0.5 - 0.02);
    }
  return exact;
}

}  // namespace tangle::test
