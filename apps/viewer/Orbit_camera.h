// The camera both panes share: it orbits a target point, zooms and pans, in the frame where the
// original mesh is centred at the origin with a bounding-box diagonal of 1 (Render_mesh.h).
#ifndef CGAL_POLICIES_APPS_VIEWER_ORBIT_CAMERA_H
#define CGAL_POLICIES_APPS_VIEWER_ORBIT_CAMERA_H

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace apps {

class Orbit_camera {
 public:
  // Angles in radians; `dx`, `dy` of pan are fractions of the pane's height.
  void orbit(float d_yaw, float d_pitch) {
    m_yaw += d_yaw;
    m_pitch = std::clamp(m_pitch + d_pitch, -1.55f, 1.55f);
  }
  void zoom(float factor) { m_distance = std::clamp(m_distance * factor, 0.05f, 20.0f); }
  void pan(float dx, float dy) {
    const Eigen::Matrix3f to_world = rotation().transpose();
    const float height = 2 * m_distance * std::tan(kFieldOfView / 2);
    m_target -= to_world * Eigen::Vector3f(dx * height, -dy * height, 0);
  }

  Eigen::Matrix4f view() const {
    Eigen::Affine3f view = Eigen::Affine3f::Identity();
    view.translate(Eigen::Vector3f(0, 0, -m_distance));
    view.linear() = rotation();
    view.translate(-m_target);
    return view.matrix();
  }

  static Eigen::Matrix4f projection(float aspect) {
    const float f = 1 / std::tan(kFieldOfView / 2), near = 0.01f, far = 50.0f;
    Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
    p(0, 0) = f / aspect;
    p(1, 1) = f;
    p(2, 2) = (far + near) / (near - far);
    p(2, 3) = 2 * far * near / (near - far);
    p(3, 2) = -1;
    return p;
  }

 private:
  static constexpr float kFieldOfView = 0.7f;  // vertical, radians (40 degrees)

  Eigen::Matrix3f rotation() const {
    return (Eigen::AngleAxisf(m_pitch, Eigen::Vector3f::UnitX()) *
            Eigen::AngleAxisf(m_yaw, Eigen::Vector3f::UnitY()))
        .toRotationMatrix();
  }

  float m_yaw = 0, m_pitch = 0;
  float m_distance = 1.6f;  // the unit-diagonal mesh fills most of the pane
  Eigen::Vector3f m_target = Eigen::Vector3f::Zero();
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_ORBIT_CAMERA_H
