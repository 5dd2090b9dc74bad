#include "core/io/vector_array_choice.h"

#include <algorithm>
#include <map>
#include <set>

#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

bool isNumeric(vtkAbstractArray* a) {
  return vtkDataArray::SafeDownCast(a) != nullptr;
}

// Named numeric arrays of one location with `components` components, in file order.
std::vector<std::string> arraysWith(vtkFieldData* fd, int components) {
  std::vector<std::string> names;
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray* a = fd->GetAbstractArray(i);
    if (isNumeric(a) && a->GetNumberOfComponents() == components && a->GetName() &&
        !std::string_view(a->GetName()).starts_with("vtk"))
      names.emplace_back(a->GetName());
  }
  return names;
}

// Names across blocks, each once, in the order first met.
void addUnique(std::vector<std::string>& to, const std::vector<std::string>& names) {
  for (const std::string& n : names)
    if (std::find(to.begin(), to.end(), n) == to.end()) to.push_back(n);
}

std::vector<std::string> splitComponents(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    std::string part =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    while (!part.empty() && part.front() == ' ')
      part.erase(part.begin());
    while (!part.empty() && part.back() == ' ')
      part.pop_back();
    parts.push_back(part);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return parts;
}

// Sets of three one-component arrays named as components of one vector.
std::vector<std::vector<std::string>> componentSets(const std::vector<std::string>& scalars) {
  const std::set<std::string> have(scalars.begin(), scalars.end());
  std::vector<std::vector<std::string>> sets;
  for (const char* uvw : {"u", "U"}) {
    const std::string u = uvw, v = u == "u" ? "v" : "V", w = u == "u" ? "w" : "W";
    if (have.count(u) && have.count(v) && have.count(w)) sets.push_back({u, v, w});
  }
  for (const std::string& name : scalars) {
    if (name.size() < 2) continue;
    const char last = name.back();
    if (last != 'x' && last != 'X') continue;
    const std::string stem = name.substr(0, name.size() - 1);
    const bool upper = last == 'X';
    const std::string y = stem + (upper ? "Y" : "y"), z = stem + (upper ? "Z" : "z");
    if (have.count(y) && have.count(z)) sets.push_back({name, y, z});
  }
  return sets;
}

std::string joinedName(const std::vector<std::string>& parts) {
  std::string stem = parts[0].substr(0, parts[0].size() - 1);
  bool alike = true;
  for (std::size_t i = 1; i < parts.size(); ++i)
    alike = alike && parts[i].substr(0, parts[i].size() - 1) == stem;
  while (!stem.empty() && (stem.back() == '_' || stem.back() == '-' || stem.back() == '.'))
    stem.pop_back();
  return alike && !stem.empty() ? stem : "velocity";
}

std::string quotedList(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names)
    out += concat(out.empty() ? "'" : ", '", n, "'");
  return out;
}

vtkAbstractArray* findArray(vtkDataSet* data, const std::string& name, bool& cellData) {
  if (vtkAbstractArray* a = data->GetPointData()->GetAbstractArray(name.c_str())) {
    cellData = false;
    return a;
  }
  cellData = true;
  return data->GetCellData()->GetAbstractArray(name.c_str());
}

[[noreturn]] void ask(const std::string& file, const std::string& why,
                      const std::vector<VtkBlock>& blocks) {
  throw Error(concat(file, ": ", why,
                     "; choose one by name (--array NAME, or the config's field.name; three "
                     "components as --array u,v,w or field.name = [\"u\", \"v\", \"w\"]). "
                     "Arrays present: ",
                     arrayInventory(blocks)));
}

// The chosen name checked in every block: a numeric array of 3 components
// where it is present, or of 2 (a 2D simulation's: `planar` then) in every
// block that has it. True when some block has it.
bool checkNamed(const std::vector<VtkBlock>& blocks, const std::string& name,
                const std::string& file, bool* planar = nullptr) {
  bool found = false;
  int components = 0;
  for (const VtkBlock& b : blocks) {
    bool cell = false;
    vtkAbstractArray* a = findArray(b.data, name, cell);
    if (!a) continue;
    if (!isNumeric(a))
      throw Error(concat(file, ": array '", name, "' is not numeric; expected a 3-component ",
                         "vector array. Arrays present: ", arrayInventory(blocks)));
    const int n = a->GetNumberOfComponents();
    if (n != 3 && !(n == 2 && planar))
      throw Error(concat(file, ": array '", name, "' has ", n,
                         " component(s); expected a 3-component vector array (or a "
                         "2-component one, read as x and y), or three components joined "
                         "(--array u,v,w). Arrays present: ",
                         arrayInventory(blocks)));
    if (components != 0 && n != components)
      throw Error(concat(file, ": array '", name, "' has ", components,
                         " components in one block and ", n, " in another; expected the same"));
    components = n;
    found = true;
  }
  if (planar) *planar = components == 2;
  return found;
}

