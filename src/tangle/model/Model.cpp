#include "tangle/model/Model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tangle/catenary/ElasticCatenary.hpp"
#include "tangle/core/Error.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/Rotation.hpp"
#include "tangle/seabed/Seabed.hpp"

namespace tangle::model {

namespace {
/// Default torsional stiffness when a beam type gives none: GJ = EI / (1 + nu) with nu = 0.3
/// (solid or thin-walled circular section: J = 2I, G = E / (2 (1 + nu))).
double torsionalStiffnessOf(const section::LineType& t) {
  return t.torsionalStiffness > 0.0 ? t.torsionalStiffness : t.bendingStiffness / 1.3;
}
}  // namespace

Model::Model(ModelSpec spec) : m_spec(std::make_unique<ModelSpec>(std::move(spec))) {
  m_seabedSurface = m_spec->environment.seabedSurface
                        ? m_spec->environment.seabedSurface
                        : std::make_shared<const seabed::SeabedSurface>(
                              seabed::SeabedSurface::flat(m_spec->environment.waterDepth));
  resolveSectionTypes();
  seatAnchorsOnSeabed();
  placePointBodies();
  for (int i = 0; i < static_cast<int>(m_spec->lines.size()); ++i) buildLine(i);
  buildPoints();
  for (int v = 0; v < static_cast<int>(m_spec->vessels.size()); ++v) buildVessel(v);
  m_dofs.finalize();
  m_parted = std::make_unique<PartedElements>(m_elements.size());
}

void Model::seatAnchorsOnSeabed() {
  // The seabed supports a line on its contact surface: a laid node's centreline rests one contact radius
  // above the seabed along its normal (Seabed). An anchor given on the seabed (within that radius of it) is
  // placed on the same surface, so the line leaves it level: with the anchor on the seabed itself the first
  // element would climb one radius to the laid nodes, an uplift and a bending peak that are artefacts of the
  // geometry (issue 30). It sits at the laid line's resting penetration, level with the laid nodes next to
  // it.
  const seabed::SeabedSurface& bed = *m_seabedSurface;
  for (std::size_t l = 0; l < m_spec->lines.size(); ++l) {
    LineSpec& line = m_spec->lines[l];
    if (line.sections.empty()) continue;
    for (int end = 0; end < 2; ++end) {
      EndSpec& e = end == 0 ? line.endA : line.endB;
      if (e.kind != EndKind::Anchored) continue;
      const section::LineType& type =
          sectionType(static_cast<int>(l), end == 0 ? 0 : static_cast<int>(line.sections.size()) - 1);
      const double radius = 0.5 * type.contactDiameter;
      const double weight = type.submergedWeight(m_spec->environment.waterDensity, m_spec->environment.gravity);
      if (bed.gap(e.position, radius) < 0.0)
        e.position.z() = bed.restingZ(
            e.position.x(), e.position.y(), radius,
            seabed::Seabed::restingPenetration(weight, m_spec->environment.seabed.normalStiffness));
    }
  }
}

void Model::resolveSectionTypes() {
  m_sectionTypes.resize(m_spec->lines.size());
  for (std::size_t l = 0; l < m_spec->lines.size(); ++l) {
    const LineSpec& ls = m_spec->lines[l];
    for (const SectionSpec& sec : ls.sections) {
      const auto it = m_spec->lineTypes.find(sec.lineType);
      if (it == m_spec->lineTypes.end())
        throw InputError(m_spec->sourceFile, 0, "lines." + ls.name + ".sections",
                         "unknown line type '" + sec.lineType + "'");
      const double density = std::isnan(sec.contentsDensity) ? ls.contents.density : sec.contentsDensity;
      if (it->second.internalDiameter > 0.0 && density > 0.0) {
        m_contentTypes.push_back(std::make_unique<section::LineType>(it->second));
        m_contentTypes.back()->contentsDensity = density;
        m_sectionTypes[l].push_back(m_contentTypes.back().get());
      } else {
        m_sectionTypes[l].push_back(&it->second);
      }
    }
  }
}

void Model::internalPressure(int l, const std::vector<Vec3>& x, std::vector<double>& p) const {
  const Line& line = m_lines[static_cast<std::size_t>(l)];
  const ContentsSpec& contents = line.spec->contents;
  const auto n = static_cast<std::size_t>(line.nodeCount);
  p.assign(n, 0.0);
  if (!line.pipe) return;
  const double g = m_spec->environment.gravity;
  const double zRef = line.contentsReferenceZ;
  const auto density = [&](std::size_t e) {
    return m_elements[static_cast<std::size_t>(line.firstElement) + e].type->contentsDensity;
  };
  // Head below end A, H_k = sum of g rho_e (z_1 - z_2) over the elements before node k (it grows downwards):
  // the hydrostatics of the contents column along the bore.
  for (std::size_t e = 0; e + 1 < n; ++e) p[e + 1] = p[e] + g * density(e) * (x[e].z() - x[e + 1].z());
  // Head at the reference level: on the first element (from end A) that reaches z_ref, interpolated; a line
  // wholly above or below it extends the nearer end's element to z_ref.
  double reference = 0.0;
  bool found = false;
  for (std::size_t e = 0; e + 1 < n && !found; ++e) {
    const double z1 = x[e].z(), z2 = x[e + 1].z();
    if ((z1 - zRef) * (z2 - zRef) > 0.0) continue;
    reference = z1 == z2 ? p[e] : p[e] + (z1 - zRef) / (z1 - z2) * (p[e + 1] - p[e]);
    found = true;
  }
  if (!found && n >= 2) {
    const bool nearA = std::abs(x.front().z() - zRef) <= std::abs(x.back().z() - zRef);
    reference = nearA ? p.front() + g * density(0) * (x.front().z() - zRef)
                      : p.back() + g * density(n - 2) * (x.back().z() - zRef);
  }
  for (double& value : p) value = contents.pressure + value - reference;
}

void Model::buildVessel(int v) {
  const VesselSpec& vs = m_spec->vessels[v];
  const int node = m_dofs.nodeCount();
  const int first = m_dofs.addNode(6);
  m_vesselNode.push_back(node);
  m_nodeLine.push_back(-1);
  m_tributaryLength.push_back(0.0);
  m_nodeContactDiameter.push_back(0.0);
  m_nodeMass.push_back(0.0);  // the vessel contributor adds its 6x6 mass matrix
  m_nodeRotationalInertia.push_back(0.0);
  m_momentScale.push_back(10.0);  // moments on a hull compared with forces over a 10 m lever
  // A pinned free vessel: its translations are held (a host may move them), its rotations solved.
  const int held = vs.mode != VesselMode::Free ? 6 : vs.pinned ? 3 : 0;
  for (int k = 0; k < held; ++k) m_dofs.constrain(first + k);
}

namespace {
/// The line ends at point `name`, input order: (line, 0 for end A / 1 for end B).
std::vector<std::pair<int, int>> endsAtPoint(const ModelSpec& spec, const std::string& name) {
  std::vector<std::pair<int, int>> ends;
  for (std::size_t l = 0; l < spec.lines.size(); ++l)
    for (int end = 0; end < 2; ++end) {
      const EndSpec& e = end == 0 ? spec.lines[l].endA : spec.lines[l].endB;
      if (e.kind == EndKind::Point && e.point == name) ends.emplace_back(static_cast<int>(l), end);
    }
  return ends;
}
}  // namespace

void Model::placePointBodies() {
  for (const PointSpec& p : m_spec->points) {
    const std::vector<std::pair<int, int>> ends = endsAtPoint(*m_spec, p.name);
    if (ends.empty())
      throw InputError(m_spec->sourceFile, p.sourceLine, "points[" + p.name + "]",
                       "no line end is at this point");
    const AttachmentSpec& b = p.body;
    if (b.mass == 0.0 && b.volume == 0.0 && b.dragArea == 0.0 && b.addedMass == 0.0) continue;
    LineSpec& carrier = m_spec->lines[static_cast<std::size_t>(ends.front().first)];
    AttachmentSpec body = b;
    body.shared = false;
    body.arcLength = 0.0;
    if (ends.front().second == 1)
      for (const SectionSpec& section : carrier.sections) body.arcLength += section.length;
    carrier.attachments.push_back(body);
  }
}

void Model::buildPoints() {
  for (const PointSpec& p : m_spec->points) {
    const std::vector<std::pair<int, int>> ends = endsAtPoint(*m_spec, p.name);
    JunctionPoint j;
    j.name = p.name;
    for (const auto& [l, end] : ends) {
      const Line& line = m_lines[static_cast<std::size_t>(l)];
      j.endNodes.push_back(end == 0 ? line.firstNode : line.lastNode());
    }
    j.node = j.endNodes.front();
    const bool body =
        p.body.mass != 0.0 || p.body.volume != 0.0 || p.body.dragArea != 0.0 || p.body.addedMass != 0.0;
    if (body)  // placePointBodies put it last among its carrier line's attachments
      for (std::size_t a = m_attachments.size(); a-- > 0;)
        if (m_attachments[a].node == j.node) {
          j.attachments.push_back(static_cast<int>(a));
          break;
        }
    for (std::size_t k = 1; k < ends.size(); ++k) {
      const auto [l, end] = ends[k];
      const Line& line = m_lines[static_cast<std::size_t>(l)];
      const LineElement& el = m_elements[static_cast<std::size_t>(
          end == 0 ? line.firstElement : line.firstElement + line.elementCount - 1)];
      // As stiff as a vessel's link (VesselSystem): the tie stretches by 1 % of the end element's extension.
      m_ties.push_back({j.endNodes[k], j.node, 100.0 * el.type->axialStiffness / el.restLength,
                        static_cast<int>(m_points.size())});
    }
    m_points.push_back(std::move(j));
  }
}

Vec3 Model::endPosition(const EndSpec& end) const {
  if (end.kind != EndKind::Vessel) return end.position;
  const int v = vesselIndex(end.vessel);
  return m_spec->vessels[v].position + vesselRotation(v) * end.position;
}

Mat3 Model::vesselRotation(int v) const {
  return Eigen::AngleAxisd(m_spec->vessels[v].heading, Vec3::UnitZ()).toRotationMatrix();
}

std::array<double, 6> Model::vesselMotion(const State& state, int v) const {
  const auto node = static_cast<std::size_t>(vesselNode(v));
  const Vec3 r = geometry::logMap(state.triad[node] * vesselRotation(v).transpose()) * 180.0 / kPi;
  const Vec3& p = state.position[node];
  return {p.x(), p.y(), p.z(), r.x(), r.y(), r.z()};
}

int Model::lineIndex(const std::string& name) const {
  const auto it = m_lineIndex.find(name);
  return it == m_lineIndex.end() ? -1 : it->second;
}

int Model::vesselIndex(const std::string& name) const {
  for (int v = 0; v < static_cast<int>(m_spec->vessels.size()); ++v)
    if (m_spec->vessels[v].name == name) return v;
  return -1;
}

std::string Model::describeNode(int node) const {
  if (node < 0) return "unknown node";
  const int line = m_nodeLine[node];
  if (line < 0) {
    for (int v = 0; v < static_cast<int>(m_vesselNode.size()); ++v)
      if (m_vesselNode[v] == node) return fmt::format("vessel '{}'", m_spec->vessels[v].name);
    return "unknown node";
  }
  const int local = node - m_lines[line].firstNode;
  return fmt::format("line '{}' node {} (arc length {:.2f} m)", m_lines[line].name, local,
                     m_lines[line].arcLength[local]);
}

void Model::buildLine(int lineIndex) {
  const LineSpec& ls = m_spec->lines[lineIndex];
  Line line;
  line.name = ls.name;
  line.spec = &ls;
  line.firstNode = m_dofs.nodeCount();
  line.firstElement = static_cast<int>(m_elements.size());

  // Element list first, to know which nodes need rotations.
  std::vector<LineElement> elements;
  std::vector<double> arc{0.0};
  for (std::size_t k = 0; k < ls.sections.size(); ++k) {
    const SectionSpec& sec = ls.sections[k];
    const section::LineType& type = sectionType(lineIndex, static_cast<int>(k));
    line.pipe = line.pipe || type.internalDiameter > 0.0;
    const double le = sec.length / sec.elements;
    for (int e = 0; e < sec.elements; ++e) {
      LineElement el;
      el.line = lineIndex;
      el.type = &type;
      el.restLength = le;
      if (type.isBeam()) {
        el.beam.emplace(
            element::BeamProperties{type.axialStiffness, type.bendingStiffness, torsionalStiffnessOf(type)},
            le);
      } else {
        el.bar.emplace(type.axialStiffness, le, type.tensionStrain.get());
      }
      elements.push_back(std::move(el));
      arc.push_back(arc.back() + le);
    }
  }
  const int nodeCount = static_cast<int>(arc.size());
  for (int n = 0; n < nodeCount; ++n) {
    const bool beamLeft = n > 0 && elements[n - 1].isBeam();
    const bool beamRight = n < nodeCount - 1 && elements[n].isBeam();
    m_dofs.addNode(beamLeft || beamRight ? 6 : 3);
    m_nodeLine.push_back(lineIndex);
    m_tributaryLength.push_back(0.0);
    m_nodeContactDiameter.push_back(0.0);
    m_nodeMass.push_back(0.0);
    m_nodeRotationalInertia.push_back(0.0);
    m_momentScale.push_back(0.0);
  }
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    LineElement& el = elements[e];
    el.node1 = line.firstNode + e;
    el.node2 = line.firstNode + e + 1;
    const double half = 0.5 * el.restLength;
    const double d = el.type->contactDiameter;
    // Rotational inertia of a solid circular section about a transverse axis per length is
    // m * D^2 / 16; an isotropic approximation is enough for slender lines (it barely matters).
    const double rot = el.type->totalMassPerLength() * half * el.type->outerDiameter * el.type->outerDiameter / 16.0;
    for (int node : {el.node1, el.node2}) {
      m_tributaryLength[node] += half;
      m_momentScale[node] += half;
      m_nodeContactDiameter[node] = std::max(m_nodeContactDiameter[node], d);
      m_nodeMass[node] += el.type->totalMassPerLength() * half;
      m_nodeRotationalInertia[node] += rot;
    }
  }
  line.nodeCount = nodeCount;
  line.elementCount = static_cast<int>(elements.size());
  line.contentsReferenceZ = std::isnan(ls.contents.referenceZ)
                                ? std::max(endPosition(ls.endA).z(), endPosition(ls.endB).z())
                                : ls.contents.referenceZ;
  line.arcLength = arc;
  line.length = arc.back();
  for (const LineElement& el : elements)
    line.contactRadius = std::max(line.contactRadius, 0.5 * el.type->contactDiameter);
  for (auto& el : elements) m_elements.push_back(std::move(el));

