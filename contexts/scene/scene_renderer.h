// SceneRenderer: the scene particles are composited against: a sky, the
// terrain (or flat ground), the downdraft demo's helicopter, the tracked
// wand's ray, the streamlines and, as a guide, the field's bounding box. It draws
// into the bound framebuffer with depth, using the view and render blocks
// already bound (bindings 1 and 2).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "contexts/gl/objects.h"
#include "contexts/gl/program.h"
#include "contexts/scene/scene_background.h"
#include "contexts/scene/scene_field.h"
#include "contexts/scene/slice_renderer.h"
#include "contexts/scene/streakline_renderer.h"
#include "contexts/scene/streamline_renderer.h"
#include "contexts/scene/unit_cube.h"
#include "contexts/scene/unit_mesh.h"
#include "contexts/scene/wand_renderer.h"
#include "core/field/box.h"
#include "core/field/field_placement.h"
#include "core/field/height_map.h"
#include "core/obstacles/obstacle.h"
#include "core/sim/helicopter.h"

namespace sandstorm {

class SceneRenderer {
 public:
  SceneRenderer();

  void setTerrain(std::shared_ptr<const HeightMap> terrain);
  // The box drawn around the field; nothing is drawn without one. Its edges
  // are drawn by SceneBackground's compute pass (fieldBoxEdges), not raster.
  void setFieldBox(std::optional<Box> bounds, const FieldPlacement& placement);
  // The field box's twelve edges in world space (none without a box), and their colour.
  std::vector<std::array<glm::vec3, 2>> fieldBoxEdges() const;
  static constexpr glm::vec3 kFieldBoxColor{0.25f, 0.25f, 0.3f};
  // A simple helicopter proxy (fuselage, tail boom, rotor) at the hub the settings give.
  void setHelicopter(const HelicopterSettings& helicopter, float rotorRadius);
  // The obstacles (the enabled ones are drawn, solid green as in the Mali sample).
  void setObstacles(std::vector<Obstacle> obstacles) { obstacles_ = std::move(obstacles); }
  // The field editor's primitives: a ball where each active one is, a rod along its axis.
  void setPrimitives(std::vector<FieldPrimitive> primitives) {
    primitives_ = std::move(primitives);
  }
  // The tracked wand's ray and the emitters' handles (nothing while the ray is hidden).
  // `handles`: what the wand can grab (wand_handles.h), world positions.
  void setWand(const WandRay& ray, const Navigation& navigation, std::vector<glm::vec3> handles);
  // Once a frame, before the views: the field's streamlines and slice follow
  // the state (streamlines are traced again only when something changed).
  // `dt`, `reset`: the frame's simulated seconds and reset (streaklines).
  void updateFlow(const ParticleState& state, std::shared_ptr<const FieldUpdate> field, float blend,
                  float dt = 0.0f, bool reset = false);
  void bindColorGrid() const { sceneField_.bindColorGrid(); }
  // The probe's marker: a small box `radius` across at the point (none: hidden).
  void setProbe(std::optional<glm::vec3> point, float radius) {
    probe_ = point;
    probeRadius_ = radius;
  }
  // The opaque items into the bound scene framebuffer: a height map's
  // terrain (a flat ground is SceneBackground's), props, the field's box, the
  // wand, the probe, streamlines. Then SceneBackground, then the translucent
  // ones (streaklines, the slice), which blend over the ground and sky and
  // are hidden behind them by the scene's depth (scene_occlusion.glsl).
  void drawOpaque() const;
  void drawTranslucent() const;
  // Whether drawOpaque or drawTranslucent draws anything: without raster
  // items a view's scene is SceneBackground's alone, and the raster pass
  // (its depth clear cost 0.15 ms a 1920x1080 view on an H100) is skipped.
  bool rasterItems() const;
  // The ground where it is flat (SceneBackground draws it), found once when
  // the terrain is set.
  const std::optional<FlatGround>& flatGround() const { return flatGround_; }

 private:
  // A mesh of the mesh program's (unit size) stretched to `size` at `center`.
  template <class Mesh>
  void drawProp(const Mesh& mesh, const glm::vec3& center, const glm::vec3& size,
                const glm::vec4& color) const;

  gl::Program terrain_, mesh_;
  gl::VertexArray terrainVao_;
  gl::Buffer terrainVertices_, terrainIndices_;
  UnitCube cube_;
  UnitMesh sphere_ = UnitMesh::sphere(), cylinder_ = UnitMesh::cylinder();
  std::vector<Obstacle> obstacles_;
  std::vector<FieldPrimitive> primitives_;
  void drawPrimitives() const;
  WandRenderer wand_;
  SceneField sceneField_;  // before the passes that read it
  StreamlineRenderer streamlines_{sceneField_};
  SliceRenderer slice_{sceneField_};
  StreaklineRenderer streaklines_{sceneField_};
  std::shared_ptr<const HeightMap> ground_;
  std::optional<FlatGround> flatGround_;
  HelicopterSettings helicopter_;
  float rotorRadius_ = 7.0f;
  struct ModelMesh {
    UnitMesh mesh;
    glm::vec4 color;
  };
  std::vector<ModelMesh> helicopterModel_;  // core/props/helicopter_model.h, for rotorRadius_
  void drawHelicopter(bool translucent) const;
  int terrainIndexCount_ = 0;
  std::optional<Box> box_;
  std::optional<glm::vec3> probe_;
  float probeRadius_ = 0.25f;
  FieldPlacement placement_;
};

}  // namespace sandstorm
