/// @file VtkWriterTest.cpp
/// Tests of the ParaView writers (tangle::io::writeVtu, writeVtuPoints, PvdSeries): the files are read
/// back as text and their VTK structure (counts, connectivity, offsets, cell types, arrays) and XML
/// well-formedness are checked.

#include "tangle/io/VtkWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tangle/core/Error.hpp"

namespace tangle::io {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Part of `xml` between `<tag` and `</tag>` (first occurrence); empty if absent.
std::string section(const std::string& xml, const std::string& tag) {
  const std::size_t a = xml.find("<" + tag);
  if (a == std::string::npos) return {};
  const std::size_t b = xml.find("</" + tag + ">", a);
  if (b == std::string::npos) return {};
  return xml.substr(a, b - a);
}

/// Whether `text` holds a DataArray named `name`.
bool hasArray(const std::string& text, const std::string& name) {
  return text.find("Name=\"" + name + "\"") != std::string::npos;
}

/// Numbers of the DataArray named `name` in `text` (empty if absent).
std::vector<double> arrayValues(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const std::size_t begin = text.find('>', at) + 1;
  const std::size_t end = text.find("</DataArray>", begin);
  std::istringstream in(text.substr(begin, end - begin));
  std::vector<double> v;
  double x = 0.0;
  while (in >> x) v.push_back(x);
  return v;
}

/// Value of attribute `attr` of the first element `<tag ...>` in `xml`.
std::string attribute(const std::string& xml, const std::string& tag, const std::string& attr) {
  const std::size_t a = xml.find("<" + tag + " ");
  if (a == std::string::npos) return {};
  const std::size_t close = xml.find('>', a);
  const std::size_t at = xml.find(" " + attr + "=\"", a);
  if (at == std::string::npos || at > close) return {};
  const std::size_t v = at + attr.size() + 3;
  return xml.substr(v, xml.find('"', v) - v);
}

/// Every `<DataSet .../>` element of a .pvd, as its full tag text.
std::vector<std::string> dataSets(const std::string& pvd) {
  std::vector<std::string> out;
  for (std::size_t a = pvd.find("<DataSet "); a != std::string::npos; a = pvd.find("<DataSet ", a + 1)) {
    out.push_back(pvd.substr(a, pvd.find('>', a) - a + 1));
  }
  return out;
}

/// Minimal well-formedness check: one XML declaration first, comments closed, start and end tags
/// balanced and properly nested, exactly one root element, no stray '<' or '&' in text.
::testing::AssertionResult wellFormed(const std::string& xml) {
  if (xml.rfind("<?xml", 0) != 0) return ::testing::AssertionFailure() << "no XML declaration at the start";
  std::vector<std::string> stack;
  int roots = 0;
  std::size_t i = 0;
  while (i < xml.size()) {
    const std::size_t lt = xml.find('<', i);
    const std::string text = xml.substr(i, (lt == std::string::npos ? xml.size() : lt) - i);
    if (text.find('>') != std::string::npos) return ::testing::AssertionFailure() << "stray '>' in text";
    for (std::size_t amp = text.find('&'); amp != std::string::npos; amp = text.find('&', amp + 1)) {
      if (text.find(';', amp) == std::string::npos)
        return ::testing::AssertionFailure() << "bare '&' in text";
    }
    if (stack.empty() && text.find_first_not_of(" \t\r\n") != std::string::npos) {
      return ::testing::AssertionFailure() << "text outside the root element";
    }
    if (lt == std::string::npos) break;
    if (xml.compare(lt, 4, "<!--") == 0) {
      const std::size_t end = xml.find("-->", lt + 4);
      if (end == std::string::npos) return ::testing::AssertionFailure() << "unclosed comment";
      if (xml.substr(lt + 4, end - lt - 4).find("--") != std::string::npos) {
        return ::testing::AssertionFailure() << "'--' inside a comment";
      }
      i = end + 3;
      continue;
    }
    if (xml.compare(lt, 2, "<?") == 0) {
      if (lt != 0) return ::testing::AssertionFailure() << "processing instruction after the start";
      i = xml.find("?>", lt) + 2;
      continue;
    }
    const std::size_t gt = xml.find('>', lt);
    if (gt == std::string::npos) return ::testing::AssertionFailure() << "unclosed tag at " << lt;
    const std::string tag = xml.substr(lt + 1, gt - lt - 1);
    if (tag.find('<') != std::string::npos) return ::testing::AssertionFailure() << "'<' inside tag " << tag;
    if (tag.empty()) return ::testing::AssertionFailure() << "empty tag";
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (stack.empty() || stack.back() != name) {
        return ::testing::AssertionFailure() << "end tag </" << name << "> does not match <"
                                             << (stack.empty() ? std::string("none") : stack.back()) << ">";
      }
      stack.pop_back();
    } else {
      const std::string name = tag.substr(0, tag.find_first_of(" \t\r\n/"));
      if (stack.empty() && ++roots > 1) return ::testing::AssertionFailure() << "more than one root element";
      // Attribute values must be quoted in pairs.
      std::size_t quotes = 0;
      for (const char c : tag) quotes += c == '"' ? 1 : 0;
      if (quotes % 2 != 0) return ::testing::AssertionFailure() << "unbalanced quotes in <" << tag << ">";
      if (tag.back() != '/') stack.push_back(name);
    }
    i = gt + 1;
  }
  if (!stack.empty()) return ::testing::AssertionFailure() << "unclosed element <" << stack.back() << ">";
  if (roots != 1) return ::testing::AssertionFailure() << "no root element";
  return ::testing::AssertionSuccess();
}

