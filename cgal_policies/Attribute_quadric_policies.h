// Attribute_quadric_policies: edge collapse under quadrics over position and corner attributes
// ([GH98], [Hoppe99]; docs/attributes.md). Each vertex keeps one quadric per wedge, a wedge being
// the corners of the vertex that share their texture coordinates, normal and colour: a vertex on a
// seam has several, and they merge only through the faces of the edge collapsed. A collapse between
// two free vertices solves the new position with the attributes at their best, then the attributes
// at it; elsewhere Corner_attribute_carrier's rules fix the point and the seam values, and the cost
// measures those. Without a carrier (carry_with) it is a plain area-weighted quadric policy with
// border planes.
// Models CGAL's `GetCost` and `GetPlacement` in one object with `Update_tag`, for a
// CGAL::Surface_mesh. Parameters: Attribute_quadric_options.
// Usage:
//   cgal_policies::Corner_attribute_carrier<Point> carrier(mesh);
//   cgal_policies::Attribute_quadric_policies<Mesh, Kernel> policies(mesh);
//   policies.carry_with(carrier);
//   SMS::edge_collapse(mesh, stop,
//       CGAL::parameters::get_cost(policies.get_cost())
//           .get_placement(cgal_policies::Seam_keeping_placement<Point, decltype(policies)>(
//               policies.get_placement(), &carrier))
//           .filter(cgal_policies::Seam_keeping_filter<Point, Filter>(filter, &carrier))
//           .visitor(a visitor calling carrier.collapsing and carrier.collapsed));
#ifndef CGAL_POLICIES_ATTRIBUTE_QUADRIC_POLICIES_H
#define CGAL_POLICIES_ATTRIBUTE_QUADRIC_POLICIES_H

#include <cgal_policies/Attribute_quadric_options.h>
#include <cgal_policies/Corner_attribute_carrier.h>
#include <cgal_policies/Face_weighting.h>
#include <cgal_policies/internal/Attribute_quadric.h>
#include <cgal_policies/internal/cgal_version.h>
#include <cgal_policies/internal/mesh_geometry.h>
#include <cgal_policies/internal/plane_quadrics.h>
#include <cgal_policies/internal/quadric_placement.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/tags.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace cgal_policies {

template <typename TriangleMesh, typename GeomTraits>
class Attribute_quadric_policies {
  using Point = typename GeomTraits::Point_3;
  static_assert(std::is_same_v<TriangleMesh, CGAL::Surface_mesh<Point>>,
                "corner attributes live on a CGAL::Surface_mesh");
  using Carrier = Corner_attribute_carrier<Point>;
  using Vertex = typename TriangleMesh::Vertex_index;
  using Halfedge = typename TriangleMesh::Halfedge_index;
  using Face = typename TriangleMesh::Face_index;
  using Quadric = internal::Quadric;
  using Attribute_quadric = internal::Attribute_quadric;
  using Values = Attribute_quadric::Attributes;

  struct Wedge {
    Values value;  // as stored on the corners (NaN where there is none)
    Attribute_quadric quadric;
  };
  using Wedges = boost::container::small_vector<Wedge, 1>;

  // The wedges of a collapse's two ends (v0's first), and the group each joins: wedges of v0 and
  // v1 on one face of the edge become one wedge of the kept vertex.
  struct Merge {
    const Wedges* ends[2];
    boost::container::small_vector<int, 8> group;
    int groups = 0;
  };

  // What a collapse about to happen leaves: each surviving face at v0 or v1 with the group of its
  // corner there.
  struct Pending {
    Vertex v0, v1;
    std::vector<Attribute_quadric> group_quadrics;
    std::vector<std::pair<Face, int>> faces;
  };

  struct State {
    explicit State(TriangleMesh& its_mesh, const Attribute_quadric_options& its_options)
        : mesh(&its_mesh), options(its_options) {
      wedges = mesh->template add_property_map<Vertex, Wedges>().first;
      border_quadrics = mesh->template add_property_map<Vertex, Quadric>().first;
    }
    ~State() {
      mesh->remove_property_map(wedges);
      mesh->remove_property_map(border_quadrics);
    }
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    TriangleMesh* mesh;
    Attribute_quadric_options options;
    Carrier* carrier = nullptr;
    Values scale = Values::Zero();  // attribute units to length units, weights included
    typename TriangleMesh::template Property_map<Vertex, Wedges> wedges;
    typename TriangleMesh::template Property_map<Vertex, Quadric> border_quadrics;
    std::optional<Pending> pending;
  };

