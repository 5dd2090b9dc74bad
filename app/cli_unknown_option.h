// unknownOption(): a command line's first --option that `cli` does not know,
// as an error naming the option it most likely meant. CLI11 on its own reads
// `sandstorm --frmaes 3` as an unknown flag and then 3 as the field file to
// open ("--field: Path does not exist: 3"), which names neither mistake.
// Header-only: the application's and the tools' command lines can share it.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "core/util/nearest_name.h"

namespace sandstorm {

// "" when every --option in argv is one of `cli`'s (or --help); else, e.g.,
// "unknown option '--frmaes' (did you mean '--frames'?); --help lists the options".
inline std::string unknownOption(const CLI::App& cli, int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--") break;  // what follows is not options
    if (token.size() <= 2 || !token.starts_with("--")) continue;
    const std::string name = token.substr(0, token.find('='));
    if (name == "--help" || cli.get_option_no_throw(name) != nullptr) continue;
    std::vector<std::string> known{"--help"};
    for (const CLI::Option* option : cli.get_options()) {
      if (option->get_group().empty()) continue;  // hidden: not offered
      for (const std::string& longName : option->get_lnames())
        known.push_back("--" + longName);
    }
    return "unknown option '" + name + "'" + didYouMean(name, known) + "; --help lists the options";
  }
  return {};
}

}  // namespace sandstorm
