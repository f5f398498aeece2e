#include "tangle/solver/Assembler.hpp"

#include <algorithm>
#include <cmath>

#include "tangle/seabed/FlatSeabed.hpp"

namespace tangle::solver {

namespace {
/// Fraction of a segment between heights z1 and z2 [m] that lies below still water (z = 0).
double submergedFraction(double z1, double z2) {
  if (z1 <= 0.0 && z2 <= 0.0) return 1.0;
  if (z1 >= 0.0 && z2 >= 0.0) return 0.0;
  const double below = z1 < 0.0 ? -z1 : -z2;
  return below / std::abs(z2 - z1);
}
}  // namespace

Assembler::Assembler(const model::Model& model) : m_model(&model) {
  const auto& env = model.environment();
  for (const auto& el : model.elements()) {
    const double w = std::abs(el.type->submergedWeight(env.waterDensity, env.gravity)) * el.restLength;
    const double wAir = el.type->massPerLength * env.gravity * el.restLength;
    m_referenceForce = std::max({m_referenceForce, w, 0.1 * wAir});
    m_roundoffForce = std::max(m_roundoffForce, 1e-14 * el.type->axialStiffness);
  }
}

void Assembler::assemble(const model::State& state, const AssemblyRequest& request, VecX& force,
                         SystemMatrix* matrix) {
  force.setZero(m_model->dofs().fullDofCount());
  if (matrix) matrix->clear();
  SystemMatrix* m = request.wantMatrix ? matrix : nullptr;
  addElements(state, request, force, m);
  addWeight(state, request, force);
  addSeabed(state, request, force, m);
  for (LoadContributor* c : m_contributors) c->addForces(state, request, force, m);
}

void Assembler::addElements(const model::State& state, const AssemblyRequest& request, VecX& force,
                            SystemMatrix* matrix) {
  const model::DofMap& dofs = m_model->dofs();
  const double beta = request.dynamic ? m_model->spec().dynamics.rayleighBeta : 0.0;
  for (const model::LineElement& el : m_model->elements()) {
    const int d1 = dofs.firstDof(el.node1);
    const int d2 = dofs.firstDof(el.node2);
    if (el.bar) {
      Vec6 f;
      Mat6 k;
      el.bar->compute(state.position[el.node1], state.position[el.node2], f, k);
      const int map[6] = {d1, d1 + 1, d1 + 2, d2, d2 + 1, d2 + 2};
      if (beta > 0.0) {
        Vec6 v;
        for (int i = 0; i < 6; ++i) v[i] = state.velocity[map[i]];
        f += beta * k * v;
      }
      for (int i = 0; i < 6; ++i) force[map[i]] += f[i];
      if (matrix) matrix->addBlock(map, 6, k, request.kf + request.cf * beta);
      if (request.dynamic && el.type->axialDamping > 0.0) addAxialDamping(state, el, d1, d2, request, force, matrix);
    } else {
      Vec12 f;
      Mat12 k;
      el.beam->compute(state.position[el.node1], state.triad[el.node1], state.position[el.node2],
                       state.triad[el.node2], f, matrix || beta > 0.0 ? &k : nullptr);
      const int map[12] = {d1, d1 + 1, d1 + 2, d1 + 3, d1 + 4, d1 + 5, d2, d2 + 1, d2 + 2, d2 + 3, d2 + 4, d2 + 5};
      if (beta > 0.0) {
        Vec12 v;
        for (int i = 0; i < 12; ++i) v[i] = state.velocity[map[i]];
        f += beta * k * v;
      }
      for (int i = 0; i < 12; ++i) force[map[i]] += f[i];
      if (matrix) matrix->addBlock(map, 12, k, request.kf + request.cf * beta);
      if (request.dynamic && el.type->axialDamping > 0.0) addAxialDamping(state, el, d1, d2, request, force, matrix);
    }
  }
}

void Assembler::addAxialDamping(const model::State& state, const model::LineElement& el, int d1, int d2,
                                const AssemblyRequest& request, VecX& force, SystemMatrix* matrix) const {
  // Structural axial damping: N_d = c * strain rate = c e.(v2 - v1) / L0 (c = LineType::axialDamping [N s]),
  // acting along the chord e (as OrcaFlex's axial damping and MoorDyn's internal damping).
  const Vec3 chord = state.position[el.node2] - state.position[el.node1];
  const Vec3 e = chord.normalized();
  const double c = el.type->axialDamping / el.restLength;
  const double nd = c * e.dot(state.velocity.segment<3>(d2) - state.velocity.segment<3>(d1));
  force.segment<3>(d1) -= nd * e;
  force.segment<3>(d2) += nd * e;
  if (matrix && request.cf != 0.0) {
    const Mat3 ee = c * e * e.transpose();
    matrix->add3x3(d1, d1, ee, request.cf);
    matrix->add3x3(d2, d2, ee, request.cf);
    matrix->add3x3(d1, d2, ee, -request.cf);
    matrix->add3x3(d2, d1, ee, -request.cf);
  }
}

void Assembler::addWeight(const model::State& state, const AssemblyRequest& request, VecX& force) {
  const model::DofMap& dofs = m_model->dofs();
  const auto& env = m_model->environment();
  const double g = env.gravity;
  const double rho = env.waterDensity;
  for (const model::LineElement& el : m_model->elements()) {
    const double frac = submergedFraction(state.position[el.node1].z(), state.position[el.node2].z());
    const double weight =
        (el.type->massPerLength - rho * el.type->displacedAreaPerLength() * frac) * g * el.restLength;
    // Out-of-balance force: F = f_int - f_ext, and the external load is -weight/2 * z at each node.
    force[dofs.firstDof(el.node1) + 2] += 0.5 * weight * request.loadFactor;
    force[dofs.firstDof(el.node2) + 2] += 0.5 * weight * request.loadFactor;
  }
  for (const model::NodeAttachment& a : m_model->attachments()) {
    const double submerged = state.position[a.node].z() < 0.0 ? 1.0 : 0.0;
    const double weight = (a.spec.mass - rho * a.spec.volume * submerged) * g;
    force[dofs.firstDof(a.node) + 2] += weight * request.loadFactor;
  }
}

void Assembler::addSeabed(const model::State& state, const AssemblyRequest& request, VecX& force,
                          SystemMatrix* matrix) {
  const model::DofMap& dofs = m_model->dofs();
  const auto& env = m_model->environment();
  const seabed::FlatSeabed bed(env.seabed, env.waterDepth);
  const auto& trib = m_model->tributaryLength();
  const auto& diameter = m_model->nodeContactDiameter();
  for (int n = 0; n < m_model->nodeCount(); ++n) {
    const int d = dofs.firstDof(n);
    const Vec3 v = state.velocity.segment<3>(d);
    const seabed::SeabedNodeReaction r = bed.reaction(state.position[n], v, trib[n], 0.5 * diameter[n], request.dynamic);
    if (r.penetration <= 0.0) continue;
    force.segment<3>(d) -= r.force;
    if (matrix) {
      matrix->add3x3(d, d, r.stiffness, request.kf);
      if (request.cf != 0.0) matrix->add3x3(d, d, r.damping, request.cf);
    }
  }
}

void Assembler::addMass(const model::State& state, double mf, SystemMatrix* matrix, const VecX* acceleration,
                        VecX* out) {
  const model::DofMap& dofs = m_model->dofs();
  const auto& mass = m_model->nodeMass();
  const auto& inertia = m_model->nodeRotationalInertia();
  const bool consistent = !m_model->spec().dynamics.lumpedMass;
  if (consistent) {
    // Consistent translational mass of each element (linear shape functions: m L / 6 [2 1; 1 2],
    // e.g. Cook et al. 2002, "Concepts and applications of FE analysis", sec. 11.3); attachments stay
    // point masses; rotational inertia stays lumped.
    for (const model::LineElement& el : m_model->elements()) {
      const double m = el.type->massPerLength * el.restLength;
      const int d1 = dofs.firstDof(el.node1), d2 = dofs.firstDof(el.node2);
      for (int k = 0; k < 3; ++k) {
        if (matrix) {
          matrix->add(d1 + k, d1 + k, mf * m / 3.0);
          matrix->add(d2 + k, d2 + k, mf * m / 3.0);
          matrix->add(d1 + k, d2 + k, mf * m / 6.0);
          matrix->add(d2 + k, d1 + k, mf * m / 6.0);
        }
        if (out) {
          (*out)[d1 + k] += m / 3.0 * (*acceleration)[d1 + k] + m / 6.0 * (*acceleration)[d2 + k];
          (*out)[d2 + k] += m / 6.0 * (*acceleration)[d1 + k] + m / 3.0 * (*acceleration)[d2 + k];
        }
      }
    }
    for (const model::NodeAttachment& a : m_model->attachments()) {
      const int d = dofs.firstDof(a.node);
      for (int k = 0; k < 3; ++k) {
        if (matrix) matrix->add(d + k, d + k, mf * a.spec.mass);
        if (out) (*out)[d + k] += a.spec.mass * (*acceleration)[d + k];
      }
    }
  }
  for (int n = 0; n < m_model->nodeCount(); ++n) {
    const int d = dofs.firstDof(n);
    for (int k = 0; k < 3 && !consistent; ++k) {
      if (matrix) matrix->add(d + k, d + k, mf * mass[n]);
      if (out) (*out)[d + k] += mass[n] * (*acceleration)[d + k];
    }
    if (dofs.hasRotations(n)) {
      for (int k = 3; k < 6; ++k) {
        if (matrix) matrix->add(d + k, d + k, mf * inertia[n]);
        if (out) (*out)[d + k] += inertia[n] * (*acceleration)[d + k];
      }
    }
  }
  for (const model::NodeAttachment& a : m_model->attachments()) {
    const int d = dofs.firstDof(a.node);
    for (int k = 0; k < 3; ++k) {
      if (matrix) matrix->add(d + k, d + k, mf * a.spec.addedMass);
      if (out) (*out)[d + k] += a.spec.addedMass * (*acceleration)[d + k];
    }
  }
  for (LoadContributor* c : m_contributors) c->addMass(state, mf, matrix, acceleration, out);
}

std::vector<double> Assembler::elementTension(const model::State& state) const {
  std::vector<double> t;
  t.reserve(m_model->elements().size());
  for (const model::LineElement& el : m_model->elements()) {
    if (el.bar) {
      t.push_back(el.bar->axialForce(state.position[el.node1], state.position[el.node2]));
    } else {
      t.push_back(el.beam
                      ->sectionForces(state.position[el.node1], state.triad[el.node1], state.position[el.node2],
                                      state.triad[el.node2])
                      .axialForce);
    }
  }
  return t;
}

}  // namespace tangle::solver
