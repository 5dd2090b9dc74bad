// Turns the configuration's field and scene sections into what the main
// context and the walls share: the vector field (static, or a time-varying
// timeline) and the terrain.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/config/app_config.h"
#include "core/field/field_timeline.h"
#include "core/field/height_map.h"
#include "core/io/field_stream_scanner.h"
#include "core/io/load_options.h"
#include "core/sim/frame_packet.h"

namespace sandstorm {

struct FieldSource {
  FieldUpdate update;  // a static field
  std::optional<FieldTimeline>
      timeline;  // or a time-varying one (update then holds its first frame)
  std::string description;
  // A series streamed from disk: its reader (for the read rate the run reports).
  std::shared_ptr<class SeriesReader> series;
  // A watched source (a folder, or a .pvd with watch): its scanner, past the
  // first step (the timeline's only frame), and how its steps load.
  std::shared_ptr<class FieldStreamScanner> stream;
  LoadOptions streamOptions;
};

// Bakes an analytic field ("analytic" source, `name` from the factory), or
// loads a file (VTK, VDB, FGA, VF; a .pvd is a time series). Relative paths
// resolve against `baseDir`. Throws Error naming the source on failure.
FieldSource makeField(const FieldSpec& spec, const std::filesystem::path& baseDir);
// Hands a field to the main context: static or timeline.
void useField(class MainContext& main, const FieldSource& source);

// What a run does with its field once read, before packet 0, by the main
// context's changes (sandstorm FILE's seeding plane, which needs the field's
// mean flow). A replayed run skips it: its session holds the changes.
using FieldSeeding = std::function<void(class MainContext& main, const FieldSource& field)>;

// The field files under data/ and the analytic fields, as the menu offers them
// ("analytic:tornado", "data/tornado.vti", ...).
// Files are named relative to `base`.
std::vector<std::string> fieldChoices(const std::filesystem::path& dataDir,
                                      const std::filesystem::path& base);
// A menu choice turned into a field spec (placement and resolution from `base`).
FieldSpec fieldSpecFor(const std::string& choice, const FieldSpec& base);

std::shared_ptr<const HeightMap> makeTerrain(const SceneSpec& spec,
                                             const std::filesystem::path& baseDir);

}  // namespace sandstorm
