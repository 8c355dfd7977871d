// textured_obj IN.obj OUT.obj: the library's default pipeline on a textured OBJ, its seams kept.
#include <cgal_policies/Simplification_pipeline.h>
#include <cgal_policies/io/mesh_io.h>

#include <iostream>

int main(int argc, char** argv) try {
  namespace io = cgal_policies::io;
  if (argc != 3) return std::cerr << "usage: textured_obj IN.obj OUT.obj\n", 2;
  io::Read_report read;  // the materials, for OUT's mtllib
  io::Mesh mesh = io::read_triangle_mesh(argv[1], &read, io::Corner_attribute_reading::keep);
  cgal_policies::Simplification_options options;  // the default pipeline
  options.target = cgal_policies::Face_target::ratio(0.1);
  const cgal_policies::Simplification_report report = cgal_policies::simplify(mesh, options);
  io::write_mesh_atomically(mesh, argv[2], read.materials);
  std::cout << report.input_faces << " -> " << report.output_faces << " faces, corner attributes "
            << (report.attributes_carried ? "carried" : "none") << '\n';
} catch (const cgal_policies::io::Io_error& e) {
  using Kind = cgal_policies::io::Io_error::Kind;
  return std::cerr << e.what() << '\n', e.kind() == Kind::unreadable_input ? 3 : 4;
}
