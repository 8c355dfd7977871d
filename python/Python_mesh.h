// A mesh as the Python module hands it around: the apps' Surface_mesh with its corner attributes
// (texture coordinates, normals, colours and materials, seams included), the materials its faces
// refer to outside it (so that an OBJ or glTF written from it keeps them), and what the reader
// repaired. The numpy views are copies: the C++ mesh stays the one source of truth.
#ifndef CGAL_POLICIES_PYTHON_PYTHON_MESH_H
#define CGAL_POLICIES_PYTHON_PYTHON_MESH_H

#include "io/mesh_io.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

namespace cgal_policies {
namespace python {

namespace py = pybind11;

class Python_mesh {
 public:
  // Corner values given per face and corner, (m, 3, k) arrays; NaN where a corner has none. A
  // material is an index into `material_names`, -1 for none.
  struct Corner_arrays {
    std::optional<py::array> uv, normals, colors, materials;
    std::vector<std::string> material_names, material_libraries;
  };

  Python_mesh() = default;
  Python_mesh(io::Mesh mesh, io::Read_report read);

  // Builds the mesh as the file readers do once they have parsed a file
  // (io::triangle_mesh_from_soup): ValueError with the reader's message for bad input, repairs
  // recorded. The arrays are read once, the GIL released while the mesh is built.
  static Python_mesh from_arrays(const py::array& vertices, const py::array& faces,
                                 const Corner_arrays& corners);

  py::array_t<double> vertices() const;
  // Each face's corners in the order the writers give them: the targets of halfedge(f), next,
  // next of next; the corner arrays below follow it.
  py::array_t<std::int64_t> faces() const;
  std::optional<py::array_t<double>> uv() const;
  std::optional<py::array_t<double>> normals() const;
  std::optional<py::array_t<double>> colors() const;
  std::optional<py::array_t<std::int64_t>> materials() const;

  io::Mesh mesh;  // compact: no garbage
  io::Material_references references;
  std::vector<std::string> repairs;
};

}  // namespace python
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_PYTHON_PYTHON_MESH_H
