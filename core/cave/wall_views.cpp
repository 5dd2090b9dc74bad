#include "core/cave/wall_views.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace sandstorm {

bool isStereo(StereoMode mode) {
  return mode != StereoMode::Mono && mode != StereoMode::LeftEye && mode != StereoMode::RightEye;
}

std::vector<View> wallViews(const WallSpec& wall, const Viewer& viewer, float aspect,
                            float nearPlane, float farPlane) {
  const glm::mat4 worldToRoom = viewer.navigation.worldToRoom();
  std::vector<glm::vec3> eyes;  // room coordinates
  glm::vec3 right = viewer.head.right;
  glm::vec3 center = viewer.head.position;
  if (wall.camera) {
    center = wall.camera->position;
    const glm::vec3 forward = glm::normalize(wall.camera->target - wall.camera->position);
    right = glm::normalize(glm::cross(forward, glm::vec3(0, 0, 1)));
  }
  const float half = 0.5f * viewer.head.eyeSeparation;
  if (wall.stereo == StereoMode::LeftEye) {
    eyes = {center - right * half};
  } else if (wall.stereo == StereoMode::RightEye) {
    eyes = {center + right * half};
  } else if (isStereo(wall.stereo)) {
    eyes = {center - right * half, center + right * half};
  } else {
    eyes = {center};
  }
  std::vector<View> views;
  for (const glm::vec3& eye : eyes) {
    View v;
    if (wall.camera) {
      const glm::vec3 target = wall.camera->target + (eye - center);
      v = perspectiveView(eye, target, {0, 0, 1}, glm::radians(wall.camera->fovDegrees), aspect,
                          nearPlane, farPlane);
    } else {
      v = offAxisView(wall.corners, eye, nearPlane, farPlane);
    }
    v.view = v.view * worldToRoom;
    v.eye = viewer.navigation.roomToWorld(eye);
    views.push_back(v);
  }
  return views;
}

std::vector<glm::ivec4> eyeViewports(StereoMode mode, glm::ivec2 size) {
  if (mode == StereoMode::SideBySide)
    return {{0, 0, size.x / 2, size.y}, {size.x / 2, 0, size.x / 2, size.y}};
  if (mode == StereoMode::TopBottom)
    return {{0, size.y / 2, size.x, size.y / 2}, {0, 0, size.x, size.y / 2}};
  return {{0, 0, size.x, size.y}};
}

glm::vec2 eyeImageSize(StereoMode mode, glm::vec2 imageSize) {
  if (mode == StereoMode::SideBySide) return {imageSize.x * 0.5f, imageSize.y};
  if (mode == StereoMode::TopBottom) return {imageSize.x, imageSize.y * 0.5f};
  return imageSize;
}

glm::vec2 pointInEyeImage(StereoMode mode, glm::vec2 imageSize, glm::vec2 point) {
  const glm::vec2 eye = eyeImageSize(mode, imageSize);
  // The second eye's half starts where the first one's ends.
  if (mode == StereoMode::SideBySide && point.x >= eye.x) point.x -= eye.x;
  if (mode == StereoMode::TopBottom && point.y >= eye.y) point.y -= eye.y;
  return point;
}

WorldRay wallClickRay(const WallSpec& wall, const Viewer& viewer, glm::vec2 at, float aspect,
                      float nearPlane, float farPlane) {
  const std::vector<View> views = wallViews(wall, viewer, aspect, nearPlane, farPlane);
  std::size_t eye = 0;
  if (wall.stereo == StereoMode::SideBySide) {
    eye = at.x < 0.5f ? 0 : 1;
    at.x = at.x < 0.5f ? 2.0f * at.x : 2.0f * at.x - 1.0f;
  } else if (wall.stereo == StereoMode::TopBottom) {
    eye = at.y < 0.5f ? 0 : 1;
    at.y = at.y < 0.5f ? 2.0f * at.y : 2.0f * at.y - 1.0f;
  }
  const View& v = views[std::min(eye, views.size() - 1)];
  const glm::vec2 ndc(2.0f * at.x - 1.0f, 1.0f - 2.0f * at.y);
  const glm::mat4 inverse = glm::inverse(v.projection * v.view);
  const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
  const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
  return {v.eye, glm::normalize(b - a)};
}

}  // namespace sandstorm
