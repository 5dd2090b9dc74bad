#include "core/io/pvd_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "core/io/vtk_message_trap.h"
#include "core/util/error.h"

namespace sandstorm {

std::vector<PvdFrame> readPvd(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::is_regular_file(path))
    throw Error(concat(file, ": cannot open the file for reading"));
  VtkMessageTrap trap(path);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.c_str());
  const int ok = parser->Parse();
  trap.throwIfFailed("parsing the .pvd XML");
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!ok || !root) throw Error(concat(file, ": is not well-formed XML"));
  if (std::strcmp(root->GetName(), "VTKFile") != 0 || !root->GetAttribute("type") ||
      std::strcmp(root->GetAttribute("type"), "Collection") != 0)
    throw Error(concat(file, ": the root element is not <VTKFile type=\"Collection\">"));
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (!collection) throw Error(concat(file, ": has no <Collection> element"));

  std::vector<PvdFrame> frames;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    if (std::strcmp(e->GetName(), "DataSet") != 0) continue;
    const int line = i + 1;  // the DataSet element number (VTK keeps no line numbers)
    if (const char* part = e->GetAttribute("part"); part && std::atoi(part) != 0) continue;
    const char* name = e->GetAttribute("file");
    if (!name || !*name)
      throw Error(concat(file, ": <DataSet> number ", line, " has no file attribute"));
    const char* step = e->GetAttribute("timestep");
    double time = double(frames.size());
    if (step) {
      char* end = nullptr;
      time = std::strtod(step, &end);
      if (end == step || *end != '\0' || !std::isfinite(time))
        throw Error(
            concat(file, ": <DataSet> number ", line, ": timestep \"", step, "\" is not a number"));
    }
    std::filesystem::path target(name);
    if (target.is_relative()) target = path.parent_path() / target;
    frames.push_back({time, target});
  }
  if (frames.empty()) throw Error(concat(file, ": the collection lists no <DataSet>"));
  std::stable_sort(frames.begin(), frames.end(),
                   [](const PvdFrame& a, const PvdFrame& b) { return a.time < b.time; });
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i].time == frames[i - 1].time)
      throw Error(concat(file, ": timestep ", frames[i].time, " appears twice (",
                         frames[i - 1].file.filename().string(), ", ",
                         frames[i].file.filename().string(), "); expected one file per time"));
  return frames;
}

}  // namespace sandstorm
