// Border_pair_contraction: the manifold-safe part of pair contraction ([QEM-tutorial] §2.1: pairs
// (vi, vj), |vi - vj| < t, that are not edges; docs/quadric_core.md), a crack-closing pre-pass for
// any policy on a `MutableFaceGraph` such as CGAL::Surface_mesh. Only border vertices of different
// loops closer than t = relative_distance * D (D the bounding-box diagonal) pair, with their mutual
// nearest candidate (else "ambiguous"); a pair is merged at its midpoint only with a border edge it
// can stitch (else "pinch") and never into a doubled edge ("duplicate_edge"). Deterministic; a
// manifold mesh stays manifold.
// Parameter: relative_distance, t as a fraction of D (default 0: nothing is merged).
// Usage:
//   const cgal_policies::Border_pair_contraction contraction(1e-4);
//   const cgal_policies::Border_pair_contraction_report report = contraction(mesh);
//   // report.merged_pairs, report.refused_pairs, report.refused_by_reason
#ifndef CGAL_POLICIES_BORDER_PAIR_CONTRACTION_H
#define CGAL_POLICIES_BORDER_PAIR_CONTRACTION_H

#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cgal_policies {

struct Border_pair_contraction_report {
  std::size_t merged_pairs = 0;    // vertex pairs merged into one vertex
  std::size_t stitched_edges = 0;  // border edge pairs stitched into one edge
  std::size_t refused_pairs = 0;
  std::map<std::string, std::size_t> refused_by_reason;  // "ambiguous", "pinch", "duplicate_edge"
};

class Border_pair_contraction {
 public:
  explicit Border_pair_contraction(double relative_distance = 0)
      : m_relative_distance(relative_distance) {}

  template <typename TriangleMesh>
  Border_pair_contraction_report operator()(TriangleMesh& tm) const {
    return (*this)(tm, get(CGAL::vertex_point, tm));
  }

