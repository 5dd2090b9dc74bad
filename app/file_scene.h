// openFileScene: `sandstorm data.vti` opens a field file as ParaView opens
// one: the field where the walls see it (a desktop camera framing its bounds,
// or, for a configuration with room walls, the field scaled into the room),
// its outline drawn, an emitter seeding a plane across its bounds upstream of
// the mean flow (or its horizontal middle plane when there is none) at a rate
// that fills it, and the particles coloured by speed with a legend. The
// streamline rake (the bounds' diagonal), the slice and the probe (the
// centre) are placed in the field and sized to it, off until turned on.
//
// A .vti, a .pvti or a legacy .vtk of STRUCTURED_POINTS, and a .pvd series of
// them, is framed from its (first step's) header (fileSceneFrame, frameFileScene)
// and read while the walls open; its seeding plane, which needs the mean
// flow, comes with packet 0 (seedFileScene). Other files are read first
// (openFileScene).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/scene_setup.h"
#include "core/config/app_config.h"
#include "core/field/vector_field.h"
#include "core/io/vtk_image_frame.h"

namespace sandstorm {

// Rewrites `config` (the desktop scene, or the configuration the user gave)
// around `field`, read from `file` (fileSceneField).
void openFileScene(AppConfig& config, const std::filesystem::path& file, const VectorField& field);

// The same from a field's bounds and points alone, before it is read: all
// but the seeding plane, which needs the field's mean flow (seedFileScene);
// the emitter seeds the horizontal middle plane until then.
void frameFileScene(AppConfig& config, const std::filesystem::path& file, const Box& box,
                    glm::ivec3 dims);

// A .vti's or .pvti's bounds and points from its header (readVtkImageFrame),
// or a legacy .vtk's of STRUCTURED_POINTS (readVtkLegacyFrame), or a .pvd's
// from its first step's, where that is one of these; none for other formats,
// where the header does not say, where field.resolution resamples the grid
// or field.watch follows the series (the file is read first).
std::optional<VtkImageFrame> fileSceneFrame(const FieldSpec& spec);

// What a run framed by frameFileScene does once the field is read, before
// packet 0: emitter 0 moved to the seeding plane of openFileScene by the
// main context's changes (`maximum`: the particle count it fills the field
// with), except for the emitter settings a --set in `sets` gave.
FieldSeeding seedFileScene(const std::filesystem::path& file, const VtkImageFrame& frame,
                           int maximum, const std::vector<std::string>& sets);

// Points `config` (as loaded, before the run's `--set`s) at `file`: its
// [field] reads the file's array or grid `array`, keeping the
// configuration's field.memory_budget, precision, storage, read_ahead and
// upload_ahead; then the run's `sets` are applied on top as for any run, so
// that `--set 'field.resolution=[64,64,64]'` or `--set field.watch=true`
// shape the file's field and are checked against it. fileSceneField then
// reads it as the run reads its [field]: a grid, a series streamed, an
// OpenVDB grid kept sparse. The file is read once: openFileScene frames
// `update.field` (a sparse grid's overview, a series' first step) and the
// run starts from the returned source (App's `field`).
// Throws Error for a --set of field.source (the file is the source), or of
// field.name beside a non-empty `array`, and as applyConfigSets throws.
FieldSource fileSceneField(AppConfig& config, const std::filesystem::path& file,
                           const std::string& array, const std::vector<std::string>& sets);
// Only the first part: `config`'s [field] pointed at `file`, for the run to read.
void pointAtFile(AppConfig& config, const std::filesystem::path& file, const std::string& array,
                 const std::vector<std::string>& sets);

// The emitter the file scene seeds with: exposed for tests.
Emitter seedingPlane(const VectorField& field, int maximum);

}  // namespace sandstorm
