#include "tangle/vessel/HullContact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "tangle/core/Error.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace tangle::vessel {
namespace {

/// Points closer to contact than this are "near" [m]: their approach limits the time step and gives an
/// impact's velocity; the nodes of elements this near a hull are marked as loaded (markLoadedNodes).
constexpr double kNearReach = 2.0;
/// Speed below which the hysteretic restitution factor is smoothed [m/s] (contact::HystereticRestitution:
/// the rebound of an impact at v0 is e v0 up to terms of order (v_s / v0)^2).
constexpr double kRestitutionSpeed = 0.005;
/// Steps per contact half period pi sqrt(m / k) (limitStep).
constexpr double kStepsPerContact = 20.0;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

int intervals(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

/// Distance of point p from segment [a, b] [m].
double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double l2 = d.squaredNorm();
  const double s = l2 > 0.0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (p - a - s * d).norm();
}

/// A body's DOFs seen from a contact point: the point's velocity is G q' over these DOFs (signed: -G for
/// hull B, so that the relative velocity of A's point to B's is the sum over the entries).
struct Entry {
  int dof = 0;
  Mat3 map = Mat3::Identity();
};

}  // namespace

bool HullContact::wanted(const model::Model& model) {
  return std::any_of(model.vessels().begin(), model.vessels().end(),
                     [](const model::VesselSpec& v) { return !v.hull.empty(); });
}

