#pragma once
/// @file HeadingTable.hpp
/// Periodic linear interpolation of a coefficient table against relative heading
/// (model::HeadingTable: OCIMF-style current/wind coefficients, mean wave-drift coefficients).

#include <string>

#include "tangle/core/Types.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::vessel {

/// Value of a heading table and its derivative with respect to the heading.
struct HeadingSample {
  Vec3 value = Vec3::Zero();  ///< interpolated (x, y, yaw) values [table units]
  Vec3 slope = Vec3::Zero();  ///< d(value)/d(heading) of the active segment [table units / rad]
};

/// Checks a heading table: non-empty, as many values as headings, headings strictly ascending and in
/// [0, 2 pi). @param name used in the message. @throws tangle::Error naming the table and the fault.
void validateHeadingTable(const model::HeadingTable& table, const std::string& name = "heading table");

/// Periodic linear interpolation over [0, 2 pi): the heading is first wrapped into [0, 2 pi); between the
/// last heading h_{n-1} and the first h_0 the table wraps around (segment h_{n-1} -> h_0 + 2 pi).
/// One entry means a constant. @param relativeHeading [rad], any value.
/// @throws tangle::Error on an empty, inconsistent or unsorted table (validateHeadingTable).
Vec3 interpolate(const model::HeadingTable& table, double relativeHeading);

/// Same interpolation, also returning the slope d(value)/d(heading) [per rad] of the segment that contains
/// the heading (at a table heading: the slope of the segment that starts there; 0 for a single entry).
/// @throws tangle::Error as interpolate().
HeadingSample interpolateWithSlope(const model::HeadingTable& table, double relativeHeading);

/// Angle wrapped into [0, 2 pi) [rad].
double wrapTwoPi(double angle);

}  // namespace tangle::vessel
