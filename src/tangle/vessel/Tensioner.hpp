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
/// (initial) position [m], positive down/out. With S the total stroke and T the nominal tension:
///   |s| <= S/2:  force = T,                         stiffness = 0
///   s >  S/2:    force = T + k (s - S/2),           stiffness = k   (end stop: fully extended)
///   s < -S/2:    force = T + k (s + S/2) (< T),     stiffness = k   (end stop: fully collapsed; the stop
///                                                                    pushes the end back, force may turn negative)
/// k = spec.stopStiffness. The law is continuous (piecewise linear). An idealised hydro-pneumatic tensioner
/// (e.g. API RP 16Q 2017, API RP 2RD 2013 riser tensioner systems) with the gas-spring stiffness neglected.
/// The `enabled` flag is not looked at (the caller decides).
/// @throws tangle::Error if the tension, stroke or stop stiffness is negative or not finite, or the stroke is
///         not finite.
TensionerForce tensionerForce(const model::TensionerSpec& spec, double stroke);

}  // namespace tangle::vessel
