#!/usr/bin/env bash
# The ctest test gltf_validator: simplify writes each shipped textured mesh (bob's map_Kd
# embedded), the vertex-colour PLY and glTF files other tools made (gltfpack, gltf-pipeline's
# Draco) as .glb and .gltf, bob with its texture missing, then bob with its texture as a data URI,
# then bob with a second set of texture coordinates (TEXCOORD_1) in each encoding, then bob
# skinned (JOINTS_0, WEIGHTS_0, three joints, an animation) in each encoding, alone and as levels,
# then with an unskinned prop under a joint (a fourth joint),
# then bob as a chain of levels of detail (--lod, MSFT_lod), then spot, the vertex-colour PLY and
# bob's chain in the quantized and meshopt encodings (--gltf-encoding), and the Khronos
# glTF-Validator (validate_gltf.mjs) must find no error in any of them; its warnings are printed.
# Exits 77, which ctest counts as skipped, without node or the validator, and in CI's sanitized
# pass (CGAL_POLICIES_SKIP_REAL_MESHES: the Release pass runs the real meshes).
#
#   validate_outputs.sh SIMPLIFY SOURCE_DIR NODE_MODULES WORK_DIR
set -euo pipefail
[ $# -eq 4 ] || { echo "usage: validate_outputs.sh SIMPLIFY SOURCE_DIR NODE_MODULES WORK_DIR" >&2; exit 2; }
simplify=$1 source=$2 modules=$3 work=$4
if [ -n "${CGAL_POLICIES_SKIP_REAL_MESHES+set}" ]; then
  echo "skipped: CGAL_POLICIES_SKIP_REAL_MESHES is set: real meshes run in Release only"
  exit 77
fi
if ! command -v node >/dev/null || [ ! -f "$modules/gltf-validator/package.json" ]; then
  echo "skipped: needs node and gltf-validator in $modules (./run.sh test installs both)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
outputs=()
for input in data/spot.obj data/bob_tri.obj data/spot_colors.ply \
             tests/apps/gltfpack/grid_quantized.glb tests/apps/draco/bob_draco.glb; do
  name=$(basename "${input%.*}")
  for extension in glb gltf; do
    "$simplify" "$source/$input" "$work/$name.$extension" 0.5 --quiet
    outputs+=("$work/$name.$extension")
  done
done
# bob with a material library whose map_Kd is not there: written without the texture.
cp "$source/data/bob_tri.obj" "$work/bob_missing.obj"
printf 'newmtl feathers\nmap_Kd missing.png\n' >"$work/bob_tri.mtl"
for extension in glb gltf; do
  "$simplify" "$work/bob_missing.obj" "$work/bob_missing.$extension" 0.5 --quiet
  outputs+=("$work/bob_missing.$extension")
done
# bob's output with its texture as a data URI instead, simplified again: the image is written
# into the GLB's buffer, and into the .gltf's.
node -e 'const fs = require("fs"), [gltf, png, out] = process.argv.slice(1);
  const g = JSON.parse(fs.readFileSync(gltf));
  g.images = [{uri: "data:image/png;base64," + fs.readFileSync(png).toString("base64")}];
  g.textures = [{source: 0}];
  g.materials[0].pbrMetallicRoughness = {baseColorTexture: {index: 0}};
  fs.writeFileSync(out, JSON.stringify(g));' \
  "$work/bob_tri.gltf" "$source/data/bob_diffuse.png" "$work/bob_textured_input.gltf"
for extension in glb gltf; do
  "$simplify" "$work/bob_textured_input.gltf" "$work/bob_textured.$extension" 0.5 --quiet
  outputs+=("$work/bob_textured.$extension")
done
# bob's output with a second set of texture coordinates (TEXCOORD_1, a copy of the first) that
# an occlusion texture reads, simplified again in each encoding: both sets are written.
node -e 'const fs = require("fs"), [gltf, out] = process.argv.slice(1);
  const g = JSON.parse(fs.readFileSync(gltf));
  for (const mesh of g.meshes)
    for (const p of mesh.primitives) p.attributes.TEXCOORD_1 = p.attributes.TEXCOORD_0;
  for (const m of g.materials)
    m.occlusionTexture = {index: m.pbrMetallicRoughness.baseColorTexture.index, texCoord: 1};
  fs.writeFileSync(out, JSON.stringify(g));' "$work/bob_tri.gltf" "$work/bob_lightmap_input.gltf"
for encoding in float quantized meshopt; do
  for extension in glb gltf; do
    "$simplify" "$work/bob_lightmap_input.gltf" "$work/bob_lightmap_$encoding.$extension" 0.5 \
      --quiet --gltf-encoding $encoding
    outputs+=("$work/bob_lightmap_$encoding.$extension")
  done
done
node -e 'const g = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (!("TEXCOORD_1" in g.meshes[0].primitives[0].attributes)) {
    console.error(`${process.argv[1]}: no TEXCOORD_1`);
    process.exit(1);
  }' "$work/bob_lightmap_float.gltf"
