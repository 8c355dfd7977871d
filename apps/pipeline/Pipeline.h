// The library's Simplification_pipeline for the apps' mesh type. Its heavy parts (each policy's
// run, the fitting pass) are instantiated once, each policy family in its own source file so that
// they build in parallel (policies_*.cpp, pipeline.cpp); the declarations below keep every other
// translation unit from instantiating them again.
#ifndef CGAL_POLICIES_APPS_PIPELINE_PIPELINE_H
#define CGAL_POLICIES_APPS_PIPELINE_PIPELINE_H

#include "app_types.h"

#include <cgal_policies/Simplification_pipeline.h>

namespace apps {

using Pipeline = cgal_policies::Simplification_pipeline<Point>;

}  // namespace apps

// The runs of the policies, by family: policies_cgal.cpp, policies_classic.cpp, ...
#define CGAL_POLICIES_APPS_POLICY_RUN(name)                                                    \
  template cgal_policies::internal::Policy_outcome cgal_policies::internal::name<apps::Point>( \
      apps::Mesh&, std::size_t, const cgal_policies::Simplification_options&, const apps::Mesh*)

extern CGAL_POLICIES_APPS_POLICY_RUN(run_gh);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_gh_probabilistic);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_lt);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_classic);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_curvature);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_fusion);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_fast);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_flat_lt);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_hausdorff);
extern CGAL_POLICIES_APPS_POLICY_RUN(run_attributes);
// pipeline.cpp
extern template cgal_policies::Two_sided_fit_report
cgal_policies::internal::fit_carrying_corner_values<apps::Point>(
    apps::Mesh&, const apps::Mesh&, cgal_policies::Two_sided_fit_options,
    const std::function<bool(CGAL::SM_Vertex_index)>&);

#endif  // CGAL_POLICIES_APPS_PIPELINE_PIPELINE_H
