// Malformed DTrack datagrams for sandstorm-tracker-sim --malformed: the bad
// input a receiver must survive, made from a good datagram: truncated at a
// random byte, binary junk, a count that does not match its blocks, NaN and
// infinity, absurd ids and counts, a matrix that is no rotation, and a 64 KiB
// wall of text. Deterministic for a given generator state.
#pragma once

#include <random>
#include <string>

namespace sandstorm {

std::string malformDatagram(const std::string& good, std::mt19937& random);

}  // namespace sandstorm
