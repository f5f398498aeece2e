/// @file ViscoelasticElements.cpp
#include "tangle/solver/ViscoelasticElements.hpp"

#include <algorithm>

namespace tangle::solver {

ViscoelasticElements::ViscoelasticElements(const model::Model& model) : m_model(&model) {
  const auto& elements = model.elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const model::LineElement& el = elements[e];
    if (!el.bar || !el.type->viscoelastic.present()) continue;
    if (m_index.empty()) m_index.assign(elements.size(), -1);
    m_index[e] = static_cast<int>(m_elements.size());
    m_elements.push_back(e);
    const section::Viscoelasticity& v = el.type->viscoelastic;
    m_laws.emplace_back(element::ViscoelasticConstants{el.type->axialStiffness, v.dynamicStiffness,
                                                       v.dynamicStiffnessSlope, v.slowDamping,
                                                       v.dynamicDamping});
  }
}

void ViscoelasticElements::strainOf(std::size_t e, const model::State& state, double& strain,
                                    double& rate) const {
  const model::LineElement& el = m_model->elements()[e];
  const Vec3 chord = state.position[el.node2] - state.position[el.node1];
  const double l = chord.norm();
  strain = (l - el.restLength) / el.restLength;
  rate = 0.0;
  const int d1 = m_model->dofs().firstDof(el.node1), d2 = m_model->dofs().firstDof(el.node2);
  if (l > 0.0 && state.velocity.size() > std::max(d1, d2) + 2)
    rate = (chord / l).dot(state.velocity.segment<3>(d2) - state.velocity.segment<3>(d1)) / el.restLength;
}

ViscoelasticElements::Axial ViscoelasticElements::axial(int k, const model::State& state, double strain,
                                                        double strainRate, double compressionFactor) const {
  const std::size_t kk = static_cast<std::size_t>(k);
  const element::ViscoelasticAxialLaw& law = m_laws[kk];
  const double ea = law.constants().staticStiffness;
  const double dt = state.time - state.viscoelastic.time;
  if (strain < 0.0) return {compressionFactor * ea * strain, compressionFactor * ea, 0.0};
  if (!(dt > 0.0)) return {state.viscoelastic.tension[kk], ea, 0.0};
  const element::ViscoelasticAxialLaw::Step s =
      law.step(strain, strainRate, state.viscoelastic.slowStrain[kk], dt);
  return {s.tension, s.dTensionDStrain, s.dTensionDRate};
}

void ViscoelasticElements::commit(model::State& state) const {
  if (m_elements.empty()) return;
  model::State::Viscoelastic& v = state.viscoelastic;
  const bool first = v.slowStrain.size() != m_elements.size();
  const double dt = state.time - v.time;
  if (!first && !(dt > 0.0)) return;  // the same state again
  v.slowStrain.resize(m_elements.size());
  v.tension.resize(m_elements.size());
  for (std::size_t k = 0; k < m_elements.size(); ++k) {
    double strain = 0.0, rate = 0.0;
    strainOf(m_elements[k], state, strain, rate);
    const element::ViscoelasticAxialLaw& law = m_laws[k];
    const double compression = m_model->elements()[m_elements[k]].type->compressionFactor;
    if (first) {
      v.slowStrain[k] = law.relaxedSlowStrain(std::max(strain, 0.0));
      v.tension[k] = law.constants().staticStiffness * strain * (strain < 0.0 ? compression : 1.0);
    } else {
      const element::ViscoelasticAxialLaw::Step s = law.step(strain, rate, v.slowStrain[k], dt);
      v.slowStrain[k] = s.slowStrain;
      v.tension[k] = strain < 0.0 ? compression * law.constants().staticStiffness * strain : s.tension;
    }
  }
  v.time = state.time;
}

}  // namespace tangle::solver
