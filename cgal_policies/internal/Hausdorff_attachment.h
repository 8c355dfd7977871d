// How the mesh of a Hausdorff-bounded run is tied to the input (docs/hausdorff.md, "the pieces"):
// input pieces attached to covering faces, frozen faces (the bound broken from the start), and each
// vertex's distance to a nearby input triangle, where walks start.
#ifndef CGAL_POLICIES_INTERNAL_HAUSDORFF_ATTACHMENT_H
#define CGAL_POLICIES_INTERNAL_HAUSDORFF_ATTACHMENT_H

#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/Triangle_bvh.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/piece_cover.h>
#include <cgal_policies/internal/triangle_distance.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Hausdorff_attachment {
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using Piece_list_property = CGAL::dynamic_face_property_t<std::vector<std::uint32_t>>;
  // Not bool: a bool map of OpenMesh's is a std::vector<bool>, which CGAL's map cannot refer into.
  using Frozen_property = CGAL::dynamic_face_property_t<std::uint8_t>;
  using Sample_property = CGAL::dynamic_vertex_property_t<Reference_sample>;

 public:
  explicit Hausdorff_attachment(TriangleMesh& tm)
      : m_face_pieces(get(Piece_list_property(), tm)),
        m_frozen(get(Frozen_property(), tm)),
        m_samples(get(Sample_property(), tm)) {}

  const Triangle_corners& piece(std::uint32_t i) const { return m_pieces[i]; }
  decltype(auto) pieces_of(face_descriptor f) const { return get(m_face_pieces, f); }
  bool frozen(face_descriptor f) const { return get(m_frozen, f) != 0; }
  Reference_sample sample(vertex_descriptor v) const { return get(m_samples, v); }
  void set_sample(vertex_descriptor v, const Reference_sample& s) { put(m_samples, v, s); }

  // `tm` is the input itself: each face is its own piece (none with `pieces` false: local mode).
  template <typename VertexPointMap>
  void attach_to_itself(const TriangleMesh& tm, const VertexPointMap& vpm, bool pieces) {
    m_pieces.clear();
    std::size_t index = 0;
    for (auto f : faces(tm)) {
      for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
        put(m_samples, v, Reference_sample{0.0, index});
      ++index;
      put(m_frozen, f, false);
      std::vector<std::uint32_t> list;
      if (pieces) {
        list.push_back(std::uint32_t(m_pieces.size()));
        m_pieces.push_back(face_corners(f, tm, vpm));
      }
      put(m_face_pieces, f, std::move(list));
    }
  }

  // `tm` approximates the input: each piece goes to a covering face around the face nearest its
  // centroid; with none, that face is frozen, since the bound is broken there already.
  template <typename VertexPointMap>
  void attach_to_approximation(const TriangleMesh& tm, const VertexPointMap& vpm,
                               const Hausdorff_input_surface& input, int max_refinement) {
    m_pieces.clear();
    std::vector<Triangle_corners> current;
    std::vector<face_descriptor> current_faces;
    for (auto f : faces(tm)) {
      current.push_back(face_corners(f, tm, vpm));
      current_faces.push_back(f);
      put(m_face_pieces, f, std::vector<std::uint32_t>());
      put(m_frozen, f, false);
    }
    for (auto v : vertices(tm)) put(m_samples, v, input.nearest(to_eigen(get(vpm, v))));
    if (current.empty()) return;
    const Triangle_bvh tree(current);
    for (std::size_t i = 0; i < input.size(); ++i) {
      const Triangle_corners& piece = input.corners(i);
      const Eigen::Vector3d centroid = (piece[0] + piece[1] + piece[2]) / 3;
      const face_descriptor f = current_faces[tree.nearest(centroid).triangle];
      std::vector<face_descriptor> around;
      for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
        for (auto g : CGAL::faces_around_target(h, tm))
          if (g != Graph_traits::null_face() &&
              std::find(around.begin(), around.end(), g) == around.end())
            around.push_back(g);
      std::vector<Triangle_corners> patch;
      for (auto g : around) patch.push_back(face_corners(g, tm, vpm));
      std::vector<Piece_cover> covers;
      std::size_t hint = 0;
      if (cover_piece(piece, kNewPiece, patch, input.tolerance(), max_refinement, hint, covers)) {
        for (const Piece_cover& c : covers) attach(c.piece, around[c.triangle]);
      } else {
        attach(piece, f);
        put(m_frozen, f, true);
      }
    }
  }

  // After a patch changed: the pieces of `faces` and `removed` are those of `covers`.
  void reattach(const std::vector<face_descriptor>& faces,
                const std::vector<face_descriptor>& removed,
                const std::vector<Piece_cover>& covers) {
    for (auto f : removed) put(m_face_pieces, f, std::vector<std::uint32_t>());
    for (auto f : faces) put(m_face_pieces, f, std::vector<std::uint32_t>());
    for (const Piece_cover& c : covers) {
      const face_descriptor f = faces[c.triangle];
      if (c.source == kNewPiece) {
        attach(c.piece, f);
      } else {
        std::vector<std::uint32_t> list = get(m_face_pieces, f);
        list.push_back(c.source);
        put(m_face_pieces, f, std::move(list));
      }
    }
  }

 private:
  void attach(const Triangle_corners& piece, face_descriptor f) {
    std::vector<std::uint32_t> list = get(m_face_pieces, f);
    list.push_back(std::uint32_t(m_pieces.size()));
    m_pieces.push_back(piece);
    put(m_face_pieces, f, std::move(list));
  }

  std::vector<Triangle_corners> m_pieces;
  typename boost::property_map<TriangleMesh, Piece_list_property>::type m_face_pieces;
  typename boost::property_map<TriangleMesh, Frozen_property>::type m_frozen;
  typename boost::property_map<TriangleMesh, Sample_property>::type m_samples;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_HAUSDORFF_ATTACHMENT_H
