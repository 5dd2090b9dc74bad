// UnitCube: the cube -0.5..0.5 with face normals (position, normal per
// vertex, 36 vertices), for props drawn as stretched boxes: the helicopter
// proxy, the wand's beam and the emitter handles. Draw with mesh.vert/.frag.
#pragma once

#include "contexts/gl/objects.h"

namespace sandstorm {

class UnitCube {
 public:
  UnitCube();
  void draw() const;  // binds its vertex array and draws the 36 vertices

 private:
  gl::Buffer vertices_;
  gl::VertexArray vao_;
};

}  // namespace sandstorm
