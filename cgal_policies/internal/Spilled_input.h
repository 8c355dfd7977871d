// A source too large to hold whole (the concept is in Streamed_cut.h), read and cut as a streamed
// run cuts it (docs/scale.md): its points kept, its cells found on a sample of its centroids, its
// triangles spilled to a temporary file per cell. Simplification_pipeline::run_streamed simplifies
// the parts it gives; Simplification_pipeline::cut_streamed writes them down for a job.
#ifndef CGAL_POLICIES_INTERNAL_SPILLED_INPUT_H
#define CGAL_POLICIES_INTERNAL_SPILLED_INPUT_H

#include <cgal_policies/Simplification_options.h>
#include <cgal_policies/internal/Hausdorff_input_surface.h>
#include <cgal_policies/internal/Spatial_cells.h>
#include <cgal_policies/internal/Spill_files.h>
#include <cgal_policies/internal/Streamed_cut.h>
#include <cgal_policies/internal/run_partitioned.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace cgal_policies {
namespace internal {

template <class Point>
class Spilled_input {
 public:
  // Three passes over `source`, cut into the cells `options` ask for its face count.
  template <class Source>
  Spilled_input(const Source& source, const Simplification_options& options)
      : m_input(read_streamed_input<Point>(source)),
        m_cells(m_input.sample, options.cell_count(m_input.faces), options.threads),
        m_spills(m_cells.size(), streamed_corner_doubles<Point>(m_input.kinds)),
        m_vertex_cell(cut_into_spills(source, m_input, m_cells, m_spills)) {}

  std::size_t faces() const { return m_input.faces; }
  std::size_t vertices() const { return m_input.points.size(); }
  const Spatial_cells& cells() const { return m_cells; }
  double diagonal() const {
    return diagonal_length(CGAL::bbox_3(m_input.points.begin(), m_input.points.end()));
  }

  // The part of cell c (streamed_part()), of the cells spilled here or by spill_shifted().
  CGAL::Surface_mesh<Point> part(const Spill_files& spills, std::size_t c) const {
    return streamed_part(m_input.points, m_vertex_cell, spills.read(c), m_input.kinds);
  }
  const Spill_files& spills() const { return m_spills; }

  // The cells of the fit's second half, and the triangles spilled again into them, into files
  // that `to` makes.
  Spatial_cells shifted_cells(std::size_t threads) const {
    return internal::shifted_cells(m_input.sample, m_cells, threads);
  }
  void spill_shifted(const Spatial_cells& shifted, std::optional<Spill_files>& to) const {
    spill_again(m_input, m_spills, shifted, to.emplace(shifted.size(), m_spills.doubles()));
  }

 private:
  Streamed_input<Point> m_input;
  Spatial_cells m_cells;
  Spill_files m_spills;
  std::vector<std::uint32_t> m_vertex_cell;
};

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_SPILLED_INPUT_H
