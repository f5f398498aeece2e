// End tensions of LineResults at a free end (issue 32 review): a free end with nothing attached carries no
// force, whatever the end element's own section force; with a mass attached at it, the line holds the mass.

#include <gtest/gtest.h>

#include <vector>

#include "support/ModelFactory.hpp"
#include "tangle/analysis/Simulation.hpp"
#include "tangle/solver/LineResults.hpp"

namespace tangle::solver {
namespace {

/// A 30 m hanging beam (3 elements, the last of a heavy type: a riser's LMRP) pinned at the top, free at
/// the bottom, straight down; optionally a 2 t mass at the free end.
model::ModelSpec hanging(bool massAtEnd) {
  model::ModelSpec spec;
  spec.sourceFile = "free end (test)";
  spec.environment.waterDepth = 200.0;
  spec.lineTypes["pipe"] = test::solidRodType("pipe", 0.3, 2.0e11, 7850.0);
  spec.lineTypes["lmrp"] = test::solidRodType("lmrp", 1.0, 2.0e11, 7850.0);
  model::LineSpec l = test::simpleLine("riser", "pipe", 20.0, 2, model::EndKind::Pinned, Vec3(0, 0, -10),
                                       model::EndKind::Free, Vec3(0, 0, -40));
  l.sections.push_back({"lmrp", 10.0, 1});
  if (massAtEnd) l.attachments.push_back({30.0, 2000.0, 0.0, 0.0, 0.0});
  spec.lines.push_back(l);
  return spec;
}

/// The line stretched by 0.1 % (every element in tension EA / 1000).
model::State stretched(analysis::Simulation& sim) {
  model::State s = sim.state();
  const model::Line& line = sim.model().lines()[0];
  for (int i = 0; i < line.nodeCount; ++i)
    s.position[static_cast<std::size_t>(line.firstNode + i)] = Vec3(0, 0, -10.0 - 1.001 * line.arcLength[static_cast<std::size_t>(i)]);
  return s;
}

TEST(LineResults, AFreeEndWithNothingAttachedHasNoEndTension) {
  analysis::Simulation sim(hanging(false));
  std::vector<LineSnapshot> out;
  computeLineResults(sim.model(), sim.assembler(), stretched(sim), nullptr, out, LineResultDetail::SectionForces);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_GT(out[0].endTensionA, 1e6);  // the held end: EA / 1000 of the pipe
  EXPECT_EQ(out[0].endTensionB, 0.0);
  EXPECT_EQ(out[0].endTensionForceB, Vec3::Zero());
  EXPECT_EQ(out[0].tension.back(), 0.0);
}

TEST(LineResults, AFreeEndWithAMassKeepsTheElementsForce) {
  analysis::Simulation sim(hanging(true));
  std::vector<LineSnapshot> out;
  computeLineResults(sim.model(), sim.assembler(), stretched(sim), nullptr, out, LineResultDetail::SectionForces);
  // Not zeroed: the line holds what is attached at its end (the value itself is the extrapolation's).
  EXPECT_GT(out[0].endTensionB, 1e6);
}

}  // namespace
}  // namespace tangle::solver
