#include "contexts/scene/unit_mesh.h"

#include <epoxy/gl.h>

#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

namespace sandstorm {
namespace {

struct Vertex {
  glm::vec3 position, normal;
};

glm::vec3 onSphere(int i, int j, int segments) {
  const float theta = glm::pi<float>() * float(j) / float(segments / 2);
  const float phi = glm::two_pi<float>() * float(i) / float(segments);
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

UnitMesh UnitMesh::sphere(int segments) {
  std::vector<Vertex> data;
  for (int j = 0; j < segments / 2; ++j)
    for (int i = 0; i < segments; ++i) {
      const glm::vec3 a = onSphere(i, j, segments), b = onSphere(i + 1, j, segments),
                      c = onSphere(i + 1, j + 1, segments), d = onSphere(i, j + 1, segments);
      for (const glm::vec3& n : {a, d, c, a, c, b})
        data.push_back({0.5f * n, n});
    }
  UnitMesh mesh;
  mesh.upload(&data[0].position.x, data.size());
  return mesh;
}

UnitMesh UnitMesh::cylinder(int segments) {
  std::vector<Vertex> data;
  const glm::vec3 up(0, 0, 1);
  for (int i = 0; i < segments; ++i) {
    const float a0 = glm::two_pi<float>() * float(i) / float(segments);
    const float a1 = glm::two_pi<float>() * float(i + 1) / float(segments);
    const glm::vec3 n0(std::cos(a0), std::sin(a0), 0.0f), n1(std::cos(a1), std::sin(a1), 0.0f);
    const glm::vec3 p0 = 0.5f * n0, p1 = 0.5f * n1;
    const glm::vec3 h(0.0f, 0.0f, 0.5f);
    data.insert(
        data.end(),
        {{p0 - h, n0}, {p1 - h, n1}, {p1 + h, n1}, {p0 - h, n0}, {p1 + h, n1}, {p0 + h, n0}});
    data.insert(data.end(), {{h, up}, {p0 + h, up}, {p1 + h, up}});
    data.insert(data.end(), {{-h, -up}, {p1 - h, -up}, {p0 - h, -up}});
  }
  UnitMesh mesh;
  mesh.upload(&data[0].position.x, data.size());
  return mesh;
}

UnitMesh UnitMesh::triangles(std::span<const ModelVertex> vertices) {
  static_assert(sizeof(ModelVertex) == 6 * sizeof(float));
  UnitMesh mesh;
  mesh.upload(&vertices[0].position.x, vertices.size());
  return mesh;
}

void UnitMesh::upload(const float* vertices, std::size_t count) {
  vertices_ = gl::createBuffer();
  vao_ = gl::createVertexArray();
  glNamedBufferStorage(vertices_.id(), GLsizeiptr(count * sizeof(Vertex)), vertices, 0);
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(vao_.id(), a);
    glVertexArrayAttribFormat(vao_.id(), a, 3, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec3));
    glVertexArrayAttribBinding(vao_.id(), a, 0);
  }
  glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(Vertex));
  count_ = int(count);
}

void UnitMesh::draw() const {
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, count_);
}

}  // namespace sandstorm
