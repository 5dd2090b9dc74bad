// The configuration as text, one "key = value" line per setting that must be
// the same on every rank (the run, field, scene, particles, head, navigation,
// walls and their placement, the cluster section, and the command-line
// options that change them). Numbers are written exactly (hex floats). Ranks
// compare hashes of it before anything starts: a rank that read another file,
// or another version of it, is an error that names the differing line.
// No MPI here.
#pragma once

#include <string>

#include "app/app.h"
#include "core/config/app_config.h"

namespace sandstorm {

std::string configFingerprint(const AppConfig& config, const AppOptions& options);

// The first line where two fingerprints differ, as "ours | theirs"; empty if equal.
std::string firstDifference(const std::string& ours, const std::string& theirs);

}  // namespace sandstorm
