// nearestName(): the name a typo most likely meant, for "did you mean ...?"
// in errors about unknown keys, attributes and choices. The distance is
// Damerau-Levenshtein's (insertions, deletions, substitutions and swaps of
// neighbours, each 1; letters compared without case), and a name is offered
// only when it is the one nearest and within a third of the typed length
// (at least 1): 'sise' -> 'size', 'spead' -> 'speed', but no guess for a
// word that resembles nothing, nor for words longer than 64 letters.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sandstorm {

std::size_t editDistance(std::string_view a, std::string_view b);

std::optional<std::string> nearestName(std::string_view typed,
                                       const std::vector<std::string>& names);

// " (did you mean 'NAME'?)" for nearestName's answer, or "": for after the
// word typed.
std::string didYouMean(std::string_view typed, const std::vector<std::string>& names);

}  // namespace sandstorm
