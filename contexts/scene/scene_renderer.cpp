#include "contexts/scene/scene_renderer.h"

#include <algorithm>

#include <epoxy/gl.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

#include "core/cave/window_segments.h"
#include "core/obstacles/helicopter_shape.h"

namespace sandstorm {

SceneRenderer::SceneRenderer()
    : terrain_(std::vector<std::string>{"terrain.vert", "terrain.frag"}),
      mesh_(std::vector<std::string>{"mesh.vert", "mesh.frag"}) {
  setTerrain(std::make_shared<HeightMap>(HeightMap::flat(0.0f)));
}

void SceneRenderer::setHelicopter(const HelicopterSettings& helicopter, float rotorRadius) {
  helicopter_ = helicopter;
  if (helicopter.enabled && (helicopterModel_.empty() || rotorRadius != rotorRadius_)) {
    helicopterModel_.clear();
    for (const ModelPart& part : helicopterModel(rotorRadius))
      helicopterModel_.push_back({UnitMesh::triangles(part.triangles), part.color});
  }
  rotorRadius_ = rotorRadius;
}

// The helicopter's opaque parts, or (after the opaque scene, blended, the
// depth kept) its rotors' translucent blur.
void SceneRenderer::drawHelicopter(bool translucent) const {
  if (!helicopter_.enabled) return;
  const glm::mat4 model =
      glm::translate(glm::mat4(1.0f), helicopterHub(helicopter_, ground_.get()));
  mesh_.use();
  glProgramUniformMatrix4fv(mesh_.id(), 0, 1, GL_FALSE, glm::value_ptr(model));
  if (translucent) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  }
  for (const ModelMesh& part : helicopterModel_) {
    if ((part.color.w < 1.0f) != translucent) continue;
    glProgramUniform4f(mesh_.id(), 1, part.color.x, part.color.y, part.color.z, part.color.w);
    part.mesh.draw();
  }
  if (translucent) {
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
}

template <class Mesh>
void SceneRenderer::drawProp(const Mesh& mesh, const glm::vec3& center, const glm::vec3& size,
                             const glm::vec4& color) const {
  const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), center), size);
  glProgramUniformMatrix4fv(mesh_.id(), 0, 1, GL_FALSE, glm::value_ptr(model));
  glProgramUniform4f(mesh_.id(), 1, color.x, color.y, color.z, color.w);
  mesh.draw();
}

// A ball (0.2 m) at each active primitive, coloured by its kind (a sink red),
// and for the kinds with a direction a rod of 1 m from it along its axis.
void SceneRenderer::drawPrimitives() const {
  for (const FieldPrimitive& p : primitives_) {
    if (!p.active()) continue;
    glm::vec3 color(0.7f, 0.4f, 0.9f);  // curl noise
    bool directed = true;
    switch (p.kind) {
      case PrimitiveKind::Vortex:
        color = {0.95f, 0.55f, 0.1f};
        break;
      case PrimitiveKind::Source:
        color = p.strength < 0.0f ? glm::vec3(0.9f, 0.2f, 0.2f) : glm::vec3(0.2f, 0.5f, 0.95f);
        directed = false;
        break;
      case PrimitiveKind::Wind:
        color = {0.6f, 0.65f, 0.95f};
        break;
      case PrimitiveKind::Tornado:
        color = {0.95f, 0.8f, 0.2f};
        break;
      case PrimitiveKind::SphereFlow:
        color = {0.3f, 0.8f, 0.8f};
        break;
      default:
        directed = false;
        break;
    }
    drawProp(sphere_, p.position, glm::vec3(0.2f), glm::vec4(color, 1.0f));
    const float length = glm::length(p.axis);
    if (!directed || !(length > 0.0f)) continue;
    // The rod: the unit cube turned so that its z runs along the axis.
    const glm::vec3 z = p.axis / length;
    const glm::vec3 x = glm::normalize(
        glm::cross(std::abs(z.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0), z));
    const glm::mat4 turn(glm::vec4(x, 0.0f), glm::vec4(glm::cross(z, x), 0.0f), glm::vec4(z, 0.0f),
                         glm::vec4(p.position + 0.5f * z, 1.0f));
    const glm::mat4 model = turn * glm::scale(glm::mat4(1.0f), glm::vec3(0.05f, 0.05f, 1.0f));
    glProgramUniformMatrix4fv(mesh_.id(), 0, 1, GL_FALSE, glm::value_ptr(model));
    glProgramUniform4f(mesh_.id(), 1, color.x, color.y, color.z, 1.0f);
    cube_.draw();
  }
}

