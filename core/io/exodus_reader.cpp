#include "core/io/exodus_reader.h"

#include <algorithm>
#include <map>
#include <vector>

#include <netcdf.h>

#include <vtkCompositeDataSet.h>
#include <vtkDataObjectTree.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkExodusIIReader.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>

#include "core/io/budget_advice.h"
#include "core/io/exodus_spread.h"
#include "core/io/netcdf_header.h"
#include "core/io/vtk_blocks.h"
#include "core/io/vtk_cell_check.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_time_steps.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

// Every kind of Exodus object with its count and its ids.
struct ExodusObjects {
  const char* count;
  const char* ids;
  const char* what;
};
constexpr ExodusObjects kObjects[] = {
    {"num_el_blk", "eb_prop1", "element block"}, {"num_node_sets", "ns_prop1", "node set"},
    {"num_side_sets", "ss_prop1", "side set"},   {"num_ed_blk", "ed_prop1", "edge block"},
    {"num_fa_blk", "fa_prop1", "face block"},    {"num_elem_sets", "els_prop1", "element set"},
    {"num_edge_sets", "es_prop1", "edge set"},   {"num_face_sets", "fs_prop1", "face set"},
    {"num_node_maps", "nm_prop1", "node map"},   {"num_elem_maps", "em_prop1", "element map"},
    {"num_edge_maps", "edm_prop1", "edge map"},  {"num_face_maps", "fam_prop1", "face map"}};
constexpr std::uint64_t kMaxObjects = 100000;  // of one kind
constexpr double kMaxNameLength = 256;         // NetCDF's NC_MAX_NAME

// A variable's values as integers, through the NetCDF library.
std::vector<long long> integers(const NetcdfFile& f, const NetcdfHeader& h, const NetcdfVariable& v,
                                const std::string& file) {
  int var = -1;
  if (nc_inq_varid(f.id(), v.name.c_str(), &var) != NC_NOERR)
    throw Error(concat(file, ": the NetCDF library finds no '", v.name, "'"));
  std::vector<long long> values(std::size_t(h.values(v)));
  if (!values.empty() && nc_get_var_longlong(f.id(), var, values.data()) != NC_NOERR)
    throw Error(concat(file, ": reading '", v.name, "' failed"));
  return values;
}

// The Exodus II layout the reader walks: every object count with its ids,
// every block with its sizes and connectivity, the coordinates, the result
// variables' names and values, each of the shape its dimensions give (VTK's
// reader fails, and leaks, on files that lack one).
void checkExodusLayout(const NetcdfHeader& h, const std::string& file) {
  auto fail = [&](const std::string& what) {
    throw Error(concat(file, ": ", what, " (the Exodus II layout)"));
  };
  auto length = [&](const std::string& dim) -> std::uint64_t {
    const auto* d = h.dimension(dim);
    return d ? d->length : 0;
  };
  // A variable named `name` whose dimensions are `dims` exactly.
  auto expect = [&](const std::string& name, const std::vector<std::string>& dims) {
    const NetcdfVariable* v = h.variable(name);
    if (!v) fail(concat("no variable '", name, "'"));
    bool same = v->dims.size() == dims.size();
    for (std::size_t i = 0; same && i < dims.size(); ++i)
      same = h.dims[v->dims[i]].name == dims[i];
    if (!same) {
      std::string want;
      for (const std::string& d : dims)
        want += (want.empty() ? "" : ", ") + d;
      fail(concat("variable '", name, "' is not shaped (", want, ")"));
    }
  };
  for (const ExodusObjects& o : kObjects)
    if (h.dimension(o.count)) expect(o.ids, {o.count});
  if (length("num_nodes") > 0) {
    if (h.variable("coord")) {
      expect("coord", {"num_dim", "num_nodes"});
    } else {
      const char* axes[] = {"coordx", "coordy", "coordz"};
      for (std::uint64_t a = 0; a < std::min<std::uint64_t>(length("num_dim"), 3); ++a)
        expect(axes[a], {"num_nodes"});
    }
  }
  for (const ExodusObjects& o : kObjects)
    if (length(o.count) > kMaxObjects) fail(concat(length(o.count), " objects (", o.count, ")"));
  // The reader sizes its name buffers by this attribute, unchecked.
  for (const NetcdfAttribute& a : h.attributes)
    if (a.name == "maximum_name_length" &&
        (a.values.size() != 1 || !(a.values[0] >= 0.0 && a.values[0] <= kMaxNameLength)))
      fail(concat("maximum_name_length is ",
                  a.values.empty() ? std::string("not a number") : concat(a.values[0]),
                  "; Exodus II names hold at most ", kMaxNameLength, " characters"));
  const std::uint64_t blocks = length("num_el_blk");
  for (std::uint64_t b = 1; b <= blocks; ++b) {
    const std::string in = concat("num_el_in_blk", b), per = concat("num_nod_per_el", b);
    if (!h.dimension(in)) fail(concat("no dimension '", in, "'"));
    if (length(in) > 0) {
      if (!h.dimension(per)) fail(concat("no dimension '", per, "'"));
      expect(concat("connect", b), {in, per});
      const NetcdfAttribute* type = h.variable(concat("connect", b))->attribute("elem_type");
      if (!type || type->text.empty() || type->text.size() > 32)
        fail(concat("connect", b, " has no elem_type naming its elements"));
    }
  }
  for (const char* kind : {"nod", "elem", "glo"}) {
    const std::string count = concat("num_", kind, "_var");
    if (length(count) > 0) expect(concat("name_", kind, "_var"), {count, "len_name"});
  }
  const std::uint64_t nodal = length("num_nod_var");
  if (h.variable("vals_nod_var")) {
    expect("vals_nod_var", {"time_step", "num_nod_var", "num_nodes"});
  } else {
    for (std::uint64_t v = 1; v <= nodal; ++v)
      expect(concat("vals_nod_var", v), {"time_step", "num_nodes"});
  }
  if (h.dimension("time_step")) expect("time_whole", {"time_step"});
  for (const NetcdfVariable& v : h.variables) {
    // vals_elem_var<v>eb<b>: one step of block b's elements.
    if (v.name.rfind("vals_elem_var", 0) != 0) continue;
    const std::size_t eb = v.name.find("eb");
    if (eb == std::string::npos) fail(concat("variable '", v.name, "' names no block"));
    expect(v.name, {"time_step", concat("num_el_in_blk", v.name.substr(eb + 2))});
  }
}

