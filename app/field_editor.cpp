#include "app/field_editor.h"

#include <chrono>
#include <fstream>

#include "core/editor/field_composer.h"
#include "core/editor/field_editor_block.h"
#include "core/io/field_writer.h"
#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

std::vector<FieldPrimitive> activeOf(const ParticleState& state) {
  std::vector<FieldPrimitive> active;
  for (const FieldPrimitive& p : state.primitives)
    if (p.active()) active.push_back(p);
  return active;
}

}  // namespace

FieldEditor::FieldEditor(FieldSpec spec) : spec_(std::move(spec)) {}

void FieldEditor::update(MainContext& main) {
  // The live flow makes the field while it runs (from the field it started
  // from, the primitives included); the editor waits, or the two would take
  // turns making each other's field their base.
  const ParticleState state = main.state();  // one copy a frame
  const bool solving = state.solver.enabled;
  const std::vector<FieldPrimitive> active = activeOf(state);
  if (solving != waiting_ && !active.empty())
    log::info(solving ? "field editor: the live flow makes the field now; primitives wait"
                      : "field editor: the live flow stopped; primitives apply again");
  waiting_ = solving;
  if (solving) return;
  const std::shared_ptr<const FieldUpdate> current = main.field();
  // Another field took over since the last grid handed over: it is the base now.
  const bool replaced = lastField_ && (!current || current->field != lastField_);
  if (replaced) {
    lastField_.reset();
    base_.reset();
    applied_.clear();
  }
  if (active == applied_) return;
  if (active.empty()) {
    if (base_) main.setField(*base_);
    log::info("field editor: no primitives; the field they were added to is back");
    base_.reset();
    lastField_.reset();
    applied_.clear();
    return;
  }
  if (!base_) {
    if (!current || !current->field) return;
    if (current->sparse) {
      log::warn(
          "field editor: the field in use is a sparse grid; primitives are added to a dense "
          "one (field.storage = \"dense\", or field = \"analytic\", name = \"still\")");
      applied_ = active;  // said once per change
      return;
    }
    if (current->next) {
      log::warn(
          "field editor: the field in use changes with time; primitives are added to a "
          "still field only (load one, or use field = \"analytic\", name = \"still\")");
      applied_ = active;  // said once per change
      return;
    }
    base_ = current;
  }
  const auto start = std::chrono::steady_clock::now();
  const FieldPlacement& placement = base_->placement;
  VectorField composed = composeField(*base_->field, placement, active, &pool_);
  // A half-precision field stays one (field.precision), unless the
  // primitives take a component beyond what halves hold.
  if (base_->field->halfPrecision()) try {
      composed.roundToHalf();
    } catch (const Error& e) {
      log::warn("field editor: ", e.what(),
                "; the field with its primitives stays in 32-bit floats");
    }
  lastField_ = std::make_shared<const VectorField>(std::move(composed));
  main.setField(FieldUpdate{.field = lastField_, .placement = placement});
  applied_ = active;
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  log::debug("field editor: ", active.size(), " primitive(s) added to the field in ", ms,
             " ms; fastest ", lastField_->maxMagnitude(), " m/s");
}

void FieldEditor::save(const std::filesystem::path& path, const ParticleState& state) const {
  if (path.extension() != ".toml")
    throw Error(concat("field editor: save '", path.string(),
                       "': expected a .toml file (a configuration block)"));
  const std::string text = fieldEditorBlock(spec_, state.primitives);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw Error(concat("field editor: cannot write '", path.string(), "'"));
  log::info("field editor: saved the composition to ", path.string());
}

void FieldEditor::bake(const std::filesystem::path& path, const MainContext& main) const {
  const std::shared_ptr<const FieldUpdate> current = main.field();
  if (!current || !current->field) throw Error("field editor: bake: there is no field yet");
  saveField(path, *current->field);
  log::info("field editor: baked the field in use to ", path.string(), " (",
            current->field->dims().x, "x", current->field->dims().y, "x", current->field->dims().z,
            ", the field's own coordinates: load it with the same [field] placement)");
}

}  // namespace sandstorm
