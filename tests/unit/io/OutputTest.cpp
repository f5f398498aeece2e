/// @file OutputTest.cpp
/// Tests of the result-file layer (issue 13): every write checked, safe and unique file names, JSON that
/// is valid whatever bytes the names hold.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "tangle/core/Error.hpp"
#include "tangle/core/JsonWriter.hpp"
#include "tangle/core/OutputFile.hpp"
#include "tangle/io/ResultWriter.hpp"

namespace tangle::io {
namespace {

namespace fs = std::filesystem;

/// A fresh empty folder under the system temp dir.
fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tangle-output-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(OutputFile, FullDiskThrowsNamingTheFile) {
  // /dev/full accepts the open and fails every write with ENOSPC: what a full disk does.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full not available";
  core::OutputFile f("/dev/full");
  try {
    for (int i = 0; i < 100000; ++i) f.write("0123456789,0123456789,0123456789\n");
    f.close();
    FAIL() << "no OutputError on a full disk";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
  }
}

TEST(OutputFile, MissingFolderThrowsNamingTheFile) {
  const fs::path p = fs::temp_directory_path() / "tangle-no-such-folder" / "x.csv";
  fs::remove_all(p.parent_path());
  try {
    core::OutputFile f(p);
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
}

TEST(OutputFile, RowsAreKeptUntilAMegabyteAndAllWrittenAtTheEnd) {
  // writeRows holds the rows below 1 MiB (nothing written: the file stays empty) and writes them, in order,
  // once they reach it and at the last call; a full disk still throws (the check of write()).
  const fs::path dir = freshDir("rows");
  const fs::path p = dir / "rows.csv";
  core::OutputFile f(p);
  std::string rows, expected;
  const std::string row = "0.000000,line1-line2,1.234560e+01,10.0000,20.0000\n";  // 50 bytes
  rows += row;
  expected += row;
  f.writeRows(rows);
  f.flush();
  EXPECT_EQ(rows, row);
  EXPECT_EQ(fs::file_size(p), 0u);
  for (int i = 0; i < 30000; ++i) {  // 1.5 MB
    rows += row;
    expected += row;
    f.writeRows(rows);
  }
  EXPECT_LT(rows.size(), std::size_t{1} << 20);
  f.writeRows(rows, true);
  EXPECT_TRUE(rows.empty());
  f.close();
  std::ifstream in(p, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(written, expected);
  fs::remove_all(dir);
  if (fs::exists("/dev/full")) {
    core::OutputFile full("/dev/full");
    std::string big(std::size_t{1} << 21, 'x');
    EXPECT_THROW(
        {
          full.writeRows(big);
          full.close();
        },
        OutputError);
  }
}

TEST(OutputFile, StaticTableOnAFullDiskIsAnError) {
  // Before issue 13 the CSV writer never checked its stream: a cut table and exit 0.
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full not available";
  const fs::path dir = freshDir("full-disk");
  fs::create_directories(dir / "statics");
  fs::create_symlink("/dev/full", dir / "statics" / "riser.csv");
  solver::LineSnapshot s;
  s.name = "riser";
  for (int i = 0; i < 2000; ++i) {
    s.arcLength.push_back(i);
    s.position.push_back(Vec3::Zero());
    s.tension.push_back(1.0);
    s.bendingMoment.push_back(0.0);
    s.bendingMomentVector.push_back(Vec3::Zero());
    s.curvature.push_back(0.0);
    s.torque.push_back(0.0);
    s.rotation.push_back(Vec3::Zero());
  }
  EXPECT_THROW(writeStaticLineTables(dir, {s}), OutputError);
  fs::remove_all(dir);
}

TEST(FileNames, NamesThatMapToOneFileGetDistinctStems) {
  const std::vector<std::string> stems = uniqueFileStems({"riser/1", "riser_1", "RISER_1", "riser 1"});
  EXPECT_EQ(stems, (std::vector<std::string>{"riser_1", "riser_1-2", "RISER_1-3", "riser_1-4"}));
}

TEST(FileNames, NoHiddenFilesNoParentFolderNoNonAscii) {
  EXPECT_EQ(safeFileName(".."), "_.");
  EXPECT_EQ(safeFileName(".hidden"), "_hidden");
  EXPECT_EQ(safeFileName("a/../b"), "a_.._b");
  EXPECT_EQ(safeFileName("r\xc3\xa9sum\xe9"), "r__sum_");
  EXPECT_EQ(safeFileName(""), "line");
  EXPECT_EQ(safeFileName(std::string(300, 'x')).size(), 64u);
}

/// True when every byte of `s` is printable ASCII or a newline.
bool isPlainAscii(const std::string& s) {
  for (char c : s)
    if (static_cast<unsigned char>(c) >= 0x7f || (static_cast<unsigned char>(c) < 0x20 && c != '\n')) return false;
  return true;
}

TEST(JsonWriter, NonUtf8BytesBecomeReplacementCharacters) {
  std::ostringstream out;
  core::JsonWriter j(out);
  j.beginObject();
  j.field("latin1", "caf\xe9");          // Latin-1 e-acute: not UTF-8
  j.field("truncated", "x\xe2\x82");     // cut 3-byte sequence
  j.field("overlong", "\xc0\xaf");       // overlong '/'
  j.field("control", "a\x01\x7f");
  j.endObject();
  const std::string text = out.str();
  EXPECT_TRUE(isPlainAscii(text)) << text;
  EXPECT_NE(text.find("\"caf\\ufffd\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"x\\ufffd\\ufffd\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"\\ufffd\\ufffd\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"a\\u0001\\u007f\""), std::string::npos) << text;
}

TEST(JsonWriter, ValidUtf8IsKept) {
  std::ostringstream out;
  core::JsonWriter j(out);
  j.beginArray();
  j.value("\xc3\xa9\xe2\x82\xac\xf0\x9f\x8c\x8a");  // e-acute, euro, wave emoji
  j.endArray();
  EXPECT_NE(out.str().find("\"\xc3\xa9\xe2\x82\xac\xf0\x9f\x8c\x8a\""), std::string::npos) << out.str();
}

}  // namespace
}  // namespace tangle::io