# bob's output skinned: three joints in a chain along x (hip, knee, foot), each vertex weighted by
# the Bernstein polynomials of its x, under a node moved by 5, which glTF ignores, and an animation
# that turns the knee. Simplified in each encoding, as one level and as a chain of levels: each
# file must hold the skin, its joints and the animation, every level's node skinned.
node -e 'const fs = require("fs"), [gltf, out] = process.argv.slice(1);
  const g = JSON.parse(fs.readFileSync(gltf));
  let bytes = Buffer.from(g.buffers[0].uri.split(",")[1], "base64");
  const append = (data, target) => {
    bytes = Buffer.concat([bytes, Buffer.alloc((4 - bytes.length % 4) % 4)]);
    g.bufferViews.push(Object.assign({buffer: 0, byteOffset: bytes.length, byteLength: data.length},
                                     target ? {target} : {}));
    bytes = Buffer.concat([bytes, data]);
    return g.bufferViews.length - 1;
  };
  const accessor = (view, componentType, type, count) =>
    g.accessors.push({bufferView: view, componentType, type, count}) - 1;
  const positions = g.accessors[g.meshes[0].primitives[0].attributes.POSITION];
  const low = positions.min[0], length = positions.max[0] - positions.min[0];
  const view = g.bufferViews[positions.bufferView];
  const count = positions.count, joints = Buffer.alloc(4 * count), weights = Buffer.alloc(16 * count);
  for (let v = 0; v < count; ++v) {
    const at = (view.byteOffset || 0) + (positions.byteOffset || 0) + v * (view.byteStride || 12);
    const t = (bytes.readFloatLE(at) - low) / length;
    [0, 1, 2].forEach((j) => joints.writeUInt8(j, 4 * v + j));
    [(1 - t) * (1 - t), 2 * t * (1 - t), t * t].forEach((w, j) => weights.writeFloatLE(w, 16 * v + 4 * j));
  }
  const matrices = Buffer.alloc(3 * 64);
  [0, 0.5, 1].forEach((along, j) => {
    [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -(low + along * length), 0, 0, 1].forEach(
      (c, k) => matrices.writeFloatLE(c, 64 * j + 4 * k));
  });
  for (const p of g.meshes[0].primitives) {
    p.attributes.JOINTS_0 = accessor(append(joints, 34962), 5121, "VEC4", count);
    p.attributes.WEIGHTS_0 = accessor(append(weights, 34962), 5126, "VEC4", count);
  }
  const first = g.nodes.length;
  g.nodes.push({name: "hip", translation: [low, 0, 0], children: [first + 1]},
               {name: "knee", translation: [length / 2, 0, 0], children: [first + 2]},
               {name: "foot", translation: [length / 2, 0, 0]});
  g.skins = [{joints: [first, first + 1, first + 2], skeleton: first,
              inverseBindMatrices: accessor(append(matrices, 0), 5126, "MAT4", 3)}];
  g.nodes[0].skin = 0;
  g.nodes[0].translation = [5, 0, 0];
  const times = Buffer.alloc(8), turn = Buffer.alloc(32);
  [0, 1].forEach((t, k) => times.writeFloatLE(t, 4 * k));
  [0, 0, 0, 1, 0, 0, 0.6, 0.8].forEach((c, k) => turn.writeFloatLE(c, 4 * k));
  const input = g.accessors.push({bufferView: append(times, 0), componentType: 5126, type: "SCALAR",
                                  count: 2, min: [0], max: [1]}) - 1;
  const output = accessor(append(turn, 0), 5126, "VEC4", 2);
  g.animations = [{name: "bend", samplers: [{input, output}],
                   channels: [{sampler: 0, target: {node: first + 1, path: "rotation"}}]}];
  g.scenes[0].nodes.push(first);
  g.buffers[0] = {byteLength: bytes.length,
                  uri: "data:application/octet-stream;base64," + bytes.toString("base64")};
  fs.writeFileSync(out, JSON.stringify(g));' "$work/bob_tri.gltf" "$work/bob_skinned_input.gltf"