  for (const AttachmentSpec& a : ls.attachments) {
    if (a.shared) {
      // Lever rule on the element that holds the module: weights (1 - w, w) of its two nodes, w the
      // module's fraction of the element from its first node. Mass, volume, drag area and added mass all
      // scale (drag is linear in Cd A).
      const auto next = std::upper_bound(arc.begin() + 1, arc.end() - 1, a.arcLength);
      const auto e = static_cast<std::size_t>(next - arc.begin()) - 1;
      const double w = std::clamp((a.arcLength - arc[e]) / (arc[e + 1] - arc[e]), 0.0, 1.0);
      for (const auto& [local, share] : {std::pair{e, 1.0 - w}, std::pair{e + 1, w}}) {
        if (share <= 0.0) continue;
        AttachmentSpec part = a;
        part.mass *= share;
        part.volume *= share;
        part.dragArea *= share;
        part.addedMass *= share;
        const int node = line.firstNode + static_cast<int>(local);
        m_attachments.push_back({node, part});
        m_nodeMass[node] += part.mass;
      }
      continue;
    }
    const auto nearest = std::min_element(arc.begin(), arc.end(), [&](double x, double y) {
      return std::abs(x - a.arcLength) < std::abs(y - a.arcLength);
    });
    const int node = line.firstNode + static_cast<int>(nearest - arc.begin());
    m_attachments.push_back({node, a});
    m_nodeMass[node] += a.mass;
  }