 public:
  using Update_tag = CGAL::Tag_true;
  using Get_cost = Attribute_quadric_policies;
  using Get_placement = Attribute_quadric_policies;
  using FT = typename GeomTraits::FT;

  explicit Attribute_quadric_policies(TriangleMesh& tm,
                                      const Attribute_quadric_options& options = {})
      : m_state(std::make_shared<State>(tm, options)) {
    CGAL_precondition(options.uv_weight >= 0 && options.normal_weight >= 0 &&
                      options.color_weight >= 0 && options.border_weight >= 0);
  }

  const Get_cost& get_cost() const { return *this; }
  const Get_placement& get_placement() const { return *this; }

  // Puts the corner attributes of the carrier's mesh (the policy's) into the quadrics, and gives
  // the carrier the values of each free collapse. The second set of texture coordinates and the
  // skin influences have no term in the quadric: the carrier interpolates them. Call before
  // edge_collapse.
  void carry_with(Carrier& carrier) {
    const std::shared_ptr<State> state = m_state;
    state->carrier = &carrier;
    typename Carrier::Solver solver;
    solver.free_collapse_values = [state](Halfedge edge, const Point& x,
                                          typename Carrier::Values& values) {
      const TriangleMesh& mesh = *state->mesh;
      const Attribute_quadric quadric = state->wedges[mesh.source(edge)].front().quadric +
                                        state->wedges[mesh.target(edge)].front().quadric;
      const Values s = unscaled(*state, quadric.best_attributes(internal::to_eigen(x)));
      values.uv = {s[0], s[1]};
      const Eigen::Vector3d n = internal::unit_or_zero(Eigen::Vector3d(s[2], s[3], s[4]));
      const double none = std::numeric_limits<double>::quiet_NaN();
      using Vector = typename Carrier::Attributes::Vector;
      values.normal = n.norm() > 0 ? Vector(n.x(), n.y(), n.z()) : Vector(none, none, none);
      // Solved colours may leave [0, 1] a little where the fields of the faces disagree.
      for (int d = 0; d < 4; ++d) values.color[d] = std::clamp(s[5 + d], 0.0, 1.0);
    };
    solver.before_collapse = [state](Halfedge edge) { prepare_collapse(*state, edge); };
    carrier.solve_with(std::move(solver));
  }

  template <typename VertexPointMap>
  void initialize(const TriangleMesh& tm, const VertexPointMap& vpm, const GeomTraits&) const {
    State& state = *m_state;
    state.scale = attribute_scale(tm, vpm, state);
    for (Vertex v : vertices(tm)) {
      state.wedges[v].clear();
      state.border_quadrics[v] = Quadric();
    }
    for (Face f : faces(tm)) {
      std::array<Halfedge, 3> corners;
      std::array<Eigen::Vector3d, 3> p;
      std::array<Values, 3> s;
      int k = 0;
      for (Halfedge h : CGAL::halfedges_around_face(tm.halfedge(f), tm)) {
        corners[k] = h;
        p[k] = internal::to_eigen(get(vpm, tm.target(h)));
        s[k] = scaled(state, corner_value(state, h));
        ++k;
      }
      const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
      const Attribute_quadric quadric = Attribute_quadric::from_face(p, s, area);
      for (Halfedge h : corners) {
        Wedges& wedges = state.wedges[tm.target(h)];
        const Values value = corner_value(state, h);
        const int found = find_wedge(wedges, value);
        if (found < 0)
          wedges.push_back({value, quadric});
        else
          wedges[found].quadric += quadric;
        const bool on_border = tm.is_border(tm.opposite(h));
        if (!on_border && !(state.carrier && state.carrier->is_seam_edge(h))) continue;
        const Quadric border = internal::border_plane_quadric(
            h, tm, vpm, on_border ? state.options.border_weight : state.options.seam_weight,
            Face_weighting::area);
        state.border_quadrics[tm.source(h)] += border;
        state.border_quadrics[tm.target(h)] += border;
      }
    }
  }

  // Cost.
  template <typename Profile>
  internal::Optional<typename Profile::FT> operator()(
      const Profile& profile, const internal::Optional<typename Profile::Point>& placement) const {
    if (!placement) return {};
    const State& state = *m_state;
    const Eigen::Vector3d x = internal::to_eigen(*placement);
    const Merge merge = merged_wedges(state, profile.v0_v1());
    // The end whose point the collapse keeps, when its seam values are kept too.
    int fixed = -1;
    if (!is_free_collapse(state, profile)) {
      if (*placement == profile.p0()) fixed = 0;
      if (*placement == profile.p1()) fixed = 1;
    }
    double error = 0;
    for (int g = 0; g < merge.groups; ++g) {
      const Attribute_quadric quadric = group_quadric(merge, g);
      const Wedge* kept = fixed < 0 ? nullptr : wedge_in_group(merge, g, fixed);
      error += kept ? quadric.evaluate(x, scaled(state, kept->value))
                    : quadric.position_quadric().evaluate(x);
    }
    error += border_quadric(state, profile).evaluate(x);
    return typename Profile::FT((std::max)(0.0, error));
  }

