#pragma once
/// @file MoorDynConversion.hpp
/// A MoorDyn v2 deck converted into a tangle model (YAML text with comments saying where each value came
/// from) and the map from the deck's points and lines to the model's line ends and nodes, which `tangle
/// run DECK`, `tangle convert` and the MoorDyn-compatible C API (capi/) use. The mapping is documented in
/// docs/moordyn.md.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "tangle/io/MoorDynDeck.hpp"

namespace tangle::io {

/// Where a deck's line went in the tangle model: a tangle line may hold several deck lines joined in
/// series at free points (each joined free point becomes an attachment at the junction node).
struct MoorDynLineMap {
  int deckId = 0;
  std::string tangleLine;  ///< name of the tangle line
  int firstNode = 0;       ///< index along the tangle line (0 = its end A) of the deck line's end A node
  int segments = 0;        ///< the deck line's segments (= elements)
  bool reversed = false;   ///< the deck line's end A is at the larger node index
};

/// Where a deck's point went in the tangle model.
struct MoorDynPointMap {
  int deckId = 0;
  MoorDynPointKind kind = MoorDynPointKind::Fixed;
  Vec3 position = Vec3::Zero();  ///< the deck's position [m]
  /// The tangle line ends held at this point (line name, 0 = end A / 1 = end B): every end of a Fixed or
  /// Coupled point, or of a Free point joining three or more deck lines (a tangle point: its carrier first);
  /// for a Free point the one end it is (a free end), or none when it joins two deck lines.
  std::vector<std::pair<std::string, int>> ends;
  /// Free point joining two deck lines: the tangle line holding it; joining three or more: the line whose end
  /// node carries the tangle point (model::JunctionPoint).
  std::string junctionLine;
  int junctionNode = -1;                           ///< and the node index along that line
  std::vector<std::pair<int, int>> attachedLines;  ///< (deck line id, 0 = end A / 1 = end B) attached here
};

/// Where a deck's rod went in the tangle model: a pinned or free rod of length > 0 is a stiff beam line
/// (`rod<id>`, its nodes the rod's); a fixed or coupled rod, or a zero-length rod, is its ends' points.
struct MoorDynRodMap {
  int deckId = 0;
  MoorDynRodKind kind = MoorDynRodKind::Fixed;
  std::string tangleLine;  ///< name of the tangle line, empty when the rod is not one
  int segments = 0;        ///< its elements (NumSegs)
  /// The tangle line ends held at each end (0 = A, 1 = B; a zero-length rod's at A): a fixed or coupled rod's
  /// end points' lines; at end A of a pinned or coupled-pinned rod that is a line, the rod's own end first.
  /// What a host moves when it moves the rod (capi::MoorDynSystem).
  std::array<std::vector<std::pair<std::string, int>>, 2> endLines;
  /// A zero-length rod: the point it is (its lines' ends there, or the node inside the tangle line that joins
  /// two of them), as a deck point's map; its position the rod's.
  MoorDynPointMap point;
};

/// Where a deck's body went in the tangle model: a free body is the free vessel `vessel` ("body<id>"), whose
/// reference point is the centre of gravity of the body and its points and whose axes are the global axes at
/// t = 0; a fixed or coupled body holds what is on it where the deck puts it (no vessel).
struct MoorDynBodyMap {
  int deckId = 0;
  MoorDynBodyKind kind = MoorDynBodyKind::Free;
  std::string vessel;                ///< the tangle vessel, empty for a held body
  Vec3 origin = Vec3::Zero();        ///< the deck's reference point X0, Y0, Z0 at t = 0 [m]
  Mat3 rotation = Mat3::Identity();  ///< body axes to global at t = 0 (Rx(r0) Ry(p0) Rz(y0))
  Vec3 reference = Vec3::Zero();     ///< the vessel's reference point at t = 0 [m]
};

/// A deck converted into a tangle model.
struct MoorDynConversion {
  std::string yaml;  ///< the tangle model file, with comments saying where each value came from
  std::vector<MoorDynLineMap> lines;    ///< in deck order
  std::vector<MoorDynPointMap> points;  ///< in deck order
  std::vector<MoorDynRodMap> rods;      ///< in deck order
  std::vector<MoorDynBodyMap> bodies;   ///< in deck order
  std::vector<std::string> notes;       ///< what differs from MoorDyn (also in the YAML's comments)
};

/// Converts a deck. @throws InputError for what tangle cannot represent (a line whose two ends are the same
/// point, lines joined at free points in a loop, ...), naming the deck's file and line.
MoorDynConversion convertMoorDynDeck(const MoorDynDeck& deck);

}  // namespace tangle::io