  constrainEnd(line.firstNode, ls.endA);
  constrainEnd(line.lastNode(), ls.endB);
  // A run of consecutive beam elements whose ends both leave rotations free (pinned, anchored, point or free
  // line ends, or a cable section next to it, which carries no moment) can twist as a rigid body about its
  // own axis: a zero-stiffness mechanism (a buoyant hose above a chain tether in current took 2 611 statics
  // iterations and arc-length continuation past folds of the path with it, 33 without; pinned 1 m short of
  // taut it did not converge, 163 without). Restrain the rotation component along the global axis closest
  // to the line's chord at one node of the run (the "torsion lock" of 3D frame supports): a line end of the
  // run held in translation if it has one, else the run's first node. A fixed end holds every rotation and a
  // vessel's beam end has a torsion spring (VesselSystem, with or without a flex joint), so a run reaching
  // either is held already. The lock also holds the bending rotation's component
  // along that axis at its node: nothing where the run leaves the node along the line's chord, but a run
  // that lies across the chord (a beam section rising from a cable laid along it) keeps its twist nearly free
  // and has that node's bending held: the axis should be the run's own, whose shape is not known here (not
  // built). A line held nowhere (both ends free) is not locked: every rigid motion of it is free in statics,
  // and its inertia holds them in dynamics.
  const auto heldInTranslation = [](EndKind k) {
    return k == EndKind::Anchored || k == EndKind::Pinned || k == EndKind::Point;
  };
  const auto holdsTwist = [](EndKind k) { return k == EndKind::Fixed || k == EndKind::Vessel; };
  const Vec3 chord = (endPosition(ls.endB) - endPosition(ls.endA)).cwiseAbs();
  int axis = 0;
  chord.maxCoeff(&axis);
  const bool heldLine = heldInTranslation(ls.endA.kind) || heldInTranslation(ls.endB.kind) ||
                        holdsTwist(ls.endA.kind) || holdsTwist(ls.endB.kind);
  for (int e = 0; heldLine && e < line.elementCount;) {
    if (!m_elements[static_cast<std::size_t>(line.firstElement + e)].isBeam()) {
      ++e;
      continue;
    }
    int last = e;  // the run is elements [e, last]: nodes firstNode + e to firstNode + last + 1
    while (last + 1 < line.elementCount &&
           m_elements[static_cast<std::size_t>(line.firstElement + last + 1)].isBeam())
      ++last;
    const bool atA = e == 0, atB = last + 1 == line.elementCount;
    if (!(atA && holdsTwist(ls.endA.kind)) && !(atB && holdsTwist(ls.endB.kind))) {
      const int lockNode = atA && heldInTranslation(ls.endA.kind)   ? line.firstNode
                           : atB && heldInTranslation(ls.endB.kind) ? line.lastNode()
                                                                    : line.firstNode + e;
      m_dofs.constrain(m_dofs.firstDof(lockNode) + 3 + axis);
    }
    e = last + 1;
  }
  m_lineIndex.emplace(line.name, static_cast<int>(m_lines.size()));  // the first of a name, as before
  m_lines.push_back(std::move(line));
}

