#include "core/flow/streamline_vtp.h"

#include <functional>
#include <sstream>

#include "core/util/error.h"
#include "core/util/output_file.h"

namespace sandstorm {
namespace {

// A name as an XML attribute's value (a file's array may be called "a<b").
std::string escaped(const std::string& name) {
  std::string out;
  for (char c : name)
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  return out;
}

void dataArray(std::ostringstream& out, const char* type, const std::string& name, int components,
               const std::function<void(std::ostringstream&)>& values) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << escaped(name) << "\"";
  if (components > 1) out << " NumberOfComponents=\"" << components << "\"";
  out << " format=\"ascii\">\n";
  values(out);
  out << "\n        </DataArray>\n";
}

std::string componentName(ColorQuantity q) {
  switch (q) {
    case ColorQuantity::VelocityX:
      return "velocity_x";
    case ColorQuantity::VelocityY:
      return "velocity_y";
    case ColorQuantity::VelocityZ:
      return "velocity_z";
    default:
      return "";
  }
}

}  // namespace

void writeStreamlinesVtp(std::span<const Streamline> lines, ColorQuantity colorBy,
                         const std::filesystem::path& path, const std::string& what,
                         std::span<const PointArray> extra) {
  std::size_t points = 0;
  for (const Streamline& l : lines)
    points += l.points.size();
  for (const PointArray& a : extra)
    if (a.values.size() != points)
      throw Error(concat(what, " ", path.string(), ": array '", a.name, "' has ", a.values.size(),
                         " values for ", points, " points"));
  auto each = [&](const std::function<void(const Streamline&, std::size_t)>& f) {
    for (const Streamline& l : lines)
      for (std::size_t i = 0; i < l.points.size(); ++i)
        f(l, i);
  };
  std::ostringstream out;
  out.precision(9);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << points << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << lines.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <PointData Vectors=\"velocity\" Scalars=\"speed\">\n";
  dataArray(out, "Float32", "velocity", 3, [&](std::ostringstream& o) {
    each([&](const Streamline& l, std::size_t i) {
      const glm::vec3 v = l.points[i].velocity;
      o << v.x << ' ' << v.y << ' ' << v.z << ' ';
    });
  });
  dataArray(out, "Float32", "speed", 1, [&](std::ostringstream& o) {
    each(
        [&](const Streamline& l, std::size_t i) { o << glm::length(l.points[i].velocity) << ' '; });
  });
  dataArray(out, "Float32", "arc_length", 1, [&](std::ostringstream& o) {
    for (const Streamline& l : lines) {
      std::vector<float> arc(l.points.size(), 0.0f);
      const std::size_t seed = std::size_t(l.seedIndex);
      for (std::size_t i = seed + 1; i < l.points.size(); ++i)
        arc[i] = arc[i - 1] + glm::length(l.points[i].position - l.points[i - 1].position);
      for (std::size_t i = seed; i-- > 0;)
        arc[i] = arc[i + 1] - glm::length(l.points[i + 1].position - l.points[i].position);
      for (float a : arc)
        o << a << ' ';
    }
  });
  if (const std::string name = componentName(colorBy); !name.empty()) {
    const int axis = int(colorBy) - int(ColorQuantity::VelocityX);
    dataArray(out, "Float32", name, 1, [&](std::ostringstream& o) {
      each([&](const Streamline& l, std::size_t i) { o << l.points[i].velocity[axis] << ' '; });
    });
  }
  for (const PointArray& a : extra)
    dataArray(out, "Float32", a.name, 1, [&](std::ostringstream& o) {
      for (float v : a.values)
        o << v << ' ';
    });
  out << "      </PointData>\n      <Points>\n";
  dataArray(out, "Float32", "Points", 3, [&](std::ostringstream& o) {
    each([&](const Streamline& l, std::size_t i) {
      const glm::vec3 p = l.points[i].position;
      o << p.x << ' ' << p.y << ' ' << p.z << ' ';
    });
  });
  out << "      </Points>\n      <Lines>\n";
  dataArray(out, "Int64", "connectivity", 1, [&](std::ostringstream& o) {
    for (std::size_t i = 0; i < points; ++i)
      o << i << ' ';
  });
  dataArray(out, "Int64", "offsets", 1, [&](std::ostringstream& o) {
    std::size_t end = 0;
    for (const Streamline& l : lines)
      o << (end += l.points.size()) << ' ';
  });
  out << "      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  const std::string text = out.str();
  writeFile(path, std::span<const char>(text.data(), text.size()), what);
}

}  // namespace sandstorm
