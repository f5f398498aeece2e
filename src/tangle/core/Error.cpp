#include "tangle/core/Error.hpp"

#include <fmt/format.h>

namespace tangle {

std::string InputError::format(const std::string& file, int line, const std::string& key,
                               const std::string& expected) {
  const std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  return key.empty() ? fmt::format("{}: {}", where, expected) : fmt::format("{}: key '{}': {}", where, key, expected);
}

}  // namespace tangle
