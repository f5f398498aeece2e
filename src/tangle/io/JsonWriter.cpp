#include "tangle/io/JsonWriter.hpp"

#include <cmath>
#include <fmt/format.h>

namespace tangle::io {

void JsonWriter::separator() {
  if (m_afterKey) {
    m_afterKey = false;
    return;
  }
  if (!m_first.empty()) {
    if (!m_first.back()) *m_out << ",";
    m_first.back() = false;
    *m_out << "\n" << std::string(2 * m_first.size(), ' ');
  }
}

void JsonWriter::beginObject() {
  separator();
  *m_out << "{";
  m_first.push_back(true);
}

void JsonWriter::endObject() {
  const bool empty = m_first.back();
  m_first.pop_back();
  if (!empty) *m_out << "\n" << std::string(2 * m_first.size(), ' ');
  *m_out << "}";
  if (m_first.empty()) *m_out << "\n";
}

void JsonWriter::beginArray() {
  separator();
  *m_out << "[";
  m_first.push_back(true);
}

void JsonWriter::endArray() {
  const bool empty = m_first.back();
  m_first.pop_back();
  if (!empty) *m_out << "\n" << std::string(2 * m_first.size(), ' ');
  *m_out << "]";
}

void JsonWriter::key(std::string_view k) {
  separator();
  writeString(k);
  *m_out << ": ";
  m_afterKey = true;
}

void JsonWriter::value(double v) {
  separator();
  if (std::isfinite(v)) {
    *m_out << fmt::format("{:.10g}", v);
  } else {
    *m_out << "null";
  }
}

void JsonWriter::value(int v) {
  separator();
  *m_out << v;
}

void JsonWriter::value(bool v) {
  separator();
  *m_out << (v ? "true" : "false");
}

void JsonWriter::value(std::string_view v) {
  separator();
  writeString(v);
}

void JsonWriter::value(const std::vector<double>& v) {
  separator();
  *m_out << "[";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) *m_out << ", ";
    if (std::isfinite(v[i])) {
      *m_out << fmt::format("{:.10g}", v[i]);
    } else {
      *m_out << "null";
    }
  }
  *m_out << "]";
}

void JsonWriter::writeString(std::string_view s) {
  *m_out << '"';
  for (char c : s) {
    switch (c) {
      case '"': *m_out << "\\\""; break;
      case '\\': *m_out << "\\\\"; break;
      case '\n': *m_out << "\\n"; break;
      case '\t': *m_out << "\\t"; break;
      case '\r': *m_out << "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          *m_out << fmt::format("\\u{:04x}", static_cast<int>(c));
        } else {
          *m_out << c;
        }
    }
  }
  *m_out << '"';
}

}  // namespace tangle::io
