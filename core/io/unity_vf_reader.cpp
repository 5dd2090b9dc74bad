#include "core/io/unity_vf_reader.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/io/grid_resample.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

VectorField readUnityVf(const std::filesystem::path& path, const LoadOptions& options,
                        LoadReport& report) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(concat(file, ": cannot open the file for reading"));
  const std::uintmax_t size = std::filesystem::file_size(path);
  auto read = [&](void* out, std::size_t n, const char* what) {
    in.read(static_cast<char*>(out), std::streamsize(n));
    if (std::size_t(in.gcount()) != n)
      throw Error(concat(file, ": the file ends inside its ", what, " (", size, " bytes)"));
  };
  char magic[4];
  read(magic, 4, "magic number");
  Box box = options.unityBounds;
  std::size_t header = 0;
  std::uint16_t n[3];
  if (std::memcmp(magic, "VF_V", 4) == 0) {
    read(n, 6, "dimensions");
    header = 10;
    report.format = "Unity volume file, version 1";
  } else if (std::memcmp(magic, "VF2X", 4) == 0) {
    std::uint8_t info[3];
    read(info, 3, "header");
    if (info[1] != 2)
      throw Error(concat(file, ": data type ", int(info[1]),
                         " is not Vector3 (2); expected a vector field, not ",
                         info[1] == 0 ? "a scalar" : "another", " volume"));
    read(n, 6, "dimensions");
    float m[16];
    read(m, 64, "transform matrix");
    header = 77;
    // The unit box's scale on the diagonal; the translation in a14..a34 or a41..a43.
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (r != c && m[4 * r + c] != 0.0f)
          throw Error(concat(file, ": its transform rotates the volume; only scale and ",
                             "translation are supported"));
    const glm::vec3 scale(m[0], m[5], m[10]);
    const glm::vec3 t = (m[12] != 0.0f || m[13] != 0.0f || m[14] != 0.0f)
                            ? glm::vec3(m[12], m[13], m[14])
                            : glm::vec3(m[3], m[7], m[11]);
    if (!(scale.x > 0.0f && scale.y > 0.0f && scale.z > 0.0f))
      throw Error(concat(file, ": its transform's scale (", scale.x, ", ", scale.y, ", ", scale.z,
                         ") is not positive"));
    box = Box{t - 0.5f * scale, t + 0.5f * scale};
    report.format = "Unity volume file, version 2";
  } else if (std::memcmp(magic, "VF_F", 4) == 0) {
    throw Error(concat(file, ": holds scalar values (VF_F); expected a vector field (VF_V)"));
  } else {
    throw Error(concat(file, ": not a Unity volume file (no VF_V or VF2X magic)"));
  }
  const glm::ivec3 dims(n[0], n[1], n[2]);
  for (int a = 0; a < 3; ++a)
    if (dims[a] == 0)
      throw Error(concat(file, ": dimension ", "xyz"[a], " is 0; expected at least one voxel"));
  for (int a = 0; a < 3; ++a)
    if (!(box.max[a] > box.min[a]))
      throw Error(concat(file, ": the bounds along ", "xyz"[a], " are empty; expected max > min"));
  const std::uintmax_t count = std::uintmax_t(dims.x) * dims.y * dims.z;
  const std::uintmax_t expected = header + count * 12;
  if (size != expected)
    throw Error(concat(file, ": ", size, " bytes, but its ", dims.x, "x", dims.y, "x", dims.z,
                       " vectors need ", expected,
                       size < expected ? "; the file is truncated"
                                       : "; the value count differs "
                                         "from the point count"));
  if (double(count) * 12.0 > double(options.memoryBudget))
    throw Error(concat(file, ": ", count,
                       " vectors exceed the memory budget (field.memory_budget) of ",
                       options.memoryBudget, " bytes"));
  std::vector<glm::vec3> raw(count);
  read(raw.data(), count * 12, "vectors");
  std::size_t nonFinite = 0;
  for (glm::vec3& v : raw)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      v = glm::vec3(0.0f);
      ++nonFinite;
    }
  report.nonFinite += nonFinite;
  if (nonFinite > 0) log::warn(file, ": ", nonFinite, " vectors are NaN or Inf; replaced by zero");

  // Voxel centres.
  const glm::vec3 cell = (box.max - box.min) / glm::vec3(dims);
  const glm::vec3 pmin = box.min + 0.5f * cell, pmax = box.max - 0.5f * cell;
  report.sourceDims = dims;
  VectorField field;
  if (options.convertEngineAxes) {
    const glm::ivec3 out(dims.x, dims.z, dims.y);
    std::vector<glm::vec3> values(count);
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i) {
          const glm::vec3 v =
              raw[std::size_t(i) + std::size_t(dims.x) * (j + std::size_t(dims.y) * k)];
          // Unity index (i, j, k) along (x, y-up, z-forward) -> Sandstorm (i, k, j).
          values[std::size_t(i) + std::size_t(out.x) * (k + std::size_t(out.y) * j)] =
              glm::vec3(v.x, v.z, v.y);
        }
    field = VectorField(Box{glm::vec3(pmin.x, pmin.z, pmin.y), glm::vec3(pmax.x, pmax.z, pmax.y)},
                        out, std::move(values));
    report.notes.push_back("Unity axes converted: (x, y, z) -> (x, z, y), y-up to z-up");
  } else {
    field = VectorField(Box{pmin, pmax}, dims, std::move(raw));
  }
  if (options.resolution != glm::ivec3(0) && options.resolution != field.dims()) {
    report.resampled = true;
    return resampleField(field, options.resolution);
  }
  return field;
}

}  // namespace sandstorm
