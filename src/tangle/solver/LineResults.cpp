#include "tangle/solver/LineResults.hpp"

#include <algorithm>
#include <cmath>

namespace tangle::solver {

std::vector<LineSnapshot> computeLineResults(const model::Model& model, const Assembler& assembler,
                                             const model::State& state, const VecX& fullForce) {
  const std::vector<double> tension = assembler.elementTension(state);
  const model::DofMap& dofs = model.dofs();
  const double depth = model.environment().waterDepth;
  std::vector<LineSnapshot> out;
  for (const model::Line& line : model.lines()) {
    LineSnapshot s;
    s.name = line.name;
    s.arcLength = line.arcLength;
    const int n = line.nodeCount;
    s.position.resize(n);
    s.tension.assign(n, 0.0);
    s.bendingMoment.assign(n, 0.0);
    s.bendingMomentVector.assign(n, Vec3::Zero());
    s.curvature.assign(n, 0.0);
    std::vector<int> count(n, 0);
    std::vector<double> ei(n, 0.0);
    for (int i = 0; i < n; ++i) s.position[i] = state.position[line.firstNode + i];
    for (int e = 0; e < line.elementCount; ++e) {
      const model::LineElement& el = model.elements()[line.firstElement + e];
      const double t = tension[line.firstElement + e];
      s.tension[e] += t;
      s.tension[e + 1] += t;
      ++count[e];
      ++count[e + 1];
      if (el.beam) {
        const element::BeamSectionForces f = el.beam->sectionForces(
            state.position[el.node1], state.triad[el.node1], state.position[el.node2], state.triad[el.node2]);
        s.bendingMomentVector[e] += f.moment1;
        s.bendingMomentVector[e + 1] += f.moment2;
        ei[e] += el.beam->properties().bendingStiffness;
        ei[e + 1] += el.beam->properties().bendingStiffness;
      }
    }
    for (int i = 0; i < n; ++i) {
      s.tension[i] /= count[i];
      s.bendingMomentVector[i] /= count[i];
      ei[i] /= count[i];
      s.bendingMoment[i] = s.bendingMomentVector[i].norm();
      if (ei[i] > 0.0) {
        s.curvature[i] = s.bendingMoment[i] / ei[i];
      } else if (i > 0 && i < n - 1) {
        // Discrete curvature of the polyline: turning angle / mean segment length.
        const Vec3 a = s.position[i] - s.position[i - 1];
        const Vec3 b = s.position[i + 1] - s.position[i];
        const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
        s.curvature[i] = angle / (0.5 * (a.norm() + b.norm()));
      }
    }
    // Support reactions: the out-of-balance force at a held end is the reaction on the line; the line
    // pulls its support with the opposite force.
    s.endForceA = -fullForce.segment<3>(dofs.firstDof(line.firstNode));
    s.endForceB = -fullForce.segment<3>(dofs.firstDof(line.lastNode()));
    // Touchdown: last node (from end A) of the first grounded stretch that is followed by suspended line.
    std::vector<bool> grounded(n);
    for (int i = 0; i < n; ++i) {
      const double r = 0.5 * model.nodeContactDiameter()[line.firstNode + i];
      grounded[i] = s.position[i].z() - r <= -depth + 1e-6;
      if (grounded[i]) ++s.seabedNodes;
    }
    // A held end on the seabed (an anchor) is not a grounded stretch by itself.
    if (n >= 2) {
      grounded[0] = grounded[0] && grounded[1];
      grounded[n - 1] = grounded[n - 1] && grounded[n - 2];
    }
    for (int i = 0; i + 1 < n; ++i) {
      if (grounded[i] != grounded[i + 1]) {
        s.touchdownArcLength = grounded[i] ? s.arcLength[i] : s.arcLength[i + 1];
        break;
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace tangle::solver