HullContact::HullContact(const model::Model& model, const model::State& start)
    : m_model(&model), m_spec(model.spec().hullContact) {
  m_restitution.amplitude = contact::HystereticRestitution::amplitudeFor(m_spec.restitution);
  m_restitution.speed = kRestitutionSpeed;
  const std::string& file = model.spec().sourceFile;
  const auto excluded = [&](const std::string& a, const std::string& b) {
    return std::any_of(m_spec.exclude.begin(), m_spec.exclude.end(), [&](const auto& pair) {
      return (pair.first == a && pair.second == b) || (pair.first == b && pair.second == a);
    });
  };
  for (int v = 0; v < static_cast<int>(model.vessels().size()); ++v) {
    const model::VesselSpec& spec = model.vessels()[static_cast<std::size_t>(v)];
    if (spec.hull.empty()) continue;
    Hull h;
    h.vessel = v;
    h.node = model.vesselNode(v);
    h.free = spec.mode == model::VesselMode::Free;
    h.shapes = spec.hull;
    for (const geometry::HullShape& s : h.shapes) {
      h.reach = std::max(h.reach, s.reach(Vec3::Zero()));
      h.shapeCentre.push_back(s.centre());
      h.shapeReach.push_back(s.reach(s.centre()));
      for (const Vec3& p : s.surfacePoints(m_spec.pointSpacing)) {
        // A point inside another shape of the same hull (a column's ring inside a pontoon) is never on the
        // hull's surface: left out.
        const bool inside = std::any_of(h.shapes.begin(), h.shapes.end(), [&](const geometry::HullShape& o) {
          return &o != &s && o.distance(p).distance < -1e-9;
        });
        if (!inside) h.points.push_back(p);
      }
    }
    for (int k = 0; k < 3; ++k) {
      h.mass(k, k) = spec.mass + spec.addedMass[static_cast<std::size_t>(k)];
      h.mass(k + 3, k + 3) = spec.inertia[k] + spec.addedMass[static_cast<std::size_t>(k + 3)];
    }
    m_hulls.push_back(std::move(h));
  }
  std::vector<HullImpact> names;
  const auto& lines = model.lines();
  for (int b = 0; b < static_cast<int>(m_hulls.size()); ++b) {
    const std::string& vesselName = model.vessels()[static_cast<std::size_t>(m_hulls[b].vessel)].name;
    for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
      const model::Line& line = lines[static_cast<std::size_t>(l)];
      if (excluded(line.name, vesselName)) continue;
      const auto onVessel = [&](const model::EndSpec& e) {
        return e.kind == model::EndKind::Vessel && e.vessel == vesselName;
      };
      const bool own = onVessel(line.spec->endA) || onVessel(line.spec->endB);
      if (own && !m_spec.ownLines) continue;
      Pair pair;
      pair.line = l;
      pair.hullB = b;
      pair.event = static_cast<int>(names.size());
      pair.skip.assign(static_cast<std::size_t>(line.elementCount), 0);
      m_pairs.push_back(std::move(pair));
      HullImpact name;
      name.bodyA = line.name;
      name.bodyB = vesselName;
      name.lineOnHull = true;
      names.push_back(name);
    }
  }
  for (int a = 0; a < static_cast<int>(m_hulls.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(m_hulls.size()); ++b) {
      if (!m_hulls[a].free && !m_hulls[b].free) continue;  // neither can move: nothing to compute
      const std::string& nameA = model.vessels()[static_cast<std::size_t>(m_hulls[a].vessel)].name;
      const std::string& nameB = model.vessels()[static_cast<std::size_t>(m_hulls[b].vessel)].name;
      if (excluded(nameA, nameB)) continue;
      const int event = static_cast<int>(names.size());
      Pair ab;
      ab.hullA = a;
      ab.hullB = b;
      ab.event = event;
      Pair ba = ab;
      std::swap(ba.hullA, ba.hullB);
      m_pairs.push_back(ab);
      m_pairs.push_back(ba);
      HullImpact name;
      name.bodyA = nameA;
      name.bodyB = nameB;
      names.push_back(name);
    }
  // At the start: a line tied to the vessel leaves out its elements already in the hull (own_lines); any
  // other line or hull inside a hull is an input error.
  std::vector<int> startHits(m_pairs.size(), 0);
  std::vector<Point> firstHit(m_pairs.size());
  forEachPoint(start, 0.0, false, [&](const Point& p, int element, double) {
    Pair& pair = m_pairs[static_cast<std::size_t>(p.pair)];
    if (pair.line >= 0) {
      const model::Line& line = lines[static_cast<std::size_t>(pair.line)];
      const std::string& vesselName =
          model.vessels()[static_cast<std::size_t>(m_hulls[pair.hullB].vessel)].name;
      const bool own = line.spec->endA.vessel == vesselName || line.spec->endB.vessel == vesselName;
      if (own) {
        pair.skip[static_cast<std::size_t>(element - line.firstElement)] = 1;
        return;
      }
    }
    if (startHits[static_cast<std::size_t>(p.pair)]++ == 0) firstHit[static_cast<std::size_t>(p.pair)] = p;
  });
  for (std::size_t k = 0; k < m_pairs.size(); ++k) {
    if (startHits[k] == 0) continue;
    const Pair& pair = m_pairs[k];
    const HullImpact& name = names[static_cast<std::size_t>(pair.event)];
    const Point& p = firstHit[k];
    throw InputError(
        file, m_spec.sourceLine,
        pair.line >= 0 ? "lines[" + name.bodyA + "]" : "vessels[" + name.bodyA + "].hull",
        fmt::format("{} '{}' to start clear of the hull of vessel '{}'; {} of its points are inside it, the "
                    "first at ({:.2f}, {:.2f}, {:.2f}) m, {:.3g} m deep: move it, or leave the pair out with "
                    "hull_contact.exclude: [[{}, {}]]",
                    pair.line >= 0 ? "line" : "the hull of vessel", name.bodyA, name.bodyB, startHits[k],
                    p.position.x(), p.position.y(), p.position.z(), -p.gap, name.bodyA, name.bodyB));
  }
  m_impacts = std::make_unique<HullImpacts>(std::move(names), model.spec().contact.impactVelocityThreshold);
  m_lineHalfPeriod.assign(lines.size(), kInf);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    double perLength = 0.0;  // the heaviest section's mass per metre (in air, with contents) [kg/m]
    for (int e = 0; e < lines[l].elementCount; ++e)
      perLength = std::max(
          perLength,
          model.elements()[static_cast<std::size_t>(lines[l].firstElement + e)].type->totalMassPerLength());
    m_lineHalfPeriod[l] = std::numbers::pi * std::sqrt(perLength / m_spec.lineStiffness);
  }
}