// A vector array of `n` tuples to fill: doubles where the source is, else floats.
vtkSmartPointer<vtkDataArray> newVectors(const char* name, bool isDouble, vtkIdType n) {
  vtkSmartPointer<vtkDataArray> out;
  if (isDouble)
    out = vtkSmartPointer<vtkDoubleArray>::New();
  else
    out = vtkSmartPointer<vtkFloatArray>::New();
  out->SetName(name);
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(n);
  return out;
}

// A two-component array as three, z 0.
vtkSmartPointer<vtkDataArray> planarVectors(vtkDataArray* xy) {
  const vtkIdType n = xy->GetNumberOfTuples();
  vtkSmartPointer<vtkDataArray> out = newVectors(xy->GetName(), xy->GetDataType() == VTK_DOUBLE, n);
  for (vtkIdType i = 0; i < n; ++i) {
    out->SetComponent(i, 0, xy->GetComponent(i, 0));
    out->SetComponent(i, 1, xy->GetComponent(i, 1));
    out->SetComponent(i, 2, 0.0);
  }
  return out;
}

std::string planarNote(const std::string& name) {
  return concat("vector array '", name,
                "' has two components (a 2D simulation's): read as (x, y, 0)");
}

bool checkComponents(const std::vector<VtkBlock>& blocks, const std::vector<std::string>& parts,
                     const std::string& file) {
  bool found = false;
  for (const VtkBlock& b : blocks) {
    int present = 0;
    for (const std::string& part : parts) {
      bool cell = false;
      vtkAbstractArray* a = findArray(b.data, part, cell);
      if (!a) continue;
      ++present;
      if (!isNumeric(a) || a->GetNumberOfComponents() != 1)
        throw Error(concat(file, ": array '", part, "' has ", a->GetNumberOfComponents(),
                           " components; a vector joined from components needs "
                           "one-component arrays. Arrays present: ",
                           arrayInventory(blocks)));
    }
    if (present == int(parts.size())) found = true;
  }
  return found;
}

vtkSmartPointer<vtkDataArray> joinComponents(vtkDataSet* data, const VectorChoice& choice,
                                             bool& cellData) {
  // Two components (a 2D simulation's u, v): z is 0.
  const int given = int(choice.components.size());
  vtkDataArray* parts[3] = {nullptr, nullptr, nullptr};
  bool cell[3] = {false, false, false};
  bool isDouble = false;
  for (int c = 0; c < given; ++c) {
    parts[c] =
        vtkDataArray::SafeDownCast(findArray(data, choice.components[std::size_t(c)], cell[c]));
    if (!parts[c]) return nullptr;
    isDouble = isDouble || parts[c]->GetDataType() == VTK_DOUBLE;
  }
  for (int c = 1; c < given; ++c)
    if (cell[c] != cell[0]) return nullptr;
  cellData = cell[0];
  const vtkIdType n = parts[0]->GetNumberOfTuples();
  for (int c = 1; c < given; ++c)
    if (parts[c]->GetNumberOfTuples() != n) return nullptr;
  vtkSmartPointer<vtkDataArray> out = newVectors(choice.name.c_str(), isDouble, n);
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      out->SetComponent(i, c, c < given ? parts[c]->GetComponent(i, 0) : 0.0);
  return out;
}

vtkSmartPointer<vtkDataSet> cellsToPoints(vtkDataSet* data, const std::filesystem::path& path) {
  // A cell array named as a point array would replace it at the points.
  vtkSmartPointer<vtkDataSet> input;
  input.TakeReference(data->NewInstance());
  input->ShallowCopy(data);
  vtkCellData* cd = input->GetCellData();
  for (int i = cd->GetNumberOfArrays() - 1; i >= 0; --i)
    if (const char* name = cd->GetArrayName(i); name && input->GetPointData()->GetArray(name))
      cd->RemoveArray(i);
  VtkMessageTrap trap(path);
  vtkNew<vtkCellDataToPointData> filter;
  trap.watch(filter);
  filter->SetInputData(input);
  filter->PassCellDataOff();
  filter->Update();
  trap.throwIfFailed("moving cell data to the points (vtkCellDataToPointData)");
  return filter->GetOutput();
}

