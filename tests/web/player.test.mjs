// The three.js player (app/web/visemelab-player.js) against the C++ runtime evaluator: the avatar is
// loaded with three's GLTFLoader (three from npm, in node), the track written by
// write_player_reference is played, and every mesh's morphTargetInfluences must equal the C++ key
// weights (written beside the track) at every sampled time within 1e-5, for linear, cubic and
// dominance blending, on the original avatar (full track) and on the reduced one in both name
// modes (reduced track, and the full track through merged names), and on a merged-name file of key
// table version 1 (written before 2026-11-28: every mesh repeating the table and listing every alias).
//   node player.test.mjs THREE_DIR REFERENCE_DIR AVATAR.glb MERGED.glb MERGED_V1.glb
import { existsSync, readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import path from 'node:path';

const [threeDir, referenceDir, avatarPath, mergedPath, mergedV1Path] = process.argv.slice(2);
if (!existsSync(path.join(threeDir, 'node_modules/three/package.json'))) {
  console.log(`SKIPPED: three is not installed in ${threeDir} (no npm registry?)`);
  process.exit(77);
}
const moduleUrl = (p) => pathToFileURL(path.resolve(p)).href;
const { GLTFLoader } = await import(moduleUrl(path.join(threeDir, 'node_modules/three/examples/jsm/loaders/GLTFLoader.js')));
const { MeshoptDecoder } = await import(moduleUrl(path.join(threeDir, 'node_modules/three/examples/jsm/libs/meshopt_decoder.module.js')));
const player = await import(moduleUrl(new URL('../../app/web/visemelab-player.js', import.meta.url).pathname));

let failures = 0, checks = 0;
const fail = (message) => { failures++; console.log(`FAIL ${message}`); };

async function loadAvatar(file) {
  const bytes = readFileSync(file);
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const loader = new GLTFLoader();
  loader.setMeshoptDecoder(MeshoptDecoder);
  // Node has no image decoding: textures are not needed to drive morph targets.
  loader.register(() => ({ name: 'no_textures', loadTexture: () => Promise.resolve(null) }));
  return new Promise((resolve, reject) => loader.parse(buffer, '', resolve, reject));
}

function morphMeshes(root) {
  const meshes = [];
  root.traverse((o) => { if (o.morphTargetInfluences && o.morphTargetDictionary) meshes.push(o); });
  return meshes;
}

// An independent statement of which target a key drives: by exact name, else the member's own name,
// else the target the mesh's extras.targetAliases give (key table version 2 lists only names the
// table does not resolve), else the first target on the mesh of the root table's key named so or
// listing a member (mesh extras.visemeKeys[k]: key k's targets), else the merged target whose
// '+'-joined name holds a member.
function meshUserData(mesh) {
  return mesh.userData.visemeKeys ? mesh.userData : (mesh.parent && mesh.parent.userData) || {};
}
function expectedTarget(mesh, key, table) {
  const dict = mesh.morphTargetDictionary;
  if (key.name in dict) return dict[key.name];
  for (const m of key.members) if (m in dict) return dict[m];
  const data = meshUserData(mesh);
  const aliases = data.targetAliases || {};
  for (const m of [key.name, ...key.members]) if (m in aliases) return aliases[m];
  const names = [key.name, ...key.members];
  const k = table ? table.keys.findIndex((t) => names.includes(t.name || t.members.join('+')) || t.members.some((m) => names.includes(m))) : -1;
  if (k >= 0 && data.visemeKeys && data.visemeKeys[k] && data.visemeKeys[k].length) return data.visemeKeys[k][0];
  for (const [name, index] of Object.entries(dict)) if (name.split('+').some((p) => key.members.includes(p))) return index;
  return -1;
}

function check(label, gltf, track, weights, face) {
  const scene = gltf.scene, table = gltf.userData.visemelab;
  const p = new player.VisemePlayer(gltf, track, { face });
  if (p.unbound.length) fail(`${label}: keys bound to no target: ${p.unbound.join(', ')}`);
  const meshes = morphMeshes(scene);
  const keys = track.playback[face].keys;
  let worst = 0;
  weights.times.forEach((t, row) => {
    const before = meshes.map((m) => Array.from(m.morphTargetInfluences));
    p.update(t);
    meshes.forEach((mesh, mi) => {
      const expected = Array.from(before[mi]);
      const driven = new Set(keys.map((k) => expectedTarget(mesh, k, table)).filter((x) => x >= 0));
      for (const target of driven) expected[target] = 0;
      keys.forEach((k, ki) => { const target = expectedTarget(mesh, k, table); if (target >= 0) expected[target] += weights[face][row][ki]; });
      expected.forEach((value, target) => {
        const diff = Math.abs(mesh.morphTargetInfluences[target] - value);
        worst = Math.max(worst, diff);
        checks++;
        if (diff > 1e-5) fail(`${label}: t = ${t}, mesh ${mesh.name}, target ${target}: ${mesh.morphTargetInfluences[target]} != ${value}`);
      });
    });
  });
  console.log(`${label}: ${weights.times.length} times on ${meshes.length} meshes, largest difference ${worst.toExponential(2)}`);
}

const original = await loadAvatar(avatarPath);
const reduced = await loadAvatar(path.join(referenceDir, 'reduced.glb'));
const merged = await loadAvatar(mergedPath);
const mergedV1 = await loadAvatar(mergedV1Path);
for (const blend of ['linear', 'cubic', 'dominance']) {
  const track = JSON.parse(readFileSync(path.join(referenceDir, `${blend}.track.json`), 'utf8'));
  const weights = JSON.parse(readFileSync(path.join(referenceDir, `${blend}.weights.json`), 'utf8'));
  check(`${blend}, original avatar, full track`, original, track, weights, 'full');
  check(`${blend}, reduced avatar (original names), reduced track`, reduced, track, weights, 'reduced');
  check(`${blend}, merged-name avatar, full track`, merged, track, weights, 'full');
  check(`${blend}, merged-name avatar of key table version 1, full track`, mergedV1, track, weights, 'full');
  // Given only the scene (no root table), the merged-name avatar binds every key as with the table.
  const withTable = new player.VisemePlayer(merged, track, { face: 'full' });
  const sceneOnly = new player.VisemePlayer(merged.scene, track, { face: 'full' });
  if (sceneOnly.unbound.length) fail(`${blend}: scene only: keys bound to no target: ${sceneOnly.unbound.join(', ')}`);
  sceneOnly.bindings.forEach((b, i) => {
    checks++;
    if (b.targets.join() !== withTable.bindings[i].targets.join()) fail(`${blend}: scene only binds ${b.mesh.name} otherwise`);
  });
  // Version 1 resolved every name on the meshes: a page passing only the scene keeps working.
  check(`${blend}, merged-name avatar of key table version 1 (scene only), full track`,
    { scene: mergedV1.scene, userData: {} }, track, weights, 'full');
  // The player's own choice: a VisemeLab-reduced avatar plays the reduced face (given the loader's
  // result, whose userData holds the key table, or only its scene, whose meshes list their keys).
  for (const given of [reduced, reduced.scene])
    if (new player.VisemePlayer(given, track).face !== 'reduced') fail(`${blend}: auto did not pick the reduced face`);
  if (new player.VisemePlayer(original, track).face !== 'full') fail(`${blend}: auto did not pick the full face`);
}
// The merged-name avatar as three.js loads it: names Blender keeps whole (<= 63 bytes), one key table
// at the root, and every original viseme name (members and resting visemes) resolving on every mesh
// that has its key: to the key's target, a resting viseme to its own zero target.
const table = merged.userData.visemelab;
if (!table || table.version !== 2) fail(`merged-name avatar: no key table version 2 at the root`);
const originalNames = table ? [...table.resting, ...table.keys.flatMap((k) => k.members)] : [];
for (const mesh of morphMeshes(merged.scene)) {
  for (const name of Object.keys(mesh.morphTargetDictionary))
    if (Buffer.byteLength(name, 'utf8') > 63) fail(`merged target name over 63 bytes: ${name}`);
  const lists = meshUserData(mesh).visemeKeys;
  if (!Array.isArray(lists)) { fail(`${mesh.name}: no visemeKeys`); continue; }
  for (const name of originalNames) {
    const k = table.keys.findIndex((key) => key.members.includes(name));
    const want = k < 0 ? mesh.morphTargetDictionary[name] : (lists[k] || [])[0];
    if (want === undefined) continue; // neither the key nor the resting viseme is on this mesh
    checks++;
    const got = player.targetOfKey(mesh, { name, members: [name] }, table);
    if (got !== want) fail(`${mesh.name}: ${name} resolves to ${got}, not ${want}`);
  }
}
// Spellings: every Oculus name in the forms players meet.
for (const [name, canonical] of [['viseme_aa', 'aa'], ['viseme_I', 'ih'], ['O', 'oh'], ['viseme_U', 'ou'], ['PP', 'PP'], ['jawOpen', null]])
  if (player.oculusVisemeOf(name) !== canonical) fail(`oculusVisemeOf(${name}) = ${player.oculusVisemeOf(name)}`);
console.log(`${checks - failures} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);
