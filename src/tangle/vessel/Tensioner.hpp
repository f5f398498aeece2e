#pragma once
/// @file Tensioner.hpp
/// Constant-tension tensioner (riser/line tensioner) with stiff end stops.

#include "tangle/model/ModelSpec.hpp"

namespace tangle::vessel {

/// Force of a tensioner on the line end it holds.
struct TensionerForce {
  double force;      ///< force pulling the line end UP/IN along the tensioner axis [N] (negative: pushes it out)
  double stiffness;  ///< d(force)/d(stroke) [N/m], >= 0: the force grows as the end moves down/out, so this
                     ///< is the restoring stiffness against the stroke direction (0 within the stroke)
};

/// Tensioner law. Stroke s = displacement of the line end along the tensioner axis from the mid-stroke
/// (initial) position [m], positive down/out. With S the total stroke, T the nominal tension, k_g the
/// gas-spring stiffness (spec.stiffness) and k the end-stop stiffness (spec.stopStiffness):
///   |s| <= S/2:  force = T + k_g s,                             stiffness = k_g
///   s >  S/2:    force = T + k_g S/2 + k (s - S/2),             stiffness = k  (end stop: fully extended)
///   s < -S/2:    force = T - k_g S/2 + k (s + S/2),             stiffness = k  (end stop: fully collapsed;
///                                                                the stop pushes the end back, force may
///                                                                turn negative)
/// The law is continuous (piecewise linear). A hydro-pneumatic tensioner (e.g. API RP 16Q 2017, API RP 2RD
/// 2013 riser tensioner systems) with its gas spring linearised about mid-stroke: k_g = n p A / V per
/// cylinder (polytropic exponent n, pressure p, piston area A, gas volume V); k_g = 0 is the ideal
/// constant-tension tensioner, which holds a hanging line within its stroke only if T equals the line's
/// weight exactly. The `enabled` flag is not looked at (the caller decides).
/// @throws tangle::Error if the tension, stroke or a stiffness is negative or not finite, or the stroke is
///         not finite.
TensionerForce tensionerForce(const model::TensionerSpec& spec, double stroke);

}  // namespace tangle::vessel
