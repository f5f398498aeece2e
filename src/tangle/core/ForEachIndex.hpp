#pragma once
/// @file ForEachIndex.hpp
/// One loop body for "every item" and "the items of a list" (assembly of the whole model or of a part).

#include <cstddef>
#include <vector>

namespace tangle {

/// Calls fn(i) for every index of `list` in its order, or for i = 0 ... count - 1 when `list` is null.
template <class Fn>
inline void forEachIndex(const std::vector<int>* list, std::size_t count, Fn&& fn) {
  if (list) {
    for (const int i : *list) fn(static_cast<std::size_t>(i));
  } else {
    for (std::size_t i = 0; i < count; ++i) fn(i);
  }
}

}  // namespace tangle