void Model::constrainEnd(int node, const EndSpec& end) {
  const int first = m_dofs.firstDof(node);
  switch (end.kind) {
    case EndKind::Fixed:
      for (int k = 0; k < m_dofs.dofCount(node); ++k)
        if (k >= 3 || !end.release[k]) m_dofs.constrain(first + k);
      break;
    case EndKind::Anchored:
    case EndKind::Pinned:
      for (int k = 0; k < 3; ++k)
        if (!end.release[k]) m_dofs.constrain(first + k);
      break;
    case EndKind::Free:
    case EndKind::Point:  // free, held by the other lines at the point (NodeTie)
      break;
    case EndKind::Vessel: {
      const int v = vesselIndex(end.vessel);
      if (v < 0)
        throw InputError(m_spec->sourceFile, end.sourceLine, "end.vessel",
                         "unknown vessel '" + end.vessel + "'");
      // On a fixed or prescribed vessel the end follows the vessel's point: held (prescribed). On a free
      // vessel it is tied to the vessel node by the vessel contributor's link.
      if (m_spec->vessels[v].mode != VesselMode::Free) {
        for (int k = 0; k < 3; ++k)
          if (!(k == 2 && end.tensioner.enabled)) m_dofs.constrain(first + k);
      }
      break;
    }
  }
}