geometry::ShapeDistance HullContact::hullDistance(const model::State& state, const Hull& h, const Vec3& p,
                                                  double cutoff) const {
  const Mat3& rotation = state.triad[static_cast<std::size_t>(h.node)];
  const Vec3 local = rotation.transpose() * (p - state.position[static_cast<std::size_t>(h.node)]);
  geometry::ShapeDistance best;
  best.distance = kInf;
  for (std::size_t k = 0; k < h.shapes.size(); ++k) {
    // A lower bound first: no point of the shape is nearer than |p - c| - reach (its bounding sphere).
    const double bound = (local - h.shapeCentre[k]).norm() - h.shapeReach[k];
    if (bound >= best.distance || bound >= cutoff) continue;
    const geometry::ShapeDistance d = h.shapes[k].distance(local);
    if (d.distance < best.distance) best = d;
  }
  best.normal = rotation * best.normal;
  return best;
}

template <class Visit>
void HullContact::forEachPoint(const model::State& state, double reach, bool velocities,
                               Visit&& visit) const {
  const model::DofMap& dofs = m_model->dofs();
  const auto bodyVelocity = [&](const Hull& h, const Vec3& p) -> Vec3 {
    if (!velocities) return Vec3::Zero();
    const int dv = dofs.firstDof(h.node);
    return state.velocity.segment<3>(dv) + Vec3(state.velocity.segment<3>(dv + 3))
                                               .cross(p - state.position[static_cast<std::size_t>(h.node)]);
  };
  for (int k = 0; k < static_cast<int>(m_pairs.size()); ++k) {
    const Pair& pair = m_pairs[static_cast<std::size_t>(k)];
    const Hull& b = m_hulls[static_cast<std::size_t>(pair.hullB)];
    const Vec3& centreB = state.position[static_cast<std::size_t>(b.node)];
    Point point;
    point.pair = k;
    if (pair.line >= 0) {
      const model::Line& line = m_model->lines()[static_cast<std::size_t>(pair.line)];
      for (int le = 0; le < line.elementCount; ++le) {
        if (pair.skip[static_cast<std::size_t>(le)]) continue;
        const int e = line.firstElement + le;
        if (m_model->parted().parted(static_cast<std::size_t>(e), state.time)) continue;
        const model::LineElement& el = m_model->elements()[static_cast<std::size_t>(e)];
        const Vec3& x1 = state.position[static_cast<std::size_t>(el.node1)];
        const Vec3& x2 = state.position[static_cast<std::size_t>(el.node2)];
        const double radius = 0.5 * el.type->contactDiameter;
        if (pointSegmentDistance(centreB, x1, x2) > b.reach + radius + reach) continue;
        const int n = intervals((x2 - x1).norm(), m_spec.pointSpacing);
        for (int j = 0; j <= n; ++j) {
          const double t = static_cast<double>(j) / n;
          point.position = (1.0 - t) * x1 + t * x2;
          const geometry::ShapeDistance d = hullDistance(state, b, point.position, reach + radius);
          point.gap = d.distance - radius;
          if (!(point.gap < reach)) continue;
          point.normal = d.normal;
          point.stiffness = m_spec.lineStiffness * el.restLength / n * (j == 0 || j == n ? 0.5 : 1.0);
          point.relativeVelocity = Vec3::Zero();
          if (velocities)
            point.relativeVelocity = (1.0 - t) * state.velocity.segment<3>(dofs.firstDof(el.node1)) +
                                     t * state.velocity.segment<3>(dofs.firstDof(el.node2)) -
                                     bodyVelocity(b, point.position);
          visit(point, e, t);
        }
      }
      continue;
    }
    const Hull& a = m_hulls[static_cast<std::size_t>(pair.hullA)];
    const Vec3& centreA = state.position[static_cast<std::size_t>(a.node)];
    if ((centreA - centreB).norm() > a.reach + b.reach + reach) continue;
    const Mat3& rotationA = state.triad[static_cast<std::size_t>(a.node)];
    for (const Vec3& local : a.points) {
      point.position = centreA + rotationA * local;
      if ((point.position - centreB).norm() > b.reach + reach) continue;
      const geometry::ShapeDistance d = hullDistance(state, b, point.position, reach);
      point.gap = d.distance;
      if (!(point.gap < reach)) continue;
      point.normal = d.normal;
      point.stiffness = m_spec.stiffness;
      point.relativeVelocity = bodyVelocity(a, point.position) - bodyVelocity(b, point.position);
      visit(point, -1, 0.0);
    }
  }
}

