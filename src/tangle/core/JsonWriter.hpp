#pragma once
/// @file JsonWriter.hpp
/// A small streaming JSON writer (objects, arrays, numbers, strings, booleans) with proper escaping
/// and non-finite numbers written as null.

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace tangle::core {

/// Streaming JSON writer. Usage: beginObject(); key("a"); value(1.0); endObject();
class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : m_out(&out) {}
  void beginObject();
  void endObject();
  void beginArray();
  void endArray();
  /// Writes an object key (inside an object).
  void key(std::string_view k);
  void value(double v);
  void value(int v);
  void value(bool v);
  void value(std::string_view v);
  void value(const char* v) { value(std::string_view(v)); }
  /// Writes an array of numbers.
  void value(const std::vector<double>& v);
  /// Writes `"k": v` inside an object (key() then value()).
  template <class T>
  void field(std::string_view k, const T& v) {
    key(k);
    value(v);
  }

 private:
  void separator();
  void writeString(std::string_view s);
  std::ostream* m_out;
  std::vector<bool> m_first;  // per open container: no element written yet
  bool m_afterKey = false;
};

}  // namespace tangle::core
