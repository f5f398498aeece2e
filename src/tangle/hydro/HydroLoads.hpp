#pragma once
/// @file HydroLoads.hpp
/// Hydrodynamic loads on every line element: Morison drag, fluid inertia and added mass from the
/// current profile and the wave field (relative-velocity form), with the current reduced in the wake of
/// upstream lines where the model asks for wake interference (WakeInterference.hpp). In statics only the current acts
/// (structure at rest); in dynamics waves are ramped in over the ramp time.

#include <memory>
#include <vector>

#include "tangle/hydro/CurrentProfile.hpp"
#include "tangle/hydro/Morison.hpp"
#include "tangle/hydro/WakeInterference.hpp"
#include "tangle/hydro/WaveField.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::hydro {

/// Builds the wave field of a model (nullptr when there are no waves).
std::unique_ptr<WaveField> makeWaveField(const model::EnvironmentSpec& environment);
/// Builds the current profile of a model.
CurrentProfile makeCurrentProfile(const model::EnvironmentSpec& environment);

/// Morison loads of all elements, as a LoadContributor.
/// Wave kinematics are evaluated once per time value at the element midpoints (re-used by the
/// Newton iterations of a step: the lines move by much less than a wavelength within one step).
/// Contract: addMass() uses the added mass computed by the last addForces() call (the integrator
/// always calls them in that order at the same state).
class HydroLoads final : public solver::LoadContributor {
 public:
  explicit HydroLoads(const model::Model& model);

  void addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                 solver::SystemMatrix* matrix) override;
  void addMass(const model::State& state, double mf, solver::SystemMatrix* matrix, const VecX* acceleration,
               VecX* out) override;
  /// Local to elements and attachments but for wakes (a wake couples an element with those upstream).
  solver::LoadSource source() const override { return solver::LoadSource::Hydrodynamic; }
  bool supportsParts() const override { return !m_wake; }
  void addPartForces(const model::State& state, const solver::AssemblyRequest& request,
                     const solver::AssemblyPart& part, VecX& force, solver::SystemMatrix* matrix) override;
  void addPartMass(const model::State& state, const solver::AssemblyPart& part, double mf,
                   solver::SystemMatrix* matrix, const VecX* acceleration, VecX* out) override;

  /// Total fluid kinematics (current + ramped waves) at a point [m] and time [s].
  FluidKinematics fluidAt(const Vec3& p, double t, bool dynamic) const;
  /// Surface elevation (ramped) at (x, y) [m] and time [s].
  double surfaceAt(double x, double y, double t, bool dynamic) const;
  const WaveField* waves() const { return m_waves.get(); }  ///< nullptr without waves
  /// Wave kinematics given per model node by a host program (MoorDyn's external wave kinematics,
  /// MoorDyn_ExternalWaveKinSet; docs/moordyn.md): fluid velocity [m/s] and acceleration [m/s^2] at every
  /// node, used in the dynamics instead of the model's waves (the current is added) until cleared; each
  /// element takes the mean of its two nodes, the surface is still water (z = 0), nothing is ramped.
  /// Attachments see the current only. @throws Error when the sizes are not the model's node count
  void setNodeKinematics(std::vector<Vec3> velocity, std::vector<Vec3> acceleration);
  void clearNodeKinematics();
  /// The wake at every element from the last addForces() call (empty without wake_interference).
  const std::vector<ElementWake>& elementWake() const { return m_elementWake; }

 private:
  /// Fills the wave kinematics cache for request.time if waves act (returns whether they do).
  bool prepareWaves(const model::State& state, const solver::AssemblyRequest& request);
  // The loops of addForces and addMass, over the listed elements (attachments) or all of them.
  void addElementForces(const model::State& state, const solver::AssemblyRequest& request, bool waves,
                        VecX& force, solver::SystemMatrix* matrix, const std::vector<int>* elements);
  void addAttachmentDrag(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                         solver::SystemMatrix* matrix, const std::vector<int>* attachments) const;
  void addElementMass(double mf, solver::SystemMatrix* matrix, const VecX* acceleration, VecX* out,
                      const std::vector<int>* elements) const;

  const model::Model* m_model;
  CurrentProfile m_current;
  std::unique_ptr<WaveField> m_waves;
  double m_rampTime;
  double m_cacheTime = -1e300;
  bool m_cacheDynamic = false;
  std::vector<FluidKinematics> m_fluid;  // per element, at the cached time
  std::vector<double> m_surface;         // per element
  std::vector<Vec3> m_nodeVelocity, m_nodeAcceleration;  // setNodeKinematics (empty: the model's waves)
  std::vector<AddedMass> m_addedMass;    // per element, per node
  // Morison coefficients per line type (validated once, at construction) and each element's index into
  // them: a few entries that stay in cache, not one per element.
  std::vector<MorisonCoefficients> m_coefficients;
  std::vector<int> m_coefficientIndex;
  std::unique_ptr<WakeInterference> m_wake;  // nullptr without wake_interference
  std::vector<ElementWake> m_elementWake;    // per element, from the last addForces()
};

}  // namespace tangle::hydro
