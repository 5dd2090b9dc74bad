// sandstorm-filaments: writes a sparse OpenVDB Vec3 grid for benchmarks of
// sparse fields (field.storage = "sparse"): vertical vortex filaments, each a
// tube of active voxels around its axis spanning the box's height, in a box
// of BOX^3 voxels over the bounds, as many tubes as make about VOXELS active
// voxels. Each tube swirls (a Lamb-Oseen vortex, core radius a third of the
// tube's) and rises; outside the tubes the grid is its background, zero.
//
//   sandstorm-filaments OUT.vdb [--voxels 1e8] [--box 4096] [--radius 12]
//                       [--bounds -6 -6 0 6 6 10] [--emitters FILE.toml RATE]
//
// --emitters writes a configuration's [[emitter]] tables: a disc at the foot
// of each of the first 16 tubes, as wide as the tube, RATE particles a second
// in all, so that particles rise through the active voxels rather than sit in
// the background. Prints the tubes, the active voxels and the time taken.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>

#include "core/io/openvdb_grids.h"
#include "core/io/vdb_reader.h"

namespace {

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "sandstorm-filaments: %s\nusage: sandstorm-filaments OUT.vdb [--voxels N] [--box N] "
               "[--radius VOXELS] [--bounds XMIN YMIN ZMIN XMAX YMAX ZMAX]\n",
               why);
  std::exit(2);
}

double number(int& i, int argc, char** argv, const char* option, double lo, double hi) {
  if (++i >= argc) usage((std::string(option) + " needs a value").c_str());
  char* end = nullptr;
  const double v = std::strtod(argv[i], &end);
  if (end == argv[i] || *end != '\0' || !(v >= lo && v <= hi))
    usage((std::string(option) + " " + argv[i] + ": expected a number in [" + std::to_string(lo) +
           ", " + std::to_string(hi) + "]")
              .c_str());
  return v;
}

// A number in [0, 1) from an integer (the tubes' places, the same every run).
double hash01(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return double(x) / 4294967296.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) usage("name the file to write");
  const std::string out = argv[1];
  double voxels = 1e8, box = 4096, radius = 12;
  double bounds[6] = {-6, -6, 0, 6, 6, 10};
  std::string emitters;
  double rate = 0.0;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--voxels")
      voxels = number(i, argc, argv, "--voxels", 1, 1e10);
    else if (a == "--box")
      box = number(i, argc, argv, "--box", 8, 1 << 20);
    else if (a == "--radius")
      radius = number(i, argc, argv, "--radius", 1, 1000);
    else if (a == "--emitters") {
      if (++i >= argc) usage("--emitters needs a file and a rate");
      emitters = argv[i];
      rate = number(i, argc, argv, "--emitters RATE", 1, 1e9);
    } else if (a == "--bounds")
      for (double& b : bounds)
        b = number(i, argc, argv, "--bounds", -1e6, 1e6);
    else
      usage(("unknown option " + a).c_str());
  }
  for (int a = 0; a < 3; ++a)
    if (!(bounds[a + 3] > bounds[a])) usage("--bounds: each max must exceed its min");
  const auto start = std::chrono::steady_clock::now();
  sandstorm::initializeOpenVdb();
  const int n = int(box);
  const openvdb::Vec3d voxel((bounds[3] - bounds[0]) / (n - 1), (bounds[4] - bounds[1]) / (n - 1),
                             (bounds[5] - bounds[2]) / (n - 1));
  auto grid = openvdb::Vec3SGrid::create();
  grid->setName("velocity");
  grid->setTransform(
      std::make_shared<openvdb::math::Transform>(std::make_shared<openvdb::math::ScaleTranslateMap>(
          voxel, openvdb::Vec3d(bounds[0], bounds[1], bounds[2]))));
  const int r = int(radius);
  const double perTube = double(n) * M_PI * radius * radius;
  const int tubes = std::max(1, int(std::ceil(voxels / perTube)));
  const double core = radius / 3.0;
  auto acc = grid->getAccessor();
  std::FILE* emitterFile = emitters.empty() ? nullptr : std::fopen(emitters.c_str(), "w");
  if (!emitters.empty() && !emitterFile) usage(("cannot write " + emitters).c_str());
  const int feet = std::min(tubes, 16);
  for (int t = 0; t < tubes; ++t) {
    const int cx = r + int(hash01(2u * t) * (n - 2 * r - 1));
    const int cy = r + int(hash01(2u * t + 1) * (n - 2 * r - 1));
    if (emitterFile && t < feet)
      std::fprintf(emitterFile,
                   "[[emitter]]\nshape = \"disc\"\nposition = [%.6f, %.6f, %.6f]\nradius = %.6f\n"
                   "rate = %.1f\nlifetime = 5.0\nlifetime_variance = 1.0\nvelocity = [0.0, 0.0, "
                   "0.5]\nspread = 0.2\n\n",
                   bounds[0] + cx * voxel.x(), bounds[1] + cy * voxel.y(), bounds[2] + 0.05,
                   0.8 * radius * std::min(voxel.x(), voxel.y()), rate / feet);
    const double spin = (t % 2 ? 1.0 : -1.0) * 4.0;  // m/s at the core's edge
    for (int k = 0; k < n; ++k)
      for (int j = -r; j <= r; ++j)
        for (int i = -r; i <= r; ++i) {
          const double d2 = double(i) * i + double(j) * j;
          if (d2 > radius * radius) continue;
          const double d = std::sqrt(d2);
          // Lamb-Oseen: the tangential speed rises through the core, then falls as 1/r.
          const double swirl =
              d > 0.0 ? spin * core / d * (1.0 - std::exp(-d2 / (core * core))) * 1.4 : 0.0;
          const double up = 2.0 * (1.0 - d2 / (radius * radius));
          const double ux = d > 0.0 ? -j / d * swirl : 0.0, uy = d > 0.0 ? i / d * swirl : 0.0;
          acc.setValueOn(openvdb::Coord(cx + i, cy + j, k),
                         openvdb::Vec3s(float(ux), float(uy), float(up)));
        }
  }
  if (emitterFile) std::fclose(emitterFile);
  openvdb::io::File file(out);
  file.setCompression(openvdb::io::COMPRESS_ACTIVE_MASK);  // no zip: reads at disk speed
  file.write({grid});
  file.close();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "sandstorm-filaments: %s: %d tubes of radius %d voxels, %llu active voxels in a "
      "%d^3 box, %.1f s\n",
      out.c_str(), tubes, r, static_cast<unsigned long long>(grid->activeVoxelCount()), n, s);
  return 0;
}
