// The Python module cgal_policies._cgal_policies (docs/python.md): the library's one pipeline, the
// apps' readers, writers and evaluator, on numpy arrays or on a Mesh that carries the corner
// attributes. Options are read by the command line's code and the reports are simplify's and
// mesh_error's JSON objects, so that the module and the tools never disagree.
#include "Python_callbacks.h"
#include "Python_job.h"
#include "Python_mesh.h"
#include "keyword_options.h"
#include "simplify_report.h"

#include "cli/App_error.h"
#include "cli/Json_object.h"
#include "cli/report_fields.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "io/mesh_io.h"
#include "pipeline/Option_error.h"
#include "pipeline/Pipeline.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

namespace cgal_policies {
namespace python {
namespace {

// None, or any array-like (a list too) as an array.
std::optional<py::array> optional_array(const py::object& given) {
  if (given.is_none()) return std::nullopt;
  return py::module_::import("numpy").attr("asarray")(given).cast<py::array>();
}

// The run of simplify(), the GIL released while the pipeline works.
std::pair<Python_mesh, py::dict> simplify_mesh(
    Python_mesh mesh, const py::object& target_count, const py::object& target_reduction,
    const py::object& policy, const py::object& fit, const py::object& max_error,
    const py::object& threads, const py::object& progress, const py::kwargs& keywords) {
  const apps::Pipeline_request request = simplify_request(
      target_count, target_reduction, policy, fit, max_error, threads, py::dict(keywords));
  Simplification_options options = request.options;
  Python_callbacks callbacks(progress);
  callbacks.attach(options);
  const bool had_corner_values = Corner_attributes<io::Point>(mesh.mesh).any_corner_values();
  Simplification_report run;
  {
    py::gil_scoped_release released;
    run = apps::Pipeline(options).run(mesh.mesh);
  }
  callbacks.rethrow_if_raised();
  py::dict report = simplify_report(request, run, mesh.repairs, had_corner_values);
  return {std::move(mesh), std::move(report)};
}

py::dict measure(const Python_mesh& a, const Python_mesh& b, std::size_t samples) {
  if (samples < 1) throw py::value_error("samples must be at least 1");
  apps::Json_object report;
  {
    py::gil_scoped_release released;
    apps::add_fields(report, apps::measure_mesh_error(a.mesh, b.mesh, samples));
    apps::add_fields(report, apps::check_mesh_validity(b.mesh));
    apps::add_fields(report, apps::measure_attribute_error(a.mesh, b.mesh, samples));
  }
  return as_dict(report);
}

// Keyword spellings: `--min-component` is min_component.
std::string keyword(std::string name) {
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

py::dict policies() {
  py::dict all;
  for (const apps::Policy_entry& entry : apps::policy_registry()) {
    py::dict options;
    for (const apps::Policy_option& o : entry.options)
      options[py::str(keyword(o.name))] =
          py::dict(py::arg("default") = o.is_flag ? py::object(py::bool_(o.default_value != 0))
                                                  : py::object(py::float_(o.default_value)),
                   py::arg("min") = o.min, py::arg("max") = o.max,
                   py::arg("min_excluded") = o.min_is_excluded, py::arg("whole") = o.is_whole,
                   py::arg("flag") = o.is_flag, py::arg("help") = o.help);
    all[py::str(entry.name)] =
        py::dict(py::arg("summary") = entry.summary, py::arg("options") = options);
  }
  return all;
}

// What the mesh is read without (an image outside the asset folder, a morph target) is a
// UserWarning, as simplify prints it on stderr.
Python_mesh read(const std::filesystem::path& path,
                 const std::optional<std::filesystem::path>& asset_root) {
  io::Read_report read;
  io::Mesh mesh;
  {
    py::gil_scoped_release released;
    mesh = io::read_triangle_mesh(
        path.string(),
        {io::Corner_attribute_reading::keep, 1, asset_root ? asset_root->string() : std::string()},
        &read);
  }
  for (const std::string& line : read.left_out)
    if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0) throw py::error_already_set();
  return Python_mesh(std::move(mesh), std::move(read));
}

// A texture the file is written without is a UserWarning, as simplify prints it on stderr.
void write(const Python_mesh& mesh, const std::filesystem::path& path,
           const std::string& gltf_encoding) {
  const std::optional<io::Gltf_encoding> encoding = io::gltf_encoding_named(gltf_encoding);
  if (!encoding) throw py::value_error("gltf_encoding must be float, quantized or meshopt");
  if (*encoding != io::Gltf_encoding::float32 && !io::is_gltf_file(path.string()))
    throw py::value_error(path.string() + ": gltf_encoding needs a .gltf or .glb path");
  std::vector<std::string> left_out;
  {
    py::gil_scoped_release released;
    left_out = io::write_mesh_atomically(mesh.mesh, path.string(), mesh.references, *encoding);
  }
  for (const std::string& line : left_out)
    if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0) throw py::error_already_set();
}

void translate_errors(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const apps::App_error& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const apps::Option_error& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const io::Io_error& e) {
    PyErr_SetString(
        e.kind() == io::Io_error::Kind::unreadable_input ? PyExc_ValueError : PyExc_OSError,
        e.what());
  }
}

}  // namespace
}  // namespace python
}  // namespace cgal_policies

