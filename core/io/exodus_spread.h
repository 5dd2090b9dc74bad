// A decomposed Exodus II run: a simulation on N ranks (or SEACAS's
// nem_spread) writes one file a rank, named "<base>.<N>.<rank>" ("out.e.4.0"
// .. "out.e.4.3"; the rank zero-padded to N's digits, "out.e.16.03", or not).
// Opening any one of them opens the run: every rank's file, as ParaView's
// Exodus reader groups them. A name that only looks like one (no such
// sibling files) is an error naming the file that is missing, never a part
// of the domain shown as if it were all of it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sandstorm {

struct ExodusSpreadName {
  std::filesystem::path base;  // "dir/out.e"
  int count = 0;               // N
  int rank = 0;
};

// "<base>.<N>.<rank>" with 1 < N <= 65536 and rank < N; none for other names.
std::optional<ExodusSpreadName> parseExodusSpreadName(const std::filesystem::path& path);

// Every rank's file of the run `path` belongs to, rank 0 first; {path} for a
// file of its own. Throws Error naming the first rank's file that is missing.
std::vector<std::filesystem::path> exodusRunFiles(const std::filesystem::path& path);

}  // namespace sandstorm
