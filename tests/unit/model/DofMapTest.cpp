// Unit tests of tangle::model::DofMap's equation numbering: free DOFs numbered in full-DOF (node) order,
// each node's equations a consecutive range [firstEquation(node), firstEquation(node + 1)).

#include <gtest/gtest.h>

#include "tangle/model/DofMap.hpp"

namespace tangle::model {
namespace {

TEST(DofMap, EachNodesEquationsAreOneConsecutiveRange) {
  // A bar node with one held direction, a beam node, a bar node held in every DOF (an anchor), a bar node.
  DofMap dofs;
  const int a = dofs.addNode(3), b = dofs.addNode(6), c = dofs.addNode(3), d = dofs.addNode(3);
  dofs.constrain(a + 2);
  for (int k = 0; k < 3; ++k) dofs.constrain(c + k);
  dofs.finalize();
  ASSERT_EQ(dofs.equationCount(), 2 + 6 + 0 + 3);
  EXPECT_EQ(dofs.firstEquation(0), 0);
  EXPECT_EQ(dofs.firstEquation(1), 2);
  EXPECT_EQ(dofs.firstEquation(2), 8);
  EXPECT_EQ(dofs.firstEquation(3), 8);  // the anchor has none
  EXPECT_EQ(dofs.firstEquation(4), 11);
  // The ranges agree with the per-DOF numbering.
  for (int node = 0; node < dofs.nodeCount(); ++node)
    for (int i = dofs.firstEquation(node); i < dofs.firstEquation(node + 1); ++i)
      EXPECT_EQ(dofs.nodeOf(dofs.equationDofs()[static_cast<std::size_t>(i)]), node);
  EXPECT_EQ(dofs.equation(b + 5), 7);
  EXPECT_EQ(dofs.equation(d), 8);
}

}  // namespace
}  // namespace tangle::model
