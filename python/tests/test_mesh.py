"""Mesh: arrays in and out, the corner attributes through files, and bad input."""
import json
import struct

import numpy as np
import pytest

import cgal_policies as cp
from conftest import grid

TETRAHEDRON = (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float),
               np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]))


def test_arrays_come_back_as_given():
    mesh = cp.Mesh(*TETRAHEDRON)
    assert np.array_equal(mesh.vertices, TETRAHEDRON[0])
    assert np.array_equal(mesh.faces, TETRAHEDRON[1])
    assert mesh.uv is None and mesh.normals is None and mesh.colors is None
    assert mesh.materials is None and mesh.repairs == []
    assert repr(mesh) == "<cgal_policies.Mesh: 4 vertices, 4 faces>"


def test_corner_values_come_back_as_given():
    vertices, faces = TETRAHEDRON
    uv = np.arange(24, dtype=float).reshape(4, 3, 2) / 24
    uv[3, 2] = np.nan  # a corner without one
    mesh = cp.Mesh(vertices, faces, uv=uv, materials=[0, 1, -1, 0], material_names=["a", "b"])
    assert np.array_equal(mesh.uv, uv, equal_nan=True)
    assert np.array_equal(mesh.materials, [0, 1, -1, 0]) and mesh.material_names == ["a", "b"]
    assert repr(mesh).endswith("4 faces, uv, materials>")


def corner_rows(mesh):
    """Each corner's position and texture coordinates, sorted: the same for the same surface and
    texture however a format numbers its vertices."""
    rows = np.concatenate([mesh.vertices[mesh.faces], mesh.uv], axis=2).reshape(-1, 5)
    return rows[np.lexsort(rows.T[::-1])]


@pytest.mark.parametrize("name", ["spot.obj", "spot.glb", "spot.ply", "spot.gltf"])
def test_a_textured_round_trip_keeps_the_attributes(tmp_path, data, name):
    spot = cp.read(data / "spot.obj")
    cp.write(spot, tmp_path / name)
    back = cp.read(tmp_path / name)
    assert back.faces.shape == spot.faces.shape
    # glTF holds 32-bit floats.
    assert np.allclose(corner_rows(back), corner_rows(spot), rtol=0, atol=1e-6)
    if name.endswith(".obj"):  # numbered as read
        assert np.array_equal(back.vertices, spot.vertices)
        assert np.array_equal(back.faces, spot.faces) and np.array_equal(back.uv, spot.uv)
        assert back.material_names == spot.material_names
        assert np.array_equal(back.materials, spot.materials)


def test_an_obj_of_a_gltf_mesh_gets_its_material_library_and_image(tmp_path, data):
    """bob through a GLB (its PNG embedded), then to OBJ: the library and the PNG beside it."""
    cp.write(cp.read(data / "bob_tri.obj"), tmp_path / "bob.glb")
    bob = cp.read(tmp_path / "bob.glb")
    (tmp_path / "out").mkdir()
    cp.write(bob, tmp_path / "out" / "bob.obj")
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == \
        ["bob.mtl", "bob.obj", "bob_image0.png"]
    assert "mtllib bob.mtl\n" in (tmp_path / "out" / "bob.obj").read_text()
    assert (tmp_path / "out" / "bob.mtl").read_text().endswith(
        "newmtl feathers\nKd 1 1 1\nmap_Kd bob_image0.png\n")
    assert (tmp_path / "out" / "bob_image0.png").read_bytes() == \
        (data / "bob_diffuse.png").read_bytes()


def glb_json(path):
    """The JSON chunk of a .glb file: after the 12-byte header, its length, its type, then it."""
    data = path.read_bytes()
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A  # b"JSON" as a little-endian number
    return json.loads(data[20:20 + length])


@pytest.mark.parametrize("encoding, required", [
    ("quantized", ["KHR_mesh_quantization"]),
    ("meshopt", ["KHR_mesh_quantization", "EXT_meshopt_compression"])])
def test_a_gltf_is_written_quantized_or_compressed_on_request(tmp_path, encoding, required):
    vertices, faces = TETRAHEDRON
    uv = np.arange(24, dtype=float).reshape(4, 3, 2) / 24
    out = tmp_path / "tetrahedron.glb"
    cp.write(cp.Mesh(vertices, faces, uv=uv), out, gltf_encoding=encoding)
    assert glb_json(out)["extensionsRequired"] == required
    back = cp.read(out)
    # Within a step of the 16-bit grids over the unit box and over the texture.
    assert np.allclose(back.vertices[back.faces], vertices[faces], rtol=0, atol=1 / 65535)
    assert np.allclose(back.uv, uv, rtol=0, atol=1 / 65535)


