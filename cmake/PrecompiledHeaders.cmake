# Precompiled headers: most of a translation unit's compile time here is parsing CGAL, Eigen and
# Boost, the same headers in every unit (docs/architecture.md, "Build times"). A library of several
# units precompiles them once for itself; the tests, one unit each, share one precompiled header
# per set of compile options. The library's own headers are never precompiled, and header_check
# compiles each public header without them, so that a header missing an include still fails.
option(CGAL_POLICIES_PRECOMPILE_HEADERS "Precompile the CGAL, Eigen and standard headers" ON)

set(CGAL_POLICIES_PRECOMPILED_HEADERS
    <CGAL/Exact_predicates_inexact_constructions_kernel.h>
    <CGAL/Surface_mesh.h>
    <CGAL/boost/graph/helpers.h>
    <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
    <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
    <Eigen/Dense>
    <algorithm>
    <array>
    <functional>
    <map>
    <memory>
    <optional>
    <string>
    <unordered_map>
    <vector>)

# `target` precompiles the headers for itself.
function(cgal_policies_precompile_headers target)
  if(CGAL_POLICIES_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE ${CGAL_POLICIES_PRECOMPILED_HEADERS})
  endif()
endfunction()

# `target` uses the headers `host` precompiled: both must compile with the same options.
function(cgal_policies_reuse_precompiled_headers target host)
  if(CGAL_POLICIES_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} REUSE_FROM ${host})
  endif()
endfunction()
