#pragma once
/// @file CableSnapLimit.hpp
/// Time-step limit that resolves slack-to-taut snaps of cable (bar) elements.
///
/// A bar carries no compression, so its axial stiffness jumps from ~0 to EA / L when a slack element
/// straightens. Implicit Newmark-family schemes are unconditionally stable only for linear systems; on such
/// a bilinear spring a step that carries an element from slack deep into tension in one go does work the
/// continuous system does not (the same mechanism as penalty contact: Laursen & Chawla 1997, Int. J. Numer.
/// Meth. Eng. 40:863; Kuhl & Crisfield 1999, Int. J. Numer. Meth. Eng. 45:569), and undamped grounded chain
/// pumped by a fairlead gains energy snap after snap. Seen: the mooring example in a 1 m/s current towards
/// the anchor (grounded chain slack) reached 4e7 N anchor tension with generalized-alpha at dt = 0.01 s and
/// at 0.005 s; 1e-3 s gives 2.1e5 N.
///
/// The limit predicts each bar's strain from its strain rate at the start of the step and shortens the step
/// so that no bar at its kink (slack, or taut by less than `maxStrainStep`) stretches by more than
/// `maxStrainStep` beyond max(its strain, 0): a slack bar may close its slack, but enters tension over
/// several steps. Bars stretched beyond `maxStrainStep` are on their linear branch and are not limited:
/// limiting them too held a pretensioned wire (strain 1e-3) ringing after an impact at 1e-4 strain per step
/// (the tunnelling validation test took 828 steps instead of 387). Taut lines in ordinary motion are not
/// affected.

#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::time {

/// Largest step [s] for which no bar element of `model` with a strain below `maxStrainStep` [-] is
/// predicted to stretch by more than `maxStrainStep` beyond max(its strain now, 0), and no taut bar
/// predicted to go slack within `horizon` [s] crosses its kink from a strain above `maxStrainStep` or
/// overshoots it by more than `maxStrainStep` (the unloading half of a snap); +infinity when none is.
/// The strain rate of a bar is e . (v2 - v1) / L0 with e the unit chord [1/s].
double cableSnapStepLimit(const model::Model& model, const model::State& state, double maxStrainStep,
                          double horizon);

/// The check after a converged step of what cableSnapStepLimit predicts: the fraction [-] of the step from
/// `before` to `after` at which, interpolated linearly in strain, the first bar that went from a strain above
/// `maxStrainStep` to one below -maxStrainStep (from tension across its kink into slack in one step) reaches
/// maxStrainStep / 2; 1 when no bar did. A step with a fraction below 1 is to be taken again that much
/// shorter. The prediction from the rate at the step's start does not see a bar unload from its largest
/// length (rate 0) within a quarter of its axial period; with the accelerations too it saw unloads that do
/// not happen in a mooring line at dt = 0.05 s (the generalized-alpha accelerations of its unresolved axial
/// modes), and cut steps there. This check sees only the unloads that happened.
double cableUnloadStepFraction(const model::Model& model, const model::State& before,
                               const model::State& after, double maxStrainStep);

}  // namespace tangle::time
