#pragma once
/// @file EnergyAccount.hpp
/// The energy account of a dynamic run (theory manual 8.6): the kinetic energy of the lines and vessels
/// (with added mass) and, integrated over every accepted step by the trapezoidal rule, the work done on them
/// by each source: internal elastic forces (minus the strain energy), structural damping, weight and
/// buoyancy, hydrodynamic loads, the seabed, contact, vessels' own loads and links, and the supports (held
/// and prescribed ends). By the equation of motion the kinetic energy's change equals the total work; what
/// is left is the integrator's numerical dissipation (generalized-alpha damps high frequencies) and the
/// error of the time discretisation. A residual that grows the energy, or exceeds a few percent of the
/// energy that flowed, is a result to doubt.

#include <string>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/State.hpp"

namespace tangle::analysis {

class Simulation;

/// Energy totals since the start of the dynamics [J] (work done ON the lines and vessels: positive adds
/// energy).
struct EnergyTotals {
  double time = 0.0;                 ///< [s]
  double kinetic = 0.0;              ///< kinetic energy now [J]
  double kineticChange = 0.0;        ///< kinetic energy now minus at the start [J]
  std::vector<std::pair<std::string, double>> work;  ///< work of each source since the start [J]
  double residual = 0.0;             ///< kineticChange - sum of work [J] (< 0: dissipated numerically)
  double throughput = 0.0;           ///< sum over sources and steps of |work increment|: the energy that flowed [J]
};

class EnergyAccount {
 public:
  /// Residual, relative to the energy that flowed, above which the account does not close [-]. Smooth
  /// runs leave 1e-7 to 1e-5 (the mooring example, EnergyAccountTest: the numerical dissipation of
  /// generalized-alpha is small where the motion is resolved); 5 % is far above that and flags what the
  /// integrator did not balance (velocity jumps of impulse contacts, a source missing from the account).
  static constexpr double kTolerance = 0.05;

  explicit EnergyAccount(Simulation& simulation);
  /// The dynamics starts at `state` (after statics).
  void start(const model::State& state);
  /// An accepted step of length dt [s] ended at `state`.
  void step(const model::State& state, double dt);
  const EnergyTotals& totals() const { return m_totals; }
  /// Empty when the account closes, else why not.
  std::string warning() const;

 private:
  /// Power of each source [W] and the kinetic energy [J] at `state`.
  void powers(const model::State& state, std::vector<double>& power, double& kinetic);

  Simulation* m_simulation;
  std::vector<std::string> m_names;
  std::vector<double> m_lastPower;
  double m_startKinetic = 0.0;
  EnergyTotals m_totals;
  std::vector<double> m_work;
};

}  // namespace tangle::analysis
