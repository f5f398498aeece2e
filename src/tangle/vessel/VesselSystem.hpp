#pragma once
/// @file VesselSystem.hpp
/// Floating units in the coupled analysis. Each vessel is a 6-DOF node (reference point position and
/// orientation). Fixed and prescribed vessels are held nodes whose motion is imposed; the line ends
/// on them are held nodes that follow the vessel point (plus the first-order RAO motion). A free
/// vessel is solved with its lines in the same implicit Newton iteration: its body loads (VesselLoads)
/// and 6x6 mass enter the global system, and each line end on it is tied to the vessel point by a
/// stiff link (penalty), or hangs from a tensioner (constant tension over a stroke, end stops), with an
/// optional flex joint (rotational spring) for beam lines.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tangle/hydro/HydroLoads.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/PrescribedMotion.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/vessel/RaoMotion.hpp"
#include "tangle/vessel/VesselLoads.hpp"

namespace tangle::vessel {

/// All vessels of a model and their connections to line ends.
class VesselSystem final : public solver::LoadContributor {
 public:
  VesselSystem(const model::Model& model, const hydro::HydroLoads& hydro);
  ~VesselSystem() override;

  void addForces(const model::State& state, const solver::AssemblyRequest& request, VecX& force,
                 solver::SystemMatrix* matrix) override;
  void addMass(const model::State& state, double mf, solver::SystemMatrix* matrix, const VecX* acceleration,
               VecX* out) override;
  /// Parts of the model away from the vessels leave this contributor out (its loads act at the vessel
  /// nodes and the line ends tied to them, which it marks).
  solver::LoadSource source() const override { return solver::LoadSource::Vessels; }
  bool supportsParts() const override { return true; }
  bool markLoadedNodes(std::vector<char>& mark) const override;
  /// The links' round-off (16 eps k |x|) at the line ends on free vessels and at the vessels' nodes.
  void raiseRoundoffFloor(const model::State& state, std::vector<double>& floor) const override;
  bool raisesRoundoffFloor() const override { return true; }

  /// Held nodes that move: prescribed vessels and the line ends on fixed/prescribed vessels (RAO motion).
  std::vector<model::PrescribedNode> prescribedNodes() const;

  /// Global position [m] of a vessel point given in vessel axes at a state (without RAO motion).
  Vec3 vesselPoint(const model::State& state, int vessel, const Vec3& offset) const;

  /// The wave-frequency (first-order RAO) motion of a vessel's reference point at time t [s], as its line
  /// ends get it (prescribedNodes for held vessels, addLink for free ones): translations [m] and small
  /// rotations [deg] about the global axes, added to the low-frequency pose of the vessel node. Empty where
  /// there is none: no RAOs or no waves.
  std::optional<std::array<double, 6>> waveFrequencyMotion(int vessel, double t) const;

  /// The vessels' contribution to the out-of-balance force at the line-end nodes (links and tensioners),
  /// full DOF vector; subtracting it from F leaves at those nodes the force of the line on the vessel.
  VecX endConnectionForces(const model::State& state, double time) const;

  /// State of one tensioner (issue 13: a tensioner resting on its stop must show in the results).
  struct TensionerReading {
    int line = 0;         ///< line index
    int end = 0;          ///< 0: end A, 1: end B
    double stroke = 0.0;  ///< displacement from mid-stroke along the tensioner axis, positive down/out [m]
    double halfStroke = 0.0;  ///< stroke / 2: |stroke| beyond it rests on an end stop [m]
    double force = 0.0;       ///< force of the tensioner on the line end along its axis [N]
    double stopForce =
        0.0;  ///< part of `force` carried by the end stop (force - gas-spring force T + k_g s) [N]
  };
  /// The tensioners' strokes and forces at a state.
  std::vector<TensionerReading> tensionerReadings(const model::State& state, double time) const;

  /// What acts on one vessel, for the equilibrium audit (analysis/EquilibriumAudit).
  struct VesselLoadReading {
    std::string name;
    int node = 0;       ///< the vessel's node
    bool free = false;  ///< solved for (VesselMode::Free); otherwise held, and its balance is a reaction
    bool pinned =
        false;  ///< free but its translations held (VesselSpec::pinned): its force balance is a reaction
    /// Body loads (current, wind, wave drift, hydrostatics, damping), force [N] and moment about the
    /// reference point [N m], global axes (VesselLoads::loads).
    Vec6 body = Vec6::Zero();
    /// The station-keeping springs of a vessel held in statics (VesselSpec::heldInStatics) [N, N m].
    Vec6 hold = Vec6::Zero();
    std::vector<int> endNodes;  ///< line end nodes tied to it
  };
  /// The loads on every vessel at `state` (request.dynamic: with velocities).
  std::vector<VesselLoadReading> loadReadings(const model::State& state,
                                              const solver::AssemblyRequest& request) const;

  /// True when the model has any vessel.
  bool empty() const { return m_vessels.empty(); }

 private:
  struct Connection {
    int vessel = 0;
    int node = 0;                ///< line end node
    Vec3 offset;                 ///< fairlead in vessel axes [m]
    double linkStiffness = 0.0;  ///< [N/m]
    model::TensionerSpec tensioner;
    double flexStiffness = 0.0;  ///< [N m/rad] (0: no rotational coupling)
    /// Extra stiffness against twisting about the end's axis (the triad's first axis) [N m/rad]: a pinned
    /// end on a vessel is free to bend, not to spin.
    double twistStiffness = 0.0;
    Mat3 endTriad0 = Mat3::Identity();  ///< triad of the end node at t = 0
  };
  struct VesselData {
    const model::VesselSpec* spec = nullptr;
    int node = 0;
    Vec3 position0;
    Mat3 rotation0;
    std::unique_ptr<VesselLoads> loads;
    std::unique_ptr<RaoMotion> rao;  ///< nullptr without RAOs or waves
  };

  /// Body loads on a free vessel at `state` (VesselLoads::loads with its current; velocities in dynamics).
  BodyLoad bodyLoad(const model::State& state, const VesselData& d,
                    const solver::AssemblyRequest& request) const;
  /// Force and moment of the station-keeping springs of a vessel held in statics, on the vessel [N, N m].
  Vec6 holdLoad(const model::State& state, const VesselData& d) const;
  /// Pose (position, rotation) and 6-velocity/acceleration of a non-free vessel at time t.
  model::MotionValue prescribedPose(int vessel, double t) const;
  /// RAO displacement/velocity/acceleration of a vessel point (vessel axes offset) at t.
  model::MotionValue raoPointMotion(int vessel, const Mat3& rotation, const Vec3& offset, double t) const;
  void addLink(const model::State& state, const Connection& c, const solver::AssemblyRequest& request,
               VecX& force, solver::SystemMatrix* matrix) const;
  void addFlexJoint(const model::State& state, const Connection& c, const solver::AssemblyRequest& request,
                    VecX& force, solver::SystemMatrix* matrix) const;

  const model::Model* m_model;
  const hydro::HydroLoads* m_hydro;
  std::vector<VesselData> m_vessels;
  std::vector<Connection> m_connections;
  /// The waves' mean drift per direction of travel: amplitude squared [m^2] (a^2 of a regular wave, 2 m0 of
  /// a spectrum, the sum of a_i^2 of the components) and azimuth [rad] (VesselLoads::addWaveDrift).
  struct DriftDirection {
    double amplitudeSquared = 0.0;
    double azimuth = 0.0;
  };
  std::vector<DriftDirection> m_drift;
  double m_rampTime = 0.0;
};

}  // namespace tangle::vessel
