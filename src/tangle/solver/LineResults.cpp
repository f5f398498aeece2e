#include "tangle/solver/LineResults.hpp"

#include <algorithm>
#include <cmath>

#include "tangle/core/Units.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/seabed/Seabed.hpp"

namespace tangle::solver {

namespace {

/// Section force of an element [N]: the force the node-2 side exerts on the node-1 side across a cut,
/// constant along the element (its loads are lumped at the nodes). A bar carries the effective tension
/// along its chord; a beam also the shear that its bending moments' gradient implies. With the section
/// moment M(x) of BeamSectionForces (exerted on the node-1 side by the node-2 side), the moment balance of
/// the piece [0, x] of the element, -M1 + M(x) + x e x F = 0, gives e x F = -(M2 - M1) / L, whose part
/// across the chord e is the shear F_s = e x (M2 - M1) / L (L the current chord length).
Vec3 elementForce(const model::State& state, const model::LineElement& el, double tension,
                  const element::BeamSectionForces* beam) {
  const Vec3 chord = state.position[el.node2] - state.position[el.node1];
  const double length = chord.norm();
  if (!(length > 0.0)) return Vec3::Zero();
  const Vec3 e = chord / length;
  Vec3 force = tension * e;
  if (beam) force += e.cross(beam->moment2 - beam->moment1) / length;
  return force;
}

/// True when a point load (attachment) sits at `node`.
bool hasAttachment(const model::Model& model, int node) {
  return std::any_of(model.attachments().begin(), model.attachments().end(),
                     [node](const model::NodeAttachment& a) { return a.node == node; });
}

/// Force vector at an end point [N], pointing from node 1 to node 2 of the end element (into the line
/// at end A, out of it at end B), extrapolated as documented in LineSnapshot::endTensionA.
/// `end` is the end element, `inner` the one next to it (or nullptr); `endBeam`, `innerBeam` their beam
/// section forces (nullptr for bars); `side` +1 at end A, -1 at end B.
Vec3 endPointForce(const model::Model& model, const Assembler& assembler, const model::State& state,
                   const model::LineElement& end, double endTension,
                   const element::BeamSectionForces* endBeam, const model::LineElement* inner,
                   double innerTension, const element::BeamSectionForces* innerBeam, int sharedNode,
                   double side) {
  const Vec3 fEnd = elementForce(state, end, endTension, endBeam);
  if (!inner || inner->type != end.type || hasAttachment(model, sharedNode)) {
    // The end element alone (a one-element line, its neighbour parted, of another line type or beyond a point
    // load): the force vector's slope along the line is its own distributed weight, dT/ds = -q (equilibrium
    // of a length ds; s from end A), so the end point is half an element of weight beyond the mid-point:
    // fEnd + side q l / 2, side +1 at end A, -1 at end B. Drag and inertia are left out. Submerged when its
    // mid-point is below still water. Where the line's end node rests on the seabed, the seabed carries the
    // fraction of that weight it carries under the element's other node (theory 7.8, Assembler::addSeabed's
    // rule for an anchor): none of the slope for an element lying on the seabed.
    const model::EnvironmentSpec& env = model.environment();
    const double mid = 0.5 * (state.position[end.node1].z() + state.position[end.node2].z());
    const double weight = mid < 0.0 ? end.type->submergedWeight(env.waterDensity, env.gravity)
                                    : end.type->totalMassPerLength() * env.gravity;  // [N/m]
    const int endNode = side > 0.0 ? end.node1 : end.node2, other = side > 0.0 ? end.node2 : end.node1;
    const auto radius = [&](int node) {
      return 0.5 * model.nodeContactDiameter()[static_cast<std::size_t>(node)];
    };
    const seabed::Seabed bed(env.seabed, model.sharedSeabedSurface());
    // The other node's lumped submerged line weight over its tributary length, as Assembler's held-node
    // share takes it.
    const double carried =
        bed.penetration(state.position[static_cast<std::size_t>(endNode)], radius(endNode)) > 0.0
            ? bed.carriedFraction(state.position[static_cast<std::size_t>(other)], radius(other),
                                  assembler.restingWeightPerLength(other))
            : 0.0;
    return fEnd + Vec3(0.0, 0.0, -side * 0.5 * end.restLength * weight * (1.0 - carried));
  }
  const Vec3 fInner = elementForce(state, *inner, innerTension, innerBeam);
  // Mid-points are 0.5 (l_end + l_inner) apart; the end point is 0.5 l_end beyond the end mid-point.
  const double gap = 0.5 * (end.restLength + inner->restLength);
  const Vec3 extrapolated = fEnd + (fEnd - fInner) * (0.5 * end.restLength / gap);
  // A bar carries no compression: where the extrapolation turns a bar end's force against its chord, the end
  // point is slack (its own force where that is the slack law's small compression, c EA strain). That is a
  // tension front between the end element and its neighbour (a snap: the end element slack and the next one
  // taut), across which a linear extrapolation does not hold: a cable's end read -74 kN with its end
  // elements at about 0 N (slack) and 148 kN. (A bar with compressionFactor 1, a spring in compression, keeps
  // it.)
  if (!end.isBeam() && end.type->compressionFactor < 1.0) {
    const Vec3 axis = (state.position[static_cast<std::size_t>(end.node2)] -
                       state.position[static_cast<std::size_t>(end.node1)])
                          .normalized();
    const double floor = std::min(endTension, 0.0);  // [N]
    if (extrapolated.dot(axis) < floor) return floor * axis;
  }
  return extrapolated;
}

}  // namespace

Vec3 elementSectionForce(const model::State& state, const model::LineElement& el, double tension,
                         const element::BeamSectionForces* beam) {
  return elementForce(state, el, tension, beam);
}

std::vector<LineSnapshot> computeLineResults(const model::Model& model, const Assembler& assembler,
                                             const model::State& state, const VecX& fullForce) {
  std::vector<LineSnapshot> out;
  computeLineResults(model, assembler, state, &fullForce, out);
  return out;
}

void setWallTension(const model::Model& model, int l, LineSnapshot& s) {
  const model::Line& line = model.lines()[static_cast<std::size_t>(l)];
  if (!line.pipe) {
    s.internalPressure.clear();
    s.wallTension.clear();
    return;
  }
  model.internalPressure(l, s.position, s.internalPressure);
  const auto n = static_cast<std::size_t>(line.nodeCount);
  s.wallTension.assign(n, 0.0);
  const double rhoG = model.environment().waterDensity * model.environment().gravity;
  // T_w = T_e + p_i A_i - p_e A_e (Sparks 1984), the pressure term of each element at the node averaged
  // over the node's elements (they differ only where two line types meet).
  for (std::size_t e = 0; e + 1 < n; ++e) {
    const section::LineType& type = *model.elements()[static_cast<std::size_t>(line.firstElement) + e].type;
    for (const std::size_t k : {e, e + 1}) {
      const double weight = (k == 0 || k + 1 == n) ? 1.0 : 0.5;
      s.wallTension[k] += weight * wallTensionPressureTerm(type, s.internalPressure[k], s.position[k].z(), rhoG);
    }
  }
  for (std::size_t k = 0; k < n; ++k) s.wallTension[k] += s.tension[k];
}

void computeLineResults(const model::Model& model, const Assembler& assembler, const model::State& state,
                        const VecX* fullForce, std::vector<LineSnapshot>& out, LineResultDetail detail) {
  const bool all = detail == LineResultDetail::All;
  const bool endsOnly = detail == LineResultDetail::Ends;
  // Work space of the calling thread (the writer computes the range graphs at every step).
  thread_local std::vector<element::BeamSectionForces> beamForces;
  thread_local std::vector<double> tension;
  thread_local std::vector<int> endElements;  // Ends: the two elements at each end, all the results read
  if (endsOnly) {
    endElements.clear();
    for (const model::Line& line : model.lines()) {
      const int first = line.firstElement, last = line.firstElement + line.elementCount - 1;
      for (const int e : {first, first + 1, last - 1, last})
        if (e >= first && e <= last) endElements.push_back(e);
    }
  }
  assembler.elementTension(state, tension, &beamForces, endsOnly ? &endElements : nullptr);
  const model::DofMap& dofs = model.dofs();
  const seabed::SeabedSurface& bed = model.seabedSurface();
  out.resize(model.lines().size());
  thread_local std::vector<int> count;
  thread_local std::vector<double> ei, segmentLength;
  std::vector<char> grounded;
  for (std::size_t l = 0; l < model.lines().size(); ++l) {
    const model::Line& line = model.lines()[l];
    LineSnapshot& s = out[l];
    s.name = line.name;
    s.arcLength = line.arcLength;
    const int n = line.nodeCount;
    s.position.resize(n);
    s.tension.assign(n, 0.0);
    s.bendingMoment.assign(n, 0.0);
    s.bendingMomentVector.assign(n, Vec3::Zero());
    s.curvature.assign(n, 0.0);
    s.torque.assign(n, 0.0);
    s.rotation.assign(n, Vec3::Zero());
    s.touchdownArcLength = -1.0;
    s.seabedNodes = 0;
    count.assign(n, 0);
    ei.assign(n, 0.0);
    for (int i = 0; i < n; ++i) s.position[i] = state.position[line.firstNode + i];
    if (endsOnly) {
      // The end nodes' values of the loop below: an end node has one element.
      s.tension.front() = tension[line.firstElement];
      s.tension.back() = tension[line.firstElement + line.elementCount - 1];
      s.hasBending = std::any_of(model.elements().begin() + line.firstElement,
                                 model.elements().begin() + line.firstElement + line.elementCount,
                                 [](const model::LineElement& el) { return el.isBeam(); });
    }
    bool anyBeam = false;
    for (int e = 0; e < line.elementCount && !endsOnly; ++e) {
      const model::LineElement& el = model.elements()[line.firstElement + e];
      const double t = tension[line.firstElement + e];
      s.tension[e] += t;
      s.tension[e + 1] += t;
      ++count[e];
      ++count[e + 1];
      if (el.beam) {
        anyBeam = true;
        const element::BeamSectionForces& f = beamForces[line.firstElement + e];
        s.bendingMomentVector[e] += f.moment1;
        s.bendingMomentVector[e + 1] += f.moment2;
        s.torque[e] += f.torque;
        s.torque[e + 1] += f.torque;
        ei[e] += el.beam->properties().bendingStiffness;
        ei[e + 1] += el.beam->properties().bendingStiffness;
      }
    }
    // Discrete curvature of the polyline at an inner node: turning angle / mean length of its segments. The
    // segments' lengths are formed once per line, when first needed (a beam line with EI at every node
    // never needs them).
    bool haveSegmentLengths = false;
    const auto polylineCurvature = [&](int i) {
      if (!haveSegmentLengths) {
        segmentLength.resize(static_cast<std::size_t>(std::max(n - 1, 0)));
        for (int k = 0; k + 1 < n; ++k) segmentLength[k] = (s.position[k + 1] - s.position[k]).norm();
        haveSegmentLengths = true;
      }
      const Vec3 a = s.position[i] - s.position[i - 1];
      const Vec3 b = s.position[i + 1] - s.position[i];
      // atan(|a x b| / a.b) where the turn is below 90 degrees: within 2 ulp of atan2 and a third of its
      // cost (docs/performance.md).
      const double sine = a.cross(b).norm(), cosine = a.dot(b);
      const double angle = cosine > 0.0 ? std::atan(sine / cosine) : std::atan2(sine, cosine);
      return angle / (0.5 * (segmentLength[i - 1] + segmentLength[i]));
    };
    if (endsOnly) {
      // Nothing along the line: the end results below.
    } else if (!anyBeam) {
      s.hasBending = false;
      // A cable line (bars only) has no bending moment, torque or rotation (all stay zero) and its
      // curvature is the polyline's: the same values as the general loop below, without its work per node
      // (the writer runs this function at every step for the range graphs: docs/performance.md).
      for (int i = 0; i < n; ++i) {
        // x * 0.5 is x / 2 exactly and does not wait on the divider (docs/performance.md).
        s.tension[i] = count[i] == 2 ? s.tension[i] * 0.5 : s.tension[i] / count[i];
        if (all && dofs.hasRotations(line.firstNode + i))  // a node with rotations, as in the loop below
          s.rotation[i] = geometry::logMap(state.triad[line.firstNode + i]) * (180.0 / kPi);
      }
      for (int i = 1; i + 1 < n; ++i) s.curvature[i] = polylineCurvature(i);
    } else {
      s.hasBending = true;
      for (int i = 0; i < n; ++i) {
        s.tension[i] /= count[i];
        s.bendingMomentVector[i] /= count[i];
        s.torque[i] /= count[i];
        // Cable nodes have no rotation: zero without the logarithm (docs/performance.md).
        if (all && dofs.hasRotations(line.firstNode + i))
          s.rotation[i] = geometry::logMap(state.triad[line.firstNode + i]) * (180.0 / kPi);
        ei[i] /= count[i];
        s.bendingMoment[i] = s.bendingMomentVector[i].norm();
        if (ei[i] > 0.0) {
          s.curvature[i] = s.bendingMoment[i] / ei[i];
        } else if (i > 0 && i < n - 1) {
          s.curvature[i] = polylineCurvature(i);
        }
      }
    }
    // Support reactions: the out-of-balance force at a held end is the reaction on the line; the line
    // pulls its support with the opposite force.
    s.endForceA = fullForce ? Vec3(-fullForce->segment<3>(dofs.firstDof(line.firstNode))) : Vec3::Zero();
    s.endForceB = fullForce ? Vec3(-fullForce->segment<3>(dofs.firstDof(line.lastNode()))) : Vec3::Zero();
    {
      const auto& els = model.elements();
      const int first = line.firstElement;
      const int last = line.firstElement + line.elementCount - 1;
      // The element next to an end extrapolates the end's force only while it is attached to it: a parted
      // one (lines[].failure) carries nothing.
      const model::PartedElements& parted = model.parted();
      const bool twoA =
          line.elementCount >= 2 && !parted.parted(static_cast<std::size_t>(first + 1), state.time);
      const bool twoB =
          line.elementCount >= 2 && !parted.parted(static_cast<std::size_t>(last - 1), state.time);
      const auto beamOf = [&](int e) { return els[e].beam ? &beamForces[e] : nullptr; };
      s.endTensionForceA = endPointForce(model, assembler, state, els[first], tension[first], beamOf(first),
                                         twoA ? &els[first + 1] : nullptr, twoA ? tension[first + 1] : 0.0,
                                         twoA ? beamOf(first + 1) : nullptr, line.firstNode + 1, 1.0);
      // End B: the element force points from node 1 to node 2, out of the line; the line pulls end B back.
      s.endTensionForceB = -endPointForce(model, assembler, state, els[last], tension[last], beamOf(last),
                                          twoB ? &els[last - 1] : nullptr, twoB ? tension[last - 1] : 0.0,
                                          twoB ? beamOf(last - 1) : nullptr, line.lastNode() - 1, -1.0);
      // A compressed end element (a line pushed on) gives a negative end tension.
      const double signA = s.tension.front() < 0.0 ? -1.0 : 1.0;
      const double signB = s.tension.back() < 0.0 ? -1.0 : 1.0;
      // The end tension is the axial quantity (effective tension): the same extrapolation without the
      // beams' shear. For a bar line the two are one vector.
      const bool beams = els[first].beam || els[last].beam;
      const Vec3 axialA =
          !beams ? s.endTensionForceA
                 : endPointForce(model, assembler, state, els[first], tension[first], nullptr,
                                 twoA ? &els[first + 1] : nullptr, twoA ? tension[first + 1] : 0.0, nullptr,
                                 line.firstNode + 1, 1.0);
      const Vec3 axialB = !beams
                              ? s.endTensionForceB
                              : endPointForce(model, assembler, state, els[last], tension[last], nullptr,
                                              twoB ? &els[last - 1] : nullptr, twoB ? tension[last - 1] : 0.0,
                                              nullptr, line.lastNode() - 1, -1.0);
      s.endTensionA = signA * axialA.norm();
      s.endTensionB = signB * axialB.norm();
      // A free end with nothing attached carries no force: the extrapolation from the elements would give
      // the end element's own section force (half its weight and inertia), which is not the physics (a
      // drilling riser's free end below a one-element LMRP read 620-648 kN where the statics give 0).
      if (line.spec->endA.kind == model::EndKind::Free && !hasAttachment(model, line.firstNode)) {
        s.endTensionA = 0.0;
        s.endTensionForceA = Vec3::Zero();
      }
      if (line.spec->endB.kind == model::EndKind::Free && !hasAttachment(model, line.lastNode())) {
        s.endTensionB = 0.0;
        s.endTensionForceB = Vec3::Zero();
      }
      // An end element that parted holds nothing to its end.
      if (parted.parted(static_cast<std::size_t>(first), state.time)) {
        s.endTensionA = 0.0;
        s.endTensionForceA = Vec3::Zero();
      }
      if (parted.parted(static_cast<std::size_t>(last), state.time)) {
        s.endTensionB = 0.0;
        s.endTensionForceB = Vec3::Zero();
      }
      // One end tension everywhere: the end nodes' values along the line (range graphs, the tables, the
      // lines' maxima in the summaries and the batch table) are the end tensions, not the end elements'
      // own tension. During a snap the two differed by a quarter (439 and 557 kN at a fairlead, examples/
      // mooring-batch heading 0 at 1.5 m/s), and the summary's line maximum left the end out.
      s.tension.front() = s.endTensionA;
      s.tension.back() = s.endTensionB;
    }
    if (endsOnly) {
      s.internalPressure.clear();
      s.wallTension.clear();
      continue;
    }
    setWallTension(model, static_cast<int>(l), s);
    if (!all) continue;
    // Touchdown: last node (from end A) of the first grounded stretch that is followed by suspended line.
    grounded.assign(n, 0);
    for (int i = 0; i < n; ++i) {
      const double r = 0.5 * model.nodeContactDiameter()[line.firstNode + i];
      grounded[i] = bed.gap(s.position[i], r) <= 1e-6;
      if (grounded[i]) ++s.seabedNodes;
    }
    // A held end on the seabed (an anchor) is not a grounded stretch by itself.
    if (n >= 2) {
      grounded[0] = grounded[0] && grounded[1];
      grounded[n - 1] = grounded[n - 1] && grounded[n - 2];
    }
    // Height of the contact surface above the seabed, along its normal.
    auto height = [&](int i) {
      return std::max(0.0, bed.gap(s.position[i], 0.5 * model.nodeContactDiameter()[line.firstNode + i]));
    };
    for (int i = 0; i + 1 < n; ++i) {
      if (grounded[i] == grounded[i + 1]) continue;
      // g: last grounded node, a and b: the next two suspended nodes going away from it.
      const int g = grounded[i] ? i : i + 1;
      const int dir = grounded[i] ? 1 : -1;
      const int a = g + dir, b = g + 2 * dir;
      double td = s.arcLength[g];
      if (b >= 0 && b < n) {
        const double ra = std::sqrt(height(a)), rb = std::sqrt(height(b));
        if (rb > ra) {
          const double sa = s.arcLength[a], sb = s.arcLength[b];
          const double estimate = sa - ra * (sb - sa) / (rb - ra);
          // The last grounded node may already be lifting (the penalty seabed lets it rest a hair
          // above the contact level): the touchdown may lie up to one element before it.
          const int before = std::clamp(g - dir, 0, n - 1);
          td = std::clamp(estimate, std::min(s.arcLength[before], sa), std::max(s.arcLength[before], sa));
        }
      }
      s.touchdownArcLength = td;
      break;
    }
  }
}

}  // namespace tangle::solver
