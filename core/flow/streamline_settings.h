// StreamlineSettings: the seed rake of the streamlines every wall draws (the
// attributes streamlines.*): seeds on a line from `from` to `to`, or on a
// plane spanned by from->to and from->across, traced both ways through the
// current field, with an integrator of their own (not the particles'): by
// default adaptive Runge-Kutta 4-5 with an error tolerance, as ParaView's
// Stream Tracer.
#pragma once

#include <glm/glm.hpp>

namespace sandstorm {

enum class RakeShape : int { Line = 0, Plane = 1 };

// streamlines.integrator. RK45: Cash-Karp's embedded pair (VTK's
// vtkRungeKutta45), each step as long as `tolerance` allows, at most `step`.
enum class StreamIntegrator : int { Euler = 0, RK2 = 1, RK4 = 2, RK45 = 3 };

struct StreamlineSettings {
  bool enabled = false;
  RakeShape shape = RakeShape::Line;
  glm::vec3 from{-4.0f, 0.0f, 2.0f};  // m, where the particles are (FieldPlacement's "room")
  glm::vec3 to{4.0f, 0.0f, 2.0f};
  glm::vec3 across{-4.0f, 0.0f, 6.0f};  // the plane's second edge ends here
  int seeds = 16;                       // along each edge (a plane has seeds x seeds)
  float step = 0.05f;                   // m of arc per step (RK45: the longest step)
  StreamIntegrator integrator = StreamIntegrator::RK45;
  float tolerance = 1e-6f;  // m: RK45's largest error estimate a step may have
  float length = 30.0f;     // m: each direction stops here at the latest
  float width = 0.03f;      // m: ribbon width (0: one-pixel lines)
};

}  // namespace sandstorm
