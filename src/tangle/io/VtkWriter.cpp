#include "tangle/io/VtkWriter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <system_error>
#include <utility>

#include "tangle/core/Error.hpp"

namespace tangle::io {

namespace fs = std::filesystem;

namespace {

constexpr int kVtkVertex = 1;
constexpr int kVtkPolyLine = 4;
constexpr std::size_t kValuesPerRow = 6;     // numbers per text row inside a DataArray
constexpr const char* kIndent = "        ";  // DataArray content indentation

/// Escapes a string for an XML attribute value.
std::string xmlEscape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      case '\n':
        out += "&#10;";
        break;
      case '\r':
        out += "&#13;";
        break;
      case '\t':
        out += "&#9;";
        break;
      default:
        // Other control characters are not allowed in XML 1.0.
        out += (static_cast<unsigned char>(c) < 0x20) ? '?' : c;
    }
  }
  return out;
}

/// Makes a string safe inside an XML comment (no "--", no trailing '-', no control characters).
std::string commentSafe(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const char d = (static_cast<unsigned char>(c) < 0x20) ? '?' : c;
    if (d == '-' && !out.empty() && out.back() == '-') out += ' ';
    out += d;
  }
  if (!out.empty() && out.back() == '-') out += ' ';
  return out;
}

using Buffer = fmt::memory_buffer;

void appendDoubles(Buffer& b, const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i % kValuesPerRow == 0) {
      fmt::format_to(std::back_inserter(b), "{}{}", i == 0 ? "" : "\n", kIndent);
    } else {
      b.push_back(' ');
    }
    fmt::format_to(std::back_inserter(b), "{:.9g}", v[i]);
  }
  if (!v.empty()) b.push_back('\n');
}

void appendInts(Buffer& b, const std::vector<std::int64_t>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i % kValuesPerRow == 0) {
      fmt::format_to(std::back_inserter(b), "{}{}", i == 0 ? "" : "\n", kIndent);
    } else {
      b.push_back(' ');
    }
    fmt::format_to(std::back_inserter(b), "{}", v[i]);
  }
  if (!v.empty()) b.push_back('\n');
}

void appendArray(Buffer& b, const std::string& type, const std::string& name, const std::vector<double>& v) {
  fmt::format_to(std::back_inserter(b), "      <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n", type,
                 xmlEscape(name));
  appendDoubles(b, v);
  fmt::format_to(std::back_inserter(b), "      </DataArray>\n");
}

void appendArray(Buffer& b, const std::string& type, const std::string& name,
                 const std::vector<std::int64_t>& v) {
  fmt::format_to(std::back_inserter(b), "      <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n", type,
                 xmlEscape(name));
  appendInts(b, v);
  fmt::format_to(std::back_inserter(b), "      </DataArray>\n");
}

void appendHeader(Buffer& b, double time, const std::vector<std::string>& comments) {
  fmt::format_to(std::back_inserter(b), "<?xml version=\"1.0\"?>\n");
  for (const std::string& c : comments)
    fmt::format_to(std::back_inserter(b), "<!-- {} -->\n", commentSafe(c));
  fmt::format_to(
      std::back_inserter(b),
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <FieldData>\n"
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">\n"
      "{}{:.12g}\n"
      "      </DataArray>\n"
      "    </FieldData>\n",
      kIndent, time);
}

void appendPoints(Buffer& b, const std::vector<const Vec3*>& points) {
  fmt::format_to(
      std::back_inserter(b),
      "    <Points>\n"
      "      <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const Vec3* p : points) {
    fmt::format_to(std::back_inserter(b), "{}{:.12g} {:.12g} {:.12g}\n", kIndent, p->x(), p->y(), p->z());
  }
  fmt::format_to(std::back_inserter(b),
                 "      </DataArray>\n"
                 "    </Points>\n");
}

