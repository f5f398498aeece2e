#pragma once
/// @file SeabedSpec.hpp
/// The seabed's input (`environment.seabed`), with the seabed model that uses it (the model's ModelSpec
/// holds one; the seabed does not depend on the model).

namespace tangle::seabed {

/// Flat seabed at z = -waterDepth.
struct SeabedSpec {
  double normalStiffness = 1.0e5;  ///< penalty stiffness per unit length of line [N/m/m]
  double damping = 0.0;            ///< normal damping per unit length of line [N s/m/m]
  double frictionCoefficient = 0.0;  ///< Coulomb friction coefficient mu [-] (statics and dynamics)
  double frictionVelocity = 0.01;  ///< viscous model, dynamics: regularisation velocity, full friction above it [m/s]
  double shearStiffness = 0.0;     ///< friction spring per unit length of line [N/m/m]; 0: = normalStiffness
  /// true (`friction_model: elastic`, the default): in statics and dynamics a spring to the node's anchor
  /// point capped at mu N (with a critical dashpot beside it in dynamics), the anchors carried from statics
  /// into dynamics and committed with every accepted step; false (`viscous`): in dynamics the
  /// velocity-regularised Coulomb law mu N v / max(|v|, friction_velocity), which holds nothing at rest
  /// (statics: the elastic law).
  bool elasticFriction = true;
};

}  // namespace tangle::seabed
