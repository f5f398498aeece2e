#pragma once
/// @file Hdf5File.hpp
/// A small RAII layer over the HDF5 C API (Debian's libhdf5-dev) for result files: groups, fixed arrays,
/// series that grow along their first dimension (chunked by rows, deflate + shuffle compressed, written a
/// chunk at a time), and string / number attributes. Every failure throws OutputError naming the file
/// and the object; HDF5's own error printing is switched off.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tangle::io {

class Hdf5File {
 public:
  /// Creates (truncates) the file.
  explicit Hdf5File(std::filesystem::path path);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  /// Creates a group and its missing parents (absolute path, e.g. "/dynamics/lines/riser").
  void createGroup(const std::string& path);
  /// A fixed array of doubles of shape `dims` (row-major) with `units` and `description` attributes,
  /// stored in double or (`singlePrecision`) in single precision.
  void writeArray(const std::string& path, const std::vector<double>& data,
                  const std::vector<std::uint64_t>& dims, const std::string& units,
                  const std::string& description, bool singlePrecision = false);
  /// A fixed array of 32-bit integers (connectivity).
  void writeIntArray(const std::string& path, const std::vector<int>& data,
                     const std::vector<std::uint64_t>& dims, const std::string& description);
  void setAttribute(const std::string& objectPath, const std::string& name, const std::string& value);
  void setAttribute(const std::string& objectPath, const std::string& name, double value);

  /// A series of rows of shape `rowDims` growing along a new first dimension (time), stored in chunks of
  /// `chunkRows` rows, in single precision (7 significant digits, as the CSV files). @return its handle
  int createSeries(const std::string& path, const std::vector<std::uint64_t>& rowDims,
                   const std::string& units, const std::string& description, int chunkRows = 64,
                   bool singlePrecision = true);
  /// Appends one row (product of rowDims values); buffered, written a chunk at a time.
  void append(int series, const double* row);
  /// Rows appended to a series so far.
  std::uint64_t rows(int series) const;
  /// Writes every buffered row and flushes the file to disk (the file is readable as it is).
  void flush();
  /// flush() and close (also done by the destructor, which never throws).
  void close();

  const std::filesystem::path& path() const { return m_path; }

 private:
  struct Series {
    std::int64_t dataset = -1;
    std::vector<std::uint64_t> rowDims;
    std::size_t rowSize = 1;
    std::uint64_t written = 0;   ///< rows in the file
    std::vector<double> buffer;  ///< rows not yet written
    std::string path;
    bool singlePrecision = false;  ///< stored as float (rounded before the write: see writeArray)
  };
  void writeBuffered(Series& s);
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path m_path;
  std::int64_t m_file = -1;
  std::vector<Series> m_series;
  int m_chunkRows = 64;
};

}  // namespace tangle::io