/// Parses `file` with Python's xml.etree if Debian's python3 is installed; success otherwise.
::testing::AssertionResult parsesWithPythonIfAvailable(const fs::path& file) {
  const fs::path python = "/usr/bin/python3";
  if (!fs::exists(python)) return ::testing::AssertionSuccess();
  const std::string cmd = python.string() +
                          " -c \"import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])\" '" +
                          file.string() + "' > /dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0)
    return ::testing::AssertionFailure() << "xml.etree cannot parse " << file;
  return ::testing::AssertionSuccess();
}

// The checker itself must catch what it is meant to catch.
TEST(XmlCheckTest, DetectsMalformedXml) {
  EXPECT_TRUE(wellFormed("<?xml version=\"1.0\"?>\n<!-- c -->\n<a x=\"1\"><b/><c>1 2</c></a>\n"));
  EXPECT_FALSE(wellFormed("<a></a>"));                                     // no declaration
  EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?>\n<a><b></a></b>"));     // crossed
  EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?>\n<a><b></b>"));         // unclosed
  EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?>\n<a></a><a></a>"));     // two roots
  EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?>\n<a x=\"1></a>"));      // quotes
  EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?>\n<a>x & y</a>"));       // bare '&'
  EXPECT_FALSE(wellFormed("<?xml version=\"1.0\"?>\n<!-- a--b --><a/>"));  // '--' in comment
}

class VtkWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    m_dir =
        fs::temp_directory_path() / ("tangle_vtk_test_" + std::to_string(rd()) + "_" + std::to_string(rd()));
    fs::create_directories(m_dir);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(m_dir, ec);
  }

  /// Two lines: "riser" with 3 points and fields tension_N, bending_moment_Nm; "mooring" with 2
  /// points and only tension_N.
  static std::vector<VtkPolyline> twoLines() {
    VtkPolyline riser{"riser", {Vec3(0, 0, -100), Vec3(10, 0, -50), Vec3(20, 1, 0)}, {}};
    riser.pointScalars = {{"tension_N", {1.0e6, 1.1e6, 1.2e6}}, {"bending_moment_Nm", {5.0, 6.0, 7.0}}};
    VtkPolyline mooring{"mooring", {Vec3(-500, 0, -100), Vec3(-1, 0, -20)}, {{"tension_N", {2.0e5, 3.0e5}}}};
    return {riser, mooring};
  }

  fs::path m_dir;
};

