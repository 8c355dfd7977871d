#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora (fuzz/corpus/) from small patches of the shipped meshes.

Each patch is the first faces reached by a breadth-first walk over shared vertices from face 0 of a
mesh in data/, written in every format a reader takes (OBJ with and without texture coordinates,
ASCII and binary PLY, OFF, ASCII and binary STL) and in the binary soup layout of fuzz_soup.h for
the repair and policy targets. Deterministic: running it again writes the same bytes.
Usage: fuzz/make_seeds.py (from anywhere; it finds the repository from its own path).
"""
import base64
import json
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "fuzz", "corpus")
MESHES = ["cow.obj", "fandisk.obj", "spot.obj", "teapot.obj", "woody.obj"]
PATCH_FACES = [12, 60, 200]
POLICIES = 16  # more than the registry holds: the policy byte is taken modulo its size
SETTINGS_BYTES = 64  # kSettingsBytes in policy_fuzzer.cpp


def read_obj(path):
    points, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                points.append(tuple(float(c) for c in parts[1:4]))
            elif parts[0] == "f":
                faces.append([int(c.split("/")[0]) - 1 for c in parts[1:]])
    return points, faces


def patch(points, faces, count):
    """The first `count` faces of a walk from face 0, with their points renumbered."""
    by_vertex = {}
    for i, face in enumerate(faces):
        for v in face:
            by_vertex.setdefault(v, []).append(i)
    seen, order, queue = {0}, [], [0]
    while queue and len(order) < count:
        f = queue.pop(0)
        order.append(f)
        for v in faces[f]:
            for g in by_vertex[v]:
                if g not in seen:
                    seen.add(g)
                    queue.append(g)
    index = {}
    for f in order:
        for v in faces[f]:
            index.setdefault(v, len(index))
    new_points = [None] * len(index)
    for old, new in index.items():
        new_points[new] = points[old]
    return new_points, [[index[v] for v in faces[f]] for f in order]


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def obj(points, faces, with_uv):
    lines = ["v %.6g %.6g %.6g" % p for p in points]
    if with_uv:
        lines += ["vt %.4g %.4g" % (p[0] % 1, p[1] % 1) for p in points]
        lines += ["f " + " ".join("%d/%d" % (v + 1, v + 1) for v in f) for f in faces]
    else:
        lines += ["f " + " ".join(str(v + 1) for v in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def ply_header(points, faces, form):
    return ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
            "end_header\n" % (form, len(points), len(faces))).encode()


def ply_ascii(points, faces):
    body = ["%.6g %.6g %.6g" % p for p in points]
    body += ["%d %s" % (len(f), " ".join(map(str, f))) for f in faces]
    return ply_header(points, faces, "ascii") + ("\n".join(body) + "\n").encode()


def ply_binary(points, faces):
    out = ply_header(points, faces, "binary_little_endian")
    out += b"".join(struct.pack("<3f", *p) for p in points)
    out += b"".join(struct.pack("<B%di" % len(f), len(f), *f) for f in faces)
    return out


def off(points, faces):
    lines = ["OFF", "%d %d 0" % (len(points), len(faces))]
    lines += ["%.6g %.6g %.6g" % p for p in points]
    lines += ["%d %s" % (len(f), " ".join(map(str, f))) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def triangles(points, faces):
    for f in faces:
        for i in range(1, len(f) - 1):
            yield points[f[0]], points[f[i]], points[f[i + 1]]


def stl_ascii(points, faces):
    lines = ["solid patch"]
    for a, b, c in triangles(points, faces):
        lines += ["facet normal %g %g %g" % normal(a, b, c), "outer loop"]
        lines += ["vertex %.6g %.6g %.6g" % p for p in (a, b, c)]
        lines += ["endloop", "endfacet"]
    lines.append("endsolid patch")
    return ("\n".join(lines) + "\n").encode()


def stl_binary(points, faces):
    tris = list(triangles(points, faces))
    out = b"patch".ljust(80, b" ") + struct.pack("<I", len(tris))
    for a, b, c in tris:
        out += struct.pack("<12fH", *normal(a, b, c), *a, *b, *c, 0)
    return out


def soup(points, faces):
    """fuzz_soup.h's layout: points on a 1/256 grid, scaled into [-64, 64]."""
    lo = [min(p[i] for p in points) for i in range(3)]
    span = max(max(p[i] for p in points) - lo[i] for i in range(3)) or 1
    out = struct.pack("<H", len(points))
    for p in points:
        out += struct.pack("<3h", *(int(round((p[i] - lo[i]) / span * 128 * 256 - 64 * 256))
                                    for i in range(3)))
    out += struct.pack("<H", len(faces))
    for f in faces:
        head = 0 if len(f) == 3 else 192 + len(f)
        out += struct.pack("<B%dH" % len(f), head, *f)
    return out