// The ids of each kind of object are distinct: VTK's reader maps objects by
// id and reads past its own tables when two share one.
void checkObjectIds(const NetcdfFile& f, const NetcdfHeader& h, const std::string& file) {
  for (const ExodusObjects& o : kObjects) {
    const NetcdfVariable* v = h.variable(o.ids);
    if (!v) continue;
    const std::vector<long long> ids = integers(f, h, *v, file);
    std::map<long long, std::size_t> first;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const auto [at, added] = first.emplace(ids[i], i);
      if (!added)
        throw Error(concat(file, ": ", o.what, "s ", at->second + 1, " and ", i + 1,
                           " share the id ", ids[i], " (", o.ids,
                           "); Exodus II needs each one's id to be its own"));
    }
  }
}

// Every block's connectivity names nodes of the mesh: VTK's reader takes each
// node number as an index into the coordinates unchecked.
void checkConnectivity(const NetcdfFile& f, const NetcdfHeader& h, const std::string& file) {
  const auto* nodes = h.dimension("num_nodes");
  const auto* blocks = h.dimension("num_el_blk");
  if (!nodes || !blocks || blocks->length == 0) return;
  for (std::uint64_t b = 1; b <= blocks->length; ++b) {
    const NetcdfVariable* v = h.variable(concat("connect", b));
    if (!v) continue;
    const std::vector<long long> connectivity = integers(f, h, *v, file);
    for (std::size_t i = 0; i < connectivity.size(); ++i)
      if (connectivity[i] < 1 || connectivity[i] > (long long)nodes->length)
        throw Error(concat(file, ": element block ", b, "'s connectivity names node ",
                           connectivity[i], "; the nodes are 1..", nodes->length));
  }
}

// What the reader will hold at once (the nodes' coordinates, every block's
// connectivity, one step of the nodal variables), in bytes; and the shape of
// an Exodus file at all.
double exodusBytes(const NetcdfHeader& h, const std::string& file) {
  const auto* dims = h.dimension("num_dim");
  const auto* nodes = h.dimension("num_nodes");
  if (!dims || !nodes)
    throw Error(concat(file,
                       ": a NetCDF file without num_dim and num_nodes: not an Exodus II "
                       "mesh (a NetCDF CF field is named .nc)"));
  if (dims->length < 1 || dims->length > 3)
    throw Error(concat(file, ": num_dim is ", dims->length, "; expected 1, 2 or 3"));
  double bytes = double(nodes->length) * 3.0 * 8.0;
  double nodalVariables = 0.0;
  for (const NetcdfVariable& v : h.variables) {
    if (v.name.rfind("connect", 0) == 0) bytes += h.values(v) * 8.0;
    if (v.name.rfind("vals_nod_var", 0) == 0) nodalVariables += 1.0;
  }
  if (const auto* n = h.dimension("num_nod_var")) nodalVariables = double(n->length);
  return bytes + nodalVariables * double(nodes->length) * 8.0;
}

