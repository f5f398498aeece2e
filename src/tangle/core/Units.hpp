#pragma once
/// @file Units.hpp
/// Unit conversions. tangle works in SI (N, m, kg, s, rad internally); input files give angles in degrees.

#include <numbers>

namespace tangle {

inline constexpr double kPi = std::numbers::pi;
/// Degrees to radians.
inline constexpr double degToRad(double degrees) { return degrees * kPi / 180.0; }
/// Radians to degrees.
inline constexpr double radToDeg(double radians) { return radians * 180.0 / kPi; }
/// Standard gravity [m/s^2] (default of environment.gravity).
inline constexpr double kStandardGravity = 9.80665;
/// One tonne-force [N] (55 t pretension = 55 * kTonneForce N).
inline constexpr double kTonneForce = 1000.0 * kStandardGravity;

}  // namespace tangle
