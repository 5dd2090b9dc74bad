// readNetcdfHeader(): what a NetCDF file (a NetCDF CF field, or an Exodus II
// mesh, which is NetCDF inside) declares, checked before a library reads it.
//
// Classic files (CDF-1, 64-bit offset CDF-2, CDF-5) are walked by Sandstorm
// itself, byte by byte, as the format's specification lays them out: every
// count, name and attribute must lie within the file, every dimension id
// name a dimension (the record dimension only first), and every variable's
// data (its begin, size and, for record variables, every record) lie within
// the file. NetCDF-4 files (HDF5 inside) are asked through the NetCDF
// library's inquiry functions, which read only their metadata. Either way a
// variable claims no more than the file holds before VTK's readers allocate
// it. Throws Error naming the file and what was wrong.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sandstorm {

struct NetcdfAttribute {
  std::string name;
  std::string text;            // a CHAR attribute's text
  std::vector<double> values;  // a numeric attribute's values
};

struct NetcdfVariable {
  std::string name;
  std::vector<std::size_t> dims;  // dimension ids, slowest first
  int type = 0;                   // NC_BYTE 1 .. NC_UINT64 11
  std::vector<NetcdfAttribute> attributes;
  const NetcdfAttribute* attribute(const std::string& name) const;
};

struct NetcdfHeader {
  bool hdf5 = false;  // NetCDF-4 (HDF5 inside)
  std::uint64_t records = 0;
  struct Dimension {
    std::string name;
    std::uint64_t length = 0;  // the record dimension's: `records`
    bool unlimited = false;
  };
  std::vector<Dimension> dims;
  std::vector<NetcdfAttribute> attributes;  // global
  std::vector<NetcdfVariable> variables;

  const Dimension* dimension(const std::string& name) const;
  const NetcdfVariable* variable(const std::string& name) const;
  // Values the variable holds (the product of its dimensions' lengths).
  double values(const NetcdfVariable& v) const;
};

// A NetCDF file opened read-only through the NetCDF library, closed when it
// goes; throws Error naming the file when the library cannot open it.
class NetcdfFile {
 public:
  explicit NetcdfFile(const std::string& file);
  ~NetcdfFile();
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;
  int id() const { return id_; }

 private:
  int id_ = -1;
};

// Whether the file starts as NetCDF does ("CDF" 1, 2 or 5) or as HDF5.
bool looksLikeNetcdf(const std::string& head);

NetcdfHeader readNetcdfHeader(const std::filesystem::path& path);

}  // namespace sandstorm
