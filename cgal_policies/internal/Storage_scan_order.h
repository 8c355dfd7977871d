// [Liu17]'s single pass over the edges in storage order (docs/hausdorff.md): an edge's place is
// its cost in CGAL's queue, forgotten once tried so that a later collapse does not bring it back.
#ifndef CGAL_POLICIES_INTERNAL_STORAGE_SCAN_ORDER_H
#define CGAL_POLICIES_INTERNAL_STORAGE_SCAN_ORDER_H

#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/boost/graph/properties.h>

namespace cgal_policies {
namespace internal {

template <typename TriangleMesh>
class Storage_scan_order {
  using Order_property = CGAL::dynamic_edge_property_t<double>;

 public:
  explicit Storage_scan_order(TriangleMesh& tm) : m_order(get(Order_property(), tm)) {}

  void record(const TriangleMesh& tm) {
    double order = 0;
    for (auto e : edges(tm)) put(m_order, e, order++);
  }

  template <typename Profile>
  Optional<double> position(const Profile& profile) const {
    const double order = get(m_order, edge(profile.v0_v1(), profile.surface_mesh()));
    if (order < 0) return {};
    return order;
  }

  template <typename Profile>
  void mark_tried(const Profile& profile) const {
    put(m_order, edge(profile.v0_v1(), profile.surface_mesh()), -1.0);
  }

 private:
  typename boost::property_map<TriangleMesh, Order_property>::type m_order;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_STORAGE_SCAN_ORDER_H
