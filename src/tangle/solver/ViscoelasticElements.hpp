#pragma once
/// @file ViscoelasticElements.hpp
/// The bar elements of viscoelastic ropes (section::Viscoelasticity, section::SyropeCurves) and their
/// internal variables: the slow strain each carries from one committed dynamic state to the next
/// (model::State::viscoelastic), the tension and its tangent at a trial state, and the commit. The statics
/// uses the ropes' static EA (the rope relaxed); the dynamics starts from the relaxed slow strain of the
/// static solution (docs/theory.md 3.6).

#include <variant>
#include <vector>

#include "tangle/element/SyropeAxialLaw.hpp"
#include "tangle/element/ViscoelasticAxialLaw.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::solver {

class ViscoelasticElements {
 public:
  explicit ViscoelasticElements(const model::Model& model);

  /// True when the model has no viscoelastic element.
  bool empty() const { return m_elements.empty(); }
  /// Element e's number among the viscoelastic ones, or -1.
  int index(std::size_t e) const { return m_index.empty() ? -1 : m_index[e]; }
  /// True when `state` carries the internal variables (a dynamic state after the first commit).
  bool active(const model::State& state) const {
    return !m_elements.empty() && state.viscoelastic.slowStrain.size() == m_elements.size();
  }

  /// The axial force of viscoelastic element k at `state` (strain eps [-], strain rate eps' [1/s]) and its
  /// derivatives: a backward-Euler step from the committed slow strain over state.time - its time; at the
  /// committed time itself, the committed tension. A compressed rope (eps < 0) follows its slack law,
  /// compressionFactor x EA eps, with its slow strain still integrated. Requires active(state).
  struct Axial {
    double force;      ///< N [N]
    double stiffness;  ///< dN / d eps [N]
    double damping;    ///< dN / d eps' [N s]
  };
  Axial axial(int k, const model::State& state, double strain, double strainRate,
              double compressionFactor) const;

  /// axial()'s force of viscoelastic element k at `state`, its strain and rate from the state (the tension
  /// the results report). Requires active(state).
  double tension(int k, const model::State& state, double compressionFactor) const {
    double strain = 0.0, rate = 0.0;
    strainOf(m_elements[static_cast<std::size_t>(k)], state, strain, rate);
    return axial(k, state, strain, rate, compressionFactor).force;
  }

  /// A committed state: the first (the static solution, or the first dynamic state) sets each slow strain to
  /// the relaxed one at its strain; a later one (dt > 0) steps them from the previous commit to `state`.
  void commit(model::State& state) const;

 private:
  /// Strain and strain rate of element e at `state` (rate 0 without velocities).
  void strainOf(std::size_t e, const model::State& state, double& strain, double& rate) const;
  const model::Model* m_model;
  std::vector<int> m_index;             // per element: its number k, or -1
  std::vector<std::size_t> m_elements;  // per k: the element
  std::vector<std::variant<element::ViscoelasticAxialLaw, element::SyropeAxialLaw>> m_laws;  // per k
};

}  // namespace tangle::solver