def policy_input(policy, passes, points, faces):
    settings = bytes((policy * 37 + i * 11 + passes) % 256 for i in range(SETTINGS_BYTES))
    return bytes([policy, passes]) + (bytes([3]) if passes & 1 else b"") + settings + \
        soup(points, faces)


def write(target, name, data):
    folder = os.path.join(CORPUS, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def skinned_gltf(path):
    """The glTF at `path` (one mesh, one node, its buffer a data URI) with its mesh on three nodes:
    two under skins that share a joint (hip-knee, knee-foot; weights along x), which put it in the
    same place, and one unskinned, a prop under the knee; an animation turns the knee. The reader
    merges the skins and the prop's node into one skin."""
    with open(path) as f:
        g = json.load(f)
    data = bytearray(base64.b64decode(g["buffers"][0]["uri"].split(",")[1]))

    def append(blob, target=None):
        data.extend(bytes((4 - len(data) % 4) % 4))
        view = {"buffer": 0, "byteOffset": len(data), "byteLength": len(blob)}
        if target:
            view["target"] = target
        data.extend(blob)
        g["bufferViews"].append(view)
        return len(g["bufferViews"]) - 1

    def accessor(view, component, kind, count, **bounds):
        g["accessors"].append(dict(bufferView=view, componentType=component, type=kind,
                                   count=count, **bounds))
        return len(g["accessors"]) - 1

    primitive = g["meshes"][0]["primitives"][0]
    positions = g["accessors"][primitive["attributes"]["POSITION"]]
    view = g["bufferViews"][positions["bufferView"]]
    low, high = positions["min"][0], positions["max"][0]
    joints, weights = b"", b""
    for v in range(positions["count"]):
        x = struct.unpack_from("<f", data, view.get("byteOffset", 0) + 12 * v)[0]
        t = (x - low) / (high - low)
        joints += struct.pack("<4B", 0, 1, 0, 0)
        weights += struct.pack("<4f", 1 - t, t, 0, 0)
    primitive["attributes"]["JOINTS_0"] = accessor(append(joints, 34962), 5121, "VEC4",
                                                   positions["count"])
    primitive["attributes"]["WEIGHTS_0"] = accessor(append(weights, 34962), 5126, "VEC4",
                                                    positions["count"])

    def binding(x):
        return struct.pack("<16f", 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -x, 0, 0, 1)

    middle = (low + high) / 2
    first = len(g["nodes"])
    hip, knee, foot, second, prop = range(first, first + 5)
    g["nodes"] += [{"name": "hip", "translation": [low, 0, 0], "children": [knee]},
                   {"name": "knee", "translation": [middle - low, 0, 0], "children": [foot, prop]},
                   {"name": "foot", "translation": [high - middle, 0, 0]},
                   {"name": "second", "mesh": 0, "skin": 1},
                   {"name": "prop", "mesh": 0, "translation": [0, 0, 2]}]
    g["nodes"][0]["skin"] = 0
    g["skins"] = [
        {"joints": [hip, knee], "inverseBindMatrices": accessor(
            append(binding(low) + binding(middle)), 5126, "MAT4", 2)},
        {"joints": [knee, foot], "inverseBindMatrices": accessor(
            append(binding(middle) + binding(high)), 5126, "MAT4", 2)}]
    times = accessor(append(struct.pack("<2f", 0, 1)), 5126, "SCALAR", 2, min=[0], max=[1])
    turn = accessor(append(struct.pack("<8f", 0, 0, 0, 1, 0, 0, 0.6, 0.8)), 5126, "VEC4", 2)
    g["animations"] = [{"name": "bend", "samplers": [{"input": times, "output": turn}],
                        "channels": [{"sampler": 0, "target": {"node": knee, "path": "rotation"}}]}]
    g["scenes"][0]["nodes"] += [hip, second]
    g["buffers"][0] = {"byteLength": len(data), "uri": "data:application/octet-stream;base64,"
                       + base64.b64encode(bytes(data)).decode()}
    return json.dumps(g, separators=(",", ":")).encode()


def naming_outside(path, what):
    """The glTF at `path` (its buffer a data URI) naming a file outside its folder: with `what`
    "buffer", a second buffer (the reader refuses the file); with "image", the base colour image
    of a material of its own (the reader leaves it out)."""
    with open(path) as f:
        gltf = json.load(f)
    if what == "buffer":
        gltf["buffers"].append({"uri": "../../../../../../etc/passwd", "byteLength": 12})
    else:
        gltf["images"] = [{"uri": "%2e%2e/%2e%2e/textures/skin.png"}]
        gltf["textures"] = [{"source": 0}]
        gltf["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
        for primitive in gltf["meshes"][0]["primitives"]:
            primitive["material"] = 0
    return json.dumps(gltf, separators=(",", ":")).encode()


def main():
    for mesh in MESHES:
        points, faces = read_obj(os.path.join(ROOT, "data", mesh))
        stem = os.path.splitext(mesh)[0]
        for count in PATCH_FACES:
            p, f = patch(points, faces, count)
            name = "%s_%d" % (stem, count)
            write("read_obj", name + ".obj", obj(p, f, False))
            write("read_obj", name + "_uv.obj", obj(p, f, True))
            write("read_ply", name + "_ascii.ply", ply_ascii(p, f))
            write("read_ply", name + "_binary.ply", ply_binary(p, f))
            write("read_off", name + ".off", off(p, f))
            write("read_stl", name + "_ascii.stl", stl_ascii(p, f))
            write("read_stl", name + "_binary.stl", stl_binary(p, f))
            write("repair", name + ".soup", soup(p, f))
        p, f = patch(points, faces, 60)
        for policy in range(POLICIES):
            passes = (policy * 29) % 256
            write("policies", "%s_60_policy%d" % (stem, policy), policy_input(policy, passes, p, f))
    for i, line in enumerate([
            "in.obj out.obj 0.1",
            "in.ply out.off --faces 500 --policy lt --json",
            "in.obj out.obj 0.05 --policy hausdorff --tolerance 0.01 --steps 8 --local",
            "in.off out.ply --ratio 0.2 --policy curvature --eps 0.5 --literal --measure --samples 1000",
            "in.obj out.obj 0.1 --policy fusion --mu 0.3 --visual-weight 2 --smooth 3 --smooth-rate 0.4",
            "in.stl out.stl 0.1 --policy fast --aggressiveness 7 --lossless --quiet --force",
            "in.obj out.obj 0.1 --policy classic --max-error 0.01 --smooth 2 --smooth-bounded --fit",
            "in.obj out.obj 0.1 --policy gh --fit --fit-rounds 3 --max-normal-angle 45",
            "in.obj out.obj 0.1 --min-component 10 --drop-small-pieces --time-limit 5",
            "in.obj out.obj --faces=100 --merge-distance=0.001 --smooth-weights inverse-distance "
            "--smooth-method taubin",
            "in.gltf out.glb 0.1 --asset-root . --gltf-encoding meshopt"]):
        write("command_line", "line%d" % i, line.replace(" ", "\0").encode())
    write("read_gltf", "bob_40_faces_skins.gltf",
          skinned_gltf(os.path.join(CORPUS, "read_gltf", "bob_40_faces.gltf")))
    woody = os.path.join(CORPUS, "read_gltf", "woody_20_faces.gltf")
    write("read_gltf", "woody_20_faces_buffer_outside.gltf", naming_outside(woody, "buffer"))
    write("read_gltf", "woody_20_faces_image_outside.gltf", naming_outside(woody, "image"))
    with open(os.path.join(CORPUS, "read_obj", "woody_12_uv.obj"), "rb") as f:
        write("read_obj", "woody_12_uv_libraries_outside.obj",
              b"mtllib ../../../../etc/passwd ..\\outside.mtl /etc/hostname\nusemtl a\n" + f.read())


if __name__ == "__main__":
    main()
