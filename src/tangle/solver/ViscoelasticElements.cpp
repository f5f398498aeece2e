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
    if (const section::SyropeCurves* s = el.type->syrope.get()) {
      const element::WorkingCurveForm form =
          s->form == section::SyropeCurves::Form::Quadratic     ? element::WorkingCurveForm::Quadratic
          : s->form == section::SyropeCurves::Form::Exponential ? element::WorkingCurveForm::Exponential
                                                                : element::WorkingCurveForm::Linear;
      m_laws.emplace_back(
          element::SyropeAxialLaw({s->originalCurve, form, s->k1, s->k2, v.dynamicStiffness,
                                   v.dynamicStiffnessSlope, v.slowDamping, v.dynamicDamping}));
    } else {
      m_laws.emplace_back(
          element::ViscoelasticAxialLaw({el.type->axialStiffness, v.dynamicStiffness, v.dynamicStiffnessSlope,
                                         v.slowDamping, v.dynamicDamping}));
    }
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
  // The slack law's stiffness: the static EA (a SYROPE rope's: its static curve's largest slope).
  const double ea = m_model->elements()[m_elements[kk]].type->axialStiffness;
  const double dt = state.time - state.viscoelastic.time;
  // A rope cannot push: where the law's tension falls below the slack law's (compressed, or stretched less
  // than its lagging slow strain), the slack law holds: continuous where they cross (the cable's kink), also
  // at zero strain, where the dashpots may still pull a rope that is being stretched fast (as MoorDyn's
  // damping force acts whatever the stretch).
  const Axial slack{compressionFactor * ea * strain, compressionFactor * ea, 0.0};
  if (!(dt > 0.0)) return {state.viscoelastic.tension[kk], ea, 0.0};
  const double x0 = state.viscoelastic.slowStrain[kk];
  Axial law;
  if (const auto* syrope = std::get_if<element::SyropeAxialLaw>(&m_laws[kk])) {
    const element::SyropeAxialLaw::Step s =
        syrope->step(strain, strainRate, x0, state.viscoelastic.maxMeanTension[kk], dt);
    law = {s.tension, s.dTensionDStrain, s.dTensionDRate};
  } else {
    const element::ViscoelasticAxialLaw::Step s =
        std::get<element::ViscoelasticAxialLaw>(m_laws[kk]).step(strain, strainRate, x0, dt);
    law = {s.tension, s.dTensionDStrain, s.dTensionDRate};
  }
  return law.force > slack.force ? law : slack;
}

void ViscoelasticElements::commit(model::State& state) const {
  if (m_elements.empty()) return;
  model::State::Viscoelastic& v = state.viscoelastic;
  const bool first = v.slowStrain.size() != m_elements.size();
  const double dt = state.time - v.time;
  if (!first && !(dt > 0.0)) return;  // the same state again
  v.slowStrain.resize(m_elements.size());
  v.tension.resize(m_elements.size());
  v.meanTension.resize(m_elements.size(), 0.0);
  v.maxMeanTension.resize(m_elements.size(), 0.0);
  for (std::size_t k = 0; k < m_elements.size(); ++k) {
    double strain = 0.0, rate = 0.0;
    strainOf(m_elements[k], state, strain, rate);
    const section::LineType& type = *m_model->elements()[m_elements[k]].type;
    const double slack =
        type.compressionFactor * type.axialStiffness * strain;  // a compressed rope's tension
    if (const auto* syrope = std::get_if<element::SyropeAxialLaw>(&m_laws[k])) {
      if (first) {
        // Relaxed on the working curve of the initial Tmax: the statics' law (its sampled curve, the tension
        // the static solution is in balance with), the slow strain from the exact curve.
        const double tmax = type.syrope->initialMaxMeanTension;
        const double t = strain > 0.0 && type.tensionStrain ? type.tensionStrain->at(strain).value : 0.0;
        v.slowStrain[k] = syrope->slowStrain(t, tmax);
        v.meanTension[k] = t;
        v.maxMeanTension[k] = std::max(tmax, t);
        v.tension[k] = std::max(t, slack);
      } else {
        const element::SyropeAxialLaw::Step s =
            syrope->step(strain, rate, v.slowStrain[k], v.maxMeanTension[k], dt);
        v.slowStrain[k] = s.slowStrain;
        v.meanTension[k] = s.meanTension;
        v.maxMeanTension[k] = std::max(v.maxMeanTension[k], s.meanTension);
        v.tension[k] = std::max(s.tension, slack);
      }
      continue;
    }
    const auto& law = std::get<element::ViscoelasticAxialLaw>(m_laws[k]);
    if (first) {
      v.slowStrain[k] = law.relaxedSlowStrain(std::max(strain, 0.0));
      v.meanTension[k] = law.staticBranchStiffnessAt(v.slowStrain[k]) * v.slowStrain[k];
      v.tension[k] = std::max(law.constants().staticStiffness * strain, slack);
    } else {
      const double ea1 = law.staticBranchStiffnessAt(v.slowStrain[k]);  // lagged, as the step takes it
      const element::ViscoelasticAxialLaw::Step s = law.step(strain, rate, v.slowStrain[k], dt);
      v.slowStrain[k] = s.slowStrain;
      v.meanTension[k] = ea1 * s.slowStrain;
      v.tension[k] = std::max(s.tension, slack);
    }
  }
  v.time = state.time;
}

}  // namespace tangle::solver