bool hasCellScalars(vtkDataSet* data) {
  vtkCellData* cd = data->GetCellData();
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = cd->GetArray(i); a && a->GetNumberOfComponents() == 1 && a->GetName() &&
                                           !std::string_view(a->GetName()).starts_with("vtk"))
      return true;
  return false;
}

}  // namespace

std::string arrayInventory(const std::vector<VtkBlock>& blocks) {
  std::vector<std::string> items;
  auto list = [&](vtkFieldData* fd, const char* where) {
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
      vtkAbstractArray* a = fd->GetAbstractArray(i);
      const std::string item =
          concat("'", a->GetName() ? a->GetName() : "", "' (", a->GetNumberOfComponents(),
                 a->GetNumberOfComponents() == 1 ? " component" : " components", where, ")");
      if (std::find(items.begin(), items.end(), item) == items.end()) items.push_back(item);
    }
  };
  for (const VtkBlock& b : blocks) {
    list(b.data->GetPointData(), "");
    list(b.data->GetCellData(), ", cell data");
  }
  std::string out;
  for (const std::string& item : items)
    out += (out.empty() ? "" : ", ") + item;
  return out.empty() ? "none" : out;
}

VectorChoice chooseVectorArray(const std::vector<VtkBlock>& blocks,
                               const std::filesystem::path& path, const LoadOptions& options,
                               LoadReport& report) {
  const std::string file = path.string();
  VectorChoice choice;
  const std::string& asked = options.arrayName;
  if (asked.find(',') != std::string::npos) {
    choice.components = splitComponents(asked);
    if ((choice.components.size() != 3 && choice.components.size() != 2) ||
        std::any_of(choice.components.begin(), choice.components.end(),
                    [](const std::string& s) { return s.empty(); }))
      throw Error(concat(file, ": array '", asked,
                         "': expected one array's name, or three components' names separated "
                         "by commas (u,v,w), or two (u,v: z 0)"));
    if (!checkComponents(blocks, choice.components, file))
      throw Error(concat(file, ": no block has all of the arrays ", quotedList(choice.components),
                         "; arrays present: ", arrayInventory(blocks)));
    choice.name = joinedName(choice.components);
    report.notes.push_back(concat("vector '", choice.name, "' joined from the components ",
                                  quotedList(choice.components),
                                  choice.components.size() == 2 ? ", z 0" : ""));
    return choice;
  }
  if (!asked.empty()) {
    choice.name = asked;
    // VTK's Exodus reader names the vector it joins from vel_x, vel_y, vel_z "vel_".
    if (!checkNamed(blocks, asked, file, &choice.planar) &&
        !checkNamed(blocks, choice.name = asked + "_", file))
      throw Error(
          concat(file, ": no array named '", asked, "'; arrays present: ", arrayInventory(blocks)));
    if (choice.planar) report.notes.push_back(planarNote(choice.name));
    return choice;
  }
  // The active vectors, where a block marks them.
  for (const VtkBlock& b : blocks) {
    vtkDataArray* active = b.data->GetPointData()->GetVectors();
    if (!active || !active->GetName()) continue;
    choice.name = active->GetName();
    std::vector<std::string> all;
    for (const VtkBlock& other : blocks)
      addUnique(all, arraysWith(other.data->GetPointData(), 3));
    if (all.size() > 1)
      report.notes.push_back(concat("vector array '", choice.name,
                                    "' (the file's active vectors) of ", quotedList(all),
                                    "; --array NAME chooses another"));
    checkNamed(blocks, choice.name, file);
    return choice;
  }
  std::vector<std::string> pointVectors, cellVectors, pointScalars, cellScalars;
  for (const VtkBlock& b : blocks) {
    addUnique(pointVectors, arraysWith(b.data->GetPointData(), 3));
    addUnique(cellVectors, arraysWith(b.data->GetCellData(), 3));
    addUnique(pointScalars, arraysWith(b.data->GetPointData(), 1));
    addUnique(cellScalars, arraysWith(b.data->GetCellData(), 1));
  }
  const std::vector<std::string>& vectors = pointVectors.empty() ? cellVectors : pointVectors;
  if (vectors.size() == 1) {
    choice.name = vectors.front();
    return choice;
  }
  if (vectors.size() > 1) ask(file, "several vector arrays and none marked active", blocks);
  std::vector<std::vector<std::string>> sets = componentSets(pointScalars);
  if (sets.empty()) sets = componentSets(cellScalars);
  if (sets.size() == 1) {
    choice.components = sets.front();
    choice.name = joinedName(choice.components);
    report.notes.push_back(concat("no vector array: '", choice.name,
                                  "' joined from the components ", quotedList(choice.components),
                                  "; --array chooses others"));
    return choice;
  }
  if (sets.size() > 1) {
    std::string all;
    for (const auto& set : sets)
      all += concat(all.empty() ? "" : "; ", set[0], ",", set[1], ",", set[2]);
    ask(file, concat("no vector array, and several sets of components (", all, ")"), blocks);
  }
  // A 2D simulation's velocity: the one two-component array.
  std::vector<std::string> pointPlanar, cellPlanar;
  for (const VtkBlock& b : blocks) {
    addUnique(pointPlanar, arraysWith(b.data->GetPointData(), 2));
    addUnique(cellPlanar, arraysWith(b.data->GetCellData(), 2));
  }
  const std::vector<std::string>& planar = pointPlanar.empty() ? cellPlanar : pointPlanar;
  if (planar.size() == 1) {
    choice.name = planar.front();
    checkNamed(blocks, choice.name, file, &choice.planar);
    report.notes.push_back(planarNote(choice.name));
    return choice;
  }
  if (planar.size() > 1)
    ask(file, "no 3-component (vector) array, and several of 2 components", blocks);
  // A 2D simulation's u and v as one-component arrays, with no w.
  for (const std::vector<std::string>* scalars : {&pointScalars, &cellScalars})
    for (const auto& [u, v] : {std::pair<std::string, std::string>{"u", "v"}, {"U", "V"}})
      if (std::find(scalars->begin(), scalars->end(), u) != scalars->end() &&
          std::find(scalars->begin(), scalars->end(), v) != scalars->end()) {
        choice.components = {u, v};
        choice.name = joinedName(choice.components);
        report.notes.push_back(concat(
            "no vector array: '", choice.name, "' joined from the components ",
            quotedList(choice.components), ", z 0 (a 2D simulation's); --array chooses others"));
        return choice;
      }
  ask(file, "no 3-component (vector) array", blocks);
}

