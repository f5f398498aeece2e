#pragma once
/// @file SyropeAxialLaw.hpp
/// The SYROPE model of a polyester rope (Falkenberg, Yang & Chen 2017, "Characterization of fibre rope
/// properties for mooring design", OMAE2017-61336; as MoorDyn v2.7 builds it, Line.cpp): the rope's mean
/// tension follows a *working curve* fixed by the largest mean tension it has seen, Tmax, below Tmax and the
/// *original working curve* (OWC, the first loading) above it; its fast response is a dynamic spring of
/// stiffness alpha + beta T_mean in series, with dashpots.
///
/// With the mean tension T, the total strain on the curve X(T) (the working curve's inverse, or the OWC's),
/// the dynamic strain e_d(T) = ln(1 + beta T / alpha) / beta (the integral of dT / (alpha + beta T)) and the
/// slow strain x = Z(T) = X(T) - e_d(T), the internal variable, MoorDyn's rate law is
///   (BA + BA_d) x' = (eps - X(T)) (alpha + beta T) + BA_d eps',   N = T + BA x'.
/// Working curve of Tmax (MoorDyn's setWorkingCurve): eps_max = X_owc(Tmax), eps_min = eps_0 + k1 (eps_max -
/// eps_0) (linear with k1 >= 1: eps_max - Tmax / k1), xi = (eps - eps_min) / (eps_max - eps_min) in [0, 1]
/// and T = Tmax xi (linear), Tmax xi (k2 xi + 1 - k2) (quadratic), Tmax (1 - exp(k2 xi)) / (1 - exp(k2))
/// (exponential), inverted here in closed form (MoorDyn tabulates it). Below eps_min the rope is slack (T =
/// 0). A step integrates x by backward Euler (the mean tension is the unknown: a safeguarded scalar Newton),
/// Tmax held at its committed value. Immutable; thread-safe.

#include <memory>

#include "tangle/core/PiecewiseLinear.hpp"

namespace tangle::element {

enum class WorkingCurveForm { Linear, Quadratic, Exponential };

struct SyropeConstants {
  /// The OWC: tension [N] against strain [-], both increasing, from a point of zero tension.
  std::shared_ptr<const core::PiecewiseLinear> originalCurve;
  WorkingCurveForm form = WorkingCurveForm::Linear;
  double k1 = 0.0;  ///< the working curve's first parameter [-] (linear, k1 >= 1: its slope [N])
  double k2 = 0.0;  ///< its second parameter [-]
  double dynamicStiffness = 0.0;       ///< alpha [N] (MoorDyn's alphaMBL), > 0
  double dynamicStiffnessSlope = 0.0;  ///< beta [-] (vbeta), >= 0
  double slowDamping = 0.0;            ///< BA [N s], > 0
  double dynamicDamping = 0.0;         ///< BA_d [N s], >= 0
};

class SyropeAxialLaw {
 public:
  /// @throws tangle::Error for a curve that does not start at zero tension or does not increase, parameters
  ///         out of range, or a slow strain that does not increase along the OWC (MoorDyn's check)
  explicit SyropeAxialLaw(SyropeConstants constants);

  /// The total strain X(T) [-] on the working curve of `maxTension` (T <= Tmax) or the OWC (T > Tmax), and
  /// dX/dT [1/N].
  struct CurveStrain {
    double strain;
    double slope;
  };
  CurveStrain curveStrain(double tension, double maxTension) const;
  /// The dynamic strain e_d(T) [-].
  double dynamicStrain(double tension) const;
  /// The mean tension in equilibrium at total strain eps (both dashpots at rest) [N]: X^-1(eps), 0 where
  /// slack.
  double staticTension(double strain, double maxTension) const;
  /// The slow strain Z(T) = X(T) - e_d(T) [-].
  double slowStrain(double tension, double maxTension) const {
    return curveStrain(tension, maxTension).strain - dynamicStrain(tension);
  }
  /// The working curve's slack limit eps_min [-] for `maxTension`.
  double slackStrain(double maxTension) const;
  /// The static tension-strain curve of `maxTension` (strain [-] -> tension [N]), sampled: the rope's law in
  /// the statics (a Bar's curve). It starts at (0, 0) (a flat slack part up to eps_min).
  std::shared_ptr<const core::PiecewiseLinear> staticCurve(double maxTension) const;

  struct Step {
    double slowStrain;       ///< x at the end of the step [-]
    double meanTension;      ///< T at the end of the step [N]
    double tension;          ///< N = T + BA x' [N]
    double dTensionDStrain;  ///< dN / d eps [N]
    double dTensionDRate;    ///< dN / d eps' [N s]
  };
  /// One backward-Euler step from the committed slow strain x0 over dt [s] > 0, at total strain eps and rate
  /// eps' [1/s], the working curve that of `maxTension` [N].
  Step step(double strain, double strainRate, double slowStrain0, double maxTension, double dt) const;

  const SyropeConstants& constants() const { return m_c; }

 private:
  double owcStrain(double tension, double* slope) const;
  SyropeConstants m_c;
  std::shared_ptr<const core::PiecewiseLinear> m_inverse;  // the OWC's strain against tension
};

}  // namespace tangle::element
