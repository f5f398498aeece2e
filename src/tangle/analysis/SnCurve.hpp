#pragma once
/// @file SnCurve.hpp
/// S-N curves as data and Miner's damage sum (DNV-RP-C203 (2021) section 2.4: two-slope curves
/// log10 N = log10 a - m log10(S (t / t_ref)^k), the second slope beyond the knee; the thickness correction
/// applies for t > t_ref) and T-N curves of chain and rope: API RP 2SK (2005) 7.5, N R^m = K with R the
/// tension range over the reference breaking strength, or DNV-OS-E301 (2021) Ch.2 Sec.2 [6.2],
/// N = a_D s^-m with s the nominal stress range in MPa. Check a curve's constants against the edition the
/// design follows: the presets here are the cited ones.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tangle/analysis/Rainflow.hpp"

namespace tangle::analysis {

/// A two-slope S-N curve. Stress ranges in Pa; log10 a as the standards publish it, for stress in MPa.
struct SnCurve {
  std::string name;
  double m1 = 3.0;           ///< slope up to the knee [-]
  double logA1 = 12.164;     ///< log10 a of the first segment (MPa) [-]
  double m2 = 5.0;           ///< slope beyond the knee [-]
  double logA2 = 15.606;     ///< log10 a of the second segment (MPa) [-]
  double kneeCycles = 1e7;   ///< cycles at the knee [-] (1e7 in air and in seawater with cathodic protection)
  double thicknessExponent = 0.0;  ///< k [-]
  double referenceThickness = 0.025;  ///< t_ref [m]
  double thickness = 0.025;  ///< t [m] (the correction applies only for t > t_ref)
  /// A one-slope curve (m2 = m1, logA2 = logA1): e.g. in seawater without cathodic protection.
  bool singleSlope = false;

  /// DNV-RP-C203 (2021) Table 2-1, curve D in air: m1 = 3, log a1 = 12.164, m2 = 5, log a2 = 15.606,
  /// knee at 1e7 cycles, k = 0.20, t_ref = 25 mm.
  static SnCurve dnvD(double thickness = 0.025);
  /// A DNV-RP-C203 (2021) curve by name: "dnv-<class>-air" (Table 2-1: B1, B2, C, C1, C2, D, E, F, F1, F3,
  /// G, W1, W2, W3; knee at 1e7 cycles) or "dnv-<class>-seawater-cp" (Table 2-2, in seawater with cathodic
  /// protection: B1, C, D, E, F, F1; knee at 1e6 cycles), with the class's thickness exponent and
  /// t_ref = 25 mm. Empty for an unknown name.
  static std::optional<SnCurve> preset(std::string_view name);
  /// The names preset() knows, for messages.
  static std::vector<std::string> presetNames();

  /// Cycles to failure N at stress range `range` [Pa] ([-]; +inf for a zero range).
  double cyclesToFailure(double range) const;
  /// Stress range [Pa] at the knee.
  double kneeRange() const;
};

/// A T-N curve of chain or rope. API RP 2SK (2005) 7.5: N R^m = K, R = tension range / reference breaking
/// strength (K = 1000 for studlink, 316 for studless chain, m = 3). DNV-OS-E301 (2021) Ch.2 Sec.2 [6.2]
/// (`stressBased`): N = a_D s^-m, s = tension range / nominal area in MPa (a_D = 1.2e11 for studlink,
/// 6.0e10 for studless chain, m = 3; the nominal area of chain is two legs, pi d^2 / 2).
struct TnCurve {
  double m = 3.0;          ///< [-]
  double aD = 1000.0;      ///< K [-] (API), or a_D [MPa^m] (DNV, stressBased)
  double breakingStrength = 1.0;  ///< reference breaking strength [N] (API)
  bool stressBased = false;       ///< DNV's form
  double nominalArea = 1.0;       ///< nominal area [m^2] (DNV)
  /// A preset by name: "api-studlink", "api-studless" (then set breakingStrength), "dnv-studlink",
  /// "dnv-studless" (then set nominalArea). Empty for an unknown name.
  static std::optional<TnCurve> preset(std::string_view name);
  double cyclesToFailure(double tensionRange) const;  ///< tension range [N] -> N [-]
};

/// Miner's damage sum D = sum n_i / N_i of rainflow cycles of stress [Pa] against an S-N curve [-].
double minerDamage(const std::vector<RainflowCycle>& cycles, const SnCurve& curve);
/// Miner's damage sum of rainflow cycles of tension [N] against a chain T-N curve [-].
double minerDamage(const std::vector<RainflowCycle>& cycles, const TnCurve& curve);

}  // namespace tangle::analysis
