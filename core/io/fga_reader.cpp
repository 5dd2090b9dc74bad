#include "core/io/fga_reader.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/io/grid_resample.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

class Tokens {
 public:
  Tokens(std::string text, std::string file) : text_(std::move(text)), file_(std::move(file)) {}

  // The next number, or false at the end of the text.
  bool next(double& out) {
    while (pos_ < text_.size() &&
           (text_[pos_] == ',' || std::isspace((unsigned char)text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= text_.size()) return false;
    const char* start = text_.c_str() + pos_;
    char* end = nullptr;
    out = std::strtod(start, &end);
    const std::size_t len = std::size_t(end - start);
    const char after = pos_ + len < text_.size() ? text_[pos_ + len] : ',';
    if (len == 0 || !(after == ',' || std::isspace((unsigned char)after))) {
      std::size_t stop = pos_;
      while (stop < text_.size() && text_[stop] != ',' && !std::isspace((unsigned char)text_[stop]))
        ++stop;
      throw Error(concat(file_, ":", line_, ": '",
                         text_.substr(pos_, std::min<std::size_t>(stop - pos_, 40)),
                         "' is not a number"));
    }
    pos_ += len;
    return true;
  }
  double expect(const char* what) {
    double v;
    if (!next(v)) throw Error(concat(file_, ":", line_, ": the file ends before the ", what));
    return v;
  }
  int line() const { return line_; }

 private:
  std::string text_;
  std::string file_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

VectorField readFga(const std::filesystem::path& path, const LoadOptions& options,
                    LoadReport& report) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::size_t size = buffer.str().size();
  {
    // A file cut inside its last number still parses ("12.5" -> "1"); FGA
    // writers end the last value with a comma or a newline.
    const std::string& text = buffer.str();
    const auto last = text.find_last_not_of(" \t");
    if (last != std::string::npos && (std::isdigit((unsigned char)text[last]) || text[last] == '.'))
      throw Error(concat(file,
                         ": ends inside a number, without a final comma or newline; the "
                         "file is truncated (if it is complete, end it with a newline)"));
  }
  Tokens t(buffer.str(), file);

  glm::ivec3 n;
  for (int a = 0; a < 3; ++a) {
    const double d = t.expect("grid dimensions");
    if (!(d >= 1.0) || d != std::floor(d) || d > 1e9)
      throw Error(concat(file, ":", t.line(), ": dimension ", "xyz"[a], " is ", d,
                         "; expected a positive whole number of voxels"));
    n[a] = int(d);
  }
  const double points = double(n.x) * n.y * n.z;
  if (points > double(VectorField::kMaxPoints) || points * 12.0 > double(options.memoryBudget))
    throw Error(concat(file, ": ", n.x, "x", n.y, "x", n.z,
                       " voxels exceed the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes (12 per point)"));
  if (points * 6.0 > double(size))  // each vector takes at least "0,0,0,"
    throw Error(concat(file, ": ", n.x, "x", n.y, "x", n.z, " vectors cannot fit in its ", size,
                       " bytes; the file is truncated or its dimensions are wrong"));
  glm::dvec3 lo, hi;
  for (int a = 0; a < 3; ++a)
    lo[a] = t.expect("bounds minimum");
  for (int a = 0; a < 3; ++a)
    hi[a] = t.expect("bounds maximum");
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a]) || !std::isfinite(lo[a]) || !std::isfinite(hi[a]))
      throw Error(concat(file, ":", t.line(), ": bounds along ", "xyz"[a], " run from ", lo[a],
                         " to ", hi[a], "; expected max > min (a positive voxel size)"));

  std::vector<glm::vec3> raw(static_cast<std::size_t>(points));
  std::size_t nonFinite = 0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    glm::vec3 v;
    for (int c = 0; c < 3; ++c) {
      double x;
      if (!t.next(x))
        throw Error(concat(file, ":", t.line(), ": holds ", i, " complete vectors; expected ",
                           raw.size(), " (", n.x, "x", n.y, "x", n.z, "): the file is truncated"));
      v[c] = float(x);
    }
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      ++nonFinite;
      v = glm::vec3(0.0f);
    }
    raw[i] = v;
  }
  if (double extra; t.next(extra))
    throw Error(concat(file, ":", t.line(), ": holds more than the ", raw.size(),
                       " vectors its dimensions ", n.x, "x", n.y, "x", n.z, " call for"));
  report.nonFinite += nonFinite;
  if (nonFinite > 0) log::warn(file, ": ", nonFinite, " vectors are NaN or Inf; replaced by zero");

  // Voxel centres.
  const glm::dvec3 cell = (hi - lo) / glm::dvec3(n);
  glm::dvec3 pmin = lo + 0.5 * cell, pmax = hi - 0.5 * cell;
  report.format = "Unreal FGA vector field";
  report.sourceDims = n;
  VectorField field;
  if (options.convertEngineAxes) {
    const double cm = 0.01;
    const Box bounds{glm::vec3(cm * pmin.x, -cm * pmax.y, cm * pmin.z),
                     glm::vec3(cm * pmax.x, -cm * pmin.y, cm * pmax.z)};
    std::vector<glm::vec3> values(raw.size());
    for (int k = 0; k < n.z; ++k)
      for (int j = 0; j < n.y; ++j)
        for (int i = 0; i < n.x; ++i) {
          const glm::vec3 v = raw[std::size_t(i) + std::size_t(n.x) * (j + std::size_t(n.y) * k)];
          const std::size_t to =
              std::size_t(i) + std::size_t(n.x) * (std::size_t(n.y - 1 - j) + std::size_t(n.y) * k);
          values[to] = float(cm) * glm::vec3(v.x, -v.y, v.z);
        }
    field = VectorField(bounds, n, std::move(values));
    report.notes.push_back("Unreal axes converted: 0.01 * (x, -y, z), centimetres to metres");
  } else {
    field = VectorField(Box{glm::vec3(pmin), glm::vec3(pmax)}, n, std::move(raw));
  }
  if (options.resolution != glm::ivec3(0) && options.resolution != n) {
    report.resampled = true;
    return resampleField(field, options.resolution);
  }
  return field;
}

}  // namespace sandstorm
