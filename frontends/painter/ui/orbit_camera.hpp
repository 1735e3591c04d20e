#pragma once
/// The painter's view: a camera orbiting a target point (yaw, pitch, distance),
/// with pan and zoom; converts to hilight::Camera (spot region, screenshots)
/// and gives the world ray through a window pixel (picking).
#include "hilight/camera.hpp"
#include "hilight/math.hpp"

#include <glm/glm.hpp>

namespace hilight::painter::ui {

struct Ray {
  Vec3 origin, direction;  ///< direction unit length
};

class OrbitCamera {
public:
  /// The view hilight render uses by default (Camera::framing), as an orbit.
  static OrbitCamera framing(const Bounds& bounds, float aspect);
  /// Any eye/target/fov (session scripts set cameras this way).
  /// The target stays within kMaxReach scene diagonals of `scene_centre` and
  /// the distance within [1e-4, kMaxReach] diagonals, whatever the input, so
  /// the camera (and every ray cast from it) stays finite.
  static OrbitCamera from_camera(const Camera& camera, float scene_diagonal, const Vec3& scene_centre = Vec3(0.f));
  static constexpr float kMaxReach = 1e6f;

  Camera to_camera() const;
  Vec3 eye() const;
  const Vec3& target() const { return m_target; }
  float fov_deg() const { return m_fov_deg; }

  /// Rotates about the target (degrees); pitch stays within ±80° (where Camera::basis still takes +Y as up, as the GL view does).
  void orbit(float yaw_deg, float pitch_deg);
  /// Moves eye and target together by fractions of the view's height.
  void pan(float right_fraction, float up_fraction);
  /// Multiplies the distance to the target (< 1: closer).
  void zoom(float factor);

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  /// The ray from the eye through window pixel (x, y) (top-left origin, in
  /// the same units as width/height).
  Ray ray_through(float x, float y, float width, float height) const;

private:
  Vec3 m_target{0.f};
  float m_yaw_deg = 0.f, m_pitch_deg = 20.f, m_distance = 1.f, m_fov_deg = 50.f;
  float m_scene_diagonal = 1.f;  ///< sets near/far planes and the zoom limits
  Vec3 m_scene_centre{0.f};
  void keep_near_scene();
};

} // namespace hilight::painter::ui