void appendCells(Buffer& b, const std::vector<std::int64_t>& connectivity,
                 const std::vector<std::int64_t>& offsets, const std::vector<std::int64_t>& types) {
  fmt::format_to(std::back_inserter(b), "    <Cells>\n");
  appendArray(b, "Int64", "connectivity", connectivity);
  appendArray(b, "Int64", "offsets", offsets);
  appendArray(b, "UInt8", "types", types);
  fmt::format_to(std::back_inserter(b), "    </Cells>\n");
}

void appendFooter(Buffer& b) {
  fmt::format_to(std::back_inserter(b),
                 "    </Piece>\n"
                 "  </UnstructuredGrid>\n"
                 "</VTKFile>\n");
}

/// Writes `b` to `file` through a temporary file in the same directory and a rename.
void writeAtomically(const fs::path& file, const Buffer& b) {
  std::error_code ec;
  if (file.has_parent_path()) {
    fs::create_directories(file.parent_path(), ec);
    if (ec) {
      throw Error("VTK output: cannot create directory " + file.parent_path().string() + " for " +
                  file.string() + ": " + ec.message());
    }
  }
  fs::path tmp = file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("VTK output: cannot open " + tmp.string() + " for writing");
    out.write(b.data(), static_cast<std::streamsize>(b.size()));
    out.close();
    if (!out) {
      fs::remove(tmp, ec);
      throw Error("VTK output: write failed for " + tmp.string() + " (disk full?)");
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error("VTK output: cannot rename " + tmp.string() + " to " + file.string() + ": " + ec.message());
  }
}

/// Checks one scalar field name; `reserved` are names the writer uses itself.
void checkFieldName(const fs::path& file, const std::string& where, const std::string& name,
                    std::initializer_list<const char*> reserved) {
  if (name.empty()) throw Error("VTK output " + file.string() + ": " + where + ": empty field name");
  for (const char* r : reserved) {
    if (name == r) {
      throw Error("VTK output " + file.string() + ": " + where + ": field name '" + name +
                  "' is reserved by the writer");
    }
  }
}

}  // namespace

void writeVtu(const fs::path& file, const std::vector<VtkPolyline>& lines, double time) {
  // Validate, count and collect the union of field names in order of first appearance.
  std::vector<std::string> fieldNames;
  std::size_t nPoints = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const VtkPolyline& line = lines[l];
    const std::string where = fmt::format("line {} '{}'", l, line.name);
    if (line.points.empty()) throw Error("VTK output " + file.string() + ": " + where + " has no points");
    nPoints += line.points.size();
    for (std::size_t f = 0; f < line.pointScalars.size(); ++f) {
      const auto& [name, values] = line.pointScalars[f];
      checkFieldName(file, where, name, {"line_id", "arc_index"});
      if (values.size() != line.points.size()) {
        throw Error(fmt::format("VTK output {}: {}: field '{}' has {} values for {} points", file.string(),
                                where, name, values.size(), line.points.size()));
      }
      for (std::size_t g = 0; g < f; ++g) {
        if (line.pointScalars[g].first == name) {
          throw Error("VTK output " + file.string() + ": " + where + ": field '" + name + "' given twice");
        }
      }
      bool known = false;
      for (const std::string& n : fieldNames) known = known || n == name;
      if (!known) fieldNames.push_back(name);
    }
  }

  std::vector<const Vec3*> points;
  points.reserve(nPoints);
  std::vector<std::int64_t> connectivity, offsets, types, cellLineId, pointLineId, arcIndex;
  connectivity.reserve(nPoints);
  pointLineId.reserve(nPoints);
  arcIndex.reserve(nPoints);
  std::vector<std::string> comments;
  comments.push_back(fmt::format("tangle lines: {} poly-line cells, {} points", lines.size(), nPoints));
  for (std::size_t l = 0; l < lines.size(); ++l) {
    comments.push_back(fmt::format("line_id {}: {}", l, lines[l].name));
    for (std::size_t i = 0; i < lines[l].points.size(); ++i) {
      connectivity.push_back(static_cast<std::int64_t>(points.size()));
      points.push_back(&lines[l].points[i]);
      pointLineId.push_back(static_cast<std::int64_t>(l));
      arcIndex.push_back(static_cast<std::int64_t>(i));
    }
    offsets.push_back(static_cast<std::int64_t>(points.size()));
    types.push_back(kVtkPolyLine);
    cellLineId.push_back(static_cast<std::int64_t>(l));
  }

  Buffer b;
  appendHeader(b, time, comments);
  fmt::format_to(std::back_inserter(b), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", nPoints,
                 lines.size());
  fmt::format_to(std::back_inserter(b), "    <PointData>\n");
  std::vector<double> values;
  values.reserve(nPoints);
  for (const std::string& name : fieldNames) {
    values.clear();
    for (const VtkPolyline& line : lines) {
      const std::vector<double>* found = nullptr;
      for (const auto& field : line.pointScalars) {
        if (field.first == name) found = &field.second;
      }
      if (found != nullptr) {
        values.insert(values.end(), found->begin(), found->end());
      } else {
        values.insert(values.end(), line.points.size(), 0.0);
      }
    }
    appendArray(b, "Float64", name, values);
  }
  appendArray(b, "Int32", "line_id", pointLineId);
  appendArray(b, "Int32", "arc_index", arcIndex);
  fmt::format_to(std::back_inserter(b), "    </PointData>\n    <CellData>\n");
  appendArray(b, "Int32", "line_id", cellLineId);
  fmt::format_to(std::back_inserter(b), "    </CellData>\n");
  appendPoints(b, points);
  appendCells(b, connectivity, offsets, types);
  appendFooter(b);
  writeAtomically(file, b);
}

