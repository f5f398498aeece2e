#include "tangle/analysis/MemoryEstimate.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "tangle/analysis/Simulation.hpp"
#include "tangle/contact/LineContact.hpp"

namespace tangle::analysis {

double MemoryEstimate::total() const {
  double sum = 0.0;
  for (const auto& item : items) sum += item.second;
  return sum;
}

std::string MemoryEstimate::text() const {
  std::vector<std::pair<std::string, double>> sorted = items;
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string out;
  for (const auto& [what, bytes] : sorted) out += fmt::format("    {:>10.1f} MB  {}\n", bytes / 1e6, what);
  return out;
}

double residentMemory() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  if (!(statm >> pages >> resident)) return 0.0;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double availableMemory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024.0;
  return std::numeric_limits<double>::quiet_NaN();
}

MemoryEstimate estimateMemory(Simulation& simulation) {
  const model::Model& m = simulation.model();
  const model::DofMap& dofs = m.dofs();
  MemoryEstimate e;
  e.items.emplace_back("model, mesh and solver set-up (measured)", residentMemory());
  // Newton matrix: each element couples its two nodes' DOFs (a 12x12 or 6x6 block); stored as a sparse
  // matrix (value + index, 12 bytes), with the factor's fill taken as three times the pattern (AMD on
  // chains of elements fills little) and the banded envelope of the dynamics at most as large.
  double entries = 0.0;
  for (const model::LineElement& el : m.elements()) {
    const double n = el.isBeam() ? 12.0 : 6.0;
    entries += n * n;
  }
  entries += 36.0 * static_cast<double>(m.vessels().size());
  e.items.emplace_back("Newton matrix and its factor", entries * 12.0 * 4.0);
  const double nodes = m.nodeCount();
  // Per-step batches handed to the writer thread: 32 steps of positions (and triads with beams).
  bool rotations = false;
  for (int n = 0; n < dofs.nodeCount(); ++n) rotations = rotations || dofs.hasRotations(n);
  const auto& d = m.spec().dynamics;
  if (d.enabled) {
    e.items.emplace_back("step hand-over to the writer (32 steps)", 2.0 * 32.0 * nodes * (rotations ? 96.0 : 24.0));
    // results.h5: per line 8 series of up to 3 values per node, 64 output times buffered per chunk (4 bytes).
    e.items.emplace_back("results.h5 chunk buffers", 64.0 * nodes * 12.0 * 4.0 * 2.0);
  }
  if (const contact::LineContact* contact = simulation.contact()) {
    // Up to LineContact::kAssessedPairLimit allowed pairs every one is counted (a Newton step that moves the
    // lines far makes most element pairs candidates); beyond it, the pairs whose lines are within the
    // clearance margin at the start (the ones the clearance envelope assesses, and the only ones a run that
    // moves the lines less than the margin brings near each other).
    const bool every = contact->allowedPairCount() <= contact::LineContact::kAssessedPairLimit;
    const std::vector<std::array<int, 2>> pairs = contact->assessedPairs(simulation.state());
    double elementPairs = 0.0, nodeSides = 0.0;
    for (const auto& pair : pairs) {
      const model::Line& a = m.lines()[static_cast<std::size_t>(pair[0])];
      const model::Line& b = m.lines()[static_cast<std::size_t>(pair[1])];
      elementPairs += pair[0] == pair[1] ? 0.5 * a.elementCount * a.elementCount
                                         : static_cast<double>(a.elementCount) * b.elementCount;
      nodeSides += a.nodeCount + b.nodeCount;
    }
    e.items.emplace_back(
        every ? fmt::format("contact candidate pairs, at most ({:.3g} element pairs; a Newton step that moves the "
                            "lines far makes most of them candidates)",
                            elementPairs)
              : fmt::format("contact candidate pairs ({:.3g} element pairs of the {} line pairs within the "
                            "clearance margin at the start, of {} allowed)",
                            elementPairs, pairs.size(), contact->allowedPairCount()),
        16.0 * elementPairs);
    e.items.emplace_back(fmt::format("clearance envelope ({} line pairs)", pairs.size()), 64.0 * nodeSides);
  }
  return e;
}

}  // namespace tangle::analysis
