#include "core/io/vtkhdf_reader.h"

#include <hdf5.h>

#include <numeric>
#include <vector>

#include <vtkDataSet.h>
#include <vtkHDFReader.h>
#include <vtkNew.h>

#include "core/io/budget_advice.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// An HDF5 handle closed by its own close function when it goes.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

class Layout {
 public:
  Layout(const std::filesystem::path& path, const LoadOptions& options)
      : file_(path.string()), budget_(double(options.memoryBudget)) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors come back as values, not prints
  }

  void check() {
    Handle f(H5Fopen(file_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!f.valid()) fail("the HDF5 library cannot open it");
    Handle root(H5Gopen2(f.get(), "VTKHDF", H5P_DEFAULT), H5Gclose);
    if (!root.valid()) fail("no /VTKHDF group: not a VTKHDF file");
    const std::vector<long long> version = intAttribute(root.get(), "Version");
    if (version.size() != 2 || version[0] != 1)
      fail("Version is not 1.x: VTK 9.1 reads VTKHDF version 1");
    const std::string type = stringAttribute(root.get(), "Type");
    if (type == "ImageData")
      image(root.get());
    else if (type == "UnstructuredGrid")
      unstructured(root.get());
    else
      fail(concat("Type '", type, "': VTK 9.1 reads ImageData and UnstructuredGrid"));
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw Error(concat(file_, ": ", what)); }

  std::vector<long long> intAttribute(hid_t at, const char* name) {
    Handle a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) fail(concat("no attribute ", name));
    Handle space(H5Aget_space(a.get()), H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if (n < 1 || n > 64) fail(concat("attribute ", name, " holds ", n, " values"));
    std::vector<long long> out(static_cast<std::size_t>(n));
    if (H5Aread(a.get(), H5T_NATIVE_LLONG, out.data()) < 0)
      fail(concat("attribute ", name, " is not whole numbers"));
    return out;
  }

  std::string stringAttribute(hid_t at, const char* name) {
    Handle a(H5Aopen(at, name, H5P_DEFAULT), H5Aclose);
    if (!a.valid()) fail(concat("no attribute ", name));
    Handle type(H5Aget_type(a.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0)
      fail(concat("attribute ", name, " is not a fixed-length string"));
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0 || size > 256) fail(concat("attribute ", name, " is ", size, " bytes long"));
    std::string out(size, '\0');
    if (H5Aread(a.get(), type.get(), out.data()) < 0) fail(concat("attribute ", name, " unread"));
    return out.substr(0, out.find('\0'));
  }

  // The dataset's shape, slowest first.
  std::vector<hsize_t> shape(hid_t at, const std::string& name) {
    Handle d(H5Dopen2(at, name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!d.valid()) fail(concat("no dataset ", name));
    Handle space(H5Dget_space(d.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 1 || rank > 8) fail(concat("dataset ", name, " has rank ", rank));
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    double values = 1.0;
    for (hsize_t n : dims)
      values *= double(n);
    if (values * 8.0 > budget_)
      fail(concat("dataset ", name, " holds ", values,
                  " values, beyond the memory budget (field.memory_budget)",
                  raiseBudget(values * 8.0)));
    return dims;
  }

  std::vector<long long> values(hid_t at, const std::string& name) {
    const std::vector<hsize_t> dims = shape(at, name);
    if (dims.size() != 1) fail(concat("dataset ", name, " is not a list"));
    Handle d(H5Dopen2(at, name.c_str(), H5P_DEFAULT), H5Dclose);
    std::vector<long long> out(static_cast<std::size_t>(dims[0]));
    if (!out.empty() &&
        H5Dread(d.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
      fail(concat("dataset ", name, " cannot be read as whole numbers"));
    return out;
  }

  // Every dataset of a PointData or CellData group: `tuples` first.
  void attributes(hid_t root, const char* group, hsize_t tuples,
                  const std::vector<hsize_t>& imageShape = {}) {
    if (H5Lexists(root, group, H5P_DEFAULT) <= 0) return;
    Handle g(H5Gopen2(root, group, H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail(concat(group, " is not a group"));
    H5G_info_t info;
    if (H5Gget_info(g.get(), &info) < 0 || info.nlinks > 4096)
      fail(concat(group, " cannot be listed"));
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char name[256];
      if (H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name,
                             H5P_DEFAULT) < 0)
        fail(concat(group, ": a member cannot be named"));
      const std::vector<hsize_t> dims = shape(g.get(), name);
      const std::string what = concat(group, "/", name);
      if (!imageShape.empty()) {
        for (std::size_t a = 0; a < imageShape.size(); ++a)
          if (a >= dims.size() || dims[a] != imageShape[a])
            fail(concat(what, " is not shaped as the WholeExtent gives"));
        if (dims.size() > imageShape.size() + 1) fail(concat(what, " has too many dimensions"));
      } else if (dims[0] != tuples || dims.size() > 2) {
        fail(concat(what, " holds ", dims[0], " tuples; expected ", tuples));
      }
    }
  }

  void image(hid_t root) {
    const std::vector<long long> e = intAttribute(root, "WholeExtent");
    if (e.size() != 6) fail("WholeExtent is not six whole numbers");
    std::vector<hsize_t> points, cells;
    double count = 1.0;
    for (int a = 2; a >= 0; --a) {
      const long long n = e[std::size_t(2 * a + 1)] - e[std::size_t(2 * a)] + 1;
      if (n < 1 || n > (1LL << 31)) fail(concat("WholeExtent along ", "xyz"[a], " holds ", n));
      points.push_back(hsize_t(n));
      cells.push_back(hsize_t(std::max(n - 1, 1LL)));
      count *= double(n);
    }
    if (count * 12.0 > budget_)
      fail(concat("WholeExtent holds ", count, " points, beyond the budget"));
    attributes(root, "PointData", 0, points);
    attributes(root, "CellData", 0, cells);
  }

  void unstructured(hid_t root) {
    const std::vector<long long> points = values(root, "NumberOfPoints");
    const std::vector<long long> cells = values(root, "NumberOfCells");
    const std::vector<long long> ids = values(root, "NumberOfConnectivityIds");
    if (points.empty() || points.size() != cells.size() || points.size() != ids.size() ||
        points.size() > 100000)
      fail("NumberOfPoints, NumberOfCells and NumberOfConnectivityIds do not list the same pieces");
    auto sum = [&](const std::vector<long long>& v, const char* what) {
      long long total = 0;
      for (long long n : v) {
        if (n < 0 || n > (1LL << 40)) fail(concat(what, " holds ", n));
        total += n;
      }
      return hsize_t(total);
    };
    const hsize_t p = sum(points, "NumberOfPoints"), c = sum(cells, "NumberOfCells"),
                  k = sum(ids, "NumberOfConnectivityIds");
    auto expect = [&](const char* name, std::vector<hsize_t> want) {
      if (shape(root, name) != want)
        fail(concat("dataset ", name, " is not shaped as the counts give"));
    };
    expect("Points", {p, 3});
    expect("Types", {c});
    expect("Offsets", {c + points.size()});
    expect("Connectivity", {k});
    attributes(root, "PointData", p);
    attributes(root, "CellData", c);
    // Each piece's offsets run from 0 to its connectivity, which names its points.
    const std::vector<long long> offsets = values(root, "Offsets");
    const std::vector<long long> connectivity = values(root, "Connectivity");
    std::size_t o = 0, at = 0;
    for (std::size_t piece = 0; piece < points.size(); ++piece) {
      const long long n = cells[piece];
      if (offsets[o] != 0) fail(concat("piece ", piece, "'s offsets do not start at 0"));
      for (long long i = 0; i < n; ++i)
        if (offsets[o + std::size_t(i) + 1] < offsets[o + std::size_t(i)])
          fail(concat("piece ", piece, "'s offsets run backwards"));
      if (offsets[o + std::size_t(n)] != ids[piece])
        fail(concat("piece ", piece, "'s offsets end at ", offsets[o + std::size_t(n)],
                    ", not its ", ids[piece], " connectivity ids"));
      for (long long i = 0; i < ids[piece]; ++i)
        if (connectivity[at + std::size_t(i)] < 0 ||
            connectivity[at + std::size_t(i)] >= points[piece])
          fail(concat("piece ", piece, "'s connectivity names point ",
                      connectivity[at + std::size_t(i)], "; it has ", points[piece]));
      o += std::size_t(n) + 1;
      at += std::size_t(ids[piece]);
    }
  }

  std::string file_;
  double budget_;
};

}  // namespace

vtkSmartPointer<vtkDataObject> readVtkHdf(const std::filesystem::path& path,
                                          const LoadOptions& options, LoadReport&) {
  const std::string file = path.string();
  Layout(path, options).check();
  VtkMessageTrap trap(path);
  vtkNew<vtkHDFReader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  trap.throwIfFailed("reading the VTKHDF file");
  vtkSmartPointer<vtkDataObject> out = reader->GetOutputDataObject(0);
  auto* data = vtkDataSet::SafeDownCast(out);
  if (!data) throw Error(concat(file, ": VTK's VTKHDF reader returned nothing"));
  checkVtkCells(data, file);
  return out;
}

}  // namespace sandstorm