for encoding in float quantized meshopt; do
  for extension in glb gltf; do
    "$simplify" "$work/bob_skinned_input.gltf" "$work/bob_skinned_$encoding.$extension" 0.5 \
      --quiet --gltf-encoding $encoding
    "$simplify" "$work/bob_skinned_input.gltf" "$work/bob_skinned_lod_$encoding.$extension" \
      --lod 0.5,0.25,0.1 --quiet --gltf-encoding $encoding
    outputs+=("$work/bob_skinned_$encoding.$extension" "$work/bob_skinned_lod_$encoding.$extension")
  done
  node -e 'const g = JSON.parse(require("fs").readFileSync(process.argv[1]));
    const names = (g.nodes || []).map((n) => n.name);
    const skinned = g.nodes.filter((n) => n.mesh !== undefined).every((n) => n.skin === 0);
    const bent = (g.animations || []).length === 1 &&
                 names[g.animations[0].channels[0].target.node] === "knee";
    if (!g.skins || g.skins[0].joints.length !== 3 || !names.includes("knee") || !skinned ||
        !("JOINTS_0" in g.meshes[0].primitives[0].attributes) || !bent) {
      console.error(`${process.argv[1]}: no skin, joints or knee animation, or a node not skinned`);
      process.exit(1);
    }' "$work/bob_skinned_lod_$encoding.gltf"
done
# The skinned bob with a second bob under the knee, unskinned (a prop): it rides on its node, which
# joins the skin as a fourth joint.
node -e 'const fs = require("fs"), [gltf, out] = process.argv.slice(1);
  const g = JSON.parse(fs.readFileSync(gltf));
  const knee = g.nodes.findIndex((n) => n.name === "knee");
  g.nodes.push({name: "prop", mesh: 0, translation: [0, 0, 2]});
  g.nodes[knee].children.push(g.nodes.length - 1);
  fs.writeFileSync(out, JSON.stringify(g));' "$work/bob_skinned_input.gltf" "$work/bob_prop_input.gltf"
for encoding in float quantized; do
  "$simplify" "$work/bob_prop_input.gltf" "$work/bob_prop_$encoding.gltf" 0.5 --quiet \
    --gltf-encoding $encoding
  outputs+=("$work/bob_prop_$encoding.gltf")
  node -e 'const g = JSON.parse(require("fs").readFileSync(process.argv[1]));
    const joints = g.skins ? g.skins[0].joints.map((j) => g.nodes[j].name) : [];
    if (JSON.stringify(joints) !== JSON.stringify(["hip", "knee", "foot", "prop"])) {
      console.error(`${process.argv[1]}: joints ${JSON.stringify(joints)}, expected the prop fourth`);
      process.exit(1);
    }' "$work/bob_prop_$encoding.gltf"
done
# A chain of levels of detail in one file (MSFT_lod), textured: bob with its map_Kd embedded; the
# finest level's node must name the three coarser ones.
for extension in glb gltf; do
  "$simplify" "$source/data/bob_tri.obj" "$work/bob_lod.$extension" --lod 0.5,0.25,0.1,0.03 --quiet
  outputs+=("$work/bob_lod.$extension")
done
node -e 'const g = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const ids = JSON.stringify(g.nodes[0].extensions.MSFT_lod.ids);
  if (ids !== "[1,2,3]" || g.nodes[0].extras.MSFT_screencoverage.length !== 4) {
    console.error(`${process.argv[1]}: MSFT_lod ids ${ids}, expected [1,2,3] and 4 coverages`);
    process.exit(1);
  }' "$work/bob_lod.gltf"
# The quantized (KHR_mesh_quantization) and meshopt-compressed (EXT_meshopt_compression)
# encodings: texture coordinates, colours, and a chain whose every level's node dequantizes its own
# positions.
for encoding in quantized meshopt; do
  for extension in glb gltf; do
    for input in data/spot.obj data/spot_colors.ply; do
      name=$(basename "${input%.*}")_$encoding.$extension
      "$simplify" "$source/$input" "$work/$name" 0.5 --quiet --gltf-encoding $encoding
      outputs+=("$work/$name")
    done
    "$simplify" "$source/data/bob_tri.obj" "$work/bob_lod_$encoding.$extension" \
      --lod 0.5,0.25,0.1,0.03 --quiet --gltf-encoding $encoding
    outputs+=("$work/bob_lod_$encoding.$extension")
  done
done
node "$(dirname "$0")/validate_gltf.mjs" --modules "$modules" "${outputs[@]}"
