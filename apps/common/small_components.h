// Dirty scans: the specks and fragments around a scanned surface are connected components of
// their own, which edge collapses cannot shrink below a few faces each. simplify drops them
// whole, before the run (--min-component) or after it (--drop-small-pieces).
#ifndef CGAL_POLICIES_APPS_SMALL_COMPONENTS_H
#define CGAL_POLICIES_APPS_SMALL_COMPONENTS_H

#include "Mesh_types.h"

#include <cstddef>

namespace apps {

struct Dropped_components {
  std::size_t components = 0;
  std::size_t faces = 0;
};

// Removes every connected component of fewer than `min_faces` faces but the largest, so the mesh
// never ends empty; the mesh is left compact (garbage collected).
Dropped_components drop_components_smaller_than(Mesh& mesh, std::size_t min_faces);

// Removes connected components whole, smallest first (the first found among equals), while the
// mesh has more than `target_faces` faces; never the largest one. The mesh is left compact.
Dropped_components drop_smallest_components_until(Mesh& mesh, std::size_t target_faces);

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_SMALL_COMPONENTS_H
