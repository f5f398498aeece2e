#pragma once
/// @file IncrementLimits.hpp
/// Trust regions of the static Newton iterations (StaticSolver, ArcLengthContinuation): how far one
/// correction may move a node and stretch a cable element.

#include "tangle/core/Types.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::solver {

class Assembler;

/// Largest nodal translation [m] of one Newton correction: 5 % of the longest line, at least 10 m or five
/// of the longest elements (whichever is smaller), and at least two of the shortest elements. Keeps
/// Newton from jumping across the solution on slack lines, where the tangent is nearly singular.
double translationCap(const model::Model& model);

/// Largest nodal rotation [rad] of one Newton correction.
constexpr double kRotationCap = 0.5;

/// Largest rise of a bar's strain in one Newton iteration [-] (a trust region in cable strain). Near a
/// touchdown point the linearised step of a slack catenary stretches chain links by hundreds of percent
/// and pushes nodes metres into the seabed (seen: 6 m bars stretched to 22 m, nodes 17 m below the seabed
/// in the slack 800 m span mooring in cross current); from there Newton and the pseudo-transient
/// continuation crawl. Ten times a working strain of chain or wire (~1e-3) costs a taut line nothing and
/// a slack bar may first straighten freely (its strain counts from max(strain, 0)).
constexpr double kMaxStrainStep = 0.01;

/// The largest stretch [-] the correction `full` (full DOFs) makes any bar element take beyond max(its
/// strain at `state`, 0), in units of kMaxStrainStep: above 1 the correction is to be divided by it.
double strainStepRatio(const model::Model& model, const Assembler& assembler, const model::State& state,
                       const VecX& full);

}  // namespace tangle::solver
