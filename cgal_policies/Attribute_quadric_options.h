// Attribute_quadric_options: the settings of Attribute_quadric_policies (docs/attributes.md).
//   uv_weight      how much a texture-space error costs against a geometric one: 1 makes an error
//                  of 1% of the texture's extent cost as much as 1% of the mesh's bounding-box
//                  diagonal (>= 0; default default_uv_weight)
//   normal_weight  the same for normals: 1 makes a normal error of 0.01 (about 0.6 degrees) cost
//                  as much as 1% of the diagonal (>= 0; default default_normal_weight)
//   color_weight   the same for colours: 1 makes a colour error of 0.01 in each channel (of the
//                  range 0 to 1) cost as much as 1% of the diagonal (>= 0; default
//                  default_color_weight)
//   border_weight  weight of the plane through each border edge perpendicular to its face, times
//                  |e|^2 (>= 0; default default_border_weight)
//   seam_weight    the same for the two sides of each seam edge, so that a seam keeps its course
//                  across the surface as a border does (>= 0; default default_seam_weight)
// Usage:
//   cgal_policies::Attribute_quadric_options options;
//   options.uv_weight = 2;
//   cgal_policies::Attribute_quadric_policies<Mesh, Kernel> policies(mesh, options);
#ifndef CGAL_POLICIES_ATTRIBUTE_QUADRIC_OPTIONS_H
#define CGAL_POLICIES_ATTRIBUTE_QUADRIC_OPTIONS_H

#include <cgal_policies/Quadric_options.h>

namespace cgal_policies {

constexpr double default_uv_weight = 0.3;
constexpr double default_normal_weight = 0.01;
constexpr double default_color_weight = 0.005;
constexpr double default_seam_weight = 1.0;

struct Attribute_quadric_options {
  double uv_weight = default_uv_weight;
  double normal_weight = default_normal_weight;
  double color_weight = default_color_weight;
  double border_weight = default_border_weight;
  double seam_weight = default_seam_weight;
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_ATTRIBUTE_QUADRIC_OPTIONS_H
