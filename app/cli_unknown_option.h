// unknownOption(): a command line's first --option that `cli` does not know,
// as an error naming the option it most likely meant. CLI11 on its own reads
// `sandstorm --frmaes 3` as an unknown flag and then 3 as the field file to
// open ("--field: Path does not exist: 3"), which names neither mistake.
// Header-only: the application's and the tools' command lines can share it.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "core/util/nearest_name.h"

namespace sandstorm {

// "" when every --option in argv is one of `cli`'s or its subcommands' (or
// --help); else, e.g.,
// "unknown option '--frmaes' (did you mean '--frames'?); --help lists the options".
inline std::string unknownOption(const CLI::App& cli, int argc, const char* const* argv) {
  // Every long name, and those offered as guesses (hidden options are not).
  std::vector<std::string> all{"--help"}, offered{"--help"};
  const auto collect = [&](const CLI::App& app) {
    for (const CLI::Option* option : app.get_options())
      for (const std::string& longName : option->get_lnames()) {
        all.push_back("--" + longName);
        if (!option->get_group().empty()) offered.push_back("--" + longName);
      }
  };
  collect(cli);
  for (const CLI::App* sub : cli.get_subcommands([](const CLI::App*) { return true; }))
    collect(*sub);
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--") break;  // what follows is not options
    if (token.size() <= 2 || !token.starts_with("--")) continue;
    const std::string name = token.substr(0, token.find('='));
    if (std::find(all.begin(), all.end(), name) != all.end()) continue;
    return "unknown option '" + name + "'" + didYouMean(name, offered) +
           "; --help lists the options";
  }
  return {};
}

}  // namespace sandstorm