void HullContact::addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                            solver::SystemMatrix* matrix) {
  const model::DofMap& dofs = m_model->dofs();
  const bool dynamic = request.dynamic;
  const bool friction = dynamic && m_spec.friction > 0.0;
  // The nodes near a hull at this assembly (markLoadedNodes): every point within kNearReach is visited.
  std::fill(m_nearNodes.begin(), m_nearNodes.end(), 0);
  m_nearNodes.resize(static_cast<std::size_t>(m_model->nodeCount()), 0);
  forEachPoint(state, kNearReach, dynamic, [&](const Point& p, int element, double t) {
    const Pair& pair = m_pairs[static_cast<std::size_t>(p.pair)];
    if (pair.line >= 0) {
      const model::LineElement& el = m_model->elements()[static_cast<std::size_t>(element)];
      m_nearNodes[static_cast<std::size_t>(el.node1)] = 1;
      m_nearNodes[static_cast<std::size_t>(el.node2)] = 1;
    }
    m_nearNodes[static_cast<std::size_t>(m_hulls[static_cast<std::size_t>(pair.hullB)].node)] = 1;
    if (pair.hullA >= 0)
      m_nearNodes[static_cast<std::size_t>(m_hulls[static_cast<std::size_t>(pair.hullA)].node)] = 1;
    if (!(p.gap < 0.0)) return;
    const double penetration = -p.gap;
    const Vec3& n = p.normal;
    const double rate = -n.dot(p.relativeVelocity);  // penetration rate, > 0 approaching
    const double psi = dynamic ? m_restitution.factor(rate) : 1.0;
    const double dpsi = dynamic ? m_restitution.derivative(rate) : 0.0;
    const double fn = p.stiffness * penetration * psi;
    Vec3 onA = fn * n;
    Mat3 frictionDamping = Mat3::Zero();
    if (friction) {
      // Regularised Coulomb: f_t = -mu fn v_t / s, s = sqrt(|v_t|^2 + v_f^2); d f_t / d v_rel (v_t = P
      // v_rel).
      const Mat3 projector = Mat3::Identity() - n * n.transpose();
      const Vec3 vt = projector * p.relativeVelocity;
      const double s = std::sqrt(vt.squaredNorm() + m_spec.frictionVelocity * m_spec.frictionVelocity);
      onA -= m_spec.friction * fn / s * vt;
      frictionDamping =
          m_spec.friction * fn * (Mat3::Identity() / s - vt * vt.transpose() / (s * s * s)) * projector;
    }
    // The bodies' DOFs at the point (signed: B's entries carry minus signs).
    std::array<Entry, 4> entries;
    int count = 0;
    if (pair.line >= 0) {
      const model::LineElement& el = m_model->elements()[static_cast<std::size_t>(element)];
      entries[count++] = {dofs.firstDof(el.node1), (1.0 - t) * Mat3::Identity()};
      entries[count++] = {dofs.firstDof(el.node2), t * Mat3::Identity()};
    } else {
      const Hull& a = m_hulls[static_cast<std::size_t>(pair.hullA)];
      if (a.free) {
        const int dv = dofs.firstDof(a.node);
        entries[count++] = {dv, Mat3::Identity()};
        entries[count++] = {dv + 3,
                            -geometry::skew(p.position - state.position[static_cast<std::size_t>(a.node)])};
      }
    }
    const Hull& b = m_hulls[static_cast<std::size_t>(pair.hullB)];
    if (b.free) {
      const int dv = dofs.firstDof(b.node);
      entries[count++] = {dv, -Mat3::Identity()};
      entries[count++] = {dv + 3,
                          geometry::skew(p.position - state.position[static_cast<std::size_t>(b.node)])};
    }
    for (int i = 0; i < count; ++i) force.segment<3>(entries[i].dof) -= entries[i].map.transpose() * onA;
    if (!matrix) return;
    const Mat3 nn = n * n.transpose();
    const Mat3 k = request.kf * p.stiffness * psi * nn +
                   request.cf * (p.stiffness * penetration * dpsi * nn + frictionDamping);
    for (int i = 0; i < count; ++i)
      for (int j = 0; j < count; ++j)
        matrix->add3x3(entries[i].dof, entries[j].dof, Mat3(entries[i].map.transpose() * k * entries[j].map));
  });
}

