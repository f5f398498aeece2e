#pragma once
/// @file MoorDynCoupling.hpp
/// A MoorDyn v2 deck read for co-simulation: the deck, its conversion into a tangle model, the model and
/// the coupled points a host moves (one per Coupled point of the deck). The MoorDyn-compatible C API
/// (capi/) and the Python module's `tangle.Coupling` both build their analysis::CoupledRun from it, so a
/// deck means the same system through either. (io is above analysis in the layers, docs/architecture.md.)

#include <string>
#include <vector>

#include "tangle/analysis/CoupledRun.hpp"
#include "tangle/io/MoorDynConversion.hpp"
#include "tangle/io/MoorDynDeck.hpp"
#include "tangle/model/ModelSpec.hpp"

namespace tangle::io {

/// A deck ready to be coupled to a host.
struct DeckCoupling {
  MoorDynDeck deck;              ///< the deck as written
  MoorDynConversion conversion;  ///< the tangle model's YAML and the map from deck lines and points to it
  model::ModelSpec spec;         ///< the converted model as readModelFile reads the deck (notes in warnings)
  /// One coupled point per deck point of kind Coupled, in deck order (MoorDyn's order of the coupled
  /// DOFs), named "point<id>", holding the tangle line ends at that point (MoorDynPointMap::ends).
  std::vector<analysis::CoupledPointSpec> points;
};

/// The coupled points of a converted deck, as in DeckCoupling::points.
std::vector<analysis::CoupledPointSpec> coupledPoints(const MoorDynConversion& conversion);

/// Reads the deck at `path`, converts it and reads the converted model as `tangle run` does
/// (io::readModelFile; messages name `path`).
/// @throws InputError when the deck cannot be read, holds an entry tangle cannot represent, or the
///         converted model is refused by the model reader
DeckCoupling loadMoorDynCoupling(const std::string& path);

}  // namespace tangle::io
