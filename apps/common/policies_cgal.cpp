// CGAL's own policies, run as CGAL ships them (no extra filter), as the baselines
// (docs/evaluation.md); gh and gh-prob only step around one Debug precondition (below).
#include "edge_collapse_runner.h"
#include "policy_entries.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_probabilistic_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>

namespace SMS = CGAL::Surface_mesh_simplification;

namespace apps {
namespace {

const SMS::internal::Dummy_filter kNoFilter;

// CGAL's Garland-Heckbert policies, unchanged but for one precondition: a vertex whose faces all
// have zero area has a zero plane quadric, which CGAL's Debug builds refuse
// (GarlandHeckbert_policy_base.h) although the cost and the placement are well defined: the
// other vertex's quadric alone. Such an edge is priced and placed as CGAL's Release build does.
template <typename Policies>
class Zero_quadric_tolerant : public Policies {
 public:
  using Policies::Policies;

  const Zero_quadric_tolerant& get_cost() const { return *this; }
  const Zero_quadric_tolerant& get_placement() const { return *this; }

  template <typename Profile>
  boost::optional<typename Profile::FT> operator()(
      const Profile& profile, const boost::optional<typename Profile::Point>& placement) const {
    if (!placement || !has_zero_quadric(profile)) return Policies::operator()(profile, placement);
    const auto p = Policies::point_to_homogenous_column(*placement);
    return typename Profile::FT((p.transpose() * combined(profile) * p)(0, 0));
  }

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const {
    if (!has_zero_quadric(profile)) return Policies::operator()(profile);
    const auto optimum = Policies::construct_optimum(
        combined(profile), Policies::point_to_homogenous_column(profile.p0()),
        Policies::point_to_homogenous_column(profile.p1()));
    return typename Profile::Point(optimum(0) / optimum(3), optimum(1) / optimum(3),
                                   optimum(2) / optimum(3));
  }

 private:
  template <typename Profile>
  bool has_zero_quadric(const Profile& profile) const {
    return get(this->vcm(), profile.v0()).isZero(0) || get(this->vcm(), profile.v1()).isZero(0);
  }

  template <typename Profile>
  auto combined(const Profile& profile) const {
    return
        typename Policies::Mat_4(get(this->vcm(), profile.v0()) + get(this->vcm(), profile.v1()));
  }
};

template <typename Policies>
Simplify_outcome run_garland_heckbert(Mesh& mesh, const Simplify_settings& settings) {
  const Zero_quadric_tolerant<Policies> policies(mesh);
  return run_edge_collapse(mesh, settings, policies.get_cost(), policies.get_placement(),
                           kNoFilter);
}

Simplify_outcome run_lindstrom_turk(Mesh& mesh, const Simplify_settings& settings) {
  return run_edge_collapse(mesh, settings, SMS::LindstromTurk_cost<Mesh>(),
                           SMS::LindstromTurk_placement<Mesh>(), kNoFilter);
}

}  // namespace

std::vector<Policy_entry> cgal_baseline_policies() {
  return {
      {"gh",
       "CGAL GarlandHeckbert_plane_policies (classic QEM)",
       {},
       run_garland_heckbert<SMS::GarlandHeckbert_plane_policies<Mesh, Kernel>>},
      {"gh-prob",
       "CGAL GarlandHeckbert_probabilistic_plane_policies",
       {},
       run_garland_heckbert<SMS::GarlandHeckbert_probabilistic_plane_policies<Mesh, Kernel>>},
      {"lt", "CGAL LindstromTurk_cost and LindstromTurk_placement", {}, run_lindstrom_turk},
  };
}

}  // namespace apps
