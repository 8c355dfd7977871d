// Shows a recorded collapse sequence (collapse_recorder.h) at any face count between the input's
// and the final one, in time linear in the mesh size and without running the policy again.
//
// A halfedge collapse merges `removed` into `kept`, moves `kept`, and deletes exactly the faces
// that held both. So after s collapses a vertex stands for the last vertex its merge chain reached
// within those s steps, it sits at its last recorded point, and a face lives while its three
// vertices stand for three different vertices. Faces keep their orientation, so the replay of s
// collapses equals the mesh CGAL leaves after those s collapses.
#ifndef CGAL_POLICIES_APPS_VIEWER_COLLAPSE_REPLAY_H
#define CGAL_POLICIES_APPS_VIEWER_COLLAPSE_REPLAY_H

#include "collapse_recorder.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace apps {

// A triangle mesh over the input's vertex indices: removed vertices are simply unused.
struct Indexed_mesh {
  std::vector<Point> points;           // by input vertex index
  std::vector<std::size_t> point_ids;  // which version of each point: see Collapse_replay
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::size_t vertex_count = 0;  // vertices not removed

  static Indexed_mesh from_mesh(const Mesh& mesh);  // mesh without garbage
  Mesh to_mesh() const;                             // the used vertices only
};

class Collapse_replay {
 public:
  Collapse_replay(const Mesh& input, const Collapse_history& history);

  std::size_t steps() const { return m_faces_after.size() - 1; }
  std::size_t faces_after(std::size_t step) const { return m_faces_after[step]; }
  double seconds_after(std::size_t step) const;
  // The first step whose face count is at most `target_faces`, or the last step.
  std::size_t step_for_target(std::size_t target_faces) const;
  // Point versions: input vertex v is version v, the point of collapse i is version
  // (number of input vertices + i); callers cache per-version data (e.g. errors) by it.
  std::size_t point_versions() const { return m_points.size() + m_collapse_points.size(); }

  Indexed_mesh mesh_after(std::size_t step) const;

 private:
  static constexpr std::size_t kNever = std::size_t(-1);

  std::vector<Point> m_points;  // input points
  std::vector<std::array<std::uint32_t, 3>> m_triangles;
  std::vector<std::uint32_t> m_merged_into;    // the kept vertex of the collapse that removed it
  std::vector<std::size_t> m_merge_step;       // that collapse, or kNever
  std::vector<std::uint32_t> m_by_merge_step;  // vertices, latest merge first (kNever first)
  // The collapses that moved each vertex, in order (compressed rows over vertices).
  std::vector<std::size_t> m_moves_begin, m_moves;
  std::vector<Point> m_collapse_points;
  std::vector<double> m_collapse_seconds;
  std::vector<std::size_t> m_face_death;   // the collapse that deleted the face, or kNever
  std::vector<std::size_t> m_faces_after;  // face count after s collapses, s = 0 .. collapses
  double m_seconds = 0;                    // the whole run
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_VIEWER_COLLAPSE_REPLAY_H
