// Laplacian_smoother: Laplacian smoothing after simplification ([Liu17] §2.4, eq. 8-9;
// docs/hausdorff.md). Each pass moves every interior vertex towards the weighted mean U of its
// neighbours, P <- P + lambda (U - P), weights 1 or w_i = 1 / |P - p_i| (eq. 8), with targets
// computed before the pass; border vertices stay. Taubin's variant [Taubin95] adds a pass of factor
// mu < 0 against shrinking. An optional allow_move(v, point), e.g. Hausdorff_move_guard, vets each
// move in vertex order. Points go through a vertex point map (default: the mesh's).
// Parameters:
//   rate        lambda in [0, 1] (default 0.5)
//   weights     Smoothing_weights::uniform (default) or Smoothing_weights::inverse_distance
//   method      Smoothing_method::laplacian (default) or Smoothing_method::taubin
//   mu          Taubin's inflating factor, negative (default -0.53)
//   iterations  passes of smooth(), >= 0
// Usage:
//   using cgal_policies::Smoothing_method;
//   using cgal_policies::Smoothing_weights;
//   cgal_policies::Laplacian_smoother<Mesh> smoother(0.5, Smoothing_weights::uniform,
//                                                    Smoothing_method::taubin);
//   smoother.smooth(mesh, 10);
#ifndef CGAL_POLICIES_LAPLACIAN_SMOOTHER_H
#define CGAL_POLICIES_LAPLACIAN_SMOOTHER_H

#include <cgal_policies/internal/mesh_geometry.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace cgal_policies {

enum class Smoothing_weights { uniform, inverse_distance };
enum class Smoothing_method { laplacian, taubin };

template <typename TriangleMesh>
class Laplacian_smoother {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

 public:
  explicit Laplacian_smoother(double rate = 0.5,
                              Smoothing_weights weights = Smoothing_weights::uniform,
                              Smoothing_method method = Smoothing_method::laplacian,
                              double mu = -0.53)
      : m_rate(rate), m_weights(weights), m_method(method), m_mu(mu) {
    CGAL_precondition(rate >= 0 && rate <= 1);
  }

  // Returns how many moves allow_move refused (a Taubin iteration is a lambda and a mu pass).
  template <typename AllowMove>
  std::size_t smooth(TriangleMesh& tm, int iterations, const AllowMove& allow_move) const {
    return smooth(tm, iterations, allow_move, get(CGAL::vertex_point, tm));
  }

  // The same, with the points read from and written to `vpm`.
  template <typename AllowMove, typename VertexPointMap>
  std::size_t smooth(TriangleMesh& tm, int iterations, const AllowMove& allow_move,
                     const VertexPointMap& vpm) const {
    CGAL_precondition(iterations >= 0);
    std::size_t refused = 0;
    for (int i = 0; i < iterations; ++i) {
      refused += pass(tm, vpm, m_rate, allow_move);
      if (m_method == Smoothing_method::taubin) refused += pass(tm, vpm, m_mu, allow_move);
    }
    return refused;
  }

  void smooth(TriangleMesh& tm, int iterations) const {
    smooth(tm, iterations, [](vertex_descriptor, const auto&) { return true; });
  }

 private:
  template <typename VertexPointMap, typename AllowMove>
  std::size_t pass(TriangleMesh& tm, const VertexPointMap& vpm, double factor,
                   const AllowMove& allow_move) const {
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    std::vector<std::pair<vertex_descriptor, Eigen::Vector3d>> targets;
    for (vertex_descriptor v : vertices(tm)) {
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge() ||
          CGAL::is_border(v, tm))
        continue;
      const Eigen::Vector3d p = internal::to_eigen(get(vpm, v));
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double total = 0;
      for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(v, tm), tm)) {
        const Eigen::Vector3d q = internal::to_eigen(get(vpm, w));
        const double length = (q - p).norm();
        if (m_weights == Smoothing_weights::inverse_distance && !(length > 0)) continue;
        const double weight = m_weights == Smoothing_weights::uniform ? 1.0 : 1.0 / length;
        sum += weight * q;
        total += weight;
      }
      if (total > 0) targets.emplace_back(v, p + factor * (sum / total - p));
    }
    std::size_t refused = 0;
    for (const auto& [v, target] : targets) {
      const Point point = internal::to_point<Point>(target);
      if (allow_move(v, point))
        put(vpm, v, point);
      else
        ++refused;
    }
    return refused;
  }

  double m_rate;
  Smoothing_weights m_weights;
  Smoothing_method m_method;
  double m_mu;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_LAPLACIAN_SMOOTHER_H
