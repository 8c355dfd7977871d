// What differs between the CGAL versions the library builds against (5.5 to 6.1), in one place
// with the edge-collapse oracles' optional type (Optional.h, included here). From CGAL 6.0 on,
// Surface_mesh::property_map() answers std::optional<Property_map> (before: std::pair<Property_map,
// bool>), the AABB tree's traits and segment primitive are named with a _3, and the edge-count stop
// predicates with an Edge_ (the old headers warn). Everything else the library, the apps and the
// tests use is the same in both.
#ifndef CGAL_POLICIES_INTERNAL_CGAL_VERSION_H
#define CGAL_POLICIES_INTERNAL_CGAL_VERSION_H

#include <cgal_policies/internal/Optional.h>

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/version.h>

// Before the stop predicates: CGAL 6.1's Edge_profile.h calls is_border() unqualified without
// including its declaration, which argument-dependent lookup does not find for OpenMesh.
#include <CGAL/boost/graph/helpers.h>

#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_segment_primitive_3.h>
#include <CGAL/AABB_traits_3.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_count_stop_predicate.h>
#else
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#endif

#include <optional>
#include <string>

namespace cgal_policies {
namespace internal {

// The traits of CGAL::AABB_tree, and its primitive over segments given by an iterator.
#if CGAL_VERSION_NR >= 1060000000
template <class Kernel, class Primitive>
using Aabb_traits = CGAL::AABB_traits_3<Kernel, Primitive>;
template <class Kernel, class Iterator>
using Aabb_segment_primitive = CGAL::AABB_segment_primitive_3<Kernel, Iterator>;
#else
template <class Kernel, class Primitive>
using Aabb_traits = CGAL::AABB_traits<Kernel, Primitive>;
template <class Kernel, class Iterator>
using Aabb_segment_primitive = CGAL::AABB_segment_primitive<Kernel, Iterator>;
#endif

// CGAL's stop predicates on the edges left, a count or a share of the input's.
#if CGAL_VERSION_NR >= 1060000000
template <class TriangleMesh>
using Edge_count_stop_predicate =
    CGAL::Surface_mesh_simplification::Edge_count_stop_predicate<TriangleMesh>;
template <class TriangleMesh>
using Edge_count_ratio_stop_predicate =
    CGAL::Surface_mesh_simplification::Edge_count_ratio_stop_predicate<TriangleMesh>;
#else
template <class TriangleMesh>
using Edge_count_stop_predicate =
    CGAL::Surface_mesh_simplification::Count_stop_predicate<TriangleMesh>;
template <class TriangleMesh>
using Edge_count_ratio_stop_predicate =
    CGAL::Surface_mesh_simplification::Count_ratio_stop_predicate<TriangleMesh>;
#endif

// The property map of `mesh` with that name, index and value type; none when it has none.
template <class Index, class Value, class Point>
std::optional<typename CGAL::Surface_mesh<Point>::template Property_map<Index, Value>>
find_property_map(const CGAL::Surface_mesh<Point>& mesh, const std::string& name) {
#if CGAL_VERSION_NR >= 1060000000
  return mesh.template property_map<Index, Value>(name);
#else
  const auto [map, found] = mesh.template property_map<Index, Value>(name);
  if (!found) return std::nullopt;
  return map;
#endif
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_CGAL_VERSION_H
