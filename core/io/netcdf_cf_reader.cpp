#include "core/io/netcdf_cf_reader.h"

#include <cmath>
#include <numbers>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNetCDFCFReader.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkRectilinearGrid.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>

#include "core/io/netcdf_header.h"
#include "core/io/vtk_message_trap.h"
#include "core/io/vtk_time_steps.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

constexpr double kEarthRadius = 6371000.0;  // metres, the mean radius

std::string lower(std::string s) {
  for (char& c : s)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string textOf(const NetcdfVariable* v, const char* name) {
  if (!v) return {};
  const NetcdfAttribute* a = v->attribute(name);
  return a ? lower(a->text) : std::string();
}

// How one axis's coordinates become metres.
struct Axis {
  enum Kind { Longitude, Latitude, Metres, Kilometres, Other } kind = Other;
  bool down = false;
  std::string name, units;
};

Axis axisOf(const NetcdfHeader& h, const std::string& dimension) {
  Axis a;
  a.name = dimension;
  const NetcdfVariable* coordinate = h.variable(dimension);
  a.units = textOf(coordinate, "units");
  const std::string standard = textOf(coordinate, "standard_name");
  const std::string u = a.units;
  if (standard == "longitude" || u == "degrees_east" || u == "degree_east" || u == "degrees_e" ||
      u == "degree_e" || u == "degreese" || u == "degreee")
    a.kind = Axis::Longitude;
  else if (standard == "latitude" || u == "degrees_north" || u == "degree_north" ||
           u == "degrees_n" || u == "degree_n" || u == "degreesn" || u == "degreen")
    a.kind = Axis::Latitude;
  else if (u == "m" || u == "meter" || u == "meters" || u == "metre" || u == "metres")
    a.kind = Axis::Metres;
  else if (u == "km" || u == "kilometer" || u == "kilometers" || u == "kilometre")
    a.kind = Axis::Kilometres;
  a.down = textOf(coordinate, "positive") == "down";
  return a;
}

// The names of the flow's components: the user's, u/v/w, or by standard_name.
std::string flowArrays(const NetcdfHeader& h, const std::string& asked) {
  if (!asked.empty()) return asked;
  std::string east, north, up;
  for (const NetcdfVariable& v : h.variables) {
    const std::string standard = textOf(&v, "standard_name");
    if (standard.rfind("eastward_", 0) == 0 && east.empty()) east = v.name;
    if (standard.rfind("northward_", 0) == 0 && north.empty()) north = v.name;
    if ((standard.rfind("upward_", 0) == 0 || standard.rfind("upward", 0) == 0) && up.empty())
      up = v.name;
  }
  if (!east.empty() && !north.empty() && !up.empty()) return concat(east, ",", north, ",", up);
  // Horizontal flow alone (a surface's wind or current): z 0.
  if (!east.empty() && !north.empty()) return concat(east, ",", north);
  return {};
}

// The first variable named in `arrays` (one name, or three joined by commas).
std::string firstName(const std::string& arrays) {
  return arrays.substr(0, arrays.find(','));
}

}  // namespace

