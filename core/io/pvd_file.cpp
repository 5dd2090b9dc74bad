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

  // Every DataSet, then grouped by time: a time's parts are one dataset.
  struct Entry {
    double time;
    std::string group;
    long part;
    std::filesystem::path file;
  };
  std::vector<Entry> entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    if (std::strcmp(e->GetName(), "DataSet") != 0) continue;
    const int line = i + 1;  // the DataSet element number (VTK keeps no line numbers)
    const char* name = e->GetAttribute("file");
    if (!name || !*name)
      throw Error(concat(file, ": <DataSet> number ", line, " has no file attribute"));
    const char* step = e->GetAttribute("timestep");
    double time = double(entries.size());
    if (step) {
      char* end = nullptr;
      time = std::strtod(step, &end);
      if (end == step || *end != '\0' || !std::isfinite(time))
        throw Error(
            concat(file, ": <DataSet> number ", line, ": timestep \"", step, "\" is not a number"));
    }
    long part = 0;
    if (const char* text = e->GetAttribute("part")) {
      char* end = nullptr;
      part = std::strtol(text, &end, 10);
      if (end == text || *end != '\0' || part < 0)
        throw Error(concat(file, ": <DataSet> number ", line, ": part \"", text,
                           "\" is not a whole number of 0 or more"));
    }
    const char* group = e->GetAttribute("group");
    std::filesystem::path target(name);
    if (target.is_relative()) target = path.parent_path() / target;
    entries.push_back({time, group ? group : "", part, target});
  }
  if (entries.empty()) throw Error(concat(file, ": the collection lists no <DataSet>"));
  // By time, then part and group: a repeated part of a time lies beside its twin.
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    if (a.time != b.time) return a.time < b.time;
    return a.part != b.part ? a.part < b.part : a.group < b.group;
  });
  std::vector<PvdFrame> frames;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Entry& e = entries[i];
    if (i > 0 && e.time == entries[i - 1].time) {
      const Entry& p = entries[i - 1];
      if (e.part == p.part && e.group == p.group)
        throw Error(concat(file, ": timestep ", e.time, " appears twice (",
                           p.file.filename().string(), ", ", e.file.filename().string(),
                           e.part > 0 || p.part > 0 ? concat(", both part ", e.part) : "",
                           "); expected one file per time, or parts numbered part=\"0\", "
                           "\"1\", ..."));
      for (const std::filesystem::path& other : frames.back().parts)
        if (other.lexically_normal() == e.file.lexically_normal())
          throw Error(concat(file, ": timestep ", e.time, " names ", e.file.filename().string(),
                             " for two of its parts; expected a file a part"));
      frames.back().parts.push_back(e.file);
      continue;
    }
    frames.push_back({e.time, {e.file}});
  }
  return frames;
}

}  // namespace sandstorm
