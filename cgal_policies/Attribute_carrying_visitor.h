// Attribute_carrying_visitor: the EdgeCollapseSimplificationVisitor that tells a
// Corner_attribute_carrier about every collapse of CGAL's SMS::edge_collapse, so that the corner
// values of a CGAL::Surface_mesh (Corner_attributes.h) follow the collapses and keep their seams
// (docs/attributes.md). Seam_keeping_placement and Seam_keeping_filter refuse to run without it
// (the carrier throws std::logic_error): without the visitor, the values would silently stay where
// the collapses left them. Every event is then passed on to a base visitor (default: none), so it
// composes with a visitor of one's own.
// Usage:
//   cgal_policies::Corner_attribute_carrier<Point> carrier(mesh);
//   Carrier* carried = carrier.active() ? &carrier : nullptr;  // null: nothing to carry
//   SMS::edge_collapse(mesh, stop,
//       CGAL::parameters::get_cost(cost)
//           .get_placement(cgal_policies::Seam_keeping_placement<Point, P>(placement, carried))
//           .filter(cgal_policies::Seam_keeping_filter<Point, F>(filter, carried))
//           .visitor(cgal_policies::Attribute_carrying_visitor<Point>(carried)));
#ifndef CGAL_POLICIES_ATTRIBUTE_CARRYING_VISITOR_H
#define CGAL_POLICIES_ATTRIBUTE_CARRYING_VISITOR_H

#include <cgal_policies/Corner_attribute_carrier.h>

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>

#include <cstddef>

namespace cgal_policies {

template <class Point, class BaseVisitor = CGAL::Surface_mesh_simplification::
                           Edge_collapse_visitor_base<CGAL::Surface_mesh<Point>>>
class Attribute_carrying_visitor {
 public:
  using Mesh = CGAL::Surface_mesh<Point>;
  using Carrier = Corner_attribute_carrier<Point>;

  // `carrier` null: nothing to carry, every event goes to `base` alone.
  explicit Attribute_carrying_visitor(Carrier* carrier, const BaseVisitor& base = BaseVisitor())
      : m_carrier(carrier), m_base(base) {}

  void OnStarted(Mesh& mesh) {
    if (m_carrier) m_carrier->started();
    m_base.OnStarted(mesh);
  }
  void OnFinished(Mesh& mesh) { m_base.OnFinished(mesh); }
  template <class Profile>
  void OnStopConditionReached(const Profile& profile) {
    m_base.OnStopConditionReached(profile);
  }
  template <class Profile, class OptionalCost>
  void OnCollected(const Profile& profile, const OptionalCost& cost) {
    m_base.OnCollected(profile, cost);
  }
  template <class Profile, class OptionalCost>
  void OnSelected(const Profile& profile, const OptionalCost& cost, std::size_t initial,
                  std::size_t current) {
    m_base.OnSelected(profile, cost, initial, current);
  }
  template <class Profile, class OptionalPoint>
  void OnCollapsing(const Profile& profile, const OptionalPoint& placement) {
    if (m_carrier && placement) m_carrier->collapsing(profile, *placement);
    m_base.OnCollapsing(profile, placement);
  }
  template <class Profile, class Vertex>
  void OnCollapsed(const Profile& profile, Vertex kept) {
    if (m_carrier) m_carrier->collapsed(kept);
    m_base.OnCollapsed(profile, kept);
  }
  template <class Profile>
  void OnNonCollapsable(const Profile& profile) {
    m_base.OnNonCollapsable(profile);
  }

 private:
  Carrier* m_carrier;
  BaseVisitor m_base;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_ATTRIBUTE_CARRYING_VISITOR_H
