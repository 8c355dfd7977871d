// The fitting pass, instantiated once for the apps (Pipeline.h).
#include "Pipeline.h"

template cgal_policies::Two_sided_fit_report cgal_policies::internal::fit_carrying_corner_values<
    apps::Point>(apps::Mesh&, const apps::Mesh&, cgal_policies::Two_sided_fit_options,
                 const std::function<bool(CGAL::SM_Vertex_index)>&);