PYBIND11_MODULE(_cgal_policies, m) {
  namespace py = pybind11;
  using cgal_policies::python::Python_mesh;
  namespace python = cgal_policies::python;
  py::register_exception_translator(&python::translate_errors);

  py::class_<Python_mesh>(m, "Mesh", R"doc(
A triangle mesh with what a file can carry on its corners: texture coordinates, normals,
colours and each face's material, seams included (a vertex whose corners disagree lies on a
seam), and the materials the faces refer to outside it, so that a mesh read from an OBJ or glTF
file and written to one keeps them.

Every property returns a new array; the mesh itself does not change.
)doc")
      .def(py::init([](const py::array& vertices, const py::array& faces, const py::object& uv,
                       const py::object& normals, const py::object& colors,
                       const py::object& materials, std::vector<std::string> material_names,
                       std::vector<std::string> material_libraries) {
             return Python_mesh::from_arrays(
                 vertices, faces,
                 {python::optional_array(uv), python::optional_array(normals),
                  python::optional_array(colors), python::optional_array(materials),
                  std::move(material_names), std::move(material_libraries)});
           }),
           py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("uv") = py::none(),
           py::arg("normals") = py::none(), py::arg("colors") = py::none(),
           py::arg("materials") = py::none(),
           py::arg("material_names") = std::vector<std::string>(),
           py::arg("material_libraries") = std::vector<std::string>(), R"doc(
Builds a mesh as the file readers do once a file is parsed: `vertices` an (n, 3) float array,
`faces` an (m, 3) integer array of vertex indices. Corner values are per face and corner:
`uv` (m, 3, 2), `normals` (m, 3, 3), `colors` (m, 3, 4) RGBA in [0, 1], NaN where a corner has
none; `materials` (m,) indices into `material_names`, -1 for none; `material_libraries` the
.mtl files an OBJ output names. A soup that is not a clean triangle mesh is repaired (see
`repairs`; the repair drops the corner values). ValueError with the reader's message for bad
input: non-finite coordinates, an index out of range, no faces.
)doc")
      .def_property_readonly("vertices", &Python_mesh::vertices, "(n, 3) float64 positions.")
      .def_property_readonly("faces", &Python_mesh::faces,
                             "(m, 3) int64 vertex indices, counterclockwise.")
      .def_property_readonly("uv", &Python_mesh::uv,
                             "(m, 3, 2) texture coordinates per face corner, or None.")
      .def_property_readonly("normals", &Python_mesh::normals,
                             "(m, 3, 3) normals per face corner, or None.")
      .def_property_readonly("colors", &Python_mesh::colors,
                             "(m, 3, 4) RGBA colours per face corner, or None.")
      .def_property_readonly("materials", &Python_mesh::materials,
                             "(m,) index into material_names per face (-1: none), or None.")
      .def_property_readonly(
          "material_names", [](const Python_mesh& mesh) { return mesh.references.names; },
          "The material names that `materials` indexes.")
      .def_property_readonly(
          "material_libraries", [](const Python_mesh& mesh) { return mesh.references.libraries; },
          "The material libraries (.mtl paths) of the file read.")
      .def_property_readonly(
          "repairs", [](const Python_mesh& mesh) { return mesh.repairs; },
          "What the reader repaired, one phrase each; empty when nothing was.")
      .def("__repr__", [](const Python_mesh& mesh) {
        const cgal_policies::Corner_attributes<cgal_policies::io::Point> attributes(mesh.mesh);
        std::string kinds;
        for (const auto& [name, has] : {std::pair<const char*, bool>{"uv", bool(attributes.uvs)},
                                        {"normals", bool(attributes.normals)},
                                        {"colors", bool(attributes.colors)},
                                        {"materials", bool(attributes.materials)}})
          if (has) kinds += std::string(", ") + name;
        return "<cgal_policies.Mesh: " + std::to_string(mesh.mesh.number_of_vertices()) +
               " vertices, " + std::to_string(mesh.mesh.number_of_faces()) + " faces" + kinds + ">";
      });

  const char* const simplify_doc = R"doc(
