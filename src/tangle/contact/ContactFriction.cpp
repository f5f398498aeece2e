/// @file ContactFriction.cpp
/// Coulomb friction between lines with stick and slip, in statics and dynamics (docs/theory.md 9.8).
///
/// Per contact patch of one slave element (line A) with one master line B: an anchor ties a material
/// point of A (arc length sA) to a material point of B (sB) plus an offset fixed at the last commit. The
/// trial tangential offset delta_t = (I - n n)(x_A(sA) - x_B(sB) - offset) is resisted by an elastic
/// stick spring k_t per unit length (regularised stick: the stick displacement mu f_n / k_t is of the
/// order of mu times the penetration); if k_t |delta_t| exceeds mu f_n the patch slips: the force is
/// mu f_n in the direction of delta_t and the anchor is moved back onto the slip surface (return map).
/// addForces() only computes the trial anchor; commitIncrement()/commitStep() make it the committed one, so
/// rejected iterations or steps need no revert. Friction of the point-to-point part (large crossing
/// angles): in statics the same elastic stick and slip per point contact (its stick spring the contact's
/// point stiffness, its limit mu F_n; issue 29: a line resting across another was held by nothing in
/// statics); in dynamics the velocity-regularised law of LineContact::findContacts.

#include <algorithm>
#include <cmath>
#include <map>

#include "tangle/contact/LineContact.hpp"

