#pragma once
/// @file ReducedMass.hpp
/// The reduced mass of two bodies meeting in an impact, with an immovable side.

#include <cmath>

namespace tangle::contact {

/// Reduced mass m_a m_b / (m_a + m_b) [kg] of masses a, b [kg]; an immovable side (+inf) leaves the other,
/// two massless sides give 0.
inline double reducedMass(double a, double b) {
  if (std::isinf(a)) return b;
  if (std::isinf(b)) return a;
  return a + b > 0.0 ? a * b / (a + b) : 0.0;
}

}  // namespace tangle::contact