Mat6 HullContact::globalMass(const model::State& state, const Hull& h) const {
  const Mat3& r = state.triad[static_cast<std::size_t>(h.node)];
  Mat6 m = Mat6::Zero();
  m.block<3, 3>(0, 0) = r * h.mass.block<3, 3>(0, 0) * r.transpose();
  m.block<3, 3>(3, 3) = r * h.mass.block<3, 3>(3, 3) * r.transpose();
  return m;
}

double HullContact::bodiesMass(const model::State& state, const Pair& pair, const Vec3& p,
                               const Vec3& n) const {
  if (pair.line >= 0) return kNaN;
  double flexibility = 0.0;  // 1 / m [1/kg]
  for (const int index : {pair.hullA, pair.hullB}) {
    const Hull& h = m_hulls[static_cast<std::size_t>(index)];
    if (!h.free) continue;
    Vec6 j;
    j << n, (p - state.position[static_cast<std::size_t>(h.node)]).cross(n);
    flexibility += j.dot(globalMass(state, h).ldlt().solve(j));
  }
  return flexibility > 0.0 ? 1.0 / flexibility : kInf;
}

double HullContact::limitStep(const model::State& state, double /*step*/) {
  // Per pair: in contact (the points touching) or closing on it within three of the last steps.
  std::vector<int> touching(m_pairs.size(), 0);
  std::vector<char> near(m_pairs.size(), 0);
  std::vector<double> mass(m_pairs.size(), kInf);
  const double lastDt = m_lastDt > 0.0 ? m_lastDt : m_model->spec().dynamics.timeStep;
  const double threshold = m_model->spec().contact.impactVelocityThreshold;
  forEachPoint(state, kNearReach, true, [&](const Point& p, int, double) {
    const std::size_t k = static_cast<std::size_t>(p.pair);
    const double approach = -p.normal.dot(p.relativeVelocity);
    if (p.gap < 0.0) ++touching[k];
    // Only an impact needs the short steps: a resting or slowly closing contact (a leg lying on a pontoon)
    // is as well resolved by the integrator's own step as the seabed's contact is.
    // In contact, closing or opening (an impact's unloading needs the short steps as its loading does).
    if ((p.gap < 0.0 ? std::abs(approach) : approach) <= threshold) return;
    if (p.gap < 0.0 || p.gap < 3.0 * approach * lastDt)
      near[k] = 1;
    else
      return;
    if (m_pairs[k].line < 0 && !std::isfinite(mass[k]))
      mass[k] = bodiesMass(state, m_pairs[k], p.position, p.normal);
  });
  // An impact keeps its short steps for two half periods after its pair last moved fast (through the deepest
  // point, where the rate passes zero, and the unloading), then lets them grow.
  m_impactUntil.resize(m_pairs.size(), -kInf);
  m_impactLimit.resize(m_pairs.size(), kInf);
  double limit = kInf;
  for (std::size_t k = 0; k < m_pairs.size(); ++k) {
    if (near[k]) {
      const Pair& pair = m_pairs[k];
      const double halfPeriod =
          pair.line >= 0
              ? m_lineHalfPeriod[static_cast<std::size_t>(pair.line)]
              : std::numbers::pi * std::sqrt(mass[k] / (m_spec.stiffness * std::max(1, touching[k])));
      if (!std::isfinite(halfPeriod)) continue;
      m_impactLimit[k] = halfPeriod / kStepsPerContact;
      m_impactUntil[k] = state.time + 2.0 * halfPeriod;
    }
    if (near[k] || state.time < m_impactUntil[k]) limit = std::min(limit, m_impactLimit[k]);
  }
  return limit;
}

