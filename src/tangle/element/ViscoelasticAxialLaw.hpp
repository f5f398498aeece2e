#pragma once
/// @file ViscoelasticAxialLaw.hpp
/// The axial law of a viscoelastic (polyester) rope: a static spring EA_1 with a slow dashpot BA in parallel,
/// in series with the dynamic spring EA_2 = EA_d with a dashpot BA_d in parallel (MoorDyn's viscoelastic
/// model: Hall, Duong, Lozon 2023, "Validation of a viscoelastic model of synthetic fibre mooring ropes",
/// IOWTC2023- 119260 (ASME); its eq. 14). The series of EA_1 and EA_2 is the static stiffness EA: 1/EA =
/// 1/EA_1 + 1/EA_2. The dynamic stiffness may grow with the mean load: EA_d = EA_d0 + beta T_mean with T_mean
/// = EA_1 x, the static branch's load (ABS's rope model, MoorDyn's "EA|alphaMBL|vbeta"; its eq. 2 and 10).
///
/// The internal variable is the static branch's strain x [-] (the slow strain; MoorDyn's dl_1 / L0). With the
/// total strain eps [-] and its rate eps' [1/s], the two branches carry the same tension:
///   N = EA_1 x + BA x' = EA_2 (eps - x) + BA_d (eps' - x'),
/// so (BA + BA_d) x' = EA_2 eps - (EA_1 + EA_2) x + BA_d eps'. A time step integrates it by backward Euler
/// from the committed x_n over dt (first order, unconditionally stable: an implicit integrator's step may be
/// far longer than the relaxation time (BA + BA_d) / (EA_1 + EA_2)), with EA_1 and EA_2 taken at x_n (the
/// load- dependent stiffness lagged by one step). Stateless apart from its constants; thread-safe.
namespace tangle::element {

/// Constants of the viscoelastic law, per unit strain (MoorDyn's "EA" and "BA/-zeta" entries).
struct ViscoelasticConstants {
  double staticStiffness = 0.0;        ///< EA [N]: the stiffness under slow loading
  double dynamicStiffness = 0.0;       ///< EA_d0 [N]: the dynamic stiffness at zero mean load, > EA
  double dynamicStiffnessSlope = 0.0;  ///< beta [-]: d EA_d / d T_mean (0: a constant dynamic stiffness)
  double slowDamping = 0.0;            ///< BA [N s]: the dashpot parallel to the static branch, > 0
  double dynamicDamping = 0.0;         ///< BA_d [N s]: the dashpot parallel to the dynamic spring, >= 0
};

class ViscoelasticAxialLaw {
 public:
  /// @throws tangle::Error when EA <= 0, EA_d0 <= EA, beta < 0, BA <= 0 or BA_d < 0
  explicit ViscoelasticAxialLaw(const ViscoelasticConstants& constants);

  /// One backward-Euler step of the slow strain and the tension at its end.
  struct Step {
    double slowStrain;       ///< x at the end of the step [-]
    double tension;          ///< N = EA_1 x + BA x' [N]
    double dTensionDStrain;  ///< dN / d eps [N] (the step's consistent tangent)
    double dTensionDRate;    ///< dN / d eps' [N s]
  };
  /// @param strain eps at the end of the step [-]; @param strainRate eps' there [1/s]
  /// @param slowStrain0 the committed x_n [-]; @param dt the step [s], > 0
  Step step(double strain, double strainRate, double slowStrain0, double dt) const;

  /// The slow strain in equilibrium at a constant strain eps (both dashpots at rest): x with EA_1(x) x = EA
  /// eps (x = EA eps / EA_1 for a constant EA_d; a fixed point for a load-dependent one) [-].
  double relaxedSlowStrain(double strain) const;

  /// The dynamic stiffness EA_2 [N] with the static branch at strain x: EA_d0 + beta EA_1 x solved with
  /// EA_1 = EA_2 EA / (EA_2 - EA) (the larger root of EA_2^2 - (EA_d0 + EA + beta EA x) EA_2 + EA_d0 EA = 0;
  /// MoorDyn Line.cpp's closed form); EA_d0 when x < 0 (no mean load).
  double dynamicStiffnessAt(double slowStrain) const;
  /// The static branch's stiffness EA_1 = EA_2 EA / (EA_2 - EA) [N] at slow strain x.
  double staticBranchStiffnessAt(double slowStrain) const;

  const ViscoelasticConstants& constants() const { return m_c; }

 private:
  ViscoelasticConstants m_c;
};

}  // namespace tangle::element
