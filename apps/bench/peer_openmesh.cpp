// OpenMesh's Decimater with its quadric module (priority) and normal-flipping module (refuses a
// collapse that turns a face normal by more than the settings' angle). Initialisation and
// decimation are timed; the conversions to and from OpenMesh are not.
#include "bench_peers.h"
#include "cli/Stopwatch.h"
#include "peer_mesh.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

namespace apps {
namespace {

// As this suite's policies refuse by default (cgal_policies::Simplification_options).
constexpr double kMaxNormalAngleDeg = 90;

// Double precision, so that the peer sees the same coordinates as the other policies.
struct Open_mesh_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Open_mesh = OpenMesh::TriMesh_ArrayKernelT<Open_mesh_traits>;

Bench_run run_openmesh(Mesh& mesh, const Bench_settings& settings) {
  const Indexed_triangles input = to_indexed_triangles(mesh);
  Open_mesh om;
  std::vector<Open_mesh::VertexHandle> handles;
  for (const Point& p : input.points) handles.push_back(om.add_vertex({p.x(), p.y(), p.z()}));
  for (const auto& t : input.triangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  om.request_face_normals();
  om.update_face_normals();

  Bench_run outcome;
  const Stopwatch watch;
  {
    OpenMesh::Decimater::DecimaterT<Open_mesh> decimater(om);
    OpenMesh::Decimater::ModQuadricT<Open_mesh>::Handle quadric;
    OpenMesh::Decimater::ModNormalFlippingT<Open_mesh>::Handle flipping;
    decimater.add(quadric);
    decimater.add(flipping);
    decimater.module(flipping).set_max_normal_deviation(kMaxNormalAngleDeg);
    decimater.initialize();
    decimater.decimate_to_faces(0, settings.target_faces);
    outcome.seconds = watch.seconds();
    om.garbage_collection();  // while the decimater still holds the status flags it marked
  }

  Indexed_triangles result;
  for (const auto v : om.vertices()) {
    const Open_mesh::Point& p = om.point(v);
    result.points.emplace_back(p[0], p[1], p[2]);
  }
  for (const auto f : om.faces()) {
    std::array<std::uint32_t, 3> t{};
    std::size_t i = 0;
    for (const auto v : f.vertices()) t[i++] = std::uint32_t(v.idx());
    result.triangles.push_back(t);
  }
  outcome.stop_reason = adopt_peer_result(result, settings.target_faces, mesh);
  return outcome;
}

}  // namespace

std::vector<Bench_row> openmesh_peers() {
  return {
      {"openmesh", "OpenMesh Decimater with ModQuadric and ModNormalFlipping", {}, run_openmesh}};
}

}  // namespace apps
