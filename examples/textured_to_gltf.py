"""Reads a textured OBJ, simplifies it with the library's default pipeline, writes glTF and prints
the error: python3 examples/textured_to_gltf.py data/spot.obj /tmp/spot.glb"""
import sys

import cgal_policies as cp

source, target = sys.argv[1:3]
mesh = cp.read(source)  # with its texture coordinates, normals and materials
simplified, report = cp.simplify(mesh, target_reduction=0.9)  # lt, then the fitting pass
cp.write(simplified, target)  # a .glb keeps the seams; an OBJ input's texture goes along
error = cp.measure(mesh, simplified, samples=50000)
print(f"{report['input_faces']} -> {report['output_faces']} faces, attributes "
      f"{report['attributes']}; mean error {100 * error['mean_a_to_b_rel']:.4f}% of the diagonal, "
      f"texture coordinates {100 * error['uv_mean_rel']:.4f}% of their extent")