std::vector<Vec3> Model::startShapePositions(const Line& line, const Vec3& endA, const Vec3& endB) const {
  // The polyline end A -> points -> end B, parametrised by unstretched arc length: at the points' own
  // arc lengths where given, otherwise in proportion to the chords (scaled to the line's length). Each node
  // sits at its arc length along it, linearly between the control points.
  const std::vector<StartPoint>& shape = line.spec->startShape;
  std::vector<Vec3> control{endA};
  for (const StartPoint& p : shape) control.push_back(p.position);
  control.push_back(endB);
  std::vector<double> arc(control.size(), 0.0);
  if (std::isfinite(shape.front().arcLength)) {
    for (std::size_t k = 0; k < shape.size(); ++k) arc[k + 1] = shape[k].arcLength;
  } else {
    for (std::size_t k = 1; k < control.size(); ++k)
      arc[k] = arc[k - 1] + (control[k] - control[k - 1]).norm();
    const double total = arc.back();
    for (double& a : arc) a = total > 0.0 ? a * line.length / total : 0.0;
  }
  arc.back() = line.length;
  std::vector<Vec3> pts(static_cast<std::size_t>(line.nodeCount));
  std::size_t k = 0;
  for (int i = 0; i < line.nodeCount; ++i) {
    const double a = line.arcLength[static_cast<std::size_t>(i)];
    while (k + 2 < control.size() && a > arc[k + 1]) ++k;
    const double span = arc[k + 1] - arc[k];
    const double f = span > 0.0 ? std::clamp((a - arc[k]) / span, 0.0, 1.0) : 0.0;
    pts[static_cast<std::size_t>(i)] = (1.0 - f) * control[k] + f * control[k + 1];
  }
  return pts;
}

