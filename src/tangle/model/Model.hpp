#pragma once
/// @file Model.hpp
/// The finite-element model built from a ModelSpec: nodes, elements, DOF numbering, and the
/// initial state (analytic catenary or straight shapes) from which the static solve starts.

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tangle/element/Bar.hpp"
#include "tangle/element/CorotationalBeam.hpp"
#include "tangle/model/DofMap.hpp"
#include "tangle/model/ModelSpec.hpp"
#include "tangle/model/PartedElements.hpp"
#include "tangle/model/State.hpp"

namespace tangle::model {

/// One element of a line: a bar (cable sections) or a co-rotational beam.
struct LineElement {
  int line = 0;                                   ///< index of the line
  int node1 = 0;                                  ///< global node index at the end-A side
  int node2 = 0;                                  ///< global node index at the end-B side
  /// Section properties (owned by the ModelSpec, or by the Model for a section with contents: its line type
  /// with ContentsSpec::density or SectionSpec::contentsDensity).
  const section::LineType* type = nullptr;
  double restLength = 0.0;                        ///< unstretched length [m]
  std::optional<element::Bar> bar;                ///< set for cable elements
  std::optional<element::CorotationalBeam> beam;  ///< set for beam elements
  bool isBeam() const { return beam.has_value(); }
};

/// A point mass / buoy at a node.
struct NodeAttachment {
  int node = 0;         ///< global node index
  AttachmentSpec spec;  ///< mass, volume, drag, added mass
};

/// A free point (ModelSpec::points) as the mesh holds it: the end node of the first line end at it (input
/// order) carries the point's body (an attachment) and is the point; every other line end at it is tied to
/// that node (NodeTie).
struct JunctionPoint {
  std::string name;
  int node = 0;                  ///< the carrier node: the point's position is this node's [global index]
  std::vector<int> endNodes;     ///< every line end node at the point, the carrier's first
  std::vector<int> attachments;  ///< indices into Model::attachments() of the point's body (at most one)
};

/// A line end node tied to a point's carrier node by a stiff isotropic spring (a pin: translations only):
/// f = k (x_node - x_carrier) pulls the two together (docs/theory.md 2.5).
struct NodeTie {
  int node = 0;          ///< the tied line end node
  int carrier = 0;       ///< the point's carrier node
  double stiffness = 0;  ///< k [N/m]: 100 x EA / L of the tied line's end element, as a vessel's link
  int point = 0;         ///< index into Model::points()
};

/// A line's mesh: a contiguous range of nodes and elements.
struct Line {
  std::string name;
  const LineSpec* spec = nullptr;
  int firstNode = 0;     ///< global index of the node at end A
  int nodeCount = 0;     ///< nodes = elements + 1
  int firstElement = 0;  ///< global index of the first element
  int elementCount = 0;
  std::vector<double> arcLength;  ///< unstretched arc length of each node from end A [m]
  double length = 0.0;            ///< total unstretched length [m]
  /// Largest contact radius of its elements: half the largest contact diameter of its line types [m].
  double contactRadius = 0.0;
  /// A section of it is a pipe (its line type has an internal_diameter): its results give the internal
  /// pressure and the wall tension.
  bool pipe = false;
  /// Level of the contents' reference pressure z_ref [m] (ContentsSpec::referenceZ resolved: the higher end
  /// at t = 0 unless given).
  double contentsReferenceZ = 0.0;
  int lastNode() const { return firstNode + nodeCount - 1; }  ///< global index of the node at end B
};

/// The meshed model. Owns its ModelSpec; element line-type pointers point into it.
class Model {
 public:
  /// Meshes the model. Throws InputError for inconsistencies the reader could not see.
  explicit Model(ModelSpec spec);
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const ModelSpec& spec() const { return *m_spec; }  ///< the input
  const EnvironmentSpec& environment() const { return m_spec->environment; }
  /// The seabed's shape (environment.seabedSurface, or flat at -waterDepth).
  const seabed::SeabedSurface& seabedSurface() const { return *m_seabedSurface; }
  const std::shared_ptr<const seabed::SeabedSurface>& sharedSeabedSurface() const { return m_seabedSurface; }
  const std::vector<Line>& lines() const { return m_lines; }  ///< lines in input order
  const std::vector<LineElement>& elements() const { return m_elements; }
  /// The elements parted so far (lines[].failure): the run's state of the mesh, not its input, held here so
  /// that every part that reads the elements sees it; only analysis::LineFailure parts them.
  PartedElements& parted() const { return *m_parted; }
  const std::vector<NodeAttachment>& attachments() const { return m_attachments; }
  /// Free points joining line ends (ModelSpec::points), input order.
  const std::vector<JunctionPoint>& points() const { return m_points; }
  /// The ties of line ends to their points' carrier nodes (empty without points of two or more ends).
  const std::vector<NodeTie>& ties() const { return m_ties; }
  const DofMap& dofs() const { return m_dofs; }  ///< DOF numbering
  int nodeCount() const { return m_dofs.nodeCount(); }
  /// Line index owning a node (-1 for a vessel node).
  int lineOfNode(int node) const { return m_nodeLine[node]; }
  /// "line 'name' node i (arc length s m)" or "vessel 'name'", for messages.
  std::string describeNode(int node) const;
  /// Length [m] that turns a moment at a node into a comparable force (convergence checks).
  double momentScale(int node) const { return m_momentScale[node]; }
  /// Vessels in input order.
  const std::vector<VesselSpec>& vessels() const { return m_spec->vessels; }
  /// The 6-DOF node of vessel v.
  int vesselNode(int v) const { return m_vesselNode[v]; }
  /// Initial global position of a line end [m] (vessel ends: the vessel point at t = 0).
  Vec3 endPosition(const EndSpec& end) const;
  /// Initial rotation (vessel axes to global) of vessel v: its heading about z.
  Mat3 vesselRotation(int v) const;
  /// Motion of vessel `v` at `state`: x, y, z of its reference point [m] and its rotation from the initial
  /// attitude (the heading of the model) as a rotation vector [deg] (dynamics/vessels.csv, results.h5, Python).
  std::array<double, 6> vesselMotion(const State& state, int v) const;
  /// Index of a line by name, -1 if none.
  int lineIndex(const std::string& name) const;
  /// Index of a vessel by name, -1 if none.
  int vesselIndex(const std::string& name) const;
  /// Tributary unstretched length of each node (half of each adjacent element) [m].
  const std::vector<double>& tributaryLength() const { return m_tributaryLength; }
  /// Contact diameter of each node (largest adjacent line type) [m].
  const std::vector<double>& nodeContactDiameter() const { return m_nodeContactDiameter; }
  /// Structural mass lumped to each node, including attachments [kg].
  const std::vector<double>& nodeMass() const { return m_nodeMass; }
  /// Rotational inertia lumped to each beam node (isotropic approximation) [kg m^2].
  const std::vector<double>& nodeRotationalInertia() const { return m_nodeRotationalInertia; }

