#pragma once
/// @file ArcLengthContinuation.hpp
/// Pseudo-arc-length continuation of the static equilibrium r(q, lambda) = 0 in one load parameter lambda
/// (docs/theory.md 5.5): follows the equilibrium path through limit points (folds), where continuation in
/// lambda itself stalls because beyond the fold the path turns back in lambda.
///
/// Each step: a predictor along the path's direction (the tangent dq/dlambda = -K^-1 dr/dlambda at the
/// first point, then the secant of the last step), then Newton corrections held on the hyperplane normal to
/// the predictor (Riks 1979, "An incremental approach to the solution of snapping and buckling problems",
/// Int. J. Solids Struct. 15; the bordering solution of Crisfield 1981, "A fast incremental/iterative
/// solution procedure that handles snap-through", Comput. Struct. 13):
///   K a = -r,  K b = -dr/dlambda,  dlambda = -(g + t_q . a) / (t_q . b + psi^2 t_lambda),  dq = a + dlambda
///   b,
/// with g the hyperplane's residual and (t_q, t_lambda) the unit predictor in the norm
/// |dq|^2 + psi^2 dlambda^2 (q in metres, rotations over 1 m). Because the secant follows the path, a fold
/// is passed without the tangent's determinant: a tangent that leaves out a destabilising load term (the
/// wake's drag deficit, theory 12.2) still turns with the path. dr/dlambda is the difference quotient of
/// two assemblies (exact where r is affine in lambda, as the drag is in the square of the current).
/// Every correction keeps the statics trust regions (IncrementLimits) and the contributors' limits
/// (contact: no iterate passes through another line), scaled along with dlambda.

#include <functional>
#include <string>

#include "tangle/core/Types.hpp"
#include "tangle/model/State.hpp"
#include "tangle/solver/Assembler.hpp"

namespace tangle::solver {

/// Follows r(q, lambda) = 0 from an equilibrium at lambda0 towards a target value of lambda.
class ArcLengthContinuation {
 public:
  struct Settings {
    double tolerance = 1.0;        ///< largest out-of-balance force of a converged point [N]
    double target = 1.0;           ///< lambda to reach [-]
    double firstIncrement = 0.05;  ///< lambda increment the first arc step is sized for [-]
    int maxCorrections = 25;       ///< Newton corrections per arc step before it is cut
    int maxSteps = 400;            ///< arc steps in all
    bool debug = false;            ///< progress on stderr (TANGLE_DEBUG_STATICS)
    /// The ParameterSetter asks for a non-symmetric tangent (AssemblyRequest::wakeDragStiffness): solve by
    /// LU.
    bool nonSymmetricTangent = false;
    /// Called with every converged point of the path (state, lambda) before the next step (may be empty).
    std::function<void(const model::State&, double)> onPoint;
  };
  /// Sets the load parameter lambda [-] in an assembly request (e.g. the current's speed factor
  /// sqrt(lambda)).
  using ParameterSetter = std::function<void(double lambda, AssemblyRequest& request)>;
  /// Solves at lambda = target from a predicted state (modified in place); true when it converged there.
  using Finisher = std::function<bool(model::State& state)>;

  struct Outcome {
    bool reached = false;   ///< an equilibrium at lambda = target was found (by the finisher)
    double lambda = 0.0;    ///< the last equilibrium's lambda [-]
    int iterations = 0;     ///< Newton corrections in all
    int steps = 0;          ///< converged arc steps
    double residual = 0.0;  ///< out-of-balance force of the last correction [N]
    int worstNode = -1;     ///< where it is largest
    std::string failure;    ///< why it stopped, when not reached
  };

  ArcLengthContinuation(Assembler& assembler, Settings settings, ParameterSetter setParameter,
                        Finisher finish);

  /// From the equilibrium `state` at `lambda0` (committed in the assembler) along the path towards
  /// Settings::target; `budget` (Newton iterations left) is decreased by those used. On return `state` is the
  /// equilibrium at the target (reached) or the last one on the path.
  Outcome run(model::State& state, double lambda0, int& budget);

 private:
  /// r (over the equations) and dr/dlambda at (state, lambda); with `matrix`, the tangent K too.
  bool evaluate(const model::State& state, double lambda, VecX& r, VecX& drdl, SystemMatrix* matrix,
                std::string& why);
  /// r (over the equations) at (state, lambda), with `matrix` the tangent K too; throws what the assembly
  /// throws (an element that cannot be evaluated).
  void assembleResidual(const model::State& state, double lambda, VecX& r, SystemMatrix* matrix);

  Assembler* m_assembler;
  Settings m_settings;
  ParameterSetter m_setParameter;
  Finisher m_finish;
};

}  // namespace tangle::solver