  // Placement.
  template <typename Profile>
  internal::Optional<typename Profile::Point> operator()(const Profile& profile) const {
    const State& state = *m_state;
    const Merge merge = merged_wedges(state, profile.v0_v1());
    Quadric quadric = border_quadric(state, profile);
    for (int g = 0; g < merge.groups; ++g) quadric += group_quadric(merge, g).position_quadric();
    const internal::Quadric_placement choice = internal::optimal_placement(
        quadric, internal::to_eigen(profile.p0()), internal::to_eigen(profile.p1()));
    return internal::to_point<typename Profile::Point>(choice.point);
  }

  template <typename Profile>
  void update_after_collapse(const Profile& profile, Vertex kept) const {
    State& state = *m_state;
    TriangleMesh& mesh = *state.mesh;
    state.border_quadrics[kept] = border_quadric(state, profile);
    Wedges merged;
    if (state.pending && state.pending->v0 == profile.v0() && state.pending->v1 == profile.v1()) {
      // Each group becomes the wedge of the values its surviving faces now hold at `kept`.
      std::vector<std::vector<int>> added;  // the groups already in each new wedge
      for (const auto& [face, group] : state.pending->faces) {
        if (mesh.is_removed(face)) continue;
        Halfedge corner = mesh.halfedge(face);
        while (mesh.target(corner) != kept) corner = mesh.next(corner);
        const Values value = corner_value(state, corner);
        int found = find_wedge(merged, value);
        if (found < 0) {
          merged.push_back({value, Attribute_quadric()});
          added.emplace_back();
          found = int(merged.size()) - 1;
        }
        if (std::find(added[found].begin(), added[found].end(), group) != added[found].end())
          continue;
        added[found].push_back(group);
        merged[found].quadric += state.pending->group_quadrics[group];
      }
    } else {
      // No pending collapse: a collapse of zero length, after which every face keeps its values
      // (Corner_attribute_carrier::started), or no attributes (one wedge per vertex, all NaN).
      // The wedges of both ends merge by value.
      for (Vertex v : {profile.v0(), profile.v1()})
        for (const Wedge& w : state.wedges[v]) {
          const int found = find_wedge(merged, w.value);
          if (found < 0)
            merged.push_back(w);
          else
            merged[found].quadric += w.quadric;
        }
    }
    state.pending.reset();
    state.wedges[kept] = std::move(merged);
  }

 private:
  static bool same_values(const Values& a, const Values& b) {
    for (int j = 0; j < Values::RowsAtCompileTime; ++j)
      if (!(a[j] == b[j] || (std::isnan(a[j]) && std::isnan(b[j])))) return false;
    return true;
  }

  static int find_wedge(const Wedges& wedges, const Values& value) {
    for (std::size_t i = 0; i < wedges.size(); ++i)
      if (same_values(wedges[i].value, value)) return int(i);
    return -1;
  }

  // The values of a corner: texture coordinates, normal, colour; NaN without a carrier.
  static Values corner_value(const State& state, Halfedge h) {
    Values value = Values::Constant(std::numeric_limits<double>::quiet_NaN());
    if (!state.carrier || state.mesh->is_border(h)) return value;
    const auto corner = state.carrier->attributes().values(h);
    value << corner.uv[0], corner.uv[1], corner.normal.x(), corner.normal.y(), corner.normal.z(),
        corner.color[0], corner.color[1], corner.color[2], corner.color[3];
    return value;
  }

  // An attribute of weight 0 has no term: the carrier interpolates it.
  static Values scaled(const State& state, const Values& value) {
    Values s;
    for (int j = 0; j < Values::RowsAtCompileTime; ++j)
      s[j] =
          state.scale[j] > 0 ? value[j] * state.scale[j] : std::numeric_limits<double>::quiet_NaN();
    return s;
  }

  static Values unscaled(const State& state, const Values& s) {
    Values value;
    for (int j = 0; j < Values::RowsAtCompileTime; ++j)
      value[j] = s[j] / state.scale[j];  // NaN where the scale is 0: no term
    return value;
  }