  /// The initial state: catenary/straight shapes, triads by parallel transport, zero velocity.
  State initialState() const;
  /// Sets the triads of a line's nodes in `state` from its node positions: the first from the tangent
  /// there, the others by parallel transport along the line (a Bishop frame: no twist).
  void setLineTriads(int line, State& state) const;

  /// Total structural mass [kg] and submerged weight [N] (if fully submerged) of a line.
  double lineMass(int line) const;

  /// The line type of section `section` of line `line` as the model uses it: the input's line type, or its
  /// copy with the section's contents density (LineType::contentsDensity).
  const section::LineType& sectionType(int line, int section) const {
    return *m_sectionTypes[static_cast<std::size_t>(line)][static_cast<std::size_t>(section)];
  }
  /// Internal pressure p_i [Pa] at each node of line `line` with its nodes at `position` (the line's own
  /// nodes, end A first), into `pressure`: the contents' reference pressure plus their head,
  /// p_i = p_ref + rho_c g (z_ref - z) for one contents density; with sections of different densities the
  /// head is summed element by element along the line from the first point (from end A) at z_ref
  /// (docs/theory.md 5.3). Zero everywhere for a line without contents or pressure.
  void internalPressure(int line, const std::vector<Vec3>& position, std::vector<double>& pressure) const;

 private:
  /// Anchored ends given on the seabed (below one contact radius above it) are placed on its contact
  /// surface, where the laid line rests: centreline at -depth + contact diameter / 2 [m].
  void seatAnchorsOnSeabed();
  /// Fills m_sectionTypes: each section's line type, copied with its contents where it has any.
  void resolveSectionTypes();
  void buildLine(int lineIndex);
  /// Node positions of a line with a start shape (LineSpec::startShape) between its end positions [m].
  std::vector<Vec3> startShapePositions(const Line& line, const Vec3& endA, const Vec3& endB) const;
  void buildVessel(int vesselIndex);
  /// Each point's body becomes an attachment at the end of its carrier line (before the lines are built).
  void placePointBodies();
  /// m_points and m_ties (after the lines are built).
  void buildPoints();
  void constrainEnd(int node, const EndSpec& end);

  std::unique_ptr<ModelSpec> m_spec;
  std::vector<Line> m_lines;
  std::map<std::string, int> m_lineIndex;  // line name -> index (lineIndex)
  std::vector<LineElement> m_elements;
  std::unique_ptr<PartedElements> m_parted;
  std::shared_ptr<const seabed::SeabedSurface> m_seabedSurface;
  std::vector<NodeAttachment> m_attachments;
  std::vector<JunctionPoint> m_points;
  std::vector<NodeTie> m_ties;
  std::vector<std::unique_ptr<section::LineType>> m_contentTypes;  // line types with contents (per section)
  std::vector<std::vector<const section::LineType*>> m_sectionTypes;  // per line, per section
  std::vector<int> m_nodeLine;
  std::vector<double> m_tributaryLength;
  std::vector<double> m_nodeContactDiameter;
  std::vector<double> m_nodeMass;
  std::vector<double> m_nodeRotationalInertia;
  std::vector<double> m_momentScale;
  std::vector<int> m_vesselNode;
  DofMap m_dofs;
};

}  // namespace tangle::model
