#include "app/hash_log.h"

#include <algorithm>
#include <fstream>

#include "contexts/render/wall_renderer.h"
#include "core/sim/attribute_table.h"
#include "core/util/error.h"
#include "core/util/hash.h"

namespace sandstorm {

void HashLog::add(const WallRenderer& wall, std::uint32_t frame) {
  std::vector<Particle> particles = wall.particles().update().readBack();
  const std::size_t count = particles.size();
  // The molecules' members after the particles: one hash for both.
  const std::vector<Particle> members = wall.particles().readBackMolecules();
  particles.insert(particles.end(), members.begin(), members.end());
  const std::string state = AttributeTable::instance().describe(wall.particles().state());
  const std::string line = concat(frame, " ", wall.wall().name, " ", count, " ", std::hex,
                                  hashOf(std::span<const Particle>(particles)), " ",
                                  hashOf(std::span<const char>(state)));
  std::lock_guard lock(mutex_);
  lines_.push_back(line);
}

void HashLog::write(const std::filesystem::path& path) {
  std::sort(lines_.begin(), lines_.end(), [](const std::string& a, const std::string& b) {
    return std::stoul(a) != std::stoul(b) ? std::stoul(a) < std::stoul(b) : a < b;
  });
  std::ofstream out(path);
  for (const std::string& line : lines_)
    out << line << "\n";
  out.close();
  if (!out)
    throw Error(concat("--hash-log ", path.string(), ": writing failed (is the disk full?)"));
}

}  // namespace sandstorm
