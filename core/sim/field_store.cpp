#include "core/sim/field_store.h"

#include <algorithm>

#include "core/sim/frame_packet_codec.h"
#include "core/util/error.h"

namespace sandstorm {

FieldStore::FieldStore(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 2)) {}

std::uint64_t FieldStore::identify(const std::shared_ptr<const VectorField>& grid) {
  if (!grid) return 0;
  const auto it = hashes_.find(grid.get());
  // The weak pointer tells a grid from a new one at a freed grid's address.
  if (it != hashes_.end() && it->second.first.lock() == grid) return it->second.second;
  std::erase_if(hashes_, [](const auto& entry) { return entry.second.first.expired(); });
  const std::uint64_t hash = fieldHash(*grid);
  hashes_[grid.get()] = {grid, hash};
  return hash;
}

bool FieldStore::contains(std::uint64_t hash) const {
  return find(hash) != nullptr;
}

std::shared_ptr<const VectorField> FieldStore::find(std::uint64_t hash) const {
  if (const auto it = pinned_.find(hash); it != pinned_.end()) return it->second;
  for (const auto& [h, grid] : recent_)
    if (h == hash) return grid;
  return nullptr;
}

void FieldStore::pin(std::uint64_t hash, std::shared_ptr<const VectorField> grid) {
  std::erase_if(recent_, [&](const auto& entry) { return entry.first == hash; });
  pinned_[hash] = std::move(grid);
}

void FieldStore::use(std::span<const std::uint64_t> hashes, const Grids& incoming) {
  for (const std::uint64_t hash : hashes) {
    if (hash == 0 || pinned_.count(hash)) continue;
    const auto held = std::find_if(recent_.begin(), recent_.end(),
                                   [&](const auto& e) { return e.first == hash; });
    if (held != recent_.end()) {
      recent_.splice(recent_.begin(), recent_, held);
      continue;
    }
    const auto it = incoming.find(hash);
    if (it == incoming.end() || !it->second)
      throw Error(
          concat("field grid ", std::hex, hash, " is neither held nor arrived with this packet"));
    recent_.emplace_front(hash, it->second);
  }
  // The grids just used are at the front, so with capacity >= 2 they stay.
  while (recent_.size() > capacity_)
    recent_.pop_back();
}

}  // namespace sandstorm
