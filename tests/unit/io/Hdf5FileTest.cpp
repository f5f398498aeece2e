/// Tests of tangle::io::Hdf5File: what is written reads back through the HDF5 C API (shapes, values,
/// single-precision series across several chunks, attributes), and failures are OutputErrors.

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tangle/core/Error.hpp"
#include "tangle/io/Hdf5File.hpp"

namespace tangle::io {
namespace {

std::vector<hsize_t> shapeOf(hid_t file, const char* path) {
  const hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return dims;
}

std::vector<double> valuesOf(hid_t file, const char* path, std::size_t count) {
  std::vector<double> v(count);
  const hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(set);
  return v;
}

std::string stringAttribute(hid_t file, const char* object, const char* name) {
  const hid_t attr = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  char* text = nullptr;
  H5Aread(attr, type, &text);
  std::string out = text ? text : "";
  H5free_memory(text);
  H5Tclose(type);
  H5Aclose(attr);
  return out;
}

TEST(Hdf5File, ArraysSeriesAndAttributesReadBack) {
  const auto path = std::filesystem::temp_directory_path() / "tangle_hdf5_file_test.h5";
  {
    Hdf5File f(path);
    f.createGroup("/a/b/c");
    f.writeArray("/a/b/c/values", {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}, {2, 3}, "N", "two rows");
    f.setAttribute("/", "title", "a title with ünïcode");
    f.setAttribute("/a", "depth_m", 345.0);
    const int s = f.createSeries("/a/series", {3, 2}, "m", "rows of 3 x 2", 4);
    const int t = f.createSeries("/a/time", {}, "s", "time", 4, false);
    for (int row = 0; row < 10; ++row) {  // 10 rows: two full chunks of 4 and a partial one
      std::vector<double> v(6);
      for (int k = 0; k < 6; ++k) v[static_cast<std::size_t>(k)] = row * 100.0 + k + 0.1;
      f.append(s, v.data());
      const double time = 0.1 * row;
      f.append(t, &time);
    }
    EXPECT_EQ(f.rows(s), 10u);
    f.close();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(shapeOf(file, "/a/b/c/values"), (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(valuesOf(file, "/a/b/c/values", 6), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(stringAttribute(file, "/a/b/c/values", "units"), "N");
  EXPECT_EQ(stringAttribute(file, "/", "title"), "a title with ünïcode");
  EXPECT_EQ(shapeOf(file, "/a/series"), (std::vector<hsize_t>{10, 3, 2}));
  const std::vector<double> series = valuesOf(file, "/a/series", 60);
  for (int row = 0; row < 10; ++row)
    for (int k = 0; k < 6; ++k) {
      const double expected = row * 100.0 + k + 0.1;
      // single precision: 7 significant digits
      EXPECT_NEAR(series[static_cast<std::size_t>(6 * row + k)], expected, 1e-7 * expected);
    }
  const std::vector<double> time = valuesOf(file, "/a/time", 10);
  EXPECT_EQ(time[7], 0.1 * 7);  // double precision: exact
  H5Fclose(file);
  std::filesystem::remove(path);
}

TEST(Hdf5File, FailuresNameTheFile) {
  EXPECT_THROW(Hdf5File("/nonexistent-folder/x/results.h5"), OutputError);
  const auto path = std::filesystem::temp_directory_path() / "tangle_hdf5_fail_test.h5";
  Hdf5File f(path);
  try {
    f.writeArray("/no/such/group/values", {1.0}, {1}, "-", "-");
    FAIL() << "expected an OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  f.close();
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace tangle::io
