/// @file bench_beam_element.cpp
/// One co-rotational beam element (tangle::element::CorotationalBeam), a riser section bent and twisted by
/// a few degrees after a large rigid rotation (issue 8: the tangent dominated a matrix refresh of the
/// drilling riser):
///  - BM_BeamForce: the closed-form internal force (every residual evaluation);
///  - BM_BeamTangent: force and tangent as compute() makes them (the closed-form force in first-order jets,
///    symmetric part of its derivative);
///  - BM_BeamReferenceTangent: the same by second-order jets of the strain energy (the former tangent, now
///    the tests' reference).
/// Wall time per element (nanoseconds).
///
/// Measured (release build, this 2-core machine): force 0.11 us, tangent 2.0 us, reference tangent 6.0 us.

#include <benchmark/benchmark.h>

#include "tangle/core/Types.hpp"
#include "tangle/element/CorotationalBeam.hpp"
#include "tangle/geometry/Rotation.hpp"

namespace {

using tangle::Mat12;
using tangle::Mat3;
using tangle::Vec12;
using tangle::Vec3;

struct ElementState {
  Vec3 x1, x2;
  Mat3 q1, q2;
};

ElementState deformedState() {
  const Mat3 rigid = tangle::geometry::expMap(Vec3(0.4, -1.1, 0.7));
  const Mat3 frame =
      tangle::geometry::frameFromTangent(Vec3(1.0, 0.2, -0.1).normalized(), Vec3(0.0, 0.0, 1.0));
  ElementState s;
  s.x1 = Vec3(10.0, -3.0, -150.0);
  s.x2 = s.x1 + rigid * (3.3 * Vec3(1.0, 0.2, -0.1).normalized());
  s.q1 = rigid * frame * tangle::geometry::expMap(Vec3(0.02, 0.05, -0.03));
  s.q2 = rigid * frame * tangle::geometry::expMap(Vec3(-0.01, -0.04, 0.06));
  return s;
}

const tangle::element::CorotationalBeam kBeam({5.0e9, 2.0e7, 1.5e7}, 3.3);

void BM_BeamForce(benchmark::State& state) {
  const ElementState s = deformedState();
  Vec12 f;
  for (auto _ : state) {
    kBeam.compute(s.x1, s.q1, s.x2, s.q2, f, nullptr);
    benchmark::DoNotOptimize(f.data());
  }
}

void BM_BeamTangent(benchmark::State& state) {
  const ElementState s = deformedState();
  Vec12 f;
  Mat12 k;
  for (auto _ : state) {
    kBeam.compute(s.x1, s.q1, s.x2, s.q2, f, &k);
    benchmark::DoNotOptimize(k.data());
  }
}

void BM_BeamReferenceTangent(benchmark::State& state) {
  const ElementState s = deformedState();
  Vec12 f;
  Mat12 k;
  for (auto _ : state) {
    kBeam.referenceTangent(s.x1, s.q1, s.x2, s.q2, f, k);
    benchmark::DoNotOptimize(k.data());
  }
}

}  // namespace

BENCHMARK(BM_BeamForce);
BENCHMARK(BM_BeamTangent);
BENCHMARK(BM_BeamReferenceTangent);

BENCHMARK_MAIN();
