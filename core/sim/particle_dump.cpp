#include "core/sim/particle_dump.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// One array of the appended block: its bytes, preceded in the file by a UInt64 byte count.
struct Block {
  std::vector<char> bytes;
};

template <class T>
Block block(const std::vector<T>& values) {
  Block b;
  b.bytes.resize(values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(b.bytes.data(), values.data(), b.bytes.size());
  return b;
}

}  // namespace

void writeParticlesVtp(std::span<const Particle> particles, const std::filesystem::path& path) {
  const std::size_t n = particles.size();
  std::vector<float> points, velocity, age, life;
  std::vector<std::int64_t> connectivity(n), offsets(n);
  points.reserve(3 * n);
  velocity.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Particle& p = particles[i];
    points.insert(points.end(), {p.positionLife.x, p.positionLife.y, p.positionLife.z});
    velocity.insert(velocity.end(), {p.velocityKind.x, p.velocityKind.y, p.velocityKind.z});
    age.push_back(p.age());
    life.push_back(p.life());
    connectivity[i] = std::int64_t(i);
    offsets[i] = std::int64_t(i + 1);
  }
  const Block blocks[] = {block(points), block(velocity),     block(age),
                          block(life),   block(connectivity), block(offsets)};
  std::uint64_t offset[6];
  std::uint64_t at = 0;
  for (int i = 0; i < 6; ++i) {
    offset[i] = at;
    at += sizeof(std::uint64_t) + blocks[i].bytes.size();
  }

  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(concat("--dump-particles ", path.string(), ": cannot open for writing"));
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <PointData Vectors=\"velocity\" Scalars=\"age\">\n"
      << "        <DataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\" "
         "format=\"appended\" offset=\""
      << offset[1] << "\"/>\n"
      << "        <DataArray type=\"Float32\" Name=\"age\" format=\"appended\" offset=\""
      << offset[2] << "\"/>\n"
      << "        <DataArray type=\"Float32\" Name=\"life_remaining\" format=\"appended\" offset=\""
      << offset[3] << "\"/>\n"
      << "      </PointData>\n"
      << "      <Points>\n"
      << "        <DataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"appended\" offset=\""
      << offset[0] << "\"/>\n"
      << "      </Points>\n"
      << "      <Verts>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\""
      << offset[4] << "\"/>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\""
      << offset[5] << "\"/>\n"
      << "      </Verts>\n"
      << "    </Piece>\n"
      << "  </PolyData>\n"
      << "  <AppendedData encoding=\"raw\">\n   _";
  for (const Block& b : blocks) {
    const std::uint64_t size = b.bytes.size();
    out.write(reinterpret_cast<const char*>(&size), sizeof(size));
    out.write(b.bytes.data(), std::streamsize(b.bytes.size()));
  }
  out << "\n  </AppendedData>\n</VTKFile>\n";
  out.close();  // the last bytes reach the disk here: a full disk shows only now
  if (!out)
    throw Error(concat("--dump-particles ", path.string(), ": writing failed (is the disk full?)"));
}

}  // namespace sandstorm
