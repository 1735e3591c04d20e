#include "hilight/own_frame.hpp"

#include "hilight/enclosing_ball.hpp"
#include "hilight/scene.hpp"

#include <Eigen/Eigenvalues>

namespace hilight {

OwnFrame own_frame(const Scene& scene) {
  OwnFrame frame;
  const Ball ball = smallest_enclosing_ball(scene.positions);
  if (ball.radius <= 0.0) return frame;
  frame.centre = Vec3(ball.centre);
  // Second moments of the surface about the centre: over each triangle,
  // ∫ x xᵀ dA = A/12 · (Σ vᵢ vᵢᵀ + (Σ vᵢ)(Σ vᵢ)ᵀ), its corners vᵢ taken from the centre.
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  std::vector<std::pair<double, Eigen::Vector3d>> centroids;  // area, centroid: for the third moments
  centroids.reserve(scene.triangles.size());
  for (const auto& tri : scene.triangles) {
    Eigen::Vector3d v[3];
    for (int k = 0; k < 3; ++k) {
      const DVec3 p = DVec3(scene.positions[tri[k]]) - ball.centre;
      v[k] = Eigen::Vector3d(p.x, p.y, p.z);
    }
    const double area = 0.5 * (v[1] - v[0]).cross(v[2] - v[0]).norm();
    if (!(area > 0.0)) continue;
    const Eigen::Vector3d sum = v[0] + v[1] + v[2];
    second += area / 12.0 * (v[0] * v[0].transpose() + v[1] * v[1].transpose() + v[2] * v[2].transpose() + sum * sum.transpose());
    centroids.emplace_back(area, sum / 3.0);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(second);
  if (solver.info() != Eigen::Success) return frame;
  Eigen::Matrix3d axes = solver.eigenvectors();  // columns, least moment first
  for (int a = 0; a < 2; ++a) {
    double third = 0.0;
    for (const auto& [area, c] : centroids) third += area * std::pow(c.dot(axes.col(a)), 3);
    if (third < 0.0) axes.col(a) = -axes.col(a);
  }
  axes.col(2) = axes.col(0).cross(axes.col(1));  // right-handed, as every turn keeps it
  for (int a = 0; a < 3; ++a) frame.axes[a] = Vec3(float(axes(0, a)), float(axes(1, a)), float(axes(2, a)));
  return frame;
}

} // namespace hilight