vtkSmartPointer<vtkDataObject> readNetcdfCf(const std::filesystem::path& path, LoadOptions& options,
                                            LoadReport& report) {
  const std::string file = path.string();
  const NetcdfHeader h = readNetcdfHeader(path);
  options.arrayName = flowArrays(h, options.arrayName);
  // The flow's grid: its first variable's dimensions, or the most common
  // dimensions of three or more among the variables.
  const NetcdfVariable* flow = nullptr;
  if (!options.arrayName.empty()) {
    flow = h.variable(firstName(options.arrayName));
    if (!flow)
      throw Error(
          concat(file, ": no variable '", firstName(options.arrayName), "' (--array, field.name)"));
  } else {
    for (const char* name : {"u", "U", "velocity"})
      if (!flow) flow = h.variable(name);
    for (const NetcdfVariable& v : h.variables)
      if (!flow && v.dims.size() >= 3 && !h.dimension(v.name)) flow = &v;
  }
  if (!flow || flow->dims.size() < 2)
    throw Error(concat(file,
                       ": no variable on a grid of two or three dimensions to take the "
                       "flow from; choose one with --array (u,v,w)"));
  // Each of the flow's dimensions holds data (a record dimension no step was
  // written along holds none), and its coordinate variable, where there is
  // one, is CF's: one-dimensional along it, numeric. VTK's reader takes both
  // on trust.
  for (std::size_t d : flow->dims) {
    const auto& dim = h.dims[d];
    if (dim.length == 0)
      throw Error(concat(file, ": variable '", flow->name, "' has no values along '", dim.name, "'",
                         dim.unlimited ? " (no time step was written)" : ""));
    if (const NetcdfVariable* c = h.variable(dim.name);
        c && (c->dims.size() != 1 || c->dims[0] != d || c->type == 2 /* NC_CHAR */))
      throw Error(concat(file, ": coordinate variable '", dim.name,
                         "' is not a list of numbers along its dimension"));
  }
  // Every variable on the flow's grid is read: one step of each, together.
  double bytes = 0.0;
  for (const NetcdfVariable& v : h.variables)
    if (v.dims == flow->dims) {
      double values = h.values(v);
      if (!v.dims.empty() && h.dims[v.dims[0]].unlimited && h.records > 0)
        values /= double(h.records);
      bytes += values * 8.0;
    }
  if (bytes > double(options.memoryBudget))
    throw Error(concat(file, ": one time step of its variables on the grid of '", flow->name,
                       "' needs ", bytes,
                       " bytes, beyond the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes"));

  VtkMessageTrap trap(path);
  vtkNew<vtkNetCDFCFReader> reader;
  trap.watch(reader);
  reader->SetFileName(file.c_str());
  reader->SphericalCoordinatesOff();  // a plane in metres, not the globe
  reader->ReplaceFillValueWithNanOn();
  // Axes of one-dimensional coordinates: a rectilinear grid, whichever way
  // they run (latitudes often run north to south).
  bool rectilinear = true;
  for (std::size_t d : flow->dims) {
    const NetcdfVariable* c = h.variable(h.dims[d].name);
    rectilinear = rectilinear && (h.dims[d].unlimited || (c && c->dims.size() == 1));
  }
  if (rectilinear) reader->SetOutputTypeToRectilinear();
  reader->UpdateInformation();
  trap.throwIfFailed("reading the NetCDF file's structure");
  vtkStringArray* dims = reader->GetVariableDimensions();
  for (int i = 0; i < reader->GetNumberOfVariableArrays(); ++i)
    if (reader->GetVariableArrayName(i) == flow->name && dims && i < dims->GetNumberOfValues())
      reader->SetDimensions(dims->GetValue(i).c_str());
  updateAtStep(reader, options, report, file);
  trap.throwIfFailed("reading the NetCDF file");
  vtkSmartPointer<vtkDataObject> out = reader->GetOutputDataObject(0);
  if (!out) throw Error(concat(file, ": VTK's NetCDF reader returned nothing"));

  // The axes, fastest first: the flow's last dimensions (time aside).
  std::vector<Axis> axes;
  for (auto d = flow->dims.rbegin(); d != flow->dims.rend() && axes.size() < 3; ++d)
    if (!h.dims[*d].unlimited && lower(h.dims[*d].name) != "time")
      axes.push_back(axisOf(h, h.dims[*d].name));
  double middleLatitude = 0.0;
  double bounds[6] = {0, 0, 0, 0, 0, 0};
  if (auto* data = vtkDataSet::SafeDownCast(out)) data->GetBounds(bounds);
  for (std::size_t a = 0; a < axes.size(); ++a)
    if (axes[a].kind == Axis::Latitude) middleLatitude = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
  const double radians = std::numbers::pi / 180.0;
  auto toMetres = [&](std::size_t a, double v) {
    switch (axes[a].kind) {
      case Axis::Longitude:
        return v * radians * kEarthRadius * std::cos(middleLatitude * radians);
      case Axis::Latitude:
        return (v - middleLatitude) * radians * kEarthRadius;
      case Axis::Kilometres:
        return (axes[a].down ? -1000.0 : 1000.0) * v;
      case Axis::Metres:
        return axes[a].down ? -v : v;
      case Axis::Other:
        break;
    }
    return v;
  };
  for (std::size_t a = 0; a < axes.size(); ++a)
    if (axes[a].kind == Axis::Other) {
      const std::string note = concat("axis '", axes[a].name, "' (units '", axes[a].units,
                                      "') is not in metres or degrees: kept as the file gives it");
      report.notes.push_back(note);
      log::info(file, ": ", note);
    }
  if (auto* grid = vtkRectilinearGrid::SafeDownCast(out)) {
    vtkDataArray* coordinates[3] = {grid->GetXCoordinates(), grid->GetYCoordinates(),
                                    grid->GetZCoordinates()};
    for (std::size_t a = 0; a < axes.size(); ++a)
      for (vtkIdType i = 0; coordinates[a] && i < coordinates[a]->GetNumberOfTuples(); ++i)
        coordinates[a]->SetComponent(i, 0, toMetres(a, coordinates[a]->GetComponent(i, 0)));
  } else if (auto* image = vtkImageData::SafeDownCast(out)) {
    double origin[3], spacing[3];
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double o = toMetres(a, origin[a]), e = toMetres(a, origin[a] + spacing[a]);
      origin[a] = o;
      spacing[a] = e - o;
    }
    image->SetOrigin(origin);
    image->SetSpacing(spacing);
  } else if (auto* curvilinear = vtkStructuredGrid::SafeDownCast(out)) {
    vtkPoints* points = curvilinear->GetPoints();
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i) {
      double x[3];
      points->GetPoint(i, x);
      for (std::size_t a = 0; a < axes.size(); ++a)
        x[a] = toMetres(a, x[a]);
      points->SetPoint(i, x);
    }
  }
  if (auto* data = vtkDataSet::SafeDownCast(out)) data->ComputeBounds();
  return out;
}

}  // namespace sandstorm
