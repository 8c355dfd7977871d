// The names every layer of the apps shares: the io layer's mesh types and functions
// (cgal_policies::io, the package's installed io target), unqualified inside namespace apps.
#ifndef CGAL_POLICIES_APPS_APP_TYPES_H
#define CGAL_POLICIES_APPS_APP_TYPES_H

#include "io/Mesh_types.h"

namespace apps {

using namespace cgal_policies::io;

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_APP_TYPES_H