TEST_F(VtkWriterTest, PolylinesHaveExpectedCellsArraysAndValues) {
  const fs::path file = m_dir / "lines.vtu";
  writeVtu(file, twoLines(), 12.5);
  ASSERT_TRUE(fs::exists(file));
  const std::string xml = readText(file);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_TRUE(parsesWithPythonIfAvailable(file));

  EXPECT_EQ(attribute(xml, "VTKFile", "type"), "UnstructuredGrid");
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfPoints"), "5");
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfCells"), "2");

  const std::string cells = section(xml, "Cells");
  EXPECT_EQ(arrayValues(cells, "connectivity"), (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_EQ(arrayValues(cells, "offsets"), (std::vector<double>{3, 5}));
  EXPECT_EQ(arrayValues(cells, "types"), (std::vector<double>{4, 4}));

  const std::vector<double> pts = arrayValues(section(xml, "Points"), "Points");
  EXPECT_EQ(pts, (std::vector<double>{0, 0, -100, 10, 0, -50, 20, 1, 0, -500, 0, -100, -1, 0, -20}));

  const std::string pd = section(xml, "PointData");
  EXPECT_EQ(arrayValues(pd, "tension_N"), (std::vector<double>{1.0e6, 1.1e6, 1.2e6, 2.0e5, 3.0e5}));
  // Missing on the mooring line: zeros there.
  EXPECT_EQ(arrayValues(pd, "bending_moment_Nm"), (std::vector<double>{5, 6, 7, 0, 0}));
  EXPECT_EQ(arrayValues(pd, "line_id"), (std::vector<double>{0, 0, 0, 1, 1}));
  EXPECT_EQ(arrayValues(pd, "arc_index"), (std::vector<double>{0, 1, 2, 0, 1}));

  const std::string cd = section(xml, "CellData");
  EXPECT_EQ(arrayValues(cd, "line_id"), (std::vector<double>{0, 1}));
  EXPECT_FALSE(hasArray(cd, "tension_N"));

  EXPECT_EQ(arrayValues(section(xml, "FieldData"), "TimeValue"), (std::vector<double>{12.5}));
  // Names are listed for the human reader.
  EXPECT_NE(xml.find("line_id 0: riser"), std::string::npos);
  EXPECT_NE(xml.find("line_id 1: mooring"), std::string::npos);
  // Nothing left behind by the atomic write.
  EXPECT_FALSE(fs::exists(m_dir / "lines.vtu.tmp"));
}

TEST_F(VtkWriterTest, NumbersKeepEnoughDigits) {
  // A UTM-sized coordinate keeps millimetres; a field keeps 9 significant digits.
  const Vec3 p(612345.6789, 6712345.4321, -1234.5678);
  const double tension = 1.23456789e6;
  const double tiny = 1.2345678e-9;
  writeVtu(m_dir / "precise.vtu", {{"l", {p, p + Vec3(1, 0, 0)}, {{"tension_N", {tension, tiny}}}}},
           10800.05);
  const std::string xml = readText(m_dir / "precise.vtu");
  const std::vector<double> pts = arrayValues(section(xml, "Points"), "Points");
  ASSERT_EQ(pts.size(), 6U);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(pts[k], p[k], 1e-6);
  const std::vector<double> t = arrayValues(section(xml, "PointData"), "tension_N");
  ASSERT_EQ(t.size(), 2U);
  EXPECT_NEAR(t[0], tension, 1e-9 * tension);
  EXPECT_NEAR(t[1], tiny, 1e-8 * tiny);
  EXPECT_EQ(arrayValues(section(xml, "FieldData"), "TimeValue"), (std::vector<double>{10800.05}));
}

TEST_F(VtkWriterTest, EmptyLineListGivesValidEmptyGrid) {
  const fs::path file = m_dir / "none.vtu";
  writeVtu(file, {}, 0.0);
  const std::string xml = readText(file);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_TRUE(parsesWithPythonIfAvailable(file));
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfPoints"), "0");
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfCells"), "0");
}

TEST_F(VtkWriterTest, SpecialCharactersInNamesAreEscaped) {
  const fs::path file = m_dir / "names.vtu";
  writeVtu(file, {{"a--b<&>\"-", {Vec3::Zero(), Vec3::UnitX()}, {{"odd<&\"'>name", {1.0, 2.0}}}}}, 0.0);
  const std::string xml = readText(file);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_TRUE(parsesWithPythonIfAvailable(file));
  EXPECT_TRUE(hasArray(xml, "odd&lt;&amp;&quot;&apos;&gt;name"));
}

TEST_F(VtkWriterTest, CreatesParentDirectories) {
  const fs::path file = m_dir / "a" / "b" / "lines.vtu";
  writeVtu(file, twoLines(), 1.0);
  EXPECT_TRUE(fs::exists(file));
}

TEST_F(VtkWriterTest, RejectsInconsistentInput) {
  const fs::path file = m_dir / "bad.vtu";
  std::vector<VtkPolyline> lines = twoLines();
  lines[1].pointScalars[0].second.push_back(1.0);  // 3 values for 2 points
  EXPECT_THROW(writeVtu(file, lines, 0.0), Error);

  lines = twoLines();
  lines[1].points.clear();
  lines[1].pointScalars.clear();
  EXPECT_THROW(writeVtu(file, lines, 0.0), Error);

  lines = twoLines();
  lines[0].pointScalars.push_back({"tension_N", {1, 2, 3}});  // repeated on one line
  EXPECT_THROW(writeVtu(file, lines, 0.0), Error);

  lines = twoLines();
  lines[0].pointScalars.push_back({"line_id", {1, 2, 3}});  // reserved
  EXPECT_THROW(writeVtu(file, lines, 0.0), Error);

  lines = twoLines();
  lines[0].pointScalars.push_back({"", {1, 2, 3}});
  EXPECT_THROW(writeVtu(file, lines, 0.0), Error);

  EXPECT_THROW(writeVtuPoints(file, {Vec3::Zero()}, {{"force_N", {1.0, 2.0}}}, 0.0), Error);
  EXPECT_THROW(writeVtuPoints(file, {Vec3::Zero()}, {{"point_id", {1.0}}}, 0.0), Error);
  EXPECT_FALSE(fs::exists(file));
}

TEST_F(VtkWriterTest, IoFailureThrowsWithFileName) {
  // A regular file where a directory is needed: fails for every user, root included.
  const fs::path blocker = m_dir / "not_a_dir";
  std::ofstream(blocker) << "x";
  const fs::path file = blocker / "lines.vtu";
  try {
    writeVtu(file, twoLines(), 0.0);
    FAIL() << "expected tangle::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("lines.vtu"), std::string::npos) << e.what();
  }
  EXPECT_THROW(writeVtuPoints(file, {}, {}, 0.0), Error);
  EXPECT_THROW(PvdSeries(blocker / "series.pvd"), Error);
}

TEST_F(VtkWriterTest, PointsAreVertexCells) {
  const fs::path file = m_dir / "contacts.vtu";
  const std::vector<Vec3> pts{Vec3(1, 2, 3), Vec3(4, 5, 6), Vec3(7, 8, 9)};
  writeVtuPoints(file, pts, {{"impact_energy_J", {10.0, 20.0, 30.0}}, {"peak_force_N", {1e3, 2e3, 3e3}}},
                 4.0);
  const std::string xml = readText(file);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_TRUE(parsesWithPythonIfAvailable(file));
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfPoints"), "3");
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfCells"), "3");
  const std::string cells = section(xml, "Cells");
  EXPECT_EQ(arrayValues(cells, "connectivity"), (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(arrayValues(cells, "offsets"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(arrayValues(cells, "types"), (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(arrayValues(section(xml, "Points"), "Points"), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  const std::string pd = section(xml, "PointData");
  EXPECT_EQ(arrayValues(pd, "impact_energy_J"), (std::vector<double>{10, 20, 30}));
  EXPECT_EQ(arrayValues(pd, "peak_force_N"), (std::vector<double>{1e3, 2e3, 3e3}));
  EXPECT_EQ(arrayValues(pd, "point_id"), (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(arrayValues(section(xml, "FieldData"), "TimeValue"), (std::vector<double>{4.0}));
}

TEST_F(VtkWriterTest, NoPointsGiveValidEmptyGrid) {
  const fs::path file = m_dir / "nocontact.vtu";
  writeVtuPoints(file, {}, {{"impact_energy_J", {}}}, 1.0);
  const std::string xml = readText(file);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_TRUE(parsesWithPythonIfAvailable(file));
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfPoints"), "0");
  EXPECT_EQ(attribute(xml, "Piece", "NumberOfCells"), "0");
  EXPECT_TRUE(hasArray(xml, "impact_energy_J"));
}

TEST_F(VtkWriterTest, PvdListsEveryStepWithRelativePathsAndStaysValid) {
  const fs::path pvd = m_dir / "lines.pvd";
  PvdSeries series(pvd);
  EXPECT_EQ(series.vtuDirectory(), m_dir / "lines_vtu");
  {
    const std::string xml = readText(pvd);  // valid and empty before any step
    EXPECT_TRUE(wellFormed(xml));
    EXPECT_TRUE(dataSets(xml).empty());
  }
  const std::vector<double> times{0.0, 0.5, 1.25};
  for (std::size_t k = 0; k < times.size(); ++k) {
    const fs::path vtu = series.addStep(times[k], twoLines());
    EXPECT_TRUE(fs::exists(vtu));
    EXPECT_EQ(vtu.parent_path(), m_dir / "lines_vtu");
    // Valid after every step, listing every step so far: an interrupted run keeps a usable series.
    const std::string xml = readText(pvd);
    EXPECT_TRUE(wellFormed(xml)) << "after step " << k;
    EXPECT_TRUE(parsesWithPythonIfAvailable(pvd));
    EXPECT_EQ(dataSets(xml).size(), k + 1);
  }
  EXPECT_EQ(series.stepCount(), 3U);
  series.close();
  EXPECT_THROW(series.addStep(2.0, twoLines()), Error);
  EXPECT_NO_THROW(series.close());

  const std::string xml = readText(pvd);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_EQ(attribute(xml, "VTKFile", "type"), "Collection");
  const std::vector<std::string> sets = dataSets(xml);
  ASSERT_EQ(sets.size(), times.size());
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const std::string file = attribute(sets[k], "DataSet", "file");
    const std::string step = attribute(sets[k], "DataSet", "timestep");
    EXPECT_EQ(file, "lines_vtu/lines_00000" + std::to_string(k) + ".vtu");
    EXPECT_FALSE(fs::path(file).is_absolute());
    EXPECT_TRUE(fs::exists(m_dir / file)) << file;
    EXPECT_DOUBLE_EQ(std::stod(step), times[k]);
    const std::string vtu = readText(m_dir / file);
    EXPECT_TRUE(wellFormed(vtu));
    EXPECT_EQ(arrayValues(section(vtu, "FieldData"), "TimeValue"), (std::vector<double>{times[k]}));
  }
}

TEST_F(VtkWriterTest, PvdWithoutExplicitCloseIsComplete) {
  const fs::path pvd = m_dir / "contacts.pvd";
  {
    PvdSeries series(pvd);
    series.addPointStep(0.1, {Vec3(0, 0, 0)}, {{"impact_energy_J", {1.0}}});
    series.addPointStep(0.2, {}, {{"impact_energy_J", {}}});
    PvdSeries moved(std::move(series));  // moving keeps one owner of the file
    moved.addPointStep(0.3, {Vec3(1, 1, 1), Vec3(2, 2, 2)}, {{"impact_energy_J", {2.0, 3.0}}});
  }
  const std::string xml = readText(pvd);
  EXPECT_TRUE(wellFormed(xml));
  EXPECT_TRUE(parsesWithPythonIfAvailable(pvd));
  const std::vector<std::string> sets = dataSets(xml);
  ASSERT_EQ(sets.size(), 3U);
  EXPECT_EQ(attribute(sets[2], "DataSet", "file"), "contacts_vtu/contacts_000002.vtu");
  const std::string last = readText(m_dir / "contacts_vtu" / "contacts_000002.vtu");
  EXPECT_EQ(arrayValues(section(last, "Cells"), "types"), (std::vector<double>{1, 1}));
}

// The reader ParaView uses: VTK's Python module (from Debian's python3-paraview, installed by
// scripts/install-deps.sh, or python3-vtk9); skipped when neither is installed.
TEST_F(VtkWriterTest, VtkReaderLoadsFilesIfAvailable) {
  if (!fs::exists("/usr/bin/python3") ||
      std::system("/usr/bin/python3 -c 'import vtk' > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "python3 vtk module not installed";
  }
  writeVtu(m_dir / "lines.vtu", twoLines(), 2.0);
  writeVtuPoints(m_dir / "points.vtu", {Vec3(1, 2, 3), Vec3(4, 5, 6)}, {{"impact_energy_J", {1.0, 2.0}}},
                 2.0);
  const fs::path script = m_dir / "check.py";
  std::ofstream(script) << R"(import sys, vtk
def load(f):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(f)
    r.Update()
    return r.GetOutput()
g = load(sys.argv[1])
assert g.GetNumberOfPoints() == 5 and g.GetNumberOfCells() == 2
assert [g.GetCellType(i) for i in range(2)] == [4, 4]
assert [g.GetCell(1).GetPointId(i) for i in range(2)] == [3, 4]
pd = g.GetPointData()
assert pd.GetArray("tension_N").GetValue(4) == 3.0e5
assert pd.GetArray("bending_moment_Nm").GetValue(3) == 0.0
assert pd.GetArray("arc_index").GetValue(4) == 1
assert g.GetCellData().GetArray("line_id").GetValue(1) == 1
assert g.GetFieldData().GetArray("TimeValue").GetValue(0) == 2.0
p = load(sys.argv[2])
assert p.GetNumberOfPoints() == 2 and p.GetNumberOfCells() == 2
assert [p.GetCellType(i) for i in range(2)] == [1, 1]
assert p.GetPointData().GetArray("impact_energy_J").GetValue(1) == 2.0
)";
  const std::string cmd = "/usr/bin/python3 '" + script.string() + "' '" + (m_dir / "lines.vtu").string() +
                          "' '" + (m_dir / "points.vtu").string() + "' > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << "VTK's reader rejects the files or reads other values";
}

TEST_F(VtkWriterTest, PvdRejectsNonFiniteTime) {
  PvdSeries series(m_dir / "s.pvd");
  EXPECT_THROW(series.addStep(std::nan(""), twoLines()), Error);
  EXPECT_EQ(series.stepCount(), 0U);
  EXPECT_NO_THROW(series.addStep(0.0, twoLines()));
  EXPECT_EQ(series.stepCount(), 1U);
}

}  // namespace
}  // namespace tangle::io
