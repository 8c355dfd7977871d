#!/usr/bin/python3
"""Our textured pipelines against gltfpack's -sv simplification (issue 30, docs/attributes.md,
"Against gltfpack").

usage: texture_vs_gltfpack.py BIN_DIR OUT_DIR [--tools DIR] [--samples N] [--repetitions N]

For data/spot.obj and data/bob_tri.obj at 10% and 2% of their faces: gltfpack -sv (pinned, npm,
installed into the tools folder as run.sh installs gltf-validator), then CGAL's gh and each of our
candidate runs to the face count gltfpack reached, every output measured against its input by
BIN_DIR/mesh_error --attributes. Prints one table; OUT_DIR keeps the outputs, their measurements
(table.json) and the table (table.md). Times: simplify's own total_seconds (no reading or
writing), gltfpack's wall time (npm's gltfpack is WebAssembly under node, reading and writing
included), each the least of --repetitions runs, over gh's. Exits 77 with one line when a tool is
missing, 1 when a run fails.
"""

import argparse
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import time

GLTFPACK = "gltfpack@1.3.0"
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MESHES = ["spot", "bob_tri"]
RATIOS = [0.1, 0.02]
# Our candidates: a name and simplify's options after IN OUT --faces N.
CANDIDATES = [
    ("attributes", ["--policy", "attributes"]),
    ("attributes+fit", ["--policy", "attributes", "--fit"]),
    ("lt+fit", ["--policy", "lt", "--fit"]),
    ("attributes+fit, uv 0.5, seam 10",
     ["--policy", "attributes", "--fit", "--uv-weight", "0.5", "--seam-weight", "10"]),
]
MISSING_TOOL = 77


def missing(line):
    print(f"texture_vs_gltfpack: {line}", file=sys.stderr)
    sys.exit(MISSING_TOOL)


def run(command):
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or [""])[-1]
        sys.exit(f"texture_vs_gltfpack: {' '.join(command)} exited {done.returncode}: {last}")
    return done.stdout


