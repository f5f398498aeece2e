#include "tangle/io/MoorDynCoupling.hpp"

#include <utility>

#include "tangle/io/ModelReader.hpp"

namespace tangle::io {

std::vector<analysis::CoupledPointSpec> coupledPoints(const MoorDynConversion& conversion) {
  std::vector<analysis::CoupledPointSpec> points;
  for (const MoorDynPointMap& p : conversion.points) {
    if (p.kind != MoorDynPointKind::Coupled) continue;
    points.push_back({"point" + std::to_string(p.deckId), p.ends, {}});
  }
  return points;
}

DeckCoupling loadMoorDynCoupling(const std::string& path) {
  DeckCoupling c;
  c.deck = readMoorDynDeck(path);
  c.conversion = convertMoorDynDeck(c.deck);
  // The model as `tangle run DECK` reads it (readModelFile converts the deck the same way, names the deck
  // in the reader's messages and adds the conversion's notes to the warnings).
  c.spec = readModelFile(path);
  c.points = coupledPoints(c.conversion);
  return c;
}

}  // namespace tangle::io
