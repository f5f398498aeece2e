/// @file Hdf5File.cpp
/// RAII layer over the HDF5 C API (see Hdf5File.hpp).

#include "tangle/io/Hdf5File.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <numeric>

#include "tangle/core/Error.hpp"

namespace tangle::io {

namespace {

/// Rows per chunk are chosen so a chunk holds at least this many values (small rows, e.g. time, would
/// otherwise make tiny chunks) [values].
constexpr std::size_t kMinChunkValues = 4096;
/// Deflate level: 4 is within a few percent of 9 in size on floating-point series and much faster; 1 (after
/// the shuffle filter) is 2.2 % larger than 4 on the mooring example's results.h5 and takes 11 % fewer of the
/// writer thread's instructions, whose load slows the solver's thread on a 2-core machine.
constexpr unsigned kDeflateLevel = 1;

/// H5Dwrite of `count` doubles into `dataset`, stored in single precision when `single`. Rounded here:
/// HDF5 would convert through a type-conversion buffer that it allocates and zeroes (1 MB) on every write
/// (docs/performance.md).
herr_t writeDoubles(hid_t dataset, hid_t memSpace, hid_t fileSpace, const double* data, std::size_t count,
                    bool single) {
  if (!single) return H5Dwrite(dataset, H5T_NATIVE_DOUBLE, memSpace, fileSpace, H5P_DEFAULT, data);
  const std::vector<float> rounded(data, data + count);
  return H5Dwrite(dataset, H5T_NATIVE_FLOAT, memSpace, fileSpace, H5P_DEFAULT, rounded.data());
}

/// Closes an HDF5 identifier when it goes out of scope.
class Id {
 public:
  Id(hid_t id, herr_t (*closer)(hid_t)) : m_id(id), m_closer(closer) {}
  ~Id() {
    if (m_id >= 0) m_closer(m_id);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  hid_t get() const { return m_id; }
  bool valid() const { return m_id >= 0; }

 private:
  hid_t m_id;
  herr_t (*m_closer)(hid_t);
};

std::vector<hsize_t> toHsize(const std::vector<std::uint64_t>& d) { return {d.begin(), d.end()}; }

}  // namespace

Hdf5File::Hdf5File(std::filesystem::path path) : m_path(std::move(path)) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions here, not stderr noise
  m_file = H5Fcreate(m_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (m_file < 0) fail("cannot create the file");
}

Hdf5File::~Hdf5File() {
  try {
    close();
  } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
}

void Hdf5File::fail(const std::string& what) const {
  throw OutputError(fmt::format("cannot write {}: {} (HDF5)", m_path.string(), what));
}

void Hdf5File::createGroup(const std::string& path) {
  std::size_t pos = 0;
  while (true) {
    pos = path.find('/', pos + 1);
    const std::string part = path.substr(0, pos);  // "/a", "/a/b", ..., the whole path
    if (part.size() > 1 && H5Lexists(m_file, part.c_str(), H5P_DEFAULT) <= 0) {
      Id g(H5Gcreate2(m_file, part.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
      if (!g.valid()) fail("group " + part);
    }
    if (pos == std::string::npos) break;
  }
}

void Hdf5File::writeArray(const std::string& path, const std::vector<double>& data,
                          const std::vector<std::uint64_t>& dims, const std::string& units,
                          const std::string& description, bool singlePrecision) {
  const std::vector<hsize_t> d = toHsize(dims);
  Id space(H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr), H5Sclose);
  Id set(H5Dcreate2(m_file, path.c_str(), singlePrecision ? H5T_IEEE_F32LE : H5T_IEEE_F64LE, space.get(),
                    H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
         H5Dclose);
  if (!set.valid()) fail("dataset " + path);
  if (!data.empty() &&
      writeDoubles(set.get(), H5S_ALL, H5S_ALL, data.data(), data.size(), singlePrecision) < 0)
    fail("dataset " + path);
  setAttribute(path, "units", units);
  setAttribute(path, "description", description);
}

void Hdf5File::writeIntArray(const std::string& path, const std::vector<int>& data,
                             const std::vector<std::uint64_t>& dims, const std::string& description) {
  const std::vector<hsize_t> d = toHsize(dims);
  Id space(H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr), H5Sclose);
  Id set(H5Dcreate2(m_file, path.c_str(), H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
         H5Dclose);
  if (!set.valid()) fail("dataset " + path);
  if (!data.empty() && H5Dwrite(set.get(), H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail("dataset " + path);
  setAttribute(path, "units", "-");
  setAttribute(path, "description", description);
}

void Hdf5File::setAttribute(const std::string& objectPath, const std::string& name,
                            const std::string& value) {
  // Variable-length UTF-8: h5py reads it as str.
  Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id attr(H5Acreate_by_name(m_file, objectPath.c_str(), name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                            H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
  if (!attr.valid()) fail(fmt::format("attribute {} of {}", name, objectPath));
  const char* text = value.c_str();
  if (H5Awrite(attr.get(), type.get(), &text) < 0) fail(fmt::format("attribute {} of {}", name, objectPath));
}

void Hdf5File::setAttribute(const std::string& objectPath, const std::string& name, double value) {
  Id space(H5Screate(H5S_SCALAR), H5Sclose);
  Id attr(H5Acreate_by_name(m_file, objectPath.c_str(), name.c_str(), H5T_IEEE_F64LE, space.get(),
                            H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
  if (!attr.valid() || H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail(fmt::format("attribute {} of {}", name, objectPath));
}

int Hdf5File::createSeries(const std::string& path, const std::vector<std::uint64_t>& rowDims,
                           const std::string& units, const std::string& description, int chunkRows,
                           bool singlePrecision) {
  Series s;
  s.path = path;
  s.rowDims = rowDims;
  s.rowSize = std::accumulate(rowDims.begin(), rowDims.end(), std::size_t{1}, std::multiplies<>());
  std::vector<hsize_t> dims{0}, maxDims{H5S_UNLIMITED}, chunk;
  const auto rows = static_cast<hsize_t>(
      std::max<std::size_t>(static_cast<std::size_t>(chunkRows),
                            (kMinChunkValues + s.rowSize - 1) / std::max<std::size_t>(s.rowSize, 1)));
  chunk.push_back(rows);
  for (std::uint64_t d : rowDims) {
    dims.push_back(d);
    maxDims.push_back(d);
    chunk.push_back(std::max<hsize_t>(d, 1));
  }
  Id space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), maxDims.data()), H5Sclose);
  Id props(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(props.get(), static_cast<int>(chunk.size()), chunk.data());
  H5Pset_shuffle(props.get());
  H5Pset_deflate(props.get(), kDeflateLevel);
  // Stored in single precision: 7 significant digits, as the CSV files print (%.6e); computed in double.
  // No chunk cache: rows are written a whole chunk at a time, so each chunk is compressed and written when
  // it is full, by the thread that writes it. With HDF5's default cache (1 MB per dataset) the last ~20
  // chunks of every series stayed in memory and were all compressed at the close, on the main thread after
  // the dynamics (53 ms of the mooring example's 1.4 s run).
  Id access(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
  H5Pset_chunk_cache(access.get(), H5D_CHUNK_CACHE_NSLOTS_DEFAULT, 0, H5D_CHUNK_CACHE_W0_DEFAULT);
  s.dataset = H5Dcreate2(m_file, path.c_str(), singlePrecision ? H5T_IEEE_F32LE : H5T_IEEE_F64LE, space.get(),
                         H5P_DEFAULT, props.get(), access.get());
  if (s.dataset < 0) fail("dataset " + path);
  s.singlePrecision = singlePrecision;
  m_chunkRows = static_cast<int>(rows);
  s.buffer.reserve(rows * s.rowSize);
  m_series.push_back(std::move(s));
  setAttribute(path, "units", units);
  setAttribute(path, "description", description);
  return static_cast<int>(m_series.size()) - 1;
}

void Hdf5File::append(int series, const double* row) {
  Series& s = m_series[static_cast<std::size_t>(series)];
  s.buffer.insert(s.buffer.end(), row, row + s.rowSize);
  if (s.buffer.size() >= s.buffer.capacity()) writeBuffered(s);
}

std::uint64_t Hdf5File::rows(int series) const {
  const Series& s = m_series[static_cast<std::size_t>(series)];
  return s.written + s.buffer.size() / s.rowSize;
}

void Hdf5File::writeBuffered(Series& s) {
  const auto count = static_cast<hsize_t>(s.buffer.size() / s.rowSize);
  if (count == 0) return;
  std::vector<hsize_t> dims{s.written + count}, start{s.written}, block{count};
  for (std::uint64_t d : s.rowDims) {
    dims.push_back(d);
    start.push_back(0);
    block.push_back(d);
  }
  if (H5Dset_extent(s.dataset, dims.data()) < 0) fail("dataset " + s.path);
  Id fileSpace(H5Dget_space(s.dataset), H5Sclose);
  H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start.data(), nullptr, block.data(), nullptr);
  Id memSpace(H5Screate_simple(static_cast<int>(block.size()), block.data(), nullptr), H5Sclose);
  if (writeDoubles(s.dataset, memSpace.get(), fileSpace.get(), s.buffer.data(), s.buffer.size(),
                   s.singlePrecision) < 0)
    fail("dataset " + s.path);
  s.written += count;
  s.buffer.clear();
}

void Hdf5File::flush() {
  if (m_file < 0) return;
  for (Series& s : m_series) writeBuffered(s);
  if (H5Fflush(m_file, H5F_SCOPE_LOCAL) < 0) fail("flush");
}

void Hdf5File::close() {
  if (m_file < 0) return;
  flush();
  for (Series& s : m_series)
    if (s.dataset >= 0) {
      H5Dclose(s.dataset);
      s.dataset = -1;
    }
  const herr_t rc = H5Fclose(m_file);
  m_file = -1;
  // HDF5 keeps released blocks on free lists until the library shuts down at exit, where freeing them took
  // 7 ms of the mooring example's run; released here, by the thread that closes the file.
  H5garbage_collect();
  if (rc < 0) fail("close");
}

}  // namespace tangle::io
