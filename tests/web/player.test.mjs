// The three.js player (app/web/visemelab-player.js) against the C++ runtime evaluator: the avatar is
// loaded with three's GLTFLoader (three from npm, in node), the track written by
// write_player_reference is played, and every mesh's morphTargetInfluences must equal the C++ key
// weights (written beside the track) at every sampled time within 1e-5, for linear, cubic and
// dominance blending, on the original avatar (full track) and on the reduced one in both name
// modes (reduced track, and the full track through merged names).
//   node player.test.mjs THREE_DIR REFERENCE_DIR AVATAR.glb MERGED.glb
import { existsSync, readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import path from 'node:path';

const [threeDir, referenceDir, avatarPath, mergedPath] = process.argv.slice(2);
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
// else the target the mesh's extras.targetAliases give a member (merged names drop the members'
// shared prefix: "viseme_PP+FF"), else the merged target whose '+'-joined name holds a member.
function expectedTarget(mesh, key) {
  const dict = mesh.morphTargetDictionary;
  if (key.name in dict) return dict[key.name];
  for (const m of key.members) if (m in dict) return dict[m];
  const aliases = mesh.userData.targetAliases || (mesh.parent && mesh.parent.userData.targetAliases) || {};
  for (const m of [key.name, ...key.members]) if (m in aliases) return aliases[m];
  for (const [name, index] of Object.entries(dict)) if (name.split('+').some((p) => key.members.includes(p))) return index;
  return -1;
}

function check(label, scene, track, weights, face) {
  const p = new player.VisemePlayer(scene, track, { face });
  if (p.unbound.length) fail(`${label}: keys bound to no target: ${p.unbound.join(', ')}`);
  const meshes = morphMeshes(scene);
  const keys = track.playback[face].keys;
  let worst = 0;
  weights.times.forEach((t, row) => {
    const before = meshes.map((m) => Array.from(m.morphTargetInfluences));
    p.update(t);
    meshes.forEach((mesh, mi) => {
      const expected = Array.from(before[mi]);
      const driven = new Set(keys.map((k) => expectedTarget(mesh, k)).filter((x) => x >= 0));
      for (const target of driven) expected[target] = 0;
      keys.forEach((k, ki) => { const target = expectedTarget(mesh, k); if (target >= 0) expected[target] += weights[face][row][ki]; });
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
for (const blend of ['linear', 'cubic', 'dominance']) {
  const track = JSON.parse(readFileSync(path.join(referenceDir, `${blend}.track.json`), 'utf8'));
  const weights = JSON.parse(readFileSync(path.join(referenceDir, `${blend}.weights.json`), 'utf8'));
  check(`${blend}, original avatar, full track`, original.scene, track, weights, 'full');
  check(`${blend}, reduced avatar (original names), reduced track`, reduced.scene, track, weights, 'reduced');
  check(`${blend}, merged-name avatar, full track`, merged.scene, track, weights, 'full');
  // The player's own choice: a VisemeLab-reduced avatar plays the reduced face.
  if (new player.VisemePlayer(reduced.scene, track).face !== 'reduced') fail(`${blend}: auto did not pick the reduced face`);
  if (new player.VisemePlayer(original.scene, track).face !== 'full') fail(`${blend}: auto did not pick the full face`);
}
// The merged-name avatar as three.js loads it: names Blender keeps whole (<= 63 bytes), and every
// original viseme name resolving through the mesh's extras.targetAliases.
for (const mesh of morphMeshes(merged.scene)) {
  for (const name of Object.keys(mesh.morphTargetDictionary))
    if (Buffer.byteLength(name, 'utf8') > 63) fail(`merged target name over 63 bytes: ${name}`);
  const aliases = mesh.userData.targetAliases || (mesh.parent && mesh.parent.userData.targetAliases);
  if (!aliases || !Object.keys(aliases).length) { fail(`${mesh.name}: no targetAliases`); continue; }
  for (const [name, target] of Object.entries(aliases)) {
    checks++;
    if (!(target >= 0 && target < mesh.morphTargetInfluences.length)) fail(`${mesh.name}: alias ${name} -> ${target}`);
    if (player.targetOfKey(mesh, { name, members: [name] }) !== target) fail(`${mesh.name}: ${name} does not resolve to ${target}`);
  }
}
// Spellings: every Oculus name in the forms players meet.
for (const [name, canonical] of [['viseme_aa', 'aa'], ['viseme_I', 'ih'], ['O', 'oh'], ['viseme_U', 'ou'], ['PP', 'PP'], ['jawOpen', null]])
  if (player.oculusVisemeOf(name) !== canonical) fail(`oculusVisemeOf(${name}) = ${player.oculusVisemeOf(name)}`);
console.log(`${checks - failures} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);