void writeVtuPoints(const fs::path& file, const std::vector<Vec3>& points,
                    const std::vector<VtkScalarField>& scalars, double time) {
  for (std::size_t f = 0; f < scalars.size(); ++f) {
    const auto& [name, values] = scalars[f];
    checkFieldName(file, "points", name, {"point_id"});
    if (values.size() != points.size()) {
      throw Error(fmt::format("VTK output {}: field '{}' has {} values for {} points", file.string(), name,
                              values.size(), points.size()));
    }
    for (std::size_t g = 0; g < f; ++g) {
      if (scalars[g].first == name)
        throw Error("VTK output " + file.string() + ": field '" + name + "' given twice");
    }
  }
  const std::size_t n = points.size();
  std::vector<const Vec3*> pointPtrs;
  std::vector<std::int64_t> ids, offsets, types;
  pointPtrs.reserve(n);
  ids.reserve(n);
  offsets.reserve(n);
  types.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    pointPtrs.push_back(&points[i]);
    ids.push_back(static_cast<std::int64_t>(i));
    offsets.push_back(static_cast<std::int64_t>(i + 1));
    types.push_back(kVtkVertex);
  }

  Buffer b;
  appendHeader(b, time, {fmt::format("tangle points: {} vertex cells", n)});
  fmt::format_to(std::back_inserter(b), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n);
  fmt::format_to(std::back_inserter(b), "    <PointData>\n");
  for (const auto& [name, values] : scalars) appendArray(b, "Float64", name, values);
  appendArray(b, "Int32", "point_id", ids);
  fmt::format_to(std::back_inserter(b), "    </PointData>\n");
  appendPoints(b, pointPtrs);
  appendCells(b, ids, offsets, types);
  appendFooter(b);
  writeAtomically(file, b);
}

// ---------------------------------------------------------------------------------------------------
// PvdSeries

namespace {

constexpr const char* kPvdFooter =
    "  </Collection>\n"
    "</VTKFile>\n";

}  // namespace

