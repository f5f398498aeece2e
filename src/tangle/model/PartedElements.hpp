#pragma once
/// @file PartedElements.hpp
/// Which elements of the model have parted (lines[].failure, analysis/LineFailure.hpp) and when. A parted
/// element carries no force (axial, bending, torsion, damping), has no drag or added mass and takes no part
/// in contact; its mass, weight and buoyancy stay lumped at its nodes (docs/theory.md 8.7).
///
/// Read by the assembly, the hydrodynamic loads and the contact on the solver's thread and by the results
/// of past steps on the writer's thread while the solver's thread parts elements: each element's parting
/// time is an atomic, and whether an element is parted is asked of a state's time, so a step computed
/// before the break reads it intact whenever the writer gets to it.

#include <atomic>
#include <cstddef>
#include <limits>
#include <memory>

namespace tangle::model {

class PartedElements {
 public:
  explicit PartedElements(std::size_t elementCount)
      : m_count(elementCount), m_time(std::make_unique<std::atomic<double>[]>(elementCount)) {
    for (std::size_t e = 0; e < m_count; ++e) m_time[e].store(kIntact, std::memory_order_relaxed);
  }

  /// Element e parts after `time` [s]: states of a later time see it parted (-infinity: from the start,
  /// statics included). Parting an element twice keeps the first time.
  void part(std::size_t e, double time) {
    if (m_time[e].load(std::memory_order_relaxed) != kIntact) return;
    m_time[e].store(time, std::memory_order_release);
    m_any.store(true, std::memory_order_release);
  }
  /// True when element e is parted in a state of time `time` [s].
  bool parted(std::size_t e, double time) const {
    return m_any.load(std::memory_order_acquire) && time > m_time[e].load(std::memory_order_acquire);
  }
  /// True when any element has parted (at any time).
  bool any() const { return m_any.load(std::memory_order_acquire); }
  /// Element e's parting time [s] (+infinity while intact).
  double partingTime(std::size_t e) const { return m_time[e].load(std::memory_order_acquire); }
  std::size_t size() const { return m_count; }

 private:
  static constexpr double kIntact = std::numeric_limits<double>::infinity();
  std::size_t m_count;
  std::unique_ptr<std::atomic<double>[]> m_time;
  std::atomic<bool> m_any{false};
};

}  // namespace tangle::model
