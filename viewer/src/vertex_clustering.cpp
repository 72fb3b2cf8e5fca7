#include "vertex_clustering.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

namespace viewer::detail {

ambf_like::Mesh clusterVertices(const ambf_like::Mesh& mesh, int cells) {
  Eigen::AlignedBox3d box;
  for (const auto& v : mesh.vertices) box.extend(v);
  if (box.isEmpty() || cells < 1) return mesh;
  const Eigen::Array3d size = (box.sizes() / cells).array().max(1e-12);
  auto cellOf = [&](const ambf_like::Vec3& v) {
    const Eigen::Array3d c = ((v - box.min()).array() / size).floor();
    return (static_cast<std::int64_t>(c.x()) * (cells + 1) + static_cast<std::int64_t>(c.y())) *
               (cells + 1) +
           static_cast<std::int64_t>(c.z());
  };
  // Each cell's vertex: the mean of the vertices in it.
  std::unordered_map<std::int64_t, int> index;
  std::vector<int> merged(mesh.vertices.size());
  std::vector<ambf_like::Vec3> sums;
  std::vector<int> counts;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto [it, fresh] =
        index.try_emplace(cellOf(mesh.vertices[i]), static_cast<int>(sums.size()));
    if (fresh) {
      sums.push_back(ambf_like::Vec3::Zero());
      counts.push_back(0);
    }
    merged[i] = it->second;
    sums[it->second] += mesh.vertices[i];
    ++counts[it->second];
  }
  ambf_like::Mesh out;
  out.file = mesh.file;
  for (std::size_t c = 0; c < sums.size(); ++c) out.vertices.push_back(sums[c] / counts[c]);
  std::set<std::array<int, 3>> seen;
  for (const auto& t : mesh.triangles) {
    const std::array<int, 3> m{merged[t[0]], merged[t[1]], merged[t[2]]};
    if (m[0] == m[1] || m[1] == m[2] || m[0] == m[2]) continue;
    // One triangle per cell triple and winding (rotations are the same triangle).
    const int first = static_cast<int>(std::min_element(m.begin(), m.end()) - m.begin());
    const std::array<int, 3> key{m[first], m[(first + 1) % 3], m[(first + 2) % 3]};
    if (seen.insert(key).second) out.triangles.push_back(m);
  }
  return out;
}

}  // namespace viewer::detail
