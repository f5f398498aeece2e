#pragma once
/// @file MoorDynDeck.hpp
/// A MoorDyn v2 input file ("deck") as written (its conversion into a tangle model: MoorDynConversion.hpp).
///
/// The deck is read section by section as MoorDyn v2 reads it (MoorDyn2.cpp: a section starts at a line
/// holding "---" and the section's name; tables skip a column-name and a unit line; a section ends at the
/// next "---" line): LINE TYPES / LINE DICTIONARY, BODIES, ROD TYPES, RODS, POINTS / POINT LIST / POINT
/// PROPERTIES / CONNECTION PROPERTIES / NODE PROPERTIES, LINES / LINE LIST / LINE PROPERTIES, FAILURE,
/// OPTIONS, OUTPUTS. Every entry tangle cannot represent (failures at rods, VIV, viscoelastic or Syrope
/// stiffness laws, 4D current grids, external loads, ...) is refused with the file, the line and the entry's
/// name: nothing is skipped silently. The mapping is documented in docs/moordyn.md.
///
/// Units as in MoorDyn: SI (m, kg, N, s).

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::io {

/// One LINE TYPES row.
struct MoorDynLineType {
  std::string name;
  double diameter = 0.0;          ///< d [m]: drag, added mass, buoyancy (pi/4 d^2) and seabed contact width
  double massPerLength = 0.0;     ///< [kg/m]
  double axialStiffness = 0.0;    ///< EA [N] (with a curve: its largest slope)
  /// The EA [N] MoorDyn itself keeps for the type: EA, or with a curve file the secant to its last point
  /// (MoorDyn v2.7.1, Line.cpp, initialize: EA = stiffYs.back() / stiffXs.back()), which sets a damping
  /// ratio's BA (negative BA) and MoorDyn_GetLineConstantEA.
  double moorDynStiffness = 0.0;
  /// EA given as a curve file (MoorDyn's read_curve: three header lines, then `strain tension` rows): the
  /// points (strain [-], tension [N]); empty for a constant EA.
  std::vector<std::pair<double, double>> tensionStrain;
  std::string tensionStrainFile;  ///< the curve file's path as read
  double axialDamping = 0.0;      ///< BA [N s] (>= 0), or minus a damping ratio of the segments' axial mode
  /// A viscoelastic rope (EA "EA|EA_d" or "EA|alphaMBL|vbeta", BA "BA|BA_d"): EA_d0 [N] (0: elastic), its
  /// slope with the mean load beta [-] and the dynamic dashpot BA_d [N s]; BA is then the slow dashpot.
  double dynamicStiffness = 0.0;
  double dynamicStiffnessSlope = 0.0;
  double dynamicDamping = 0.0;
  /// A SYROPE rope (EA "SYROPE:settings|alphaMBL|vbeta"): alphaMBL and vbeta in dynamicStiffness and its
  /// slope, BA and BA_d as above; the settings file's working-curve formula ("linear", "quadratic", "exp"),
  /// k1, k2 and original working curve (read as MoorDyn's read_curve reads it: three header lines skipped).
  bool syrope = false;
  std::string syropeForm;
  double syropeK1 = 0.0;
  double syropeK2 = 0.0;
  std::vector<std::pair<double, double>> syropeCurve;  ///< (strain [-], tension [N])
  std::string syropeSettingsFile;
  std::string syropeCurveFile;
  double bendingStiffness = 0.0;  ///< EI [N m^2]
  double dragNormal = 0.0;        ///< Cd [-] on d
  double addedMassNormal = 0.0;   ///< Ca [-] on pi/4 d^2
  double dragAxial = 0.0;         ///< CdAx [-] on pi d
  double addedMassAxial = 0.0;    ///< CaAx [-] on pi/4 d^2
  int sourceLine = 0;
};

/// How a MoorDyn point is held.
enum class MoorDynPointKind {
  Fixed,    ///< Fixed / Anchor
  Coupled,  ///< Coupled / Vessel / Fairlead: moved by the host program (held where the deck puts it
            ///< standalone)
  Free,     ///< Free / Point / Connect: solved for, with its own mass, volume, drag and added mass
  Body      ///< Body<n>: fixed to body n, its position relative to the body's reference point, body axes
};

/// How a MoorDyn body is held (MoorDyn2.cpp, readBody).
enum class MoorDynBodyKind {
  Free,          ///< anything else (Free, Point, ...): 6 degrees of freedom
  Fixed,         ///< Fixed / Anchor
  Coupled,       ///< Coupled / Vessel: moved by the host (held where the deck puts it standalone)
  CoupledPinned  ///< CoupledPinned / VesselPinned: its reference point moved by the host, free to rotate
};

/// One BODIES row: a rigid body with its own mass, inertia, volume, drag and added mass, to which points
/// and rods may be fixed (MoorDyn's Body.cpp: its net weight (rho V - M) g acts at its centre of gravity,
/// drag and added mass at its reference point).
struct MoorDynBody {
  int id = 0;
  MoorDynBodyKind kind = MoorDynBodyKind::Free;
  std::string kindWord;                 ///< as written
  Vec3 position = Vec3::Zero();         ///< X0, Y0, Z0: the reference point [m]
  Vec3 rotation = Vec3::Zero();         ///< r0, p0, y0 [deg]: R = Rx(r0) Ry(p0) Rz(y0) (MoorDyn's Euler2Quat)
  double mass = 0.0;                    ///< [kg]
  Vec3 centreOfGravity = Vec3::Zero();  ///< CG: from the reference point, body axes [m] (one value: z)
  Vec3 inertia = Vec3::Zero();          ///< I: about the centre of gravity, body axes [kg m^2]
  double volume = 0.0;                  ///< [m^3]
  std::array<double, 6>
      dragArea{};  ///< CdA: x, y, z [m^2] and roll, pitch, yaw [m^5] (MoorDyn's F = 1/2 rho CdA |v| v)
  Vec3 addedMass = Vec3::Zero();  ///< Ca: x, y, z [-] on the volume
  int sourceLine = 0;
};

/// One POINTS row.
struct MoorDynPoint {
  int id = 0;
  MoorDynPointKind kind = MoorDynPointKind::Fixed;
  int body = 0;  ///< the body of a Body point (its position is then relative to the body, body axes)
  std::string kindWord;          ///< the attachment word as written (e.g. "Vessel")
  Vec3 position = Vec3::Zero();  ///< [m]
  double mass = 0.0;             ///< [kg]
  double volume = 0.0;           ///< [m^3]
  double dragArea = 0.0;         ///< CdA [m^2]
  double addedMass = 0.0;        ///< Ca [-] on the volume
  int sourceLine = 0;
};

/// One ROD TYPES row (MoorDyn's rod: a rigid cylinder with Morison loads and end effects).
struct MoorDynRodType {
  std::string name;
  double diameter = 0.0;       ///< d [m]
  double massPerLength = 0.0;  ///< [kg/m]
  double drag = 0.0;           ///< Cd [-], transverse, on d
  double addedMass = 0.0;      ///< Ca [-], transverse, on pi/4 d^2
  double dragEnd = 0.0;        ///< CdEnd [-], axial, on each end's area pi/4 d^2
  double addedMassEnd = 0.0;   ///< CaEnd [-], axial, on each end's half sphere 2/3 pi (d/2)^3
  int sourceLine = 0;
};

/// How a MoorDyn rod is held (MoorDyn2.cpp, the RODS list).
enum class MoorDynRodKind {
  Fixed,          ///< Fixed / Anchor: does not move; Body<n>: fixed to body n
  Pinned,         ///< Pinned: end A held, free to rotate about it; Body<n>Pinned: end A on body n
  Free,           ///< Free: 6 degrees of freedom (its roll is not modelled)
  Coupled,        ///< Coupled / Vessel: moved by the host (held where the deck puts it standalone)
  CoupledPinned,  ///< CoupledPinned / VesselPinned: end A moved by the host, free to rotate about it
};

/// One RODS row.
struct MoorDynRod {
  int id = 0;
  std::string rodType;
  MoorDynRodKind kind = MoorDynRodKind::Fixed;
  std::string kindWord;      ///< the attachment word as written (e.g. "Pinned")
  int body = 0;              ///< Body<n>(Pinned): the body (its ends are then relative to it, body axes)
  Vec3 endA = Vec3::Zero();  ///< [m]
  Vec3 endB = Vec3::Zero();  ///< [m]
  int segments = 0;          ///< NumSegs (0 for a zero-length rod)
  std::string outputs;       ///< RodOutputs as written
  int sourceLine = 0;
  double length() const { return (endB - endA).norm(); }
};

/// One LINES row.
struct MoorDynLine {
  int id = 0;
  std::string lineType;
  int pointA = 0;       ///< id of the point at end A (0 when end A is on a rod)
  int pointB = 0;       ///< id of the point at end B (0 when end B is on a rod)
  int rodA = 0;         ///< id of the rod end A is attached to (`R3A`, `R3B`), 0 for a point
  int rodB = 0;         ///< id of the rod end B is attached to, 0 for a point
  int rodEndA = 0;      ///< which end of rod rodA: 0 = its end A, 1 = its end B
  int rodEndB = 0;      ///< which end of rod rodB
  double length = 0.0;  ///< unstretched length [m]
  int segments = 1;
  std::string outputs;  ///< the LineOutputs flags as written ("-" for none)
  int sourceLine = 0;
};

/// One FAILURE row (MoorDyn: the listed lines' ends at the point part from it, when the time or the
/// attachment tension is reached).
struct MoorDynFailure {
  int id = 0;
  int point = 0;           ///< id of the point
  std::vector<int> lines;  ///< ids of the lines that part from it
  double time = 0.0;       ///< FailTime [s] (0: none)
  double tension = 0.0;    ///< FailTen [N] (0: none)
  int sourceLine = 0;
};

/// One SYROPE IC row: the lines' initial largest and mean tensions (MoorDyn2.cpp).
struct MoorDynSyropeIc {
  std::vector<int> lines;    ///< ids of the lines
  double maxTension = 0.0;   ///< Tmax0 [N]
  double meanTension = 0.0;  ///< Tmean0 [N]
  int sourceLine = 0;
};

/// One OPTIONS entry.
struct MoorDynOption {
  std::string name;   ///< as written
  std::string value;  ///< as written
  int sourceLine = 0;
};

/// A MoorDyn v2 input file.
struct MoorDynDeck {
  std::string file;   ///< path (used in messages)
  std::string title;  ///< the first line after the file's first line of dashes, if any
  std::vector<MoorDynLineType> lineTypes;
  std::vector<MoorDynBody> bodies;  ///< ids 1..n in order
  std::vector<MoorDynRodType> rodTypes;
  std::vector<MoorDynRod> rods;      ///< ids 1..n in order
  std::vector<MoorDynPoint> points;  ///< ids 1..n in order
  std::vector<MoorDynLine> lines;    ///< ids 1..n in order
  std::vector<MoorDynFailure> failures;
  std::vector<MoorDynSyropeIc> syropeIc;
  std::vector<MoorDynOption> options;
  std::vector<std::string> outputs;  ///< OUTPUTS channel names
};

/// A whole word of a deck (or of a file it names) read as a number, as MoorDyn's columns are; nullopt when
/// the word is not one number (a table file's name, "1e9|2e9", trailing characters).
std::optional<double> deckNumber(std::string_view word);

/// True when the file at `path` reads as a MoorDyn deck (a "---" line naming LINE TYPES or LINE DICTIONARY)
/// rather than a YAML model.
bool isMoorDynDeck(const std::string& path);

/// Reads a MoorDyn v2 input file. @throws InputError naming the file, the line, the entry and what tangle
/// expected (or why the entry is not supported).
MoorDynDeck readMoorDynDeck(const std::string& path);
/// The same from the deck's text; `file` is used in messages.
MoorDynDeck parseMoorDynDeck(const std::string& text, const std::string& file);

}  // namespace tangle::io
