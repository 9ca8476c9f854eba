#include "shadowkit/scene/scene.h"

#include <cmath>
#include <numbers>
#include <span>

#include "shadowkit/scene/triangulate.h"

namespace shadowkit {

double Camera::tan_half_fov() const {
  return std::tan(fov_y_deg * std::numbers::pi / 360.0);
}

Camera::PixelGrid Camera::pixel_grid() const {
  // x = (2 (c + 0.5) / W - 1) t W / H and y = (1 - 2 (w + 0.5) / H) t, as steps from pixel 0.
  const double t = tan_half_fov();
  const double step = 2.0 * t / height;
  return {step, -t * width / height + 0.5 * step, t - 0.5 * step};
}

Vec3 Camera::pixel_ray(int column, int row) const {
  const PixelGrid g = pixel_grid();
  return normalize(forward() + (g.x0 + g.step * column) * right() +
                   (g.y0 - g.step * row) * true_up());
}

void Scene::finalize() {
  face_object.clear();
  face_planes_.clear();
  bounds_ = {};
  triangles_ = {};
  for (std::uint32_t o = 0; o < objects.size(); ++o) {
    SceneObject& object = objects[o];
    const Mesh& mesh = object.mesh;
    object.first_face = std::uint32_t(face_object.size());
    face_object.insert(face_object.end(), mesh.face_count(), o);
    face_planes_.insert(face_planes_.end(), mesh.planes.begin(), mesh.planes.end());

    const auto base = std::uint32_t(triangles_.positions.size());
    triangles_.positions.insert(triangles_.positions.end(), mesh.vertices.begin(),
                                mesh.vertices.end());
    std::vector<std::array<std::uint32_t, 3>> local;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      local.clear();
      const std::span<const std::uint32_t> loop(&mesh.face_vertices[mesh.face_start[f]],
                                                mesh.face_size(f));
      triangulate_polygon(mesh.vertices, loop, mesh.planes[f].normal, local);
      for (const auto& t : local) {
        triangles_.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        triangles_.triangle_face.push_back(object.first_face + std::uint32_t(f));
      }
    }
    for (std::uint32_t v : mesh.face_vertices) bounds_.add(mesh.vertices[v]);
  }
  triangles_.clusters = cluster_triangles(triangles_, bounds_);
  outward_solids_ = OutwardSolids(*this);
}

void apply_transform(std::vector<Vec3>& positions, Vec3 scale, Vec3 rotate_deg, Vec3 translate) {
  const double k = std::numbers::pi / 180.0;
  const double cx = std::cos(rotate_deg.x * k), sx = std::sin(rotate_deg.x * k);
  const double cy = std::cos(rotate_deg.y * k), sy = std::sin(rotate_deg.y * k);
  const double cz = std::cos(rotate_deg.z * k), sz = std::sin(rotate_deg.z * k);
  for (Vec3& p : positions) {
    Vec3 q{p.x * scale.x, p.y * scale.y, p.z * scale.z};
    q = {q.x, cx * q.y - sx * q.z, sx * q.y + cx * q.z};   // Rx
    q = {cy * q.x + sy * q.z, q.y, -sy * q.x + cy * q.z};  // Ry
    q = {cz * q.x - sz * q.y, sz * q.x + cz * q.y, q.z};   // Rz
    p = q + translate;
  }
}

}  // namespace shadowkit
