#include "core/io/netcdf_header.h"

#include <netcdf.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "core/util/error.h"

namespace sandstorm {
namespace {

constexpr std::uint32_t kDimensionTag = 0x0A, kVariableTag = 0x0B, kAttributeTag = 0x0C;
constexpr std::uint64_t kMaxHeader = std::uint64_t{64} << 20;  // far above any real header
constexpr std::uint64_t kMaxItems = std::uint64_t{1} << 20;    // dims, vars, attributes
constexpr std::uint64_t kMaxAttributeBytes = std::uint64_t{1} << 20;

int typeSize(int type) {
  switch (type) {
    case NC_BYTE:
    case NC_CHAR:
    case NC_UBYTE:
      return 1;
    case NC_SHORT:
    case NC_USHORT:
      return 2;
    case NC_INT:
    case NC_FLOAT:
    case NC_UINT:
      return 4;
    case NC_DOUBLE:
    case NC_INT64:
    case NC_UINT64:
      return 8;
    default:
      return 0;
  }
}

// The classic formats, as the NetCDF specification lays them out.
class ClassicWalker {
 public:
  ClassicWalker(std::string bytes, std::uint64_t fileSize, std::string file)
      : bytes_(std::move(bytes)), fileSize_(fileSize), file_(std::move(file)) {}

  NetcdfHeader run() {
    NetcdfHeader h;
    const int version = std::uint8_t(bytes_.at(3));
    cdf5_ = version == 5;
    wideOffsets_ = version != 1;
    at_ = 4;
    const std::uint64_t records = cdf5_ ? u64("the record count") : u32("the record count");
    streaming_ = !cdf5_ && records == 0xFFFFFFFFu;
    h.records = streaming_ ? 0 : records;
    for (std::uint64_t i = 0, n = list(kDimensionTag, "dimension"); i < n; ++i) {
      NetcdfHeader::Dimension d;
      d.name = name("a dimension's name");
      d.length = count("dimension '" + d.name + "' length");
      d.unlimited = d.length == 0;
      if (d.unlimited) d.length = h.records;
      h.dims.push_back(d);
    }
    attributes(h.attributes, "the global attributes");
    const std::uint64_t variables = list(kVariableTag, "variable");
    headerVariables_.reserve(std::size_t(variables));
    for (std::uint64_t i = 0; i < variables; ++i) {
      NetcdfVariable v;
      v.name = name("a variable's name");
      const std::string what = "variable '" + v.name + "'";
      const std::uint64_t rank = count(what + " rank");
      if (rank > 1024) fail(concat(what, " has ", rank, " dimensions"));
      for (std::uint64_t d = 0; d < rank; ++d) {
        const std::uint64_t id = count(what + " dimension id");
        if (id >= h.dims.size())
          fail(concat(what, " names dimension ", id, "; the file has ", h.dims.size()));
        if (h.dims[id].unlimited && d != 0)
          fail(concat(what, ": the record dimension can only come first"));
        v.dims.push_back(std::size_t(id));
      }
      attributes(v.attributes, what + "'s attributes");
      v.type = int(u32(what + " type"));
      if (typeSize(v.type) == 0 || (!cdf5_ && v.type > NC_DOUBLE))
        fail(concat(what, " has type ", v.type, "; expected a NetCDF number or character type"));
      const std::uint64_t vsize = cdf5_ ? u64(what + " size") : u32(what + " size");
      const std::uint64_t begin = wideOffsets_ ? u64(what + " begin") : u32(what + " begin");
      headerVariables_.push_back({vsize, begin});
      h.variables.push_back(std::move(v));
    }
    checkData(h);
    return h;
  }

 private:
  struct Placement {
    std::uint64_t vsize, begin;
  };

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(concat(file_, ": ", what, " (NetCDF header, byte ", at_, ")"));
  }

  std::uint64_t word(int size, const std::string& what) {
    if (at_ + std::uint64_t(size) > bytes_.size())
      fail(concat("the file ends inside the header, at ", what));
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i)
      v = (v << 8) | std::uint8_t(bytes_[std::size_t(at_ + std::uint64_t(i))]);
    at_ += std::uint64_t(size);
    return v;
  }
  std::uint64_t u32(const std::string& what) { return word(4, what); }
  std::uint64_t u64(const std::string& what) { return word(8, what); }
  std::uint64_t count(const std::string& what) { return cdf5_ ? u64(what) : u32(what); }