def gltfpack_in(tools):
    """The pinned gltfpack in `tools`, installed there by npm when it is not."""
    binary = os.path.join(tools, "node_modules", ".bin", "gltfpack")
    package = os.path.join(tools, "node_modules", "gltfpack", "package.json")
    version = GLTFPACK.split("@")[1]
    try:
        with open(package) as f:
            if json.load(f).get("version") == version:
                return binary
    except OSError:
        pass
    if not shutil.which("node") or not shutil.which("npm"):
        missing("node and npm are needed for gltfpack (run.sh installs them)")
    done = subprocess.run(["npm", "install", "--prefix", tools, "--no-audit", "--no-fund", GLTFPACK],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0 or not os.path.exists(binary):
        missing(f"npm could not install {GLTFPACK} into {tools}")
    return binary


def glb_faces(path):
    """The triangle count of a GLB gltfpack wrote (indexed triangle primitives)."""
    with open(path, "rb") as f:
        data = f.read()
    length, kind = struct.unpack_from("<I4s", data, 12)
    assert kind == b"JSON", path
    gltf = json.loads(data[20:20 + length])
    return sum(gltf["accessors"][p["indices"]]["count"] // 3 for mesh in gltf["meshes"]
               for p in mesh["primitives"] if p.get("mode", 4) == 4)


def wall_seconds(command, repetitions):
    """The least wall time of `repetitions` runs."""
    best = float("inf")
    for _ in range(repetitions):
        start = time.perf_counter()
        run(command)
        best = min(best, time.perf_counter() - start)
    return best


def gltfpack_command(gltfpack, original, packed, ratio):
    # -se 1 lifts gltfpack's error limit so that it goes for the ratio; -noq keeps float positions
    # and texture coordinates; -kv keeps texture coordinates no material uses (spot.obj has no
    # material library), so that -sv weighs them; -tr leaves the texture where it is.
    return [gltfpack, "-i", original, "-o", packed, "-si", str(ratio), "-se", "1", "-sv", "-noq",
            "-kv", "-tr"]


def check_v_flip(gltfpack, mesh_error, original, out_dir):
    """gltfpack's output at ratio 1 must carry the input's texture coordinates: glTF counts v from
    the top, and our reader turns it back; otherwise every uv figure below would be wrong."""
    packed = os.path.join(out_dir, "ratio_1.glb")
    run(gltfpack_command(gltfpack, original, packed, 1))
    uv = measure(mesh_error, original, packed, 10000)["uv"]
    if not uv < 1e-4:
        sys.exit(f"texture_vs_gltfpack: gltfpack's {original} at ratio 1 reads back {uv:g}% of "
                 "the texture off: the texture coordinates do not line up")


def simplify_seconds(command, repetitions):
    """simplify's own time (simplification and fit, not reading or writing), the least of
    `repetitions` runs, and the faces it wrote."""
    reports = [json.loads(run(command + ["--json", "--quiet"])) for _ in range(repetitions)]
    return min(r["total_seconds"] for r in reports), reports[-1]["output_faces"]


def measure(mesh_error, original, output, samples):
    e = json.loads(run([mesh_error, original, output, "--attributes", "--json", "--samples",
                        str(samples)]))
    return {
        "geo": 100 * (e["mean_a_to_b_rel"] + e["mean_b_to_a_rel"]) / 2,
        "uv": 100 * e["uv_mean_rel"],
        "flipped": e["flipped_uv_faces"],
        "seams": f"{e['seam_loops_a']} / {e['seam_loops_b']}",
        "seam_edges": f"{e['seam_edges_a']} / {e['seam_edges_b']}",
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bin_dir", help="the build's bin folder (simplify, mesh_error)")
    parser.add_argument("out_dir", help="where the outputs and the table go")
    parser.add_argument("--tools", default=os.path.join(REPO, "build", "tools"),
                        help="npm prefix for gltfpack (default: build/tools)")
    parser.add_argument("--samples", type=int, default=200000)
    parser.add_argument("--repetitions", type=int, default=3, help="timed runs; the least counts")
    args = parser.parse_args()

    simplify, mesh_error = (os.path.join(args.bin_dir, n) for n in ("simplify", "mesh_error"))
    for tool in (simplify, mesh_error):
        if not os.access(tool, os.X_OK):
            missing(f"{tool} is missing: build the targets simplify and mesh_error")
    gltfpack = gltfpack_in(os.path.abspath(args.tools))
    os.makedirs(args.out_dir, exist_ok=True)

    rows = []
    for name in MESHES:
        original = os.path.join(REPO, "data", f"{name}.obj")
        check_v_flip(gltfpack, mesh_error, original, args.out_dir)
        for ratio in RATIOS:
            stem = os.path.join(args.out_dir, f"{name}_{ratio:g}")
            packed = f"{stem}_gltfpack.glb"
            pack_seconds = wall_seconds(gltfpack_command(gltfpack, original, packed, ratio),
                                        args.repetitions)
            faces = glb_faces(packed)
            runs = [("gltfpack -sv", packed, pack_seconds, faces)]
            for label, options in [("gh", ["--policy", "gh"])] + CANDIDATES:
                out = f"{stem}_{re.sub(r'[^a-z0-9.]+', '_', label)}.obj"
                seconds, got = simplify_seconds([simplify, original, out, "--faces", str(faces)] +
                                                options, args.repetitions)
                runs.append((label, out, seconds, got))
            for label, out, seconds, got in runs:
                rows.append({"mesh": name, "ratio": ratio, "run": label, "faces": got,
                             "seconds": seconds, **measure(mesh_error, original, out, args.samples)})
            pack, gh = rows[-len(runs)], rows[-len(runs) + 1]
            for row in rows[-len(runs):]:
                row["geo_vs_gltfpack"] = row["geo"] / pack["geo"]
                row["uv_vs_gltfpack"] = row["uv"] / pack["uv"]
                row["time_vs_gh"] = row["seconds"] / gh["seconds"]

    header = ("| mesh | ratio | faces | run | geo mean (% of D) | geo / gltfpack | uv (% of extent) | "
              "uv / gltfpack | flipped | seam loops in / out | time / gh |\n"
              "|---|---:|---:|---|---:|---:|---:|---:|---:|---|---:|")
    lines = [header] + [
        f"| {r['mesh']} | {r['ratio']:g} | {r['faces']} | {r['run']} | {r['geo']:.4g} | "
        f"{r['geo_vs_gltfpack']:.2f} | {r['uv']:.4g} | {r['uv_vs_gltfpack']:.2f} | {r['flipped']} | "
        f"{r['seams']} | {r['time_vs_gh']:.2f} |" for r in rows
    ]
    table = "\n".join(lines)
    print(table)
    with open(os.path.join(args.out_dir, "table.md"), "w") as f:
        f.write(table + "\n")
    with open(os.path.join(args.out_dir, "table.json"), "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
