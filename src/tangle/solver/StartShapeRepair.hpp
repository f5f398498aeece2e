#pragma once
/// @file StartShapeRepair.hpp
/// Start-shape heuristics of the static solve, apart from its Newton portfolio (StaticSolver): shapes a
/// Newton solve cannot start from (a slack suspended run of cable, a line with a free end lying straight
/// out from its support) are replaced by shapes it can (theory 7.1). Functions of the model and a state only.

#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/model/State.hpp"

namespace tangle::solver {

/// Slack suspended cable elements at `state` (element indices): shorter than unstretched by more than
/// 1e-4, neither node on the seabed.
std::vector<int> slackSuspendedBars(const model::Model& model, const model::State& state);
/// A lateral bulge of the runs of `elements` in `state`, in the direction of their distributed load: each
/// run's free nodes on a half sine whose arc length takes up the run's unstretched length.
void bulgeSlackRuns(const model::Model& model, model::State& state, const std::vector<int>& elements);
/// Lines held at one end only (the other `free`) hang from the held end in `state`: they leave it along
/// its given tangent and bend into the vertical (down for a heavy line, up for a buoyant one) over a
/// bending length 3 sqrt(EI / (w L)) (at least two elements, at most a quarter of the line), then run
/// straight (along the seabed where they reach it). Returns false when no line qualifies.
bool hangFreeLines(const model::Model& model, model::State& state);

}  // namespace tangle::solver
