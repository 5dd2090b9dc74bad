// An OpenFOAM case written as OpenFOAM writes one (no OpenFOAM here to run
// blockMesh): a box of n x n x n hexahedra in a polyMesh (points, faces,
// owner, neighbour, boundary; internal faces in upper-triangular order, each
// face's points turning about the normal from owner to neighbour), the flow
// at the cells' centres in each time folder's U, in ascii or binary, whole or
// decomposed in two processor folders along x.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sandstorm::test {

struct FoamCase {
  int n = 4;  // cells per axis over [0, 1]^3
  bool binary = false;
  bool decomposed = false;  // processor0 (x < 0.5) and processor1
  std::vector<double> times{0.0, 0.5, 1.0};
  std::function<glm::dvec3(const glm::dvec3&, double)> flow;
};

namespace foam_detail {

inline std::string header(const FoamCase& c, const std::string& type, const std::string& object) {
  return "FoamFile\n{\n    version     2.0;\n    format      " +
         std::string(c.binary ? "binary" : "ascii") +
         ";\n    arch        \"LSB;label=32;scalar=64\";\n    class       " + type +
         ";\n    object      " + object + ";\n}\n\n";
}

inline std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

template <class T>
std::string raw(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

inline void write(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// One processor's (or the whole case's) part: the cells with i in [i0, i1).
inline void writeMesh(const FoamCase& c, const std::filesystem::path& root, int i0, int i1,
                      int processor) {
  const int n = c.n;
  std::map<std::array<int, 3>, int> pointId;
  std::vector<std::array<int, 3>> points;
  auto point = [&](int i, int j, int k) {
    const auto [it, added] = pointId.emplace(std::array<int, 3>{i, j, k}, int(points.size()));
    if (added) points.push_back({i, j, k});
    return it->second;
  };
  const int nx = i1 - i0;
  auto cell = [&](int i, int j, int k) { return (i - i0) + nx * (j + n * k); };
  // A face at (i, j, k) with its normal along +axis: four corners.
  auto quad = [&](int axis, int i, int j, int k) {
    const int e[3][2][3] = {{{0, 1, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}}, {{1, 0, 0}, {0, 1, 0}}};
    const auto& a = e[axis][0];
    const auto& b = e[axis][1];
    return std::array<int, 4>{point(i, j, k), point(i + a[0], j + a[1], k + a[2]),
                              point(i + a[0] + b[0], j + a[1] + b[1], k + a[2] + b[2]),
                              point(i + b[0], j + b[1], k + b[2])};
  };
  std::vector<std::array<int, 4>> faces;
  std::vector<int> owner, neighbour, wallOwner, procOwner;
  std::vector<std::array<int, 4>> walls, proc;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = i0; i < i1; ++i) {
        const int me = cell(i, j, k);
        const int next[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (int axis = 0; axis < 3; ++axis) {
          const int* q = next[axis];
          const bool inside = (axis == 0 ? q[0] < i1 : q[axis] < n);
          const std::array<int, 4> face =
              quad(axis, axis == 0 ? i + 1 : i, axis == 1 ? j + 1 : j, axis == 2 ? k + 1 : k);
          if (inside) {
            faces.push_back(face);
            owner.push_back(me);
            neighbour.push_back(cell(q[0], q[1], q[2]));
          } else if (axis == 0 && i + 1 < n) {
            proc.push_back(face);
            procOwner.push_back(me);
          } else {
            walls.push_back(face);
            wallOwner.push_back(me);
          }
        }
        // The faces below, behind and to the left: boundary, outward (reversed).
        const int low[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis) {
          const bool boundary = axis == 0 ? i == i0 : low[axis] == 0;
          if (!boundary) continue;
          std::array<int, 4> face = quad(axis, i, j, k);
          std::swap(face[1], face[3]);
          if (axis == 0 && i > 0) {
            proc.push_back(face);
            procOwner.push_back(me);
          } else {
            walls.push_back(face);
            wallOwner.push_back(me);
          }
        }
      }
  // Internal faces in upper-triangular order: by owner, then neighbour.
  std::vector<std::size_t> order(faces.size());
  for (std::size_t f = 0; f < order.size(); ++f)
    order[f] = f;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(owner[a], neighbour[a]) < std::pair(owner[b], neighbour[b]);
  });
  std::vector<std::array<int, 4>> allFaces;
  std::vector<int> allOwner, allNeighbour;
  for (std::size_t f : order) {
    allFaces.push_back(faces[f]);
    allOwner.push_back(owner[f]);
    allNeighbour.push_back(neighbour[f]);
  }
  const int internal = int(allFaces.size());
  allFaces.insert(allFaces.end(), walls.begin(), walls.end());
  allOwner.insert(allOwner.end(), wallOwner.begin(), wallOwner.end());
  allFaces.insert(allFaces.end(), proc.begin(), proc.end());
  allOwner.insert(allOwner.end(), procOwner.begin(), procOwner.end());

  const auto mesh = root / "constant" / "polyMesh";
  std::string text = header(c, "vectorField", "points") + std::to_string(points.size()) + "\n(";
  if (c.binary) {
    std::vector<double> xyz;
    for (const auto& p : points)
      for (int a = 0; a < 3; ++a)
        xyz.push_back(double(p[std::size_t(a)]) / n);
    text += raw(xyz);
  } else {
    for (const auto& p : points)
      text += "\n(" + number(double(p[0]) / n) + " " + number(double(p[1]) / n) + " " +
              number(double(p[2]) / n) + ")";
    text += "\n";
  }
  write(mesh / "points", text + ")\n");
  if (c.binary) {
    std::vector<std::int32_t> offsets{0}, labels;
    for (const auto& f : allFaces) {
      labels.insert(labels.end(), f.begin(), f.end());
      offsets.push_back(std::int32_t(labels.size()));
    }
    write(mesh / "faces", header(c, "faceCompactList", "faces") + std::to_string(offsets.size()) +
                              "\n(" + raw(offsets) + ")\n" + std::to_string(labels.size()) + "\n(" +
                              raw(labels) + ")\n");
  } else {
    text = header(c, "faceList", "faces") + std::to_string(allFaces.size()) + "\n(\n";
    for (const auto& f : allFaces)
      text += "4(" + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
              std::to_string(f[2]) + " " + std::to_string(f[3]) + ")\n";
    write(mesh / "faces", text + ")\n");
  }
  auto labels = [&](const std::string& name, const std::vector<int>& v) {
    std::string t = header(c, "labelList", name) + std::to_string(v.size()) + "\n(";
    if (c.binary) {
      t += raw(std::vector<std::int32_t>(v.begin(), v.end()));
    } else {
      for (int x : v)
        t += "\n" + std::to_string(x);
      t += "\n";
    }
    write(mesh / name, t + ")\n");
  };
  labels("owner", allOwner);
  labels("neighbour", allNeighbour);
  const int other = 1 - processor;
  std::string boundary =
      header(c, "polyBoundaryMesh", "boundary") + std::to_string(proc.empty() ? 1 : 2) +
      "\n(\n    walls\n    {\n        type wall;\n        nFaces " + std::to_string(walls.size()) +
      ";\n        startFace " + std::to_string(internal) + ";\n    }\n";
  if (!proc.empty())
    boundary += "    procBoundary" + std::to_string(processor) + "to" + std::to_string(other) +
                "\n    {\n        type processor;\n        nFaces " + std::to_string(proc.size()) +
                ";\n        startFace " + std::to_string(internal + int(walls.size())) +
                ";\n        myProcNo " + std::to_string(processor) + ";\n        neighbProcNo " +
                std::to_string(other) + ";\n    }\n";
  write(mesh / "boundary", boundary + ")\n");

  for (double t : c.times) {
    std::string u = header(c, "volVectorField", "U") +
                    "dimensions [0 1 -1 0 0 0 0];\n\ninternalField nonuniform List<vector> " +
                    std::to_string(nx * n * n) + "\n(";
    std::vector<double> values;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = i0; i < i1; ++i) {
          const glm::dvec3 v = c.flow(glm::dvec3(i + 0.5, j + 0.5, k + 0.5) / double(n), t);
          if (c.binary)
            values.insert(values.end(), {v.x, v.y, v.z});
          else
            u += "\n(" + number(v.x) + " " + number(v.y) + " " + number(v.z) + ")";
        }
    u += c.binary ? raw(values) : "\n";
    u += ")\n;\n\nboundaryField\n{\n    walls\n    {\n        type zeroGradient;\n    }\n";
    if (!proc.empty())
      u += "    procBoundary" + std::to_string(processor) + "to" + std::to_string(other) +
           "\n    {\n        type processor;\n        value uniform (0 0 0);\n    }\n";
    write(root / number(t) / "U", u + "}\n");
  }
}

}  // namespace foam_detail

inline void writeFoamCase(const FoamCase& c, const std::filesystem::path& dir) {
  foam_detail::write(dir / "system" / "controlDict",
                     foam_detail::header(c, "dictionary", "controlDict") +
                         "application icoFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt "
                         "endTime;\nendTime 1;\ndeltaT 0.5;\nwriteControl timeStep;\n"
                         "writeInterval 1;\n");
  foam_detail::write(dir / "case.foam", "");
  if (!c.decomposed) {
    foam_detail::writeMesh(c, dir, 0, c.n, 0);
    return;
  }
  foam_detail::writeMesh(c, dir / "processor0", 0, c.n / 2, 0);
  foam_detail::writeMesh(c, dir / "processor1", c.n / 2, c.n, 1);
}

}  // namespace sandstorm::test
