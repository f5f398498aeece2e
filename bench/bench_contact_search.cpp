/// @file bench_contact_search.cpp
/// Contact search alone: broad phase (contact::BroadPhase) plus narrow phase
/// (geometry::segmentDistance on every candidate pair), on a synthetic but realistic field in
/// 345 m of water: 5 floating units within ~1.5 km of each other, each with 12 mooring lines
/// (1130 m, anchor radius 1000 m, catenary with a grounded part: the seed paper's section 7.1
/// mooring) and 8 free-hanging risers (700 m, ends 480..585 m from the unit), 200 elements per
/// line; the lines cover about 3.3 km x 2.8 km. Lines of neighbouring units cross in plan view;
/// in this layout they meet in 3D where both lie on the seabed (278 candidate pairs, 167 within
/// the margin, for the 100 lines).
///
/// Benchmarks:
///  - BM_ContactSearch/100: the 100 lines x 200 elements field, time per search (the broad phase
///    buffers are reused between searches, as in a time-stepping loop);
///  - BM_ContactSearch/{10,30,100}: the first n lines (spread over the 5 units) of the same field,
///    with the fitted complexity against N = number of elements (expect ~N log N);
///  - BM_BroadPhase/{10,30,100}: broad phase alone, same sizes.
/// Counters: elements, candidate pairs, pairs closer than the sum of radii plus margin.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "tangle/contact/BroadPhase.hpp"
#include "tangle/core/Types.hpp"
#include "tangle/core/Units.hpp"
#include "tangle/geometry/SegmentDistance.hpp"

namespace {

using tangle::Vec3;
using tangle::contact::BroadPhase;
using tangle::contact::BroadPhaseOptions;
using tangle::contact::CandidatePair;
using tangle::contact::SegmentProxy;

constexpr double kWaterDepth = 345.0;  // [m], seed paper section 7.1
constexpr int kElementsPerLine = 200;  // [-], the paper's mooring mesh
constexpr int kUnits = 5;              // [-]
constexpr int kMooringsPerUnit = 12;   // [-]
constexpr int kRisersPerUnit = 8;      // [-]
constexpr int kLinesPerUnit = kMooringsPerUnit + kRisersPerUnit;
constexpr double kMargin = 0.5;          // [m] broad-phase margin
constexpr double kMooringRadius = 0.10;  // [m] contact radius of chain / wire
constexpr double kRiserRadius = 0.15;    // [m] contact radius of a ~12 in riser

/// Horizontal span [m] of a catenary line of length `length` [m] hanging from `drop` [m] above the
/// seabed with catenary parameter lambda = H/w [m]: suspended part sqrt(drop (drop + 2 lambda))
/// and its span lambda asinh(Ls/lambda) (inextensible catenary, e.g. Faltinsen, "Sea Loads on
/// Ships and Offshore Structures", 1990, ch. 8), plus the grounded part.
double catenarySpan(double length, double drop, double lambda) {
  const double suspended = std::sqrt(drop * (drop + 2.0 * lambda));
  return lambda * std::asinh(suspended / lambda) + (length - suspended);
}

/// Nodes of a catenary with a grounded part, from the anchor/touchdown end `anchor` (on the
/// seabed) to the top end `top` [m]; the catenary parameter is found by bisection so the line of
/// length `length` spans the horizontal distance between the ends. Grounded nodes lie at
/// seabed + radius.
std::vector<Vec3> catenaryNodes(const Vec3& anchor, const Vec3& top, double length, double radius) {
  const double drop = top.z() - anchor.z();
  Vec3 horizontal = top - anchor;
  horizontal.z() = 0.0;
  const double span = horizontal.norm();
  const Vec3 direction = horizontal / span;
  double lo = 1e-3;
  double hi = (length * length - drop * drop) / (2.0 * drop);  // fully suspended, no grounded part
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (catenarySpan(length, drop, mid) < span ? lo : hi) = mid;
  }
  const double lambda = 0.5 * (lo + hi);
  const double suspended = std::sqrt(drop * (drop + 2.0 * lambda));
  const double grounded = length - suspended;
  std::vector<Vec3> nodes;
  for (int i = 0; i <= kElementsPerLine; ++i) {
    const double arc = length * i / kElementsPerLine;  // from the anchor
    double x, z;
    if (arc <= grounded) {
      x = arc;
      z = radius;
    } else {
      const double xc = lambda * std::asinh((arc - grounded) / lambda);
      x = grounded + xc;
      z = std::max(radius, lambda * (std::cosh(xc / lambda) - 1.0));
    }
    nodes.push_back(anchor + x * direction + Vec3(0.0, 0.0, z));
  }
  return nodes;
}

