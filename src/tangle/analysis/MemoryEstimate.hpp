#pragma once
/// @file MemoryEstimate.hpp
/// What a run of a model needs in memory, estimated before it starts (`tangle check`, `tangle run`), so
/// that a model the machine cannot hold is refused with the reason instead of ending in std::bad_alloc.
/// The model and solver set-up are measured (resident memory after building the Simulation); what grows
/// with the run is counted from the model: the Newton matrix and its factor, contact candidate pairs (at
/// most every allowed element pair, 16 bytes each: the broad phase's list and its Verlet copy), the
/// clearance envelope (64 bytes per node and side of every checked pair), the per-step hand-over batches
/// and the results' buffers (HDF5 chunks of 64 output times per series).

#include <string>
#include <utility>
#include <vector>

namespace tangle::analysis {

class Simulation;

struct MemoryEstimate {
  std::vector<std::pair<std::string, double>> items;  ///< what and how many bytes
  double total() const;                               ///< [bytes]
  /// One line per item, largest first, in MB.
  std::string text() const;
};

/// Estimates the memory of a run of `simulation`'s model (dynamics included when the model has them).
MemoryEstimate estimateMemory(Simulation& simulation);

/// Memory the machine can give a new allocation now [bytes] (MemAvailable of /proc/meminfo); NaN when
/// unknown.
double availableMemory();

/// Resident memory of this process now [bytes] (/proc/self/statm); 0 when unknown.
double residentMemory();

}  // namespace tangle::analysis