State Model::initialState() const {
  State s;
  const int n = nodeCount();
  s.position.assign(n, Vec3::Zero());
  s.triad.assign(n, Mat3::Identity());
  s.velocity = VecX::Zero(m_dofs.fullDofCount());
  s.acceleration = VecX::Zero(m_dofs.fullDofCount());
  const EnvironmentSpec& env = m_spec->environment;
  for (const Line& line : m_lines) {
    std::vector<catenary::CatenarySection> sections;
    const int l = static_cast<int>(&line - m_lines.data());
    for (std::size_t k = 0; k < line.spec->sections.size(); ++k) {
      const SectionSpec& sec = line.spec->sections[k];
      const section::LineType& t = sectionType(l, static_cast<int>(k));
      sections.push_back({sec.length, t.submergedWeight(env.waterDensity, env.gravity), t.axialStiffness});
    }
    // An end resting on the seabed sits one contact radius above it; the analytic shape then uses the
    // level of that end as its seabed, so the grounded part starts where it rests (not squashed).
    const double radius = line.contactRadius;
    // On a seabed that is not flat the analytic shape's flat seabed is at the deeper of the seabed under the
    // two ends (or the level of an end resting on it), never above an end; the nodes it lays are then placed
    // on the seabed's own surface below.
    const seabed::SeabedSurface& bed = *m_seabedSurface;
    const bool flat = bed.isFlat();
    const Vec3 endA = endPosition(line.spec->endA);
    const Vec3 endB = endPosition(line.spec->endB);
    double shapeDepth =
        flat ? env.waterDepth : std::max(-bed.height(endA.x(), endA.y()), -bed.height(endB.x(), endB.y()));
    for (const Vec3& end : {endA, endB})
      if (flat ? end.z() <= -env.waterDepth + radius + 1e-6 : bed.gap(end, radius) <= 1e-6)
        shapeDepth = std::min(shapeDepth, -end.z());
    if (!flat) shapeDepth = std::max({shapeDepth, -endA.z(), -endB.z()});
    double totalWeight = 0.0;
    for (const auto& sec : sections) totalWeight += sec.weight * sec.length;
    std::vector<Vec3> pts;
    if (!line.spec->startShape.empty()) {
      pts = startShapePositions(line, endA, endB);
    } else if (totalWeight < 0.0 && endA.z() < 0.0 && endB.z() < 0.0) {
      // A buoyant line floats up into an inverted catenary: the hanging catenary of the mirrored problem
      // (z -> -z, weight -> -weight, no seabed), mirrored back. A straight start would be a compressed,
      // unstable equilibrium of a cable.
      std::vector<catenary::CatenarySection> mirrored = sections;
      for (auto& sec : mirrored) sec.weight = -sec.weight;
      const Vec3 flip(1.0, 1.0, -1.0);
      const double noSeabed = 1e3 * std::max(1.0, std::abs(endA.z()) + std::abs(endB.z()) + line.length);
      pts = catenary::initialLineShape(endA.cwiseProduct(flip), endB.cwiseProduct(flip), mirrored, noSeabed,
                                     line.arcLength)
                .positions;
      for (Vec3& p : pts) p = p.cwiseProduct(flip);
    } else {
      pts = catenary::initialLineShape(endA, endB, sections, shapeDepth, line.arcLength).positions;
    }
    for (int i = 0; i < line.nodeCount; ++i) s.position[line.firstNode + i] = pts[i];
    // A start shape laid on the seabed rests one contact radius above it (as an end does); below that, it
    // is lifted there.
    if (!line.spec->startShape.empty()) {
      shapeDepth = env.waterDepth - radius;
      for (int i = 1; i + 1 < line.nodeCount; ++i) {
        Vec3& x = s.position[line.firstNode + i];
        if (flat)
          x.z() = std::max(x.z(), -shapeDepth);
        else if (bed.gap(x, radius) < 0.0)
          x.z() = bed.restingZ(x.x(), x.y(), radius, 0.0);
      }
    }
    // Grounded nodes start on the seabed's contact surface at their static penetration into it, where they
    // rest (and where a seated anchor is), so the seabed springs are active in the first Newton tangent
    // (otherwise a grounded stretch has no vertical stiffness).
    for (int i = 1; i + 1 < line.nodeCount; ++i) {
      Vec3& x = s.position[line.firstNode + i];
      const double nodeRadius = 0.5 * m_nodeContactDiameter[line.firstNode + i];
      // Flat: the nodes the analytic shape laid at its seabed. Otherwise also any node below the seabed's
      // contact surface (a shape laid flat where the seabed rises, a start shape through it).
      const bool laid = flat ? x.z() <= -shapeDepth + 1e-6
                             : (line.spec->startShape.empty() && x.z() <= -shapeDepth + 1e-6) ||
                                   bed.gap(x, nodeRadius) <= 1e-6;
      if (!laid) continue;
      const model::LineElement& el = m_elements[line.firstElement + i];
      const double w = el.type->submergedWeight(env.waterDensity, env.gravity);
      x.z() = bed.restingZ(x.x(), x.y(), nodeRadius,
                           seabed::Seabed::restingPenetration(w, env.seabed.normalStiffness));
    }

    setLineTriads(l, s);
  }
  for (int v = 0; v < static_cast<int>(m_vesselNode.size()); ++v) {
    s.position[m_vesselNode[v]] = m_spec->vessels[v].position;
    s.triad[m_vesselNode[v]] = vesselRotation(v);
  }
  return s;
}