void HullContact::commitStep(model::State& state, double dt) {
  std::size_t pairCount = 0;
  for (const Pair& p : m_pairs) pairCount = std::max(pairCount, static_cast<std::size_t>(p.event) + 1);
  std::vector<HullPairReading> readings(pairCount);
  std::vector<double> nearest(pairCount, kInf);
  // Force-weighted centre and normal of each pair's contact (the bodies' effective mass is taken there: a
  // face meeting a face pushes through the middle of the face, not at its deepest corner).
  std::vector<Vec3> centre(pairCount, Vec3::Zero()), normal(pairCount, Vec3::Zero());
  std::vector<const Pair*> pairOf(pairCount, nullptr);
  const bool dynamic = dt > 0.0;
  forEachPoint(state, kNearReach, true, [&](const Point& p, int, double) {
    const Pair& pair = m_pairs[static_cast<std::size_t>(p.pair)];
    const std::size_t k = static_cast<std::size_t>(pair.event);
    HullPairReading& r = readings[k];
    pairOf[k] = &pair;
    const double approach = -p.normal.dot(p.relativeVelocity);
    if (!r.near || approach > r.approachSpeed) r.approachSpeed = approach;
    r.near = true;
    if (p.gap < 0.0) {
      const double psi = dynamic ? m_restitution.factor(approach) : 1.0;
      const double f = p.stiffness * -p.gap * psi;
      r.force += f;
      centre[k] += f * p.position;
      // The normal of B's surface, in the direction of the pair's first listed body (A of its first entry).
      normal[k] += f * (pair.hullA >= 0 && pair.hullA > pair.hullB ? Vec3(-p.normal) : p.normal);
    }
    if (p.gap < nearest[k]) {
      nearest[k] = p.gap;
      r.penetration = std::max(0.0, -p.gap);
      r.position = p.position;
      r.separationSpeed = -approach;
      r.bodiesMass = bodiesMass(state, pair, p.position, p.normal);
    }
  });
  for (std::size_t k = 0; k < pairCount; ++k) {
    HullPairReading& r = readings[k];
    if (!(r.force > 0.0) || !pairOf[k] || pairOf[k]->line >= 0 || normal[k].norm() <= 0.0) continue;
    r.bodiesMass = bodiesMass(state, *pairOf[k], centre[k] / r.force, normal[k].normalized());
  }
  m_impacts->commit(state.time, dt, readings);
  if (dt > 0.0) m_lastDt = dt;
}

void HullContact::finish(double time) { m_impacts->finish(time); }

bool HullContact::markLoadedNodes(std::vector<char>& mark) const {
  // The nodes of the elements within reach of a hull at the last whole assembly, and the hulls' vessel
  // nodes: a part of the model away from them gets no hull force (and moves none of them).
  for (std::size_t n = 0; n < m_nearNodes.size() && n < mark.size(); ++n)
    if (m_nearNodes[n]) mark[n] = 1;
  for (const Hull& h : m_hulls) mark[static_cast<std::size_t>(h.node)] = 1;
  return true;
}

std::string HullContact::describe() const {
  std::string out;
  for (const Hull& h : m_hulls) {
    out += fmt::format("hull of vessel '{}': {} shape(s), {} surface points, reach {:.1f} m\n",
                       m_model->vessels()[static_cast<std::size_t>(h.vessel)].name, h.shapes.size(),
                       h.points.size(), h.reach);
    for (const geometry::HullShape& s : h.shapes) out += "  " + s.describe() + "\n";
  }
  return out;
}

}  // namespace tangle::vessel