Simplifies a triangle mesh with the library's pipeline (docs/pipeline.md), as the `simplify`
tool does: the same input and options give the same mesh, byte for byte once written.

simplify(vertices, faces, ...) -> (vertices, faces, report) takes and gives numpy arrays;
simplify(mesh, ...) -> (mesh, report) takes and gives a Mesh, whose texture coordinates,
normals, colours and materials are carried with their seams.

target_count      keep this many faces (simplify --faces)
target_reduction  remove this fraction of the faces, in [0, 1); the default keeps 10%
policy            one of policies(); none: the default pipeline (lt, then the fitting pass);
                  a policy named runs alone unless fit is True
fit               True: then fit the output to the input; False: never
max_error         stop before the two-sided Hausdorff distance to the input would exceed this
                  fraction of its bounding-box diagonal (edge-collapse policies)
threads           cores for a partitioned run (0: all); the output does not depend on it
progress          called with the fraction of the simplification done
**policy_options  the policy's options and the pipeline's other options, named as simplify's
                  command line names them with underscores for dashes: tolerance=0.005,
                  min_component=50, smooth=3, smooth_bounded=True, parts=4, ratio=0.1, ...

report is the object `simplify --json` prints, without the files. ValueError with the command
line's message for an unknown option or a value out of range. The GIL is released during the
work; Ctrl-C (KeyboardInterrupt) and an exception raised by `progress` stop the run and are
raised again, and nothing is returned.
)doc";
  m.def(
      "simplify",
      [](const py::array& vertices, const py::array& faces, const py::object& target_count,
         const py::object& target_reduction, const py::object& policy, const py::object& fit,
         const py::object& max_error, const py::object& threads, const py::object& progress,
         const py::kwargs& keywords) {
        auto [mesh, report] = python::simplify_mesh(Python_mesh::from_arrays(vertices, faces, {}),
                                                    target_count, target_reduction, policy, fit,
                                                    max_error, threads, progress, keywords);
        return py::make_tuple(mesh.vertices(), mesh.faces(), report);
      },
      py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("target_count") = py::none(),
      py::arg("target_reduction") = py::none(), py::arg("policy") = py::none(),
      py::arg("fit") = py::none(), py::arg("max_error") = py::none(),
      py::arg("threads") = py::none(), py::arg("progress") = py::none(), simplify_doc);
  m.def(
      "simplify",
      [](const Python_mesh& mesh, const py::object& target_count,
         const py::object& target_reduction, const py::object& policy, const py::object& fit,
         const py::object& max_error, const py::object& threads, const py::object& progress,
         const py::kwargs& keywords) {
        auto [result, report] = python::simplify_mesh(mesh, target_count, target_reduction, policy,
                                                      fit, max_error, threads, progress, keywords);
        return py::make_tuple(std::move(result), report);
      },
      py::arg("mesh"), py::kw_only(), py::arg("target_count") = py::none(),
      py::arg("target_reduction") = py::none(), py::arg("policy") = py::none(),
      py::arg("fit") = py::none(), py::arg("max_error") = py::none(),
      py::arg("threads") = py::none(), py::arg("progress") = py::none());

  py::class_<python::Python_job>(m, "PartitionedJob", R"doc(
A partitioned run (docs/scale.md) as tasks, each in whichever process or machine runs it, that
hand their work on through files in `folder`, a path they all see: cut(mesh) once; then, for
stage 0, 1, ..., run_part(stage, c) for each part c that cut counted (in any order, at once) and
stitch(stage), until stitch returns False; then result(mesh) where cut ran. Stage 0 simplifies
the parts, stages 1 and 2 run the fit by cells. The output is simplify()'s with the same options
(parts=... sets the cut), byte for byte once written. cgal_policies.dask.simplify runs it on a
Dask cluster.
)doc")
      .def(py::init([](const std::filesystem::path& folder, const py::object& target_count,
                       const py::object& target_reduction, const py::object& policy,
                       const py::object& fit, const py::object& max_error,
                       const py::object& threads, const py::kwargs& keywords) {
             return python::Python_job(
                 folder, python::simplify_request(target_count, target_reduction, policy, fit,
                                                  max_error, threads, py::dict(keywords)));
           }),
           py::arg("folder"), py::kw_only(), py::arg("target_count") = py::none(),
           py::arg("target_reduction") = py::none(), py::arg("policy") = py::none(),
           py::arg("fit") = py::none(), py::arg("max_error") = py::none(),
           py::arg("threads") = py::none(),
           "The job in `folder` (an empty folder) with simplify()'s options; ValueError as it.")
      .def("cut", &python::Python_job::cut, py::arg("mesh"),
           "Runs the repairs on a copy of `mesh`, cuts it into parts; returns their number.")
      .def("cut_file", &python::Python_job::cut_file, py::arg("path"),
           "Cuts the mesh file at `path` (binary PLY or OBJ) as cut() cuts a mesh, reading it in "
           "passes, never whole (points and triangles only); returns the number of parts.")
      .def("run_part", &python::Python_job::run_part, py::arg("stage"), py::arg("c"),
           "Runs part c of the stage: the policy on it (stage 0), or a half of the fit.")
      .def("stitch", &python::Python_job::stitch, py::arg("stage"),
           "Stitches the stage's parts; True when another stage follows.")
      .def("result", &python::Python_job::result, py::arg("mesh") = nullptr,
           "(mesh, report) as simplify(mesh) gives them; `mesh` the one given to cut(), None "
           "after cut_file().");

  m.def("read", &python::read, py::arg("path"), py::kw_only(), py::arg("asset_root") = py::none(),
        R"doc(
Reads a triangle mesh (.obj .off .ply .stl .gltf .glb) with its texture coordinates, normals,
colours and materials, polygons triangulated and soups repaired as the tools do (see
Mesh.repairs). ValueError with the reader's message when it cannot. The files the mesh's file
names (glTF buffers and images, OBJ material libraries and their textures) are read from its
folder and the folders below only, or from anywhere in asset_root, a folder holding it, for
trusted assets: a buffer from elsewhere is a ValueError, an image or a material library from
elsewhere a UserWarning, the mesh read without it.
)doc");
  m.def("write", &python::write, py::arg("mesh"), py::arg("path"), py::kw_only(),
        py::arg("gltf_encoding") = "float", R"doc(
Writes a mesh by its extension (.obj .off .ply .stl .gltf .glb), all or nothing: an OBJ, PLY or
glTF file keeps the corner attributes with their seams, an OBJ or glTF file the materials, a
glTF file an OBJ material's texture image, an OBJ file of a glTF mesh a material library and the
images the glTF file held, beside it (a UserWarning for an image that cannot be read or kept;
the file is written without it). OSError when the file cannot be written; nothing is left behind then.
gltf_encoding, for a glTF file, as simplify's --gltf-encoding: "float", "quantized"
(KHR_mesh_quantization) or "meshopt" (quantized, then EXT_meshopt_compression); ValueError for
another name or another kind of file.
)doc");
  m.def("measure", &python::measure, py::arg("a"), py::arg("b"), py::kw_only(),
        py::arg("samples") = apps::kDefaultErrorSamples, R"doc(
The two-sided Metro-style error between `a` (the reference) and `b`, the validity of `b`, and
the error of b's texture coordinates, normals and colours where both have them: the object
`mesh_error --json --attributes` prints (docs/evaluation.md). `samples` face samples per
direction; the same meshes give the same figures on every call.
)doc");
  m.def("policies", &python::policies, R"doc(
Every policy by name: its summary and its options by keyword, each with its default, range
(min, max, whether min is excluded, whether whole), whether it is a flag, and its help.
)doc");
}
