#pragma once
/// @file PointArrays.hpp
/// Bitwise comparison and copy of arrays of points (std::vector<Vec3>, as model::State::position) and of
/// VecX, as memcmp and memcpy: std::vector's own copy of Eigen's Vec3 goes element by element (2.5 k
/// instructions for 300 nodes against ~0.2 k), and a value-by-value comparison treats +0 and -0 as equal,
/// which a cache keyed on the state need not.

#include <cstring>
#include <vector>

#include "tangle/core/Types.hpp"

namespace tangle::core {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "a vector of Vec3 is an array of doubles");

/// Whether two arrays of points hold the same bits (sizes included).
inline bool sameBits(const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
  return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(Vec3)) == 0);
}

/// Whether two vectors hold the same bits (sizes included).
inline bool sameBits(const VecX& x, const VecX& y) {
  return x.size() == y.size() &&
         (x.size() == 0 ||
          std::memcmp(x.data(), y.data(), static_cast<std::size_t>(x.size()) * sizeof(double)) == 0);
}

/// to = from, as one block copy (the capacity of `to` reused).
inline void copyPoints(const std::vector<Vec3>& from, std::vector<Vec3>& to) {
  to.resize(from.size());
  if (!from.empty()) std::memcpy(static_cast<void*>(to.data()), from.data(), from.size() * sizeof(Vec3));
}

}  // namespace tangle::core
