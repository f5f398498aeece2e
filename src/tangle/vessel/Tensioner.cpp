/// @file Tensioner.cpp
/// Constant-tension tensioner with end stops (see Tensioner.hpp).

#include "tangle/vessel/Tensioner.hpp"

#include <cmath>

#include <fmt/format.h>

#include "tangle/core/Error.hpp"

namespace tangle::vessel {

TensionerForce tensionerForce(const model::TensionerSpec& spec, double stroke) {
  const auto check = [](const char* name, double v) {
    if (!std::isfinite(v) || v < 0.0) throw Error(fmt::format("tensioner: {} = {} must be finite and >= 0", name, v));
  };
  check("tension", spec.tension);
  check("stroke", spec.stroke);
  check("stopStiffness", spec.stopStiffness);
  check("stiffness", spec.stiffness);
  if (!std::isfinite(stroke)) throw Error("tensioner: the line-end stroke is not finite");
  const double half = 0.5 * spec.stroke;
  const double k = spec.stiffness;
  // Beyond a stop the gas spring is held at its stroke's end: the force grows with the stop alone.
  if (stroke > half)
    return {spec.tension + k * half + spec.stopStiffness * (stroke - half), spec.stopStiffness};
  if (stroke < -half)
    return {spec.tension - k * half + spec.stopStiffness * (stroke + half), spec.stopStiffness};
  return {spec.tension + k * stroke, k};
}

}  // namespace tangle::vessel