namespace tangle::contact {

void LineContact::addFriction(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                              solver::SystemMatrix* matrix) {
  m_patches.clear();
  const double mu = m_spec.frictionCoefficient;
  if (!(mu > 0.0)) return;
  // Group the Gauss points by (slave element, master line).
  std::map<std::pair<int, int>, std::vector<const LineSample*>> groups;
  for (const LineSample& s : m_samples)
    if (s.lineForce > 0.0) groups[{s.elementA, s.lineB}].push_back(&s);
  for (const auto& [key, samples] : groups) {
    FrictionPatch patch;
    patch.lineA = samples.front()->lineA;
    patch.lineB = key.second;
    patch.elementA = key.first;
    double load = 0.0, arcA = 0.0, arcB = 0.0;
    Vec3 n = Vec3::Zero();
    for (const LineSample* s : samples) {
      patch.length += s->length;
      load += s->lineForce * s->length;
      arcA += s->arcA * s->length;
      arcB += s->arcB * s->length;
      n += s->lineForce * s->length * s->normal;
    }
    if (!(patch.length > 0.0) || n.norm() <= 0.0) continue;
    patch.normalLoad = load / patch.length;
    patch.normal = n.normalized();
    arcA /= patch.length;
    arcB /= patch.length;
    const double kt = lineStiffness(samples.front()->elementA, samples.front()->elementB);
    stickSlip(state, request, key, arcA, arcB, kt, mu * patch.normalLoad, m_anchors, m_pendingAnchors, patch, force,
              matrix);
    m_patches.push_back(patch);
  }
}

void LineContact::stickSlip(const model::State& state, const solver::AssemblyRequest& request,
                            const std::pair<int, int>& key, double arcA, double arcB, double kt, double limit,
                            const std::map<std::pair<int, int>, FrictionAnchor>& anchors,
                            std::map<std::pair<int, int>, FrictionAnchor>& pending, FrictionPatch& patch,
                            VecX& force, solver::SystemMatrix* matrix) const {
  const auto& elements = m_model->elements();
  const model::DofMap& dofs = m_model->dofs();
  // Committed anchor; or the one this patch got when it first touched in this step's (or static
  // solve's) iterations; or a new one at the patch's centre with no elastic offset, kept for the
  // following iterations (an anchor renewed at every iterate would never resist).
  const FrictionAnchor* existing = nullptr;
  if (auto it = anchors.find(key); it != anchors.end()) {
    existing = &it->second;
  } else if (auto jt = pending.find(key); jt != pending.end()) {
    existing = &jt->second;
  }
  const bool fresh = existing == nullptr;
  FrictionAnchor anchor;
  auto [elA, wA] = pointAtArc(patch.lineA, fresh ? arcA : existing->arcA);
  auto [elB, wB] = pointAtArc(patch.lineB, fresh ? arcB : existing->arcB);
  const model::LineElement& ea = elements[elA];
  const model::LineElement& eb = elements[elB];
  const Vec3 xa = (1.0 - wA) * state.position[ea.node1] + wA * state.position[ea.node2];
  const Vec3 xb = (1.0 - wB) * state.position[eb.node1] + wB * state.position[eb.node2];
  if (fresh) {
    anchor.arcA = arcA;
    anchor.arcB = arcB;
    anchor.offset = xa - xb;
    pending[key] = anchor;
  } else {
    anchor = *existing;
  }
  const Mat3 tp = Mat3::Identity() - patch.normal * patch.normal.transpose();
  Vec3 delta = tp * (xa - xb - anchor.offset);
  const double trialNorm = kt * delta.norm();
  Mat3 stiffness3 = kt * tp;
  if (trialNorm > limit && trialNorm > 0.0) {
    patch.slipping = true;
    const Vec3 dir = delta.normalized();
    const double elastic = limit / kt;
    // Return map: the anchor follows so that the elastic offset is back on the slip surface.
    anchor.offset += (delta.norm() - elastic) * dir;
    delta = elastic * dir;
    stiffness3 = limit / trialNorm * kt * (tp - dir * dir.transpose());
  }
  patch.elastic = delta;
  patch.trial = anchor;
  patch.force = -kt * delta * patch.length;  // on A
  patch.nodeA[0] = ea.node1;
  patch.nodeA[1] = ea.node2;
  patch.nodeB[0] = eb.node1;
  patch.nodeB[1] = eb.node2;
  patch.wA = wA;
  patch.wB = wB;
  const int node[4] = {ea.node1, ea.node2, eb.node1, eb.node2};
  const double w[4] = {1.0 - wA, wA, -(1.0 - wB), -wB};
  for (int i = 0; i < 4; ++i) force.segment<3>(dofs.firstDof(node[i])) -= w[i] * patch.force;
  if (matrix) {
    const Mat3 block = request.kf * patch.length * stiffness3;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        matrix->add3x3(dofs.firstDof(node[i]), dofs.firstDof(node[j]), block, w[i] * w[j]);
  }
}

void LineContact::addPointFriction(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                                   solver::SystemMatrix* matrix) {
  const double mu = m_spec.frictionCoefficient;
  if (!(mu > 0.0) || request.dynamic) return;
  for (const ContactPoint& c : m_trial) {
    if (!(c.normalForce > 0.0)) continue;
    FrictionPatch patch;
    patch.lineA = c.lineA;
    patch.lineB = c.lineB;
    patch.elementA = c.elementA;
    patch.point = true;
    patch.elementB = c.elementB;  // the two feet of a fold share an element of A: keyed by both elements
    patch.length = 1.0;  // a point: the stick spring and the limit are forces, not per length
    patch.normalLoad = c.normalForce;
    patch.normal = c.normal;
    stickSlip(state, request, {c.elementA, c.elementB}, c.arcA, c.arcB, c.stiffness, mu * c.normalForce,
              m_pointAnchors, m_pendingPointAnchors, patch, force, matrix);
    m_patches.push_back(patch);
  }
}

void LineContact::commitFriction() {
  // Re-anchor every patch at its trial anchor; patches no longer in contact lose their anchor.
  std::map<std::pair<int, int>, FrictionAnchor> next, nextPoint;
  for (const FrictionPatch& p : m_patches) {
    if (p.point) {
      nextPoint[{p.elementA, p.elementB}] = p.trial;
    } else {
      next[{p.elementA, p.lineB}] = p.trial;
    }
  }
  m_anchors = std::move(next);
  m_pointAnchors = std::move(nextPoint);
  m_pendingAnchors.clear();
  m_pendingPointAnchors.clear();
}

}  // namespace tangle::contact