  // ABSENT, or the tag and a count.
  std::uint64_t list(std::uint32_t tag, const std::string& what) {
    const std::uint64_t got = u32(concat("the ", what, " list"));
    const std::uint64_t n = count(concat("the ", what, " count"));
    if (got == 0 && n == 0) return 0;
    if (got != tag) fail(concat("expected the ", what, " list's tag ", tag, ", found ", got));
    if (n > kMaxItems) fail(concat(n, " ", what, "s; expected at most ", kMaxItems));
    return n;
  }

  std::string name(const std::string& what) {
    const std::uint64_t n = count(what + " length");
    if (n == 0 || n > 4096) fail(concat(what, " is ", n, " bytes long; expected 1..4096"));
    if (at_ + n > bytes_.size()) fail(concat("the file ends inside ", what));
    std::string s = bytes_.substr(std::size_t(at_), std::size_t(n));
    at_ += (n + 3) / 4 * 4;
    return s;
  }

  void attributes(std::vector<NetcdfAttribute>& out, const std::string& what) {
    for (std::uint64_t i = 0, n = list(kAttributeTag, "attribute"); i < n; ++i) {
      NetcdfAttribute a;
      a.name = name("an attribute's name in " + what);
      const int type = int(u32(concat("attribute '", a.name, "' type")));
      const int size = typeSize(type);
      if (size == 0 || (!cdf5_ && type > NC_DOUBLE))
        fail(concat("attribute '", a.name, "' has type ", type));
      const std::uint64_t values = count(concat("attribute '", a.name, "' length"));
      const std::uint64_t bytes = values * std::uint64_t(size);
      if (values > kMaxAttributeBytes || at_ + bytes > bytes_.size())
        fail(concat("attribute '", a.name, "' claims ", values, " values beyond the header"));
      if (type == NC_CHAR) {
        a.text = bytes_.substr(std::size_t(at_), std::size_t(values));
        at_ += bytes;
      } else {
        for (std::uint64_t k = 0; k < values; ++k)
          a.values.push_back(number(type, size));
      }
      at_ = (at_ + 3) / 4 * 4;
      out.push_back(std::move(a));
    }
  }

  double number(int type, int size) {
    const std::uint64_t w = word(size, "an attribute's value");
    switch (type) {
      case NC_BYTE:
        return double(std::int8_t(w));
      case NC_SHORT:
        return double(std::int16_t(w));
      case NC_INT:
        return double(std::int32_t(w));
      case NC_INT64:
        return double(std::int64_t(w));
      case NC_FLOAT: {
        const std::uint32_t b = std::uint32_t(w);
        float f;
        std::memcpy(&f, &b, 4);
        return double(f);
      }
      case NC_DOUBLE: {
        double d;
        std::memcpy(&d, &w, 8);
        return d;
      }
      default:
        return double(w);
    }
  }

  // Every variable's data within the file.
  void checkData(const NetcdfHeader& h) {
    double recordSize = 0.0;
    std::size_t recordVariables = 0;
    for (std::size_t i = 0; i < h.variables.size(); ++i)
      if (!h.variables[i].dims.empty() && h.dims[h.variables[i].dims[0]].unlimited) {
        recordSize += double(headerVariables_[i].vsize);
        ++recordVariables;
      }
    for (std::size_t i = 0; i < h.variables.size(); ++i) {
      const NetcdfVariable& v = h.variables[i];
      const bool record = !v.dims.empty() && h.dims[v.dims[0]].unlimited;
      double one = double(typeSize(v.type));
      for (std::size_t d = record ? 1 : 0; d < v.dims.size(); ++d)
        one *= double(h.dims[v.dims[d]].length);
      const double begin = double(headerVariables_[i].begin);
      if (begin < double(at_) && one > 0.0)
        fail(concat("variable '", v.name, "' begins at byte ", begin, ", inside the header"));
      double end = begin + one;
      if (record && h.records > 0)
        end = begin + double(h.records - 1) * (recordVariables == 1 ? one : recordSize) + one;
      if (record && h.records == 0) end = begin;
      if (end > double(fileSize_))
        fail(concat("variable '", v.name, "' claims bytes ", begin, "..", end, "; the file has ",
                    fileSize_, " (truncated, or its sizes are wrong)"));
    }
  }

  std::string bytes_;
  std::uint64_t fileSize_;
  std::string file_;
  std::uint64_t at_ = 0;
  bool cdf5_ = false, wideOffsets_ = false, streaming_ = false;
  std::vector<Placement> headerVariables_;
};

