// The patch of a Hausdorff-bounded change (docs/hausdorff.md): the faces around the moving
// vertices before the change, what the moved patch must stay close to and must keep covering.
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_PATCH_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_PATCH_H

#include <cgal_policies/Hausdorff_bounded_options.h>
#include <cgal_policies/internal/Hausdorff_attachment.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename FaceDescriptor>
struct Hausdorff_patch {
  // The faces that survive with a moved corner, and those that vanish, as they are before.
  std::vector<FaceDescriptor> faces, removed;
  std::vector<Triangle_corners> before, removed_before;
  std::vector<std::array<bool, 3>> moving;  // which corners of `before` move
  std::vector<std::array<Reference_sample, 3>> corner_distances;
  std::vector<Triangle_corners> reference;  // local reference: the patch before the change
  // What the moved patch must cover: the pieces attached to the faces (global) or the patch before
  // (local), with each piece's index (or kNewPiece).
  std::vector<Triangle_corners> pieces;
  std::vector<std::uint32_t> piece_sources;
};

// What a patch must keep covering under the global reference: the pieces attached to its faces.
template <typename TriangleMesh>
void add_attached_pieces(
    Hausdorff_patch<typename boost::graph_traits<TriangleMesh>::face_descriptor>& patch,
    const Hausdorff_attachment<TriangleMesh>& attachment) {
  for (const auto* list : {&patch.faces, &patch.removed})
    for (auto f : *list)
      for (std::uint32_t i : attachment.pieces_of(f)) {
        patch.pieces.push_back(attachment.piece(i));
        patch.piece_sources.push_back(i);
      }
}

// The patch around v0 and v1 (v0 == v1: one vertex moves).
template <typename TriangleMesh, typename VertexPointMap>
Hausdorff_patch<typename boost::graph_traits<TriangleMesh>::face_descriptor> make_patch(
    const TriangleMesh& tm, const VertexPointMap& vpm,
    typename boost::graph_traits<TriangleMesh>::vertex_descriptor v0,
    typename boost::graph_traits<TriangleMesh>::vertex_descriptor v1,
    const Hausdorff_attachment<TriangleMesh>& attachment, Hausdorff_reference reference) {
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  Hausdorff_patch<typename Graph_traits::face_descriptor> patch;
  const bool global = reference == Hausdorff_reference::global;
  for (int pass = 0; pass < (v0 == v1 ? 1 : 2); ++pass) {
    const auto v = pass == 0 ? v0 : v1;
    for (auto f : CGAL::faces_around_target(halfedge(v, tm), tm)) {
      if (f == Graph_traits::null_face()) continue;
      std::array<typename Graph_traits::vertex_descriptor, 3> vs;
      int i = 0;
      for (auto w : CGAL::vertices_around_face(halfedge(f, tm), tm)) vs[i++] = w;
      const bool has0 = std::find(vs.begin(), vs.end(), v0) != vs.end();
      const bool has1 = std::find(vs.begin(), vs.end(), v1) != vs.end();
      if (pass == 1 && has0) continue;  // seen around v0
      Triangle_corners t;
      for (int k = 0; k < 3; ++k) t[k] = internal::to_eigen(get(vpm, vs[k]));
      if (has0 && has1 && v0 != v1) {
        patch.removed.push_back(f);
        patch.removed_before.push_back(t);
        continue;
      }
      patch.faces.push_back(f);
      patch.before.push_back(t);
      std::array<bool, 3> moving;
      std::array<Reference_sample, 3> distances;
      for (int k = 0; k < 3; ++k) {
        moving[k] = vs[k] == v0 || vs[k] == v1;
        distances[k] =
            global ? attachment.sample(vs[k]) : Reference_sample{0.0, patch.before.size() - 1};
      }
      patch.moving.push_back(moving);
      patch.corner_distances.push_back(distances);
    }
  }
  if (global) {
    add_attached_pieces(patch, attachment);
  } else {
    patch.reference = patch.before;
    patch.reference.insert(patch.reference.end(), patch.removed_before.begin(),
                           patch.removed_before.end());
    patch.pieces = patch.reference;
    patch.piece_sources.assign(patch.pieces.size(), kNewPiece);
  }
  return patch;
}

// The patch of faces whose corners stay where they are while their connectivity changes (an edge
// flip), as they are after the change; global reference only.
template <typename TriangleMesh, typename VertexPointMap>
Hausdorff_patch<typename boost::graph_traits<TriangleMesh>::face_descriptor> make_reshaped_patch(
    const TriangleMesh& tm, const VertexPointMap& vpm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
    const Hausdorff_attachment<TriangleMesh>& attachment) {
  Hausdorff_patch<typename boost::graph_traits<TriangleMesh>::face_descriptor> patch;
  for (auto f : faces) {
    patch.faces.push_back(f);
    patch.before.push_back(face_corners(f, tm, vpm));
    patch.moving.push_back({false, false, false});
    std::array<Reference_sample, 3> distances;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      distances[k++] = attachment.sample(v);
    patch.corner_distances.push_back(distances);
  }
  add_attached_pieces(patch, attachment);
  return patch;
}

template <typename TriangleMesh>
bool is_frozen(
    const Hausdorff_patch<typename boost::graph_traits<TriangleMesh>::face_descriptor>& patch,
    const Hausdorff_attachment<TriangleMesh>& attachment) {
  for (const auto* list : {&patch.faces, &patch.removed})
    for (auto f : *list)
      if (attachment.frozen(f)) return true;
  return false;
}

template <typename FaceDescriptor>
std::vector<Triangle_corners> moved(const Hausdorff_patch<FaceDescriptor>& patch,
                                    const Eigen::Vector3d& p) {
  std::vector<Triangle_corners> after = patch.before;
  for (std::size_t j = 0; j < after.size(); ++j)
    for (int k = 0; k < 3; ++k)
      if (patch.moving[j][k]) after[j][k] = p;
  return after;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_PATCH_H
