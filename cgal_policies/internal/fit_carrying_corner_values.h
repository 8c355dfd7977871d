// The fitting pass on a CGAL::Surface_mesh that may carry corner attributes (docs/fitting.md,
// "Texture coordinates, normals and colours"): with values, the seam vertices stay where they are,
// no edge flips (a flip would hand corners to other vertices), and every moved vertex takes the
// values at the point of its old star nearest its new point, as a collapse's kept vertex does
// (docs/attributes.md), unless that would turn a texture triangle around it over; then the texture
// coordinates on no seam are solved again against the input (resolve_free_uvs.h).
#ifndef CGAL_POLICIES_INTERNAL_FIT_CARRYING_CORNER_VALUES_H
#define CGAL_POLICIES_INTERNAL_FIT_CARRYING_CORNER_VALUES_H

#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Corner_attributes.h>
#include <cgal_policies/Two_sided_fit_options.h>
#include <cgal_policies/Two_sided_fit_report.h>
#include <cgal_policies/Two_sided_fitter.h>
#include <cgal_policies/internal/resolve_free_uvs.h>

#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace cgal_policies {
namespace internal {

// After a fit that moved only the vertices on no seam, and flipped nothing.
template <class Point>
void carry_corner_values(CGAL::Surface_mesh<Point>& mesh, const CGAL::Surface_mesh<Point>& before) {
  using Attributes = Corner_attributes<Point>;
  using Carrier = Corner_attribute_carrier<Point>;
  const Attributes attributes(mesh), old(before);
  for (const auto v : mesh.vertices()) {
    if (mesh.point(v) == before.point(v)) continue;
    std::vector<typename CGAL::Surface_mesh<Point>::Face_index> star;
    for (const auto f : CGAL::faces_around_target(before.halfedge(v), before))
      if (f != before.null_face()) star.push_back(f);
    const typename Attributes::Values value =
        Carrier::values_nearest(before, old, star, mesh.point(v));
    bool keeps_orientation = true;
    for (const auto h : CGAL::halfedges_around_target(v, mesh)) {
      if (mesh.is_border(h) || !attributes.uvs) continue;
      const auto& b = (*attributes.uvs)[mesh.next(h)];
      const auto& c = (*attributes.uvs)[mesh.prev(h)];
      const double was = Attributes::uv_area((*attributes.uvs)[h], b, c),
                   now = Attributes::uv_area(value.uv, b, c);
      keeps_orientation =
          keeps_orientation && !(std::isfinite(was) && was != 0 && !(was * now > 0));
    }
    if (!keeps_orientation) continue;
    for (const auto h : CGAL::halfedges_around_target(v, mesh))
      if (!mesh.is_border(h)) attributes.set_values(h, value);
  }
}

// Fits `mesh` to `original` with `options`; with corner values, as the header says. The vertices
// `pinned` names, when given, stay too. `original` is a mesh, or the Input_triangles of one without
// corner values (a cell's, for the fit by cells), against which no texture coordinate is solved.
template <class Point, class Original>
Two_sided_fit_report fit_carrying_corner_values(
    CGAL::Surface_mesh<Point>& mesh, Original&& original, Two_sided_fit_options options,
    const std::function<bool(CGAL::SM_Vertex_index)>& pinned = {}) {
  using Mesh = CGAL::Surface_mesh<Point>;
  if (!Corner_attributes<Point>(mesh).any_corner_values())
    return Two_sided_fitter<Mesh>(std::forward<Original>(original), options).fit(mesh, pinned);
  options.flips = false;
  const Mesh before = mesh;
  const Corner_attribute_carrier<Point> seams(mesh);
  const auto stays = [&](typename Mesh::Vertex_index v) {
    return seams.seam_edges_at(v) > 0 || (pinned && pinned(v));
  };
  // A mesh is only read (the fitter keeps a reference), so it is still there to solve against.
  constexpr bool from_mesh = std::is_same_v<std::decay_t<Original>, Mesh>;
  const Two_sided_fit_report report =
      Two_sided_fitter<Mesh>(std::forward<Original>(original), options).fit(mesh, stays);
  carry_corner_values(mesh, before);
  if constexpr (from_mesh)
    resolve_free_uvs(mesh, original, [&](typename Mesh::Vertex_index v) { return !stays(v); });
  return report;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_FIT_CARRYING_CORNER_VALUES_H
