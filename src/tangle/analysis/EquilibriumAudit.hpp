#pragma once
/// @file EquilibriumAudit.hpp
/// The equilibrium audit of a static solution (theory manual 7.8): for every line the sum of the forces
/// on it, source by source (weight and buoyancy, attachments, drag, seabed reaction and friction, contact,
/// and the end forces as reported, LineSnapshot::endTensionForceA/B), and for every free vessel the sum of
/// its body loads and the lines' pulls. The end forces are computed from the element section forces, the
/// other terms from the load models: a reported end force that leaves out a part of the section force (the
/// beams' shear did until issue 30) shows as a residual, as does an unconverged solution.

#include <vector>

#include "tangle/solver/ForceBalance.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::analysis {

class Simulation;

/// Sets the end forces and end tensions of the static line results `lines` (Simulation::snapshot at the
/// state of `simulation`) to the exact ones of the discrete model: the end element's section force plus
/// the loads the line lumps on the end node (what is attached at the end node is at the end: it is pulled
/// with this force). For loads uniform over the two end elements this is the extrapolated force of
/// computeLineResults; a point load near the end (a contact, a buoy, touchdown) makes them differ.
void setStaticEndForces(Simulation& simulation, std::vector<solver::LineSnapshot>& lines);

/// Audits the static state of `simulation` with the line results `lines` (Simulation::snapshot at the
/// same state).
solver::EquilibriumAudit auditStatics(Simulation& simulation, const std::vector<solver::LineSnapshot>& lines);

}  // namespace tangle::analysis