PvdSeries::PvdSeries(fs::path pvdFile) : m_pvdFile(std::move(pvdFile)) {
  if (m_pvdFile.filename().empty())
    throw Error("VTK output: '" + m_pvdFile.string() + "' is not a file path");
  m_vtuDir = m_pvdFile.parent_path() / (m_pvdFile.stem().string() + "_vtu");
  std::error_code ec;
  fs::create_directories(m_vtuDir, ec);
  if (ec) throw Error("VTK output: cannot create directory " + m_vtuDir.string() + ": " + ec.message());

  m_pvd.open(m_pvdFile, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!m_pvd) throw Error("VTK output: cannot open " + m_pvdFile.string() + " for writing");
  m_pvd << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
  m_footerPos = m_pvd.tellp();
  m_pvd << kPvdFooter;
  m_pvd.flush();
  if (!m_pvd) throw Error("VTK output: write failed for " + m_pvdFile.string());
  m_open = true;
}

PvdSeries::~PvdSeries() {
  try {
    close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; call close() to see errors
  }
}

PvdSeries::PvdSeries(PvdSeries&& other) noexcept
    : m_pvdFile(std::move(other.m_pvdFile)),
      m_vtuDir(std::move(other.m_vtuDir)),
      m_pvd(std::move(other.m_pvd)),
      m_footerPos(other.m_footerPos),
      m_steps(other.m_steps),
      m_open(std::exchange(other.m_open, false)) {}

PvdSeries& PvdSeries::operator=(PvdSeries&& other) noexcept {
  if (this != &other) {
    try {
      close();
    } catch (...) {  // NOLINT(bugprone-empty-catch): noexcept; the previous series is abandoned
    }
    m_pvdFile = std::move(other.m_pvdFile);
    m_vtuDir = std::move(other.m_vtuDir);
    m_pvd = std::move(other.m_pvd);
    m_footerPos = other.m_footerPos;
    m_steps = other.m_steps;
    m_open = std::exchange(other.m_open, false);
  }
  return *this;
}

fs::path PvdSeries::nextVtuPath(double time) const {
  if (!m_open) throw Error("VTK output: series " + m_pvdFile.string() + " is closed");
  if (!std::isfinite(time)) {
    throw Error(fmt::format("VTK output: series {}: step {} has non-finite time {}", m_pvdFile.string(),
                            m_steps, time));
  }
  return m_vtuDir / fmt::format("{}_{:06d}.vtu", m_pvdFile.stem().string(), m_steps);
}

void PvdSeries::appendEntry(double time, const fs::path& vtu) {
  // Relative to the .pvd's directory, with '/' separators (what ParaView expects on every platform).
  const std::string relative = (fs::path(m_vtuDir.filename()) / vtu.filename()).generic_string();
  m_pvd.seekp(m_footerPos);
  m_pvd << fmt::format("    <DataSet timestep=\"{:.12g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", time,
                       xmlEscape(relative));
  m_footerPos = m_pvd.tellp();
  m_pvd << kPvdFooter;
  m_pvd.flush();
  if (!m_pvd) throw Error("VTK output: write failed for " + m_pvdFile.string() + " (disk full?)");
  ++m_steps;
}

fs::path PvdSeries::addStep(double time, const std::vector<VtkPolyline>& lines) {
  const fs::path vtu = nextVtuPath(time);
  writeVtu(vtu, lines, time);
  appendEntry(time, vtu);
  return vtu;
}

fs::path PvdSeries::addPointStep(double time, const std::vector<Vec3>& points,
                                 const std::vector<VtkScalarField>& scalars) {
  const fs::path vtu = nextVtuPath(time);
  writeVtuPoints(vtu, points, scalars, time);
  appendEntry(time, vtu);
  return vtu;
}

void PvdSeries::close() {
  if (!m_open) return;
  m_open = false;
  m_pvd.flush();
  const bool ok = static_cast<bool>(m_pvd);
  m_pvd.close();
  if (!ok || m_pvd.fail()) throw Error("VTK output: write failed for " + m_pvdFile.string());
}

}  // namespace tangle::io
