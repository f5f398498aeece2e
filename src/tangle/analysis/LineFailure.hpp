#pragma once
/// @file LineFailure.hpp
/// Lines that break during a run (`lines[].failure`, docs/model-format.md "Line failure", docs/theory.md
/// 8.7): the accidental limit state of DNV-OS-E301 (a mooring line broken, the transient after it), a
/// connection parting, an anchor dragged out.
///
/// A line parts in one element (model::PartedElements): from the state after the break on, that element
/// carries no force and has no drag, added mass or contact; its nodes are the free ends of the two pieces.
/// Triggers, checked at every accepted state (LoadContributor::commitStep), the first reached wins:
///  - time: the step is cut to land on it (limitStep); the state at that time is the last intact one;
///    time 0 parts the line before the statics (the damaged static equilibrium);
///  - tension: the first accepted state where an element's effective tension reaches its threshold (a
///    number, or its line type's minimum breaking load); it parts in the element of the highest tension
///    over threshold; with `at`, the tension is that of the element at `at` (a connection parts on its own
///    end's tension, MoorDyn's FAILURE rows);
///  - clash energy: the first impact on the line (a contact event whose impact phase has ended) whose energy
///    reaches the threshold; it parts in the element where the impact started, or at `at`.
/// Where `at` names an end, the end element parts: the line keeps all but that element (its mass stays
/// lumped at the nodes, half with the held end), which is the nearest a mesh with fixed nodes comes to a
/// released end.

#include <string>
#include <vector>

#include "tangle/contact/LineContact.hpp"
#include "tangle/model/Model.hpp"
#include "tangle/solver/Assembler.hpp"
#include "tangle/solver/LoadContributor.hpp"

namespace tangle::analysis {

/// One break.
struct LineBreak {
  int line = 0;
  int element = 0;       ///< global index of the parted element
  double time = 0.0;     ///< [s]; -inf: before the statics
  double arcFrom = 0.0;  ///< unstretched arc length of the parted element's ends from end A [m]
  double arcTo = 0.0;
  std::string trigger;      ///< "time", "tension" or "clash energy"
  double value = 0.0;       ///< what reached the trigger: tension [N], clash energy [J] or time [s]
  double threshold = 0.0;   ///< the trigger's threshold, same unit
  std::string description;  ///< one sentence for the log and the summary
};

/// Watches the triggers of every line with a failure and parts the lines (file comment).
class LineFailure : public solver::LoadContributor {
 public:
  /// Parts the lines whose failure time is 0 at once (before any statics). `contact` may be null.
  LineFailure(const model::Model& model, solver::Assembler& assembler, contact::LineContact* contact);

  /// True if any line of the model has a failure.
  static bool wanted(const model::Model& model);

  void addForces(const model::State&, const solver::AssemblyRequest&, VecX&, solver::SystemMatrix*) override {
  }
  bool supportsParts() const override { return true; }
  void addPartForces(const model::State&, const solver::AssemblyRequest&, const solver::AssemblyPart&, VecX&,
                     solver::SystemMatrix*) override {}
  /// The time left to the next time trigger [s] (+inf if none is pending); right after a break, a 64th of the
  /// time step (the step then regrows twofold per step).
  double limitStep(const model::State& state, double step) override;
  /// Checks the triggers at the accepted state of a dynamic step (dt > 0) and parts the lines whose trigger
  /// is reached.
  void commitStep(model::State& state, double dt) override;

  /// The breaks so far, in the order they happened.
  const std::vector<LineBreak>& breaks() const { return m_breaks; }

  /// The element of `line` a failure at `where` parts (Where::Arc: the element holding the arc length, the
  /// one after it at a node; EndA / EndB: the end elements); -1 for Where::Trigger.
  static int elementAt(const model::Model& model, int line, const model::FailureSpec& failure);

 private:
  void part(int line, int element, double time, const std::string& trigger, double value, double threshold);
  /// The threshold tension of an element [N] (FailureSpec::tension or its type's MBL).
  double tensionThreshold(const model::FailureSpec& failure, std::size_t element) const;

  const model::Model* m_model;
  solver::Assembler* m_assembler;
  contact::LineContact* m_contact;
  std::vector<int> m_pending;     ///< lines with a failure that have not parted
  std::vector<double> m_tension;  ///< work space: every element's tension [N]
  std::vector<LineBreak> m_breaks;
  bool m_justParted = false;  ///< a line parted at the last accepted state: the next step starts small
};

}  // namespace tangle::analysis
