// fieldEditorBlock: the field editor's composition as configuration text that
// reads back to the same field: the [field] the primitives were added to (its
// source, name, parameters, grid and placement; a file's path made absolute
// so the block works from any folder) and a [[primitive]] table for each
// slot up to the last filled one (kind none for the gaps), its numbers written in full (shortest
// round-trip form), so loading the block gives the same state and the same composed grid. Use it as
// a configuration's include, or paste it in.
#pragma once

#include <span>
#include <string>

#include "core/config/app_config.h"
#include "core/editor/field_primitive.h"

namespace sandstorm {

std::string fieldEditorBlock(const FieldSpec& field, std::span<const FieldPrimitive> primitives);

}  // namespace sandstorm
