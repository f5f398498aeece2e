#include "tangle/core/JsonWriter.hpp"

#include <cmath>
#include <fmt/format.h>

namespace tangle::core {

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

namespace {

/// Length of the valid UTF-8 sequence starting at s[i], or 0 if the bytes there are not one (stray
/// continuation byte, truncated sequence, overlong form, surrogate, beyond U+10FFFF).
std::size_t utf8SequenceLength(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    if (b0 == 0xE0) lo = 0xA0;  // overlong
    if (b0 == 0xED) hi = 0x9F;  // surrogates
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    if (b0 == 0xF0) lo = 0x90;  // overlong
    if (b0 == 0xF4) hi = 0x8F;  // beyond U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

}  // namespace

void JsonWriter::writeString(std::string_view s) {
  // JSON text must be UTF-8: a byte that does not start a valid sequence (a Latin-1 name, say) is
  // written as U+FFFD, the replacement character, so the file always parses.
  *m_out << '"';
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const std::size_t n = utf8SequenceLength(s, i);
    if (n == 0) {
      *m_out << "\\ufffd";
      ++i;
      continue;
    }
    if (n > 1) {
      *m_out << s.substr(i, n);
      i += n;
      continue;
    }
    ++i;
    switch (c) {
      case '"': *m_out << "\\\""; break;
      case '\\': *m_out << "\\\\"; break;
      case '\n': *m_out << "\\n"; break;
      case '\t': *m_out << "\\t"; break;
      case '\r': *m_out << "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          *m_out << fmt::format("\\u{:04x}", static_cast<int>(c));
        } else {
          *m_out << c;
        }
    }
  }
  *m_out << '"';
}

}  // namespace tangle::core
