// FieldStore: the vector-field grids a cluster rank holds, by content hash, so
// that a grid crosses the network once per change and a frame packet carries
// only its hash (frame_packet_codec.h).
//
// The sender (rank 0) and every receiver keep a FieldStore of the same
// capacity and make the same use() calls with the same hashes in the same
// order, so they hold the same grids without ever comparing notes: the sender
// ships exactly the grids that are not yet held. Pinned grids (a rank read the
// field file itself, and the hashes agreed) are held for good.
#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <span>
#include <utility>

#include "core/field/vector_field.h"

namespace sandstorm {

class FieldStore {
 public:
  using Grids = std::map<std::uint64_t, std::shared_ptr<const VectorField>>;

  // `capacity` (>= 2: a time-varying field uses two grids at once) bounds the
  // unpinned grids held.
  explicit FieldStore(std::size_t capacity = 4);

  // A grid's content hash (fieldHash()), computed once per grid object.
  std::uint64_t identify(const std::shared_ptr<const VectorField>& grid);

  bool contains(std::uint64_t hash) const;
  std::shared_ptr<const VectorField> find(std::uint64_t hash) const;  // null if not held
  void pin(std::uint64_t hash, std::shared_ptr<const VectorField> grid);

  // A packet uses these grids (0: none): held ones become the most recent, the
  // others are taken from `incoming`; then the least recently used beyond the
  // capacity go. Throws Error naming the hash when a grid is neither held nor
  // incoming (a message was lost).
  void use(std::span<const std::uint64_t> hashes, const Grids& incoming);

  std::size_t size() const { return recent_.size() + pinned_.size(); }

 private:
  std::size_t capacity_;
  Grids pinned_;
  std::list<std::pair<std::uint64_t, std::shared_ptr<const VectorField>>>
      recent_;  // most recent first
  std::map<const VectorField*, std::pair<std::weak_ptr<const VectorField>, std::uint64_t>> hashes_;
};

}  // namespace sandstorm