// NetCDF-4: the library's own inquiry of the root group's metadata.
NetcdfHeader inquire(const std::string& file) {
  const NetcdfFile f(file);
  const int id = f.id();
  auto check = [&](int status, const std::string& what) {
    if (status != NC_NOERR)
      throw Error(concat(file, ": reading ", what, ": ", nc_strerror(status)));
  };
  NetcdfHeader h;
  h.hdf5 = true;
  int dims = 0, vars = 0, atts = 0, unlimited = -1;
  check(nc_inq(id, &dims, &vars, &atts, &unlimited), "the header");
  char name[NC_MAX_NAME + 1];
  for (int d = 0; d < dims; ++d) {
    std::size_t length = 0;
    check(nc_inq_dim(id, d, name, &length), "a dimension");
    h.dims.push_back({name, length, d == unlimited});
    if (d == unlimited) h.records = length;
  }
  auto readAttributes = [&](int var, int count, std::vector<NetcdfAttribute>& out) {
    for (int a = 0; a < count; ++a) {
      check(nc_inq_attname(id, var, a, name), "an attribute");
      nc_type type = 0;
      std::size_t length = 0;
      check(nc_inq_att(id, var, name, &type, &length), "an attribute");
      NetcdfAttribute attribute{name, {}, {}};
      if (length > kMaxAttributeBytes) continue;
      if (type == NC_CHAR) {
        attribute.text.resize(length);
        check(nc_get_att_text(id, var, name, attribute.text.data()), "an attribute");
      } else if (typeSize(type) > 0) {
        attribute.values.resize(length);
        check(nc_get_att_double(id, var, name, attribute.values.data()), "an attribute");
      }
      out.push_back(std::move(attribute));
    }
  };
  readAttributes(NC_GLOBAL, atts, h.attributes);
  for (int v = 0; v < vars; ++v) {
    NetcdfVariable variable;
    nc_type type = 0;
    int rank = 0, count = 0;
    int ids[NC_MAX_VAR_DIMS];
    check(nc_inq_var(id, v, name, &type, &rank, ids, &count), "a variable");
    variable.name = name;
    variable.type = type;
    for (int d = 0; d < rank; ++d)
      variable.dims.push_back(std::size_t(ids[d]));
    readAttributes(v, count, variable.attributes);
    h.variables.push_back(std::move(variable));
  }
  return h;
}

}  // namespace

NetcdfFile::NetcdfFile(const std::string& file) {
  if (const int status = nc_open(file.c_str(), NC_NOWRITE, &id_); status != NC_NOERR)
    throw Error(concat(file, ": the NetCDF library cannot open it: ", nc_strerror(status)));
}

NetcdfFile::~NetcdfFile() {
  nc_close(id_);
}

const NetcdfAttribute* NetcdfVariable::attribute(const std::string& n) const {
  for (const NetcdfAttribute& a : attributes)
    if (a.name == n) return &a;
  return nullptr;
}

const NetcdfHeader::Dimension* NetcdfHeader::dimension(const std::string& n) const {
  for (const Dimension& d : dims)
    if (d.name == n) return &d;
  return nullptr;
}

const NetcdfVariable* NetcdfHeader::variable(const std::string& n) const {
  for (const NetcdfVariable& v : variables)
    if (v.name == n) return &v;
  return nullptr;
}

double NetcdfHeader::values(const NetcdfVariable& v) const {
  double n = 1.0;
  for (std::size_t d : v.dims)
    n *= double(dims[d].length);
  return n;
}

bool looksLikeNetcdf(const std::string& head) {
  if (head.size() >= 4 && head.compare(0, 3, "CDF") == 0 &&
      (head[3] == 1 || head[3] == 2 || head[3] == 5))
    return true;
  return head.size() >= 8 && head.compare(0, 8, "\x89HDF\r\n\x1a\n") == 0;
}

NetcdfHeader readNetcdfHeader(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(concat(file, ": cannot read its size: ", ec.message()));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  std::string bytes(std::size_t(std::min(size, kMaxHeader)), '\0');
  in.read(bytes.data(), std::streamsize(bytes.size()));
  bytes.resize(std::size_t(in.gcount()));
  if (!looksLikeNetcdf(bytes))
    throw Error(concat(file, ": not a NetCDF file (expected 'CDF' 1, 2 or 5, or HDF5)"));
  if (bytes[0] != 'C') return inquire(file);
  return ClassicWalker(std::move(bytes), size, file).run();
}

}  // namespace sandstorm
