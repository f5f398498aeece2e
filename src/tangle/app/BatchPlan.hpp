#pragma once
/// @file BatchPlan.hpp
/// A batch of load cases (the `tangle batch` file, format in docs/batch.md): a base model and its
/// variations, expanded into one model per case.
///
/// ```yaml
/// model: ../mooring-dynamics/model.yaml      # base model, relative to the batch file
/// set: {dynamics.duration: 60}               # changes for every case (optional)
/// parameters:                                # product of value lists (optional)
///   - {name: heading, key: environment.current.azimuth, values: [0, 90, 180, 270]}
///   - {name: current, key: environment.current.speed, values: [0.5, 1.0, 1.5]}
/// seeds: [1, 2, 3, 4, 5]                     # or {count: 10, first: 1}: JONSWAP seeds (optional)
/// statistics: {probability: 0.9}             # Gumbel quantile of summary_statistics.csv (optional)
/// cases:                                     # named cases (optional), each x the product
///   - {name: intact}
///   - {name: offset, set: {"lines[mooring1].end_b.position": [830, 0, -14]}}
/// ```
/// Keys are the paths of io::ModelDocument. Cases are ordered cases-major, then the parameters in the
/// order given (the last varies fastest).

#include <string>
#include <vector>

#include "tangle/io/ModelDocument.hpp"

namespace tangle::app {

/// One load case.
struct BatchCase {
  std::string name;  ///< unique; also its folder name (letters, digits, '.', '_', '-', '=')
  /// Value of each batch parameter (BatchPlan::parameterNames order), as written in the batch file.
  std::vector<std::string> parameterValues;
  io::ModelDocument model;  ///< the base model with every change applied
};

/// The expanded batch.
struct BatchPlan {
  std::string batchFile;
  std::string baseModel;  ///< path of the base model file
  std::vector<std::string> parameterNames;  ///< with `seed` last when the batch has seeds
  std::vector<BatchCase> cases;
  /// JONSWAP seeds (`seeds`): every case is repeated for each, as the last parameter `seed`
  /// (environment.waves.seed); the batch then writes summary_statistics.csv (empty: no seeds).
  std::vector<long long> seeds;
  /// Non-exceedance probability of the Gumbel quantile in summary_statistics.csv (`statistics.probability`).
  double probability = 0.9;
};

/// Reads a batch file and expands its cases. Key paths through lists are checked against the base model
/// as they are applied; then every case is read by the model reader, so a key or value the reader refuses
/// (a typo in a path creates a key it does not know) is an error of the batch file before anything runs.
/// @throws InputError naming the batch file, the line, the key and what was expected
BatchPlan readBatchPlan(const std::string& batchFile);

}  // namespace tangle::app
