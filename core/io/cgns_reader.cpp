#include "core/io/cgns_reader.h"

#include <vtk_cgns.h>
#include VTK_CGNS(cgnslib.h)

#include <vector>

#include <vtkCGNSReader.h>
#include <vtkDataSet.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>

#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_time_steps.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

class CgnsFile {
 public:
  explicit CgnsFile(const std::string& file) : file_(file) {
    if (cg_open(file.c_str(), CG_MODE_READ, &fn_) != CG_OK) {
      fn_ = -1;
      fail(concat("the CGNS library cannot open it: ", cg_get_error()));
    }
  }
  ~CgnsFile() {
    if (fn_ >= 0) cg_close(fn_);
  }
  CgnsFile(const CgnsFile&) = delete;
  CgnsFile& operator=(const CgnsFile&) = delete;

  [[noreturn]] void fail(const std::string& what) const { throw Error(concat(file_, ": ", what)); }
  int id() const { return fn_; }
  void ok(int status, const std::string& what) const {
    if (status != CG_OK) fail(concat(what, ": ", cg_get_error()));
  }

 private:
  std::string file_;
  int fn_ = -1;
};

void checkCgns(const std::string& file, const LoadOptions& options) {
  CgnsFile f(file);
  int bases = 0;
  f.ok(cg_nbases(f.id(), &bases), "reading its bases");
  if (bases < 1) f.fail("holds no base");
  char name[64];
  int cellDim = 0, physDim = 0;
  f.ok(cg_base_read(f.id(), 1, name, &cellDim, &physDim), "reading base 1");
  if (cellDim < 1 || cellDim > 3 || physDim < 1 || physDim > 3)
    f.fail(concat("base '", name, "' has cells of dimension ", cellDim, " in ", physDim,
                  " dimensions"));
  int zones = 0;
  f.ok(cg_nzones(f.id(), 1, &zones), "reading the zones");
  if (zones < 1 || zones > 100000) f.fail(concat(zones, " zones"));
  double bytes = 0.0;
  const double budget = double(options.memoryBudget);
  for (int z = 1; z <= zones; ++z) {
    cgsize_t size[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    char zone[64];
    f.ok(cg_zone_read(f.id(), 1, z, zone, size), concat("reading zone ", z));
    CGNS_ENUMT(ZoneType_t) type;
    f.ok(cg_zone_type(f.id(), 1, z, &type), concat("reading zone '", zone, "'s type"));
    const std::string where = concat("zone '", zone, "'");
    double vertices = 1.0;
    if (type == CGNS_ENUMV(Structured)) {
      for (int a = 0; a < cellDim; ++a) {
        if (size[a] < 1) f.fail(concat(where, ": ", size[a], " vertices along an axis"));
        vertices *= double(size[a]);
      }
    } else if (type == CGNS_ENUMV(Unstructured)) {
      vertices = double(size[0]);
      if (size[0] < 1) f.fail(concat(where, ": ", size[0], " vertices"));
    } else {
      f.fail(concat(where, ": a zone type CGNS does not define"));
    }
    bytes += vertices * 8.0 * 6.0;  // coordinates and a vector of doubles
    if (bytes > budget)
      f.fail(concat(where, ": its vertices take the memory budget (field.memory_budget) of ",
                    options.memoryBudget, " bytes"));
    if (type != CGNS_ENUMV(Unstructured)) continue;
    int sections = 0;
    f.ok(cg_nsections(f.id(), 1, z, &sections), concat("reading ", where, "'s sections"));
    if (sections > 100000) f.fail(concat(where, ": ", sections, " sections"));
    for (int s = 1; s <= sections; ++s) {
      char section[64];
      CGNS_ENUMT(ElementType_t) element;
      cgsize_t start = 0, end = 0;
      int boundary = 0, parent = 0;
      f.ok(cg_section_read(f.id(), 1, z, s, section, &element, &start, &end, &boundary, &parent),
           concat("reading ", where, "'s section ", s));
      const std::string in = concat(where, " section '", section, "'");
      if (element == CGNS_ENUMV(NGON_n) || element == CGNS_ENUMV(NFACE_n))
        f.fail(concat(in, ": polyhedral (NGON_n, NFACE_n) sections are not read"));
      cgsize_t dataSize = 0;
      f.ok(cg_ElementDataSize(f.id(), 1, z, s, &dataSize), concat("sizing ", in));
      if (end < start || dataSize < 0 || double(dataSize) * 8.0 > budget - bytes)
        f.fail(concat(in, ": elements ", start, "..", end, " of ", dataSize,
                      " ids, beyond the memory budget (field.memory_budget)"));
      bytes += double(dataSize) * 8.0;
      std::vector<cgsize_t> ids(static_cast<std::size_t>(dataSize));
      std::vector<cgsize_t> parents;
      if (parent) parents.resize(static_cast<std::size_t>(4 * (end - start + 1)));
      if (dataSize > 0)
        f.ok(cg_elements_read(f.id(), 1, z, s, ids.data(), parent ? parents.data() : nullptr),
             concat("reading ", in));
      // Node ids, 1-based; a MIXED section writes each element's type first.
      for (std::size_t i = 0; i < ids.size();) {
        int nodes = 0;
        if (element == CGNS_ENUMV(MIXED)) {
          const auto t = CGNS_ENUMT(ElementType_t)(ids[i++]);
          if (cg_npe(t, &nodes) != CG_OK || nodes <= 0)
            f.fail(concat(in, ": element type ", int(t), " in a MIXED section"));
        } else {
          if (cg_npe(element, &nodes) != CG_OK || nodes <= 0)
            f.fail(concat(in, ": element type ", int(element), " is not read"));
        }
        for (int k = 0; k < nodes; ++k, ++i) {
          if (i >= ids.size()) f.fail(concat(in, ": the connectivity ends inside an element"));
          if (ids[i] < 1 || double(ids[i]) > vertices)
            f.fail(concat(in, ": an element names vertex ", ids[i], "; the zone has ", vertices));
        }
      }
    }
  }
}

}  // namespace

vtkSmartPointer<vtkDataObject> readCgns(const std::filesystem::path& path,
                                        const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  checkCgns(file, options);
  VtkMessageTrap trap(path);
  vtkNew<vtkCGNSReader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  reader->UpdateInformation();
  trap.throwIfFailed("reading the CGNS file's structure");
  reader->EnableAllPointArrays();
  reader->EnableAllCellArrays();
  vtkSmartPointer<vtkDataObject> out = readAtStep(reader, trap, options, report, file, "CGNS file");
  return out;
}

}  // namespace sandstorm
