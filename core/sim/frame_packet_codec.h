// The one wire format of FramePacket, for ranks that do not share memory
// (cluster mode, app/cluster/). Pure C++: no MPI here.
//
// A packet is small and its size does not depend on the particle count: the
// frame, clocks, seed, the validated changes, the emission counts, the viewer,
// the field blend and the level of detail's scale. A field update travels as a
// reference: the content hashes of its grids and the placement, with an
// analytic field's equation (a few numbers) inline. The grids themselves travel apart,
// once per change (encodeField), and the receiver finds them by hash
// (FieldStore).
//
// Numbers are little-endian and floats travel as their bits, so a decoded
// packet equals the original bit for bit. Decoding checks everything (magic,
// version, lengths, enums, trailing bytes) and throws Error naming what was
// wrong and where; it never reads out of bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/field/vector_field.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

// The grids a packet's field update refers to, by fieldHash() (0: none).
struct FieldRefs {
  std::uint64_t field = 0;
  std::uint64_t next = 0;
  std::uint64_t sparse = 0;  // sparseHash of FieldUpdate::sparse; 0: none
  // The update carries colour grids (when encoding, this or the update's own
  // grid says so), named as colorGridName does ("" vorticity, else a scalar
  // array): the receiver makes them again from the grids (makeColorGrid is
  // deterministic) rather than receiving them.
  std::optional<std::string> colorGrid;
};

// FNV-1a of the grid's encoding (bounds, dims, values): the grid's identity on the wire.
std::uint64_t fieldHash(const VectorField& grid);
// FNV-1a of a sparse grid's words: its identity on the wire (they travel as
// they are; the receiver checks them as SparseField's constructor does).
std::uint64_t sparseHash(const SparseField& grid);

std::vector<std::byte> encodeField(const VectorField& grid);
// Throws Error for a malformed or truncated grid; `name` goes into the message.
VectorField decodeField(std::span<const std::byte> bytes, std::string_view name = "field grid");

// `refs` must hold the hashes of packet.fieldUpdate's grids (FieldStore::identify).
std::vector<std::byte> encodePacket(const FramePacket& packet, const FieldRefs& refs = {});
// A packet with a field update comes back with the update's placement set and
// its grids null; *refs receives their hashes, for the caller to attach the
// grids it holds. Throws Error for a malformed or truncated packet.
FramePacket decodePacket(std::span<const std::byte> bytes, FieldRefs* refs = nullptr);

}  // namespace sandstorm