def test_a_gltf_encoding_is_one_of_three_and_for_gltf_only(tmp_path):
    mesh = cp.Mesh(*TETRAHEDRON)
    with pytest.raises(ValueError, match="gltf_encoding must be float, quantized or meshopt"):
        cp.write(mesh, tmp_path / "out.glb", gltf_encoding="draco")
    with pytest.raises(ValueError, match=r"out\.obj: gltf_encoding needs a \.gltf or \.glb"):
        cp.write(mesh, tmp_path / "out.obj", gltf_encoding="quantized")
    assert list(tmp_path.iterdir()) == []


def test_simplify_carries_the_texture_with_its_seams(tmp_path, data):
    spot = cp.read(data / "spot.obj")
    simplified, report = cp.simplify(spot, target_reduction=0.9)
    assert report["attributes"] == "carried"
    assert simplified.uv.shape == (report["output_faces"], 3, 2)
    assert not np.isnan(simplified.uv).any()
    assert simplified.material_names == spot.material_names
    errors = cp.measure(spot, simplified, samples=20000)
    assert errors["valid"] is True and errors["uv_mean_rel"] < 0.01


def test_colours_survive_a_ply_round_trip(tmp_path, data):
    spot = cp.read(data / "spot_colors.ply")
    simplified, _ = cp.simplify(spot, ratio=0.2)
    cp.write(simplified, tmp_path / "out.ply")
    # A PLY file holds a byte per channel.
    assert np.allclose(cp.read(tmp_path / "out.ply").colors, simplified.colors, rtol=0,
                       atol=0.5 / 255 + 1e-12)


@pytest.mark.parametrize("vertices, faces, message", [
    (TETRAHEDRON[0], [[0, 1, 9]], "mesh: face 0 refers to vertex 9 but there are only 4"),
    ([[0, 0, np.inf], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], "mesh: non-finite coordinate at vertex 0"),
    (TETRAHEDRON[0], np.zeros((0, 3), dtype=int), "mesh: no faces"),
    (TETRAHEDRON[0], [[0.0, 1.0, 2.0]], "faces must be an (m, 3) array of integers"),
    (TETRAHEDRON[0][:, :2], [[0, 1, 2]], "vertices must be an (n, 3) array of floats"),
])
def test_bad_input_raises_the_readers_message(vertices, faces, message):
    with pytest.raises(ValueError) as raised:
        cp.simplify(np.asarray(vertices), np.asarray(faces))
    assert str(raised.value) == message


def test_bad_corner_arrays_are_refused():
    with pytest.raises(ValueError, match=r"uv must be an \(m, 3, 2\) array"):
        cp.Mesh(*TETRAHEDRON, uv=np.zeros((4, 3, 3)))
    with pytest.raises(ValueError, match="materials must index material_names"):
        cp.Mesh(*TETRAHEDRON, materials=[0, 0, 0, 1], material_names=["a"])


def test_a_repaired_soup_says_so():
    vertices, faces = grid(2)
    mesh = cp.Mesh(np.vstack([vertices, [[9, 9, 9]]]), faces)  # an unused point
    assert mesh.vertices.shape == (9, 3) and mesh.repairs == ["removed 1 unused vertices"]


def test_unreadable_files_raise_the_readers_message(tmp_path):
    (tmp_path / "bad.obj").write_text("v 0 0 0\nf 1 2 3\n")
    with pytest.raises(ValueError, match="bad.obj"):
        cp.read(tmp_path / "bad.obj")
    with pytest.raises(ValueError, match="missing.off"):
        cp.read(tmp_path / "missing.off")


def test_a_failed_write_leaves_nothing(tmp_path):
    mesh = cp.Mesh(*TETRAHEDRON)
    with pytest.raises(OSError):
        cp.write(mesh, tmp_path / "no_such_folder" / "out.obj")
    with pytest.raises(OSError):
        cp.write(mesh, tmp_path / "out.xyz")
    assert list(tmp_path.iterdir()) == []


def test_a_texture_left_out_of_a_gltf_is_a_warning(tmp_path, data):
    # bob's material library without its image: the GLB is written, without the texture.
    for name in ("bob_tri.obj", "bob_tri.mtl"):
        (tmp_path / name).write_bytes((data / name).read_bytes())
    mesh = cp.read(tmp_path / "bob_tri.obj")
    with pytest.warns(UserWarning, match=r"bob_tri\.mtl: texture 'bob_diffuse\.png' does not exist"):
        cp.write(mesh, tmp_path / "out.glb")
    assert (tmp_path / "out.glb").stat().st_size > 0
