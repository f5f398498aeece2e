#pragma once
/// @file ModelFactory.hpp
/// Small builders of ModelSpec objects for tests (no YAML in between, so physics tests do not depend
/// on the reader).

#include <string>

#include "tangle/model/ModelSpec.hpp"

namespace tangle::test {

/// A beam line type: solid circular section of diameter d [m], Young's modulus e [Pa], density rho [kg/m^3].
inline section::LineType solidRodType(const std::string& name, double d, double e, double rho) {
  section::LineType t;
  t.name = name;
  const double area = 0.25 * 3.141592653589793 * d * d;
  const double i = 3.141592653589793 * d * d * d * d / 64.0;
  t.outerDiameter = d;
  t.buoyancyDiameter = d;
  t.contactDiameter = d;
  t.massPerLength = rho * area;
  t.axialStiffness = e * area;
  t.bendingStiffness = e * i;
  t.torsionalStiffness = e / 2.6 * 2.0 * i;  // G = E / (2 (1 + 0.3)), J = 2 I
  return t;
}

/// A beam line type of given properties (a flexible pipe, a hose): diameter [m], mass per length [kg/m], EA [N],
/// EI [N m^2] (torsional stiffness GJ = EI), normal drag and added-mass coefficients [-].
inline section::LineType beamType(const std::string& name, double diameter, double massPerLength, double ea,
                                  double ei, double dragNormal, double addedMassNormal) {
  section::LineType t = solidRodType(name, diameter, 1.0, 1.0);
  t.massPerLength = massPerLength;
  t.axialStiffness = ea;
  t.bendingStiffness = ei;
  t.torsionalStiffness = ei;
  t.dragNormal = dragNormal;
  t.addedMassNormal = addedMassNormal;
  return t;
}

/// A cable (bar) line type.
inline section::LineType cableType(const std::string& name, double diameter, double massPerLength, double ea) {
  section::LineType t;
  t.name = name;
  t.outerDiameter = diameter;
  t.buoyancyDiameter = diameter;
  t.contactDiameter = diameter;
  t.massPerLength = massPerLength;
  t.axialStiffness = ea;
  return t;
}

/// One-section line between two ends.
inline model::LineSpec simpleLine(const std::string& name, const std::string& type, double length, int elements,
                                  model::EndKind kindA, const Vec3& a, model::EndKind kindB, const Vec3& b) {
  model::LineSpec l;
  l.name = name;
  l.endA.kind = kindA;
  l.endA.position = a;
  l.endB.kind = kindB;
  l.endB.position = b;
  l.sections.push_back({type, length, elements});
  return l;
}

}  // namespace tangle::test