vtkSmartPointer<vtkDataSet> pointVectors(const VtkBlock& block, const VectorChoice& choice,
                                         const std::filesystem::path& path, LoadReport& report) {
  auto note = [&](const std::string& text) {
    if (std::find(report.notes.begin(), report.notes.end(), text) == report.notes.end())
      report.notes.push_back(text);
  };
  vtkSmartPointer<vtkDataSet> data = block.data;
  bool cellData = false;
  if (!choice.components.empty()) {
    vtkSmartPointer<vtkDataArray> joined = joinComponents(block.data, choice, cellData);
    if (!joined) return nullptr;
    data.TakeReference(block.data->NewInstance());
    data->ShallowCopy(block.data);
    (cellData ? static_cast<vtkFieldData*>(data->GetCellData()) : data->GetPointData())
        ->AddArray(joined);
  } else if (vtkAbstractArray* found = findArray(block.data, choice.name, cellData); !found) {
    return nullptr;
  } else if (choice.planar) {
    // The two components as three, in place of the array in a copy of the block.
    vtkSmartPointer<vtkDataArray> three = planarVectors(vtkDataArray::SafeDownCast(found));
    data.TakeReference(block.data->NewInstance());
    data->ShallowCopy(block.data);
    vtkFieldData* fd =
        cellData ? static_cast<vtkFieldData*>(data->GetCellData()) : data->GetPointData();
    fd->RemoveArray(choice.name.c_str());
    fd->AddArray(three);
  }
  if (cellData) {
    note(concat("array '", choice.name, "' is cell data: moved to the points"));
    return cellsToPoints(data, path);
  }
  // Scalar arrays in cell data (a simulation's pressure per cell) move to the
  // points too, as ParaView's Cell Data to Point Data does, to colour by them.
  if (hasCellScalars(data)) {
    note("cell-data scalar arrays moved to the points");
    return cellsToPoints(data, path);
  }
  return data;
}

}  // namespace sandstorm