void Model::setLineTriads(int lineIndex, State& s) const {
  const Line& line = m_lines.at(static_cast<std::size_t>(lineIndex));
  // Triads: first one from the initial tangent, then parallel transport along the line so that
  // the initial shape carries no twist (Bishop frame).
  auto tangentAt = [&](int i) {
    const int a = line.firstNode + std::max(i - 1, 0);
    const int b = line.firstNode + std::min(i + 1, line.nodeCount - 1);
    Vec3 t = s.position[b] - s.position[a];
    if (t.norm() < 1e-12) t = Vec3::UnitX();
    return Vec3(t.normalized());
  };
  Vec3 prev = tangentAt(0);
  Mat3 q = geometry::frameFromTangent(prev, Vec3::UnitZ());
  for (int i = 0; i < line.nodeCount; ++i) {
    const Vec3 t = tangentAt(i);
    q = geometry::rotationBetween(prev, t) * q;
    s.triad[line.firstNode + i] = q;
    prev = t;
  }
}

double Model::lineMass(int lineIndex) const {
  const Line& line = m_lines.at(lineIndex);
  double m = 0.0;
  for (int n = line.firstNode; n <= line.lastNode(); ++n) m += m_nodeMass[n];
  // A point's body is the point's, not its carrier line's.
  for (const JunctionPoint& p : m_points)
    if (m_nodeLine[static_cast<std::size_t>(p.node)] == lineIndex)
      for (const int a : p.attachments) m -= m_attachments[static_cast<std::size_t>(a)].spec.mass;
  return m;
}

}  // namespace tangle::model
