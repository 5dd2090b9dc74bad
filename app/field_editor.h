// FieldEditor: the field editor's live side, in the main context (thesis
// 7.2's "vector field creator/editor", placed in the room like the rest of
// the CAVE). The primitives are attributes (primitive.N.*: the menu's "Field
// editor" section, --set, the wand's grab, a mouse drag, sessions); once a
// frame, when the active ones differ from those it applied last, it adds them
// to the field it started from (core/editor/field_composer.h) and hands the
// grid to the main context as the field, so every wall and rank shows it at
// the same frame. With none active it gives that field back. A field set by
// something else meanwhile (a file loaded from the menu, the helicopter's
// wash baked again) becomes its new base. It also writes the composition as
// a configuration block (save) and the composed grid as .vti or .vdb (bake).
// While the live flow runs (solver.enabled) it makes the field, starting from
// the composed one; the editor waits and applies its primitives again after.
// Main thread; update() once a frame after MainContext::next().
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/config/app_config.h"
#include "core/sim/main_context.h"
#include "core/util/parallel_for.h"

namespace sandstorm {

class FieldEditor {
 public:
  // `spec`: what the field in use was made from (written by save()).
  explicit FieldEditor(FieldSpec spec);
  void update(MainContext& main);
  // The menu loaded another field: save() describes that one from now on.
  void setFieldSpec(FieldSpec spec) { spec_ = std::move(spec); }

  // Both throw Error naming the path: an unwritable place, a wrong extension.
  void save(const std::filesystem::path& path, const ParticleState& state) const;
  void bake(const std::filesystem::path& path, const MainContext& main) const;

 private:
  FieldSpec spec_;
  ParallelFor pool_;
  std::shared_ptr<const FieldUpdate> base_;       // the field the primitives are added to
  std::shared_ptr<const VectorField> lastField_;  // the grid it handed over last
  std::vector<FieldPrimitive> applied_;           // the active primitives in lastField_
  bool waiting_ = false;                          // for the live flow (solver.enabled)
};

}  // namespace sandstorm
