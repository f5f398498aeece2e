#pragma once
/// @file StartShapeCrossings.hpp
/// Start shapes of the program (catenaries) that pass through each other, laid one over the other before
/// statics (docs/theory.md 2.4).
///
/// Each line's analytic start shape ignores the other lines, so two lines whose shapes cross start with their
/// surfaces overlapping: a mooring chain laid across a pipeline on the seabed passes through it (both rest on
/// the seabed, their axes a few centimetres apart vertically). The contact then pushes them apart along the
/// normal of that overlap, which is no physical choice: the chain's axis lies below the pipeline's, so
/// statics pressed the chain under the pipeline, 7.6 cm into the soil, and lifted the pipeline onto it (39
/// kN, a 117 kN m moment in the pipeline). Which line lies on top is the analyst's (the one laid later), so
/// the rule is explicit: a line listed later in the model is laid over one listed earlier. "Over" is the side
/// of the crossing towards +z (the normal of the two axes, upwards); for lines along each other, upwards
/// square to the lower line. The upper line's nodes near the crossing are moved along that direction until
/// the surfaces are 5 % of the sum of the radii apart, over the stretch where its nodes lie near the lower
/// line plus a cosine taper; statics then lays it down on the other. A user start shape (lines[].start_shape)
/// is the user's geometry and is never moved (Simulation refuses one that passes through another line).

#include <string>
#include <vector>

#include "tangle/core/Types.hpp"
#include "tangle/model/Model.hpp"

namespace tangle::contact {

class LineContact;

/// One start shape laid over another (liftCrossedStartShapes).
struct StartShapeLift {
  int lowerLine = 0;               ///< the line left where it was
  int upperLine = 0;               ///< the line moved over it (listed later in the model)
  double arcLower = 0.0;           ///< arc length of the deepest overlap along the lower line [m]
  double arcUpper = 0.0;           ///< and along the upper line [m]
  double overlap = 0.0;            ///< how far the surfaces overlapped there [m] (> 0)
  double lift = 0.0;               ///< the largest move of the upper line's nodes [m]
  Vec3 direction = Vec3::UnitZ();  ///< the direction they moved in (unit)
  /// A sentence for the run log: which line, where, by how much, and how to choose otherwise.
  std::string describe(const model::Model& model) const;
};

/// Lays every pair of program-made start shapes that the contact finds overlapping (surfaces more than 1 % of
/// the sum of the radii into each other) one over the other in `state` (see the file comment); the moved
/// lines' triads are set again from their new shapes. Returns what was moved, in pair order. A crossing it
/// cannot clear (every node near it held, or no progress after kMaxLiftsPerPair moves) is left to statics.
std::vector<StartShapeLift> liftCrossedStartShapes(const model::Model& model, const LineContact& contact,
                                                   model::State& state);

/// Moves per pair of lines at most (a pair crossing more than once gets one per crossing).
inline constexpr int kMaxLiftsPerPair = 8;

}  // namespace tangle::contact
