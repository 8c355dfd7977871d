// An OBJ input's material libraries copied beside OBJ files written into another folder, so that
// the files name nothing outside their folder (docs/reliability.md, "What is written"): each
// library's text as it is, but for the texture files its lines name (map_Kd, map_Bump, bump, disp,
// decal, refl, ...), each named from the new folder when it lies in it, else copied beside.
#ifndef CGAL_POLICIES_IO_MATERIAL_LIBRARY_COPY_H
#define CGAL_POLICIES_IO_MATERIAL_LIBRARY_COPY_H

#include "mesh_io.h"

#include <string>
#include <vector>

namespace cgal_policies {
namespace io {

struct Material_library_copy {
  struct File {
    std::string path, bytes;
  };
  std::vector<std::string> names;     // the mtllib names of the libraries, from the OBJ's folder
  std::vector<File> files;            // the libraries, then the texture files copied
  std::vector<std::string> left_out;  // a line for each texture that could not be kept
  std::vector<std::string> sources;   // the input's files it copies (libraries, textures)
};

// The libraries of `materials` for OBJ files in the folder of `path`: a library in that folder (or
// below) is named as it is; any other is copied as `<stem>.mtl` (`<stem>_<k>.mtl` for the k-th
// when there are several), `path`'s stem. A texture a copied library names keeps its name when it
// lies in that folder and is copied as `<stem>_<its file name>` otherwise; one outside the asset
// folder (Material_references::asset_root), missing or unreadable loses its line, with a line in
// `left_out`. A library that cannot be read is left out likewise.
Material_library_copy material_library_copy(const Material_references& materials,
                                            const std::string& path);

// Io_error (unwritable output, "<file>: refusing to overwrite a file of the input") when one of
// `files` is one of `copy`'s sources.
void check_no_source_of(const Material_library_copy& copy, const std::vector<std::string>& files);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_MATERIAL_LIBRARY_COPY_H
