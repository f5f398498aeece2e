#pragma once
/// @file JunctionTies.hpp
/// The free points where three or more line ends meet (ModelSpec::points): each line end other than the
/// point's carrier is tied to the carrier node by a stiff isotropic spring (model::NodeTie), a pin that
/// passes forces and no moments. The spring is a penalty like a free vessel's link: 100 x EA / L of the tied
/// line's end element, so that it stretches by 1 % of that element's extension (docs/theory.md 2.5).

#include <vector>

#include "tangle/model/Model.hpp"
#include "tangle/solver/LoadContributor.hpp"

namespace tangle::solver {

/// The ties of line ends to their points.
class JunctionTies final : public LoadContributor {
 public:
  explicit JunctionTies(const model::Model& model);

  /// F at a tied node: +k (x_node - x_carrier) [N]; at the carrier the opposite. H: k [I -I; -I I].
  void addForces(const model::State& state, const AssemblyRequest& request, VecX& force,
                 SystemMatrix* matrix) override;
  /// The supports of line ends (like a vessel's links): the end forces and the audit leave them out.
  LoadSource source() const override { return LoadSource::Junctions; }
  /// Its loads act at the tied nodes and carriers only, which it marks.
  bool supportsParts() const override { return true; }
  bool markLoadedNodes(std::vector<char>& mark) const override;
  /// The ties' round-off (16 eps k |x|) at the tied nodes and their carriers.
  void raiseRoundoffFloor(const model::State& state, std::vector<double>& floor) const override;
  bool raisesRoundoffFloor() const override { return true; }

  /// The ties' contribution to the out-of-balance force (full DOF vector): subtracting it from F leaves at
  /// each line end at a point the force of the line on the point.
  VecX tieForces(const model::State& state) const;

 private:
  void addTies(const model::State& state, double kf, VecX& force, SystemMatrix* matrix) const;

  const model::Model* m_model;
};

}  // namespace tangle::solver
