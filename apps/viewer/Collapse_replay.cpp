#include "Collapse_replay.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace apps {

Indexed_mesh Indexed_mesh::from_mesh(const Mesh& mesh) {
  if (mesh.has_garbage()) throw std::invalid_argument("Indexed_mesh: collect garbage first");
  Indexed_mesh result;
  for (Mesh::Vertex_index v : mesh.vertices()) result.points.push_back(mesh.point(v));
  result.point_ids.resize(result.points.size());
  std::iota(result.point_ids.begin(), result.point_ids.end(), std::size_t(0));
  for (Mesh::Face_index f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    int corner = 0;
    for (Mesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      t[corner++] = std::uint32_t(v);
    result.triangles.push_back(t);
  }
  result.vertex_count = mesh.number_of_vertices();
  return result;
}

Mesh Indexed_mesh::to_mesh() const {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertex(points.size());
  for (const auto& t : triangles)
    for (std::uint32_t i : t)
      if (vertex[i] == Mesh::null_vertex()) vertex[i] = mesh.add_vertex(points[i]);
  for (const auto& t : triangles) mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]);
  return mesh;
}

Collapse_replay::Collapse_replay(const Mesh& input, const Collapse_history& history) {
  const Indexed_mesh start = Indexed_mesh::from_mesh(input);
  m_points = start.points;
  m_triangles = start.triangles;
  const std::size_t n = m_points.size(), collapses = history.collapses.size();

  m_merged_into.assign(n, 0);
  m_merge_step.assign(n, kNever);
  m_moves_begin.assign(n + 1, 0);
  for (std::size_t i = 0; i < collapses; ++i) {
    const Collapse_record& c = history.collapses[i];
    m_merged_into[std::size_t(c.removed)] = std::uint32_t(c.kept);
    m_merge_step[std::size_t(c.removed)] = i;
    ++m_moves_begin[std::size_t(c.kept) + 1];
    m_collapse_points.push_back(c.kept_point);
    m_collapse_seconds.push_back(c.seconds);
  }
  std::partial_sum(m_moves_begin.begin(), m_moves_begin.end(), m_moves_begin.begin());
  m_moves.resize(collapses);
  std::vector<std::size_t> fill(m_moves_begin.begin(), m_moves_begin.end() - 1);
  for (std::size_t i = 0; i < collapses; ++i)
    m_moves[fill[std::size_t(history.collapses[i].kept)]++] = i;

  // A kept vertex merges later than the vertices it absorbed, so the latest merges come first.
  m_by_merge_step.resize(n);
  std::iota(m_by_merge_step.begin(), m_by_merge_step.end(), std::uint32_t(0));
  std::stable_sort(
      m_by_merge_step.begin(), m_by_merge_step.end(),
      [this](std::uint32_t a, std::uint32_t b) { return m_merge_step[a] > m_merge_step[b]; });

  // Replays the merges once on the face corners to find when each face dies.
  std::vector<std::vector<std::uint32_t>> faces_of(n);
  for (std::size_t f = 0; f < m_triangles.size(); ++f)
    for (std::uint32_t v : m_triangles[f]) faces_of[v].push_back(std::uint32_t(f));
  std::vector<std::array<std::uint32_t, 3>> corners = m_triangles;
  m_face_death.assign(m_triangles.size(), kNever);
  m_faces_after.assign(collapses + 1, m_triangles.size());
  for (std::size_t i = 0; i < collapses; ++i) {
    const auto removed = std::uint32_t(history.collapses[i].removed);
    const auto kept = std::uint32_t(history.collapses[i].kept);
    std::size_t deaths = 0;
    for (std::uint32_t f : faces_of[removed]) {
      if (m_face_death[f] != kNever) continue;
      auto& c = corners[f];
      if (std::find(c.begin(), c.end(), kept) != c.end()) {
        m_face_death[f] = i;
        ++deaths;
      } else {
        std::replace(c.begin(), c.end(), removed, kept);
        faces_of[kept].push_back(f);
      }
    }
    faces_of[removed].clear();
    faces_of[removed].shrink_to_fit();
    m_faces_after[i + 1] = m_faces_after[i] - deaths;
  }
  m_seconds = history.report.seconds(cgal_policies::Simplification_pass::simplification);
}

double Collapse_replay::seconds_after(std::size_t step) const {
  if (step == steps()) return m_seconds;
  return step == 0 ? 0.0 : m_collapse_seconds[step - 1];
}

std::size_t Collapse_replay::step_for_target(std::size_t target_faces) const {
  const auto it = std::find_if(m_faces_after.begin(), m_faces_after.end(),
                               [&](std::size_t faces) { return faces <= target_faces; });
  return it == m_faces_after.end() ? steps() : std::size_t(it - m_faces_after.begin());
}

Indexed_mesh Collapse_replay::mesh_after(std::size_t step) const {
  const std::size_t n = m_points.size();
  std::vector<std::uint32_t> stands_for(n);
  for (std::uint32_t v : m_by_merge_step)
    stands_for[v] = m_merge_step[v] < step ? stands_for[m_merged_into[v]] : v;

  Indexed_mesh mesh;
  mesh.points = m_points;
  mesh.point_ids.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = m_moves.begin() + std::ptrdiff_t(m_moves_begin[v]);
    const auto last = m_moves.begin() + std::ptrdiff_t(m_moves_begin[v + 1]);
    const auto after = std::lower_bound(first, last, step);  // moves before `step`
    if (after == first) {
      mesh.point_ids[v] = v;
    } else {
      mesh.points[v] = m_collapse_points[*(after - 1)];
      mesh.point_ids[v] = n + *(after - 1);
    }
    if (m_merge_step[v] >= step) ++mesh.vertex_count;
  }
  for (std::size_t f = 0; f < m_triangles.size(); ++f)
    if (m_face_death[f] >= step) {
      const auto& t = m_triangles[f];
      mesh.triangles.push_back({stands_for[t[0]], stands_for[t[1]], stands_for[t[2]]});
    }
  return mesh;
}

}  // namespace apps
