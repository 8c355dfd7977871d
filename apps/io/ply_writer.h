// The PLY writer for meshes that carry corner attributes (cgal_policies::Corner_attributes); CGAL
// 5.5's PLY writer writes points and faces alone.
#ifndef CGAL_POLICIES_IO_PLY_WRITER_H
#define CGAL_POLICIES_IO_PLY_WRITER_H

#include "Wedge_mesh.h"

#include <string>

namespace cgal_policies {
namespace io {

// The bytes of a binary little-endian PLY file with a vertex per wedge: x y z and, when the mesh
// has them, nx ny nz, s t (texture coordinates) and red green blue alpha (uchar, 0 to 255), all
// others as doubles so that reading back gives the same values; then the triangles as
// vertex_indices. PLY has no standard way to name materials, so they are not written, and none
// for a missing value: a corner without one is written as 0.
std::string ply_bytes(const Wedge_mesh& mesh);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_PLY_WRITER_H
