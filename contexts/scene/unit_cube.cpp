#include "contexts/scene/unit_cube.h"

#include <epoxy/gl.h>

#include <vector>

#include <glm/glm.hpp>

namespace sandstorm {

UnitCube::UnitCube() : vertices_(gl::createBuffer()), vao_(gl::createVertexArray()) {
  struct Vertex {
    glm::vec3 position, normal;
  };
  std::vector<Vertex> cube;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = side;
      const glm::vec3 u = glm::vec3(n.y, n.z, n.x) * side, v = glm::cross(n, u);
      const glm::vec3 c = 0.5f * n;
      const glm::vec3 q[4] = {c - 0.5f * u - 0.5f * v, c + 0.5f * u - 0.5f * v,
                              c + 0.5f * u + 0.5f * v, c - 0.5f * u + 0.5f * v};
      for (int i : {0, 1, 2, 0, 2, 3})
        cube.push_back({q[i], n});
    }
  glNamedBufferStorage(vertices_.id(), GLsizeiptr(cube.size() * sizeof(Vertex)), cube.data(), 0);
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(vao_.id(), a);
    glVertexArrayAttribFormat(vao_.id(), a, 3, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec3));
    glVertexArrayAttribBinding(vao_.id(), a, 0);
  }
  glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
}

void UnitCube::draw() const {
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 36);
}

}  // namespace sandstorm