// One file, its header already read and held to the budget: its layout, ids
// and connectivity checked, then VTK's reader at options.timeStep.
vtkSmartPointer<vtkDataObject> readExodusFile(const std::filesystem::path& path,
                                              const NetcdfHeader& header,
                                              const LoadOptions& options, LoadReport& report) {
  const std::string file = path.string();
  checkExodusLayout(header, file);
  {
    const NetcdfFile f(file);
    checkObjectIds(f, header, file);
    checkConnectivity(f, header, file);
  }
  VtkMessageTrap trap(path);
  vtkNew<vtkExodusIIReader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  // The reader's bookkeeping arrays are no quantity to colour by.
  reader->SetGenerateObjectIdCellArray(0);
  reader->SetGenerateGlobalElementIdArray(0);
  reader->SetGenerateGlobalNodeIdArray(0);
  reader->SetGenerateImplicitElementIdArray(0);
  reader->SetGenerateImplicitNodeIdArray(0);
  reader->SetGenerateFileIdArray(0);
  if (!reader->CanReadFile(file.c_str())) {
    trap.throwIfFailed("opening the Exodus II file");
    throw Error(concat(file, ": VTK's Exodus II reader does not accept it"));
  }
  reader->UpdateInformation();
  trap.throwIfFailed("reading the Exodus II file's structure");
  for (int i = 0; i < reader->GetNumberOfObjects(vtkExodusIIReader::ELEM_BLOCK); ++i)
    reader->SetObjectStatus(vtkExodusIIReader::ELEM_BLOCK, i, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  return readAtStep(reader, trap, options, report, file, "Exodus II file");
}

// A decomposed run's files, rank after rank (the NetCDF library takes one
// call at a time: netcdf_lock.h), each rank's blocks under a block of its
// own named after its file, the leaves "rank 2: <block>".
vtkSmartPointer<vtkDataObject> readRanks(const std::vector<std::filesystem::path>& files,
                                         const std::vector<NetcdfHeader>& headers,
                                         const LoadOptions& options, LoadReport& report) {
  const std::size_t n = files.size();
  std::vector<vtkSmartPointer<vtkDataObject>> parts(n);
  std::vector<LoadReport> reports(n);
  for (std::size_t r = 0; r < n; ++r)
    parts[r] = readExodusFile(files[r], headers[r], options, reports[r]);
  for (std::size_t r = 1; r < n; ++r)
    if (reports[r].times != reports[0].times)
      throw Error(concat(files[r].string(), ": holds ", reports[r].times.size(),
                         " time steps, rank 0's file ", files[0].filename().string(), " ",
                         reports[0].times.size(),
                         " (or other times); the ranks of one run hold the same steps"));
  report.times = reports[0].times;
  auto out = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  out->SetNumberOfBlocks(unsigned(n));
  for (std::size_t r = 0; r < n; ++r) {
    vtkSmartPointer<vtkDataObjectTreeIterator> it;
    if (auto* tree = vtkDataObjectTree::SafeDownCast(parts[r])) {
      it.TakeReference(tree->NewTreeIterator());
      it->VisitOnlyLeavesOn();
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
        vtkInformation* info = it->GetCurrentMetaData();
        const char* name = info->Has(vtkCompositeDataSet::NAME())
                               ? info->Get(vtkCompositeDataSet::NAME())
                               : nullptr;
        info->Set(vtkCompositeDataSet::NAME(),
                  concat("rank ", r, ": ", name ? name : "block").c_str());
      }
    }
    out->SetBlock(unsigned(r), parts[r]);
    out->GetMetaData(unsigned(r))
        ->Set(vtkCompositeDataSet::NAME(), files[r].filename().string().c_str());
  }
  report.notes.push_back(concat("a decomposed run: its ", n, " ranks' files (",
                                files.front().filename().string(), " .. ",
                                files.back().filename().string(), ") read together"));
  return out;
}

}  // namespace

vtkSmartPointer<vtkDataObject> readExodus(const std::filesystem::path& path,
                                          const LoadOptions& options, LoadReport& report) {
  const std::vector<std::filesystem::path> files = exodusRunFiles(path);
  // Every file's header and what the reader will hold, before any reader runs.
  std::vector<NetcdfHeader> headers;
  double bytes = 0.0;
  for (const std::filesystem::path& f : files) {
    headers.push_back(readNetcdfHeader(f));
    bytes += exodusBytes(headers.back(), f.string());
  }
  if (bytes > double(options.memoryBudget))
    throw Error(concat(
        path.string(), ": ",
        files.size() == 1 ? std::string("its") : concat("its run's ", files.size(), " files'"),
        " nodes, their connectivity and one step of the nodal variables need ", bytes,
        " bytes, beyond the memory budget (field.memory_budget) of ", options.memoryBudget,
        " bytes", raiseBudget(bytes)));
  if (files.size() == 1) return readExodusFile(path, headers.front(), options, report);
  return readRanks(files, headers, options, report);
}

}  // namespace sandstorm