  // The same, with the points read from and written to `vpm`.
  template <typename TriangleMesh, typename VertexPointMap>
  Border_pair_contraction_report operator()(TriangleMesh& tm, const VertexPointMap& vpm) const {
    using Graph_traits = boost::graph_traits<TriangleMesh>;
    using Vertex = typename Graph_traits::vertex_descriptor;
    using Halfedge = typename Graph_traits::halfedge_descriptor;
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    Border_pair_contraction_report report;

    // Border vertices in mesh order, with their loop and outgoing border halfedge.
    std::vector<Vertex> vertex;
    std::vector<Halfedge> out;
    std::vector<int> loop;
    std::vector<Eigen::Vector3d> point;
    Eigen::AlignedBox3d box;
    for (Vertex v : vertices(tm)) box.extend(internal::to_eigen(get(vpm, v)));
    const double t = m_relative_distance * (box.isEmpty() ? 0.0 : box.diagonal().norm());
    if (!(t > 0)) return report;
    {
      auto id = get(CGAL::dynamic_halfedge_property_t<int>(), tm);
      for (Halfedge h : halfedges(tm)) put(id, h, -1);
      int loops = 0;
      for (Halfedge h : halfedges(tm)) {
        if (!CGAL::is_border(h, tm) || get(id, h) >= 0) continue;
        for (Halfedge g : CGAL::halfedges_around_face(h, tm)) {
          put(id, g, loops);
          vertex.push_back(source(g, tm));
          out.push_back(g);
          loop.push_back(loops);
          point.push_back(internal::to_eigen(get(vpm, source(g, tm))));
        }
        ++loops;
      }
    }
    const int n = int(vertex.size());

    // Each border vertex's nearest candidate on another loop, by a sweep along x.
    std::vector<int> order(std::size_t(n), 0);
    for (int i = 0; i < n; ++i) order[std::size_t(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return point[a].x() < point[b].x() || (point[a].x() == point[b].x() && a < b);
    });
    std::vector<int> nearest(std::size_t(n), -1);
    std::vector<double> nearest_distance(std::size_t(n), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        const int a = order[i], b = order[j];
        if (point[b].x() - point[a].x() >= t) break;
        const double d = (point[a] - point[b]).norm();
        if (d >= t || loop[a] == loop[b]) continue;
        for (auto [u, w] : {std::pair<int, int>{a, b}, {b, a}})
          if (d < nearest_distance[u] || (d == nearest_distance[u] && w < nearest[u])) {
            nearest_distance[u] = d;
            nearest[u] = w;
          }
      }
    std::vector<int> partner(std::size_t(n), -1);
    for (int a = 0; a < n; ++a) {
      if (nearest[a] < 0) continue;
      if (nearest[nearest[a]] == a)
        partner[a] = nearest[a];
      else
        refuse(report, "ambiguous");  // its nearest candidate prefers another vertex
    }

    // Stitchable edge pairs: border edge a -> next(a) and the partners' edge, opposite ways.
    // Refusing a pair can leave a neighbour without an edge, so repeat until nothing changes.
    std::vector<int> next_on_loop(std::size_t(n), -1), previous_on_loop(std::size_t(n), -1);
    {
      std::map<Halfedge, int> index_of_out;
      for (int i = 0; i < n; ++i) index_of_out[out[i]] = i;
      for (int i = 0; i < n; ++i) {
        next_on_loop[i] = index_of_out.at(next(out[i], tm));
        previous_on_loop[next_on_loop[i]] = i;
      }
    }
    auto stitched = [&](int a) {  // the edge a -> next(a) meets its partners' edge
      const int b = next_on_loop[a];
      return partner[a] >= 0 && partner[b] >= 0 && next_on_loop[partner[b]] == partner[a];
    };
    for (bool changed = true; changed;) {
      changed = false;
      std::map<Vertex, Vertex> representative;
      for (int i = 0; i < n; ++i)
        if (partner[i] >= 0) representative[vertex[i]] = vertex[std::min(i, partner[i])];
      auto merged_neighbours = [&](int a) {
        std::vector<Vertex> around;
        for (Vertex w : CGAL::vertices_around_target(vertex[a], tm)) {
          const auto it = representative.find(w);
          around.push_back(it == representative.end() ? w : it->second);
        }
        std::sort(around.begin(), around.end());
        return around;
      };
      for (int a = 0; a < n; ++a) {
        if (partner[a] < 0 || a > partner[a]) continue;
        const int b = partner[a];
        const int stitched_edges = int(stitched(a)) + int(stitched(previous_on_loop[a]));
        // Each stitched edge makes its far ends one shared neighbour; any other shared neighbour
        // (or a and b being neighbours) gives the merged vertex two edges to one vertex.
        const std::vector<Vertex> around_a = merged_neighbours(a), around_b = merged_neighbours(b);
        std::vector<Vertex> shared;
        std::set_intersection(around_a.begin(), around_a.end(), around_b.begin(), around_b.end(),
                              std::back_inserter(shared));
        const bool adjacent = std::binary_search(around_a.begin(), around_a.end(), vertex[a]);
        const char* reason = stitched_edges == 0                               ? "pinch"
                             : adjacent || int(shared.size()) > stitched_edges ? "duplicate_edge"
                                                                               : nullptr;
        if (!reason) continue;
        refuse(report, reason);
        partner[a] = partner[b] = -1;
        changed = true;
      }
    }

    std::vector<std::pair<Halfedge, Halfedge>> to_stitch;
    for (int a = 0; a < n; ++a) {
      if (partner[a] < 0) continue;
      if (a < partner[a]) {
        const Eigen::Vector3d mid = 0.5 * (point[a] + point[partner[a]]);
        put(vpm, vertex[a], internal::to_point<Point>(mid));
        put(vpm, vertex[partner[a]], internal::to_point<Point>(mid));
        ++report.merged_pairs;
      }
      const int b = next_on_loop[a];
      if (stitched(a) && a < partner[b]) to_stitch.emplace_back(out[a], out[partner[b]]);
    }
    report.stitched_edges = CGAL::Polygon_mesh_processing::stitch_borders(tm, to_stitch);
    return report;
  }

 private:
  static void refuse(Border_pair_contraction_report& report, const std::string& reason) {
    ++report.refused_pairs;
    ++report.refused_by_reason[reason];
  }

  double m_relative_distance;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_BORDER_PAIR_CONTRACTION_H
