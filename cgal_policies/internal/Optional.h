// The optional type CGAL's edge-collapse oracles exchange: boost::optional up to CGAL 5.6,
// std::optional from CGAL 6.0. Every policy names it through this one alias.
#ifndef CGAL_POLICIES_INTERNAL_OPTIONAL_H
#define CGAL_POLICIES_INTERNAL_OPTIONAL_H

#include <CGAL/version.h>

#if CGAL_VERSION_NR >= 1060000000
#include <optional>
#else
#include <boost/optional.hpp>
#endif

namespace cgal_policies {
namespace internal {

#if CGAL_VERSION_NR >= 1060000000
template <typename T>
using Optional = std::optional<T>;
#else
template <typename T>
using Optional = boost::optional<T>;
#endif

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_OPTIONAL_H