/// The full field: kUnits x kLinesPerUnit lines, ordered so that the first n lines are spread over
/// all units (line i belongs to unit i % kUnits).
std::vector<std::vector<Vec3>> fieldLines(std::vector<double>& radii) {
  const std::array<Vec3, kUnits> units{Vec3(0, 0, 0), Vec3(750, 250, 0), Vec3(-650, 450, 0),
                                       Vec3(300, -750, 0), Vec3(-500, -650, 0)};
  std::vector<std::vector<Vec3>> lines;
  radii.clear();
  const double seabed = -kWaterDepth;
  for (int slot = 0; slot < kLinesPerUnit; ++slot) {
    for (int u = 0; u < kUnits; ++u) {
      const Vec3& c = units[static_cast<std::size_t>(u)];
      const double unitHeading = 17.0 * u;  // [deg] each unit's mooring pattern is rotated
      if (slot < kMooringsPerUnit) {
        // 3 bundles of 4 lines, 5 deg apart inside a bundle, bundles 120 deg apart.
        const double azimuth = tangle::degToRad(unitHeading + 120.0 * (slot / 4) + 5.0 * (slot % 4 - 1.5));
        const Vec3 dir(std::cos(azimuth), std::sin(azimuth), 0.0);
        const Vec3 fairlead = c + 40.0 * dir + Vec3(0, 0, -20.0);
        const Vec3 anchor = c + 1000.0 * dir + Vec3(0, 0, seabed);
        lines.push_back(catenaryNodes(anchor, fairlead, 1130.0, kMooringRadius));
        radii.push_back(kMooringRadius);
      } else {
        // Risers between the mooring bundles, touchdown and flowline towards the wells.
        const int r = slot - kMooringsPerUnit;
        const double azimuth = tangle::degToRad(unitHeading + 60.0 + 120.0 * (r % 3) + 9.0 * (r / 3));
        const Vec3 dir(std::cos(azimuth), std::sin(azimuth), 0.0);
        const Vec3 hangOff = c + 30.0 * dir + Vec3(0, 0, -15.0);
        const Vec3 end = c + (480.0 + 15.0 * r) * dir + Vec3(0, 0, seabed);
        lines.push_back(catenaryNodes(end, hangOff, 700.0, kRiserRadius));
        radii.push_back(kRiserRadius);
      }
    }
  }
  return lines;
}

/// Proxies of the first `lineCount` lines of the field.
std::vector<SegmentProxy> fieldProxies(int lineCount) {
  std::vector<double> radii;
  const std::vector<std::vector<Vec3>> lines = fieldLines(radii);
  std::vector<SegmentProxy> proxies;
  for (int l = 0; l < lineCount; ++l) {
    const std::vector<Vec3>& nodes = lines[static_cast<std::size_t>(l)];
    for (int e = 0; e < kElementsPerLine; ++e) {
      proxies.push_back({l, e, nodes[static_cast<std::size_t>(e)], nodes[static_cast<std::size_t>(e) + 1],
                         radii[static_cast<std::size_t>(l)]});
    }
  }
  return proxies;
}

void BM_ContactSearch(benchmark::State& state) {
  const std::vector<SegmentProxy> proxies = fieldProxies(static_cast<int>(state.range(0)));
  BroadPhaseOptions options;
  options.margin = kMargin;
  BroadPhase broadPhase(options);
  std::vector<CandidatePair> pairs;
  std::size_t close = 0;
  for (auto _ : state) {
    broadPhase.findPairs(proxies, pairs);
    close = 0;
    for (const CandidatePair& p : pairs) {
      const SegmentProxy& a = proxies[static_cast<std::size_t>(p.first)];
      const SegmentProxy& b = proxies[static_cast<std::size_t>(p.second)];
      const auto result = tangle::geometry::segmentDistance(a.a, a.b, b.a, b.b);
      if (result.distance < a.radius + b.radius + kMargin) ++close;
    }
    benchmark::DoNotOptimize(close);
  }
  state.SetComplexityN(static_cast<benchmark::IterationCount>(proxies.size()));
  state.counters["elements"] = static_cast<double>(proxies.size());
  state.counters["candidates"] = static_cast<double>(pairs.size());
  state.counters["close"] = static_cast<double>(close);
  state.counters["boxTests"] = static_cast<double>(broadPhase.statistics().boxTests);
}
BENCHMARK(BM_ContactSearch)
    ->Arg(10)
    ->Arg(30)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

void BM_BroadPhase(benchmark::State& state) {
  const std::vector<SegmentProxy> proxies = fieldProxies(static_cast<int>(state.range(0)));
  BroadPhaseOptions options;
  options.margin = kMargin;
  BroadPhase broadPhase(options);
  std::vector<CandidatePair> pairs;
  for (auto _ : state) {
    broadPhase.findPairs(proxies, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.SetComplexityN(static_cast<benchmark::IterationCount>(proxies.size()));
  state.counters["elements"] = static_cast<double>(proxies.size());
  state.counters["candidates"] = static_cast<double>(pairs.size());
  state.counters["cellEntries"] = static_cast<double>(broadPhase.statistics().cellEntries);
}
BENCHMARK(BM_BroadPhase)
    ->Arg(10)
    ->Arg(30)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

}  // namespace

BENCHMARK_MAIN();