  // Texture coordinates scaled so that the texture's extent spans the mesh's diagonal, normals and
  // colours so that a unit difference spans it, each times its weight.
  template <typename VertexPointMap>
  static Values attribute_scale(const TriangleMesh& tm, const VertexPointMap& vpm,
                                const State& state) {
    Eigen::AlignedBox3d box;
    for (Vertex v : vertices(tm)) box.extend(internal::to_eigen(get(vpm, v)));
    const double diagonal = box.isEmpty() ? 0 : box.diagonal().norm();
    const double uv_extent = state.carrier ? state.carrier->attributes().uv_extent(tm) : 0;
    Values scale = Values::Zero();
    if (uv_extent > 0) scale.head<2>().setConstant(state.options.uv_weight * diagonal / uv_extent);
    scale.segment<3>(2).setConstant(state.options.normal_weight * diagonal);
    scale.tail<4>().setConstant(state.options.color_weight * diagonal);
    return scale;
  }

  static Merge merged_wedges(const State& state, Halfedge v0_v1) {
    const TriangleMesh& mesh = *state.mesh;
    Merge merge;
    merge.ends[0] = &state.wedges[mesh.source(v0_v1)];
    merge.ends[1] = &state.wedges[mesh.target(v0_v1)];
    const int n0 = int(merge.ends[0]->size());
    boost::container::small_vector<int, 8> parent(std::size_t(n0) + merge.ends[1]->size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for (Halfedge h : {v0_v1, mesh.opposite(v0_v1)}) {
      if (mesh.is_border(h)) continue;
      // The face of h has its corner at target(h) on h and at source(h) on prev(h).
      const bool from_v0 = h == v0_v1;
      const Halfedge at_v0 = from_v0 ? mesh.prev(h) : h, at_v1 = from_v0 ? h : mesh.prev(h);
      const int w0 = find_wedge(*merge.ends[0], corner_value(state, at_v0));
      const int w1 = find_wedge(*merge.ends[1], corner_value(state, at_v1));
      if (w0 >= 0 && w1 >= 0) parent[root(w0)] = root(n0 + w1);
    }
    boost::container::small_vector<int, 8> group_of_root(parent.size(), -1);
    merge.group.resize(parent.size());
    for (std::size_t i = 0; i < parent.size(); ++i) {
      int& group = group_of_root[root(int(i))];
      if (group < 0) group = merge.groups++;
      merge.group[i] = group;
    }
    return merge;
  }

  static Attribute_quadric group_quadric(const Merge& merge, int g) {
    Attribute_quadric quadric;
    std::size_t i = 0;
    for (const Wedges* wedges : merge.ends)
      for (const Wedge& w : *wedges)
        if (merge.group[i++] == g) quadric += w.quadric;
    return quadric;
  }

  static const Wedge* wedge_in_group(const Merge& merge, int g, int end) {
    const std::size_t first = end == 0 ? 0 : merge.ends[0]->size();
    for (std::size_t k = 0; k < merge.ends[end]->size(); ++k)
      if (merge.group[first + k] == g) return &(*merge.ends[end])[k];
    return nullptr;
  }

  template <typename Profile>
  static bool is_free_collapse(const State& state, const Profile& profile) {
    return !state.carrier || (state.carrier->seam_edges_at(profile.v0()) == 0 &&
                              state.carrier->seam_edges_at(profile.v1()) == 0);
  }

  template <typename Profile>
  static Quadric border_quadric(const State& state, const Profile& profile) {
    return state.border_quadrics[profile.v0()] + state.border_quadrics[profile.v1()];
  }

  static void prepare_collapse(State& state, Halfedge v0_v1) {
    const TriangleMesh& mesh = *state.mesh;
    const Merge merge = merged_wedges(state, v0_v1);
    Pending pending{mesh.source(v0_v1), mesh.target(v0_v1), {}, {}};
    for (int g = 0; g < merge.groups; ++g)
      pending.group_quadrics.push_back(group_quadric(merge, g));
    for (int end = 0; end < 2; ++end) {
      const Vertex v = end == 0 ? pending.v0 : pending.v1;
      const std::size_t first = end == 0 ? 0 : merge.ends[0]->size();
      for (Halfedge h : CGAL::halfedges_around_target(v, mesh)) {
        if (mesh.is_border(h)) continue;
        const int w = find_wedge(*merge.ends[end], corner_value(state, h));
        if (w >= 0) pending.faces.emplace_back(mesh.face(h), merge.group[first + std::size_t(w)]);
      }
    }
    state.pending = std::move(pending);
  }

  std::shared_ptr<State> m_state;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_ATTRIBUTE_QUADRIC_POLICIES_H