void SceneRenderer::setTerrain(std::shared_ptr<const HeightMap> terrain) {
  ground_ = std::move(terrain);
  const HeightMap& map = *ground_;
  flatGround_ = std::nullopt;
  if (map.isFlat()) flatGround_ = FlatGround{map.min(), map.max(), map.at(0, 0)};
  struct Vertex {
    glm::vec3 position, normal;
  };
  const glm::ivec2 d = map.dims();
  const glm::vec2 step = (map.max() - map.min()) / glm::vec2(d - 1);
  std::vector<Vertex> vertices;
  vertices.reserve(std::size_t(d.x) * std::size_t(d.y));
  for (int j = 0; j < d.y; ++j)
    for (int i = 0; i < d.x; ++i) {
      const glm::vec2 xy = map.min() + step * glm::vec2(i, j);
      vertices.push_back({glm::vec3(xy, map.at(i, j)), map.normalAt(xy)});
    }
  std::vector<std::uint32_t> indices;
  for (int j = 0; j + 1 < d.y; ++j)
    for (int i = 0; i + 1 < d.x; ++i) {
      const std::uint32_t a = std::uint32_t(i + d.x * j), b = a + 1, c = a + std::uint32_t(d.x),
                          e = c + 1;
      indices.insert(indices.end(), {a, b, e, a, e, c});
    }
  terrainVertices_ = gl::createBuffer();
  terrainIndices_ = gl::createBuffer();
  glNamedBufferStorage(terrainVertices_.id(), GLsizeiptr(vertices.size() * sizeof(Vertex)),
                       vertices.data(), 0);
  glNamedBufferStorage(terrainIndices_.id(), GLsizeiptr(indices.size() * 4), indices.data(), 0);
  terrainVao_ = gl::createVertexArray();
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(terrainVao_.id(), a);
    glVertexArrayAttribFormat(terrainVao_.id(), a, 3, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec3));
    glVertexArrayAttribBinding(terrainVao_.id(), a, 0);
  }
  glVertexArrayVertexBuffer(terrainVao_.id(), 0, terrainVertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(terrainVao_.id(), terrainIndices_.id());
  terrainIndexCount_ = int(indices.size());
}

void SceneRenderer::setWand(const WandRay& ray, const Navigation& navigation,
                            std::vector<glm::vec3> handles) {
  wand_.set(ray, navigation, std::move(handles));
}

void SceneRenderer::setFieldBox(std::optional<Box> bounds, const FieldPlacement& placement) {
  box_ = bounds;
  placement_ = placement;
}

std::vector<std::array<glm::vec3, 2>> SceneRenderer::fieldBoxEdges() const {
  if (!box_) return {};
  const glm::mat4 model = placement_.matrix() * glm::translate(glm::mat4(1.0f), box_->min) *
                          glm::scale(glm::mat4(1.0f), box_->extent());
  const auto edges = boxEdges(model);
  return {edges.begin(), edges.end()};
}

void SceneRenderer::updateFlow(const ParticleState& state, std::shared_ptr<const FieldUpdate> field,
                               float blend, float dt, bool reset) {
  if ((state.streamlines.enabled || state.slice.enabled || state.render.streaklines ||
       (field && field->colorGrid)) &&
      field && field->field)
    sceneField_.set(state, *field, blend, dt, ground_.get());
  streamlines_.update(state, field, blend);
  slice_.update(state, field, blend);
  streaklines_.update(state, dt, reset);
}

bool SceneRenderer::rasterItems() const {
  const bool terrain = !flatGround_ && terrainIndexCount_ > 0;
  const bool obstacles = std::any_of(obstacles_.begin(), obstacles_.end(),
                                     [](const Obstacle& o) { return o.enabled; });
  const bool primitives = std::any_of(primitives_.begin(), primitives_.end(),
                                      [](const FieldPrimitive& p) { return p.active(); });
  return terrain || helicopter_.enabled || obstacles || primitives || probe_ || wand_.visible() ||
         streamlines_.visible() || streaklines_.visible() || slice_.visible();
}

void SceneRenderer::drawOpaque() const {
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  if (!flatGround_) {  // a flat ground is SceneBackground's
    terrain_.use();
    glBindVertexArray(terrainVao_.id());
    glDrawElements(GL_TRIANGLES, terrainIndexCount_, GL_UNSIGNED_INT, nullptr);
  }

  drawHelicopter(false);
  mesh_.use();
  for (const Obstacle& o : obstacles_) {
    if (!o.enabled) continue;
    const glm::vec4 green(0.25f, 0.6f, 0.3f, 1.0f);
    if (o.shape == ObstacleShape::Sphere)
      drawProp(sphere_, o.position, glm::vec3(2.0f * o.radius), green);
    else if (o.shape == ObstacleShape::Cylinder)
      drawProp(cylinder_, o.position, glm::vec3(2.0f * o.radius, 2.0f * o.radius, o.height), green);
    else
      drawProp(cube_, o.position, o.size, green);
  }

  drawPrimitives();

  wand_.draw();
  if (probe_) {
    mesh_.use();
    const glm::mat4 model =
        glm::scale(glm::translate(glm::mat4(1.0f), *probe_), glm::vec3(0.3f * probeRadius_));
    glProgramUniformMatrix4fv(mesh_.id(), 0, 1, GL_FALSE, glm::value_ptr(model));
    glProgramUniform4f(mesh_.id(), 1, 1.0f, 0.2f, 0.6f, 1.0f);
    cube_.draw();
  }
  streamlines_.draw();
  glBindVertexArray(0);
}

void SceneRenderer::drawTranslucent() const {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  streaklines_.draw();
  slice_.draw();
  drawHelicopter(true);
  glBindVertexArray(0);
}

}  // namespace sandstorm
