// SceneFieldProgram: a scene pass's program (streamlines, the slice,
// streaklines) in the variant its SceneField needs: the grid's, or, for a
// sparse grid (FieldUpdate::sparse), the FIELD_SPARSE one that samples it
// (made on first use). Needs the GL context current.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contexts/gl/program.h"
#include "contexts/scene/scene_field.h"

namespace sandstorm {

class SceneFieldProgram {
 public:
  SceneFieldProgram(std::vector<std::string> files, std::vector<std::string> defines)
      : files_(std::move(files)), defines_(std::move(defines)), grid_(files_, defines_) {}

  const gl::Program& get(const SceneField& field) const {
    if (!field.sparse()) return grid_;
    if (!sparse_) {
      std::vector<std::string> defines = defines_;
      defines.push_back("FIELD_SPARSE");
      sparse_ = std::make_unique<gl::Program>(files_, defines);
    }
    return *sparse_;
  }

 private:
  std::vector<std::string> files_, defines_;
  gl::Program grid_;
  mutable std::unique_ptr<gl::Program> sparse_;
};

}  // namespace sandstorm
