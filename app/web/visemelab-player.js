// VisemeLab's speech player for three.js (and any scene graph whose meshes carry
// morphTargetInfluences and morphTargetDictionary): plays a `visemelab say` track on an avatar with
// the same blending as the C++ runtime (core/runtime/Animation.cpp: linear, Catmull-Rom cubic,
// dominance). Plain ES module, no imports, no build step.
//
//   import { VisemePlayer } from './visemelab-player.js';
//   const player = new VisemePlayer(gltf, track);   // gltf = GLTFLoader's result; track = the say --out JSON
//   function frame() { player.update(audio.currentTime); renderer.render(scene, camera); }
//
// Keys are bound to morph targets on every mesh by the names the file has: the key's own name, else
// a member's name (an avatar reduced with --names original keeps every viseme under its name, the
// members of a key sharing one shape), else a merged target whose '+'-joined name or extras list the
// member (--names merged, merged names at most 63 bytes, "viseme_PP+FF+TH": the key table resolves
// every original name, core/gltf/KeyTable.h), else the same Oculus viseme spelled another way
// (viseme_ prefix or not, I/O/U for ih/oh/ou, any case). Targets no key binds (blinks, brows) are left
// as they are. The key table is the glTF's root extras.visemelab, which three.js puts in the loader
// result's userData, not on the scene: pass the result (or a scene and { table }).

const OCULUS = ['sil', 'PP', 'FF', 'TH', 'DD', 'kk', 'CH', 'SS', 'nn', 'RR', 'aa', 'E', 'ih', 'oh', 'ou'];
const SPELLINGS = { i: 'ih', o: 'oh', u: 'ou' };

// The canonical Oculus name a target name stands for ("viseme_I" -> "ih"), or null.
export function oculusVisemeOf(name) {
  let base = String(name);
  if (base.toLowerCase().startsWith('viseme_')) base = base.slice(7);
  const lower = base.toLowerCase();
  if (SPELLINGS[lower]) return SPELLINGS[lower];
  for (const canonical of OCULUS) if (canonical.toLowerCase() === lower) return canonical;
  return null;
}

function smoothstep(s) {
  return s * s * (3 - 2 * s);
}

function upperIndex(keyframes, t) {
  // The index of the last keyframe with time <= t (t within the curve).
  let lo = 0, hi = keyframes.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (t < keyframes[mid].time) hi = mid; else lo = mid + 1;
  }
  return lo - 1;
}

// The runtime's KeyframeCurve: keyframes [{time, key, dominance}] (key -1 = rest) over keyCount keys.
export class KeyframeCurve {
  constructor(keyCount, keyframes, interpolation = 'cubic', dominanceRate = 25) {
    if (!['linear', 'cubic', 'dominance'].includes(interpolation))
      throw new Error(`interpolation must be linear, cubic or dominance, not '${interpolation}'`);
    if (!keyframes.length) throw new Error('no keyframes');
    keyframes.forEach((k, i) => {
      if (!Number.isFinite(k.time) || (i > 0 && !(k.time > keyframes[i - 1].time)))
        throw new Error(`keyframe ${i}: time does not increase`);
      if (k.key < -1 || k.key >= keyCount) throw new Error(`keyframe ${i}: key ${k.key} of ${keyCount}`);
    });
    this.keyCount = keyCount;
    this.keyframes = keyframes;
    this.interpolation = interpolation;
    this.dominanceRate = dominanceRate;
  }

  get startTime() { return this.keyframes[0].time; }
  get endTime() { return this.keyframes[this.keyframes.length - 1].time; }

  // Up to 4 [key, weight] terms summing to 1 (key -1: the rest pose), as KeyframeCurve::weightsAt.
  terms(t) {
    const k = this.keyframes, last = k.length - 1;
    if (this.interpolation === 'dominance') return this.dominanceTerms(Number.isNaN(t) ? -Infinity : t);
    if (!(t > k[0].time)) return [[k[0].key, 1]];
    if (t >= k[last].time) return [[k[last].key, 1]];
    const i = upperIndex(k, t);
    const t0 = k[i].time, t1 = k[i + 1].time, h = t1 - t0, s = (t - t0) / h;
    if (this.interpolation === 'linear') return [[k[i].key, 1 - s], [k[i + 1].key, s]];
    // Hermite basis with Catmull-Rom tangents (P_{i+1} - P_{i-1}) / (t_{i+1} - t_{i-1}), one-sided at the ends.
    const im1 = i > 0 ? i - 1 : i, ip2 = i + 2 <= last ? i + 2 : i + 1;
    const s2 = s * s, s3 = s2 * s;
    const h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    const a = (h10 * h) / (t1 - k[im1].time), b = (h11 * h) / (k[ip2].time - t0);
    return [[k[im1].key, -a], [k[i].key, h00 - b], [k[i + 1].key, h01 + a], [k[ip2].key, b]];
  }

  // Cohen and Massaro's dominance blend, each function tapered to the two keyframes on either side.
  dominanceTerms(t) {
    const k = this.keyframes, last = k.length - 1;
    t = Math.min(Math.max(t, k[0].time), k[last].time);
    const j = upperIndex(k, t);
    const first = j > 0 ? j - 1 : 0, end = Math.min(j + 2, last);
    const sinceJ = t - k[j].time;
    const nearest = j < last ? Math.min(sinceJ, k[j + 1].time - t) : sinceJ;
    const raw = [];
    let sum = 0;
    for (let i = first; i <= end; ++i) {
      let taper = 1;
      if (i >= 2 && t < k[i - 1].time) {
        const t0 = k[i - 2].time;
        taper = smoothstep((t - t0) / (k[i - 1].time - t0));
      } else if (i + 2 <= last && t > k[i + 1].time) {
        const t1 = k[i + 1].time;
        taper = 1 - smoothstep((t - t1) / (k[i + 2].time - t1));
      }
      const d = Math.fround(k[i].dominance) * taper * Math.exp(-this.dominanceRate * (Math.abs(t - k[i].time) - nearest));
      raw.push(d);
      sum += d;
    }
    return raw.map((d, n) => [k[first + n].key, d / sum]);
  }

  // The weight of every key at time t (the rest pose's share is 1 minus their sum).
  weightsAt(t) {
    const weights = new Float64Array(this.keyCount);
    for (const [key, w] of this.terms(t)) if (key >= 0) weights[key] += Math.fround(w);
    return weights;
  }
}

// The curve of one face ("full" or "reduced") of a track's playback section.
export function curveOfTrack(track, face = 'full') {
  const playback = track && track.playback;
  if (!playback) throw new Error('the track has no playback section: write it with visemelab say (VisemeLab 2026-11 or later)');
  const f = playback[face];
  if (!f) throw new Error(`the track has no '${face}' face`);
  const keyframes = f.keyframes.map(([time, key, dominance]) => ({ time, key, dominance }));
  return new KeyframeCurve(f.keys.length, keyframes, playback.interpolation, playback.dominanceRate);
}

// Every object below root that has morph targets (three.js meshes, each primitive its own mesh).
function morphMeshes(root) {
  const meshes = [];
  const visit = (o) => {
    if (o.morphTargetInfluences && o.morphTargetDictionary) meshes.push(o);
    for (const child of o.children || []) visit(child);
  };
  visit(root);
  return meshes;
}

// Extras of the glTF mesh a three.js primitive came from (on itself or, for several primitives,
// on the group above it).
function meshExtras(mesh) {
  const own = mesh.userData || {};
  if (own.visemeKeys || own.targetAliases) return own;
  const parent = mesh.parent && mesh.parent.userData;
  return parent && (parent.visemeKeys || parent.targetAliases) ? parent : own;
}

// The scene to drive and the root key table: `root` is GLTFLoader's result ({scene, userData}) or a
// scene (whose userData may carry the table, e.g. copied there by the page).
function avatarParts(root, table) {
  const scene = root && root.scene && !root.isObject3D ? root.scene : root;
  const data = (root && root.userData) || {};
  return { scene, table: table || data.visemelab || null };
}

const hasOwn = (object, name) => Object.prototype.hasOwnProperty.call(object, name);

// Key table version 2 (extras.visemelab version 2: mesh visemeKeys[k] = key k's targets on the mesh):
// the first target of the key that lists one of `names` as a member or is named by one of them.
function tableTarget(mesh, table, names) {
  const lists = meshExtras(mesh).visemeKeys;
  if (!table || !Array.isArray(table.keys) || !Array.isArray(lists)) return -1;
  for (let k = 0; k < table.keys.length && k < lists.length; ++k) {
    const key = table.keys[k] || {};
    const members = Array.isArray(key.members) ? key.members : [];
    const keyName = typeof key.name === 'string' ? key.name : members.join('+');
    if (!names.some((n) => n === keyName || members.includes(n))) continue;
    const target = Array.isArray(lists[k]) ? lists[k][0] : undefined;
    if (Number.isInteger(target) && target >= 0 && target < (mesh.morphTargetInfluences || []).length) return target;
  }
  return -1;
}

// The member names a merged target name (core/gltf/MergedNames.h) may stand for: its first part is a
// whole name, the others dropped the prefix all members share up to a separator ("viseme_PP+FF" ->
// viseme_PP, FF, viseme_FF), so that a scene without the key table still binds them.
function mergedMembersOf(name) {
  const [first, ...rest] = name.split('+');
  const prefixes = [...first].flatMap((c, i) => ('_.-: '.includes(c) ? [first.slice(0, i + 1)] : []));
  return [first, ...rest.flatMap((part) => [part, ...prefixes.map((p) => p + part)])];
}

// The target index key {name, members} drives on `mesh`, or -1; `table`: the root key table, if any.
export function targetOfKey(mesh, key, table = null) {
  const dict = mesh.morphTargetDictionary;
  if (hasOwn(dict, key.name)) return dict[key.name];
  const members = key.members && key.members.length ? key.members : [key.name];
  for (const m of members) if (hasOwn(dict, m)) return dict[m];
  // --names merged: the target a name now resolves to: the mesh's extras.targetAliases (version 1
  // lists every original name, version 2 only those the key table does not resolve), then the key
  // table, then (version 1) the mesh's visemeKeys that list the member, or a name joining it with '+'.
  // A resting viseme keeps its zero target under its own name.
  const extras = meshExtras(mesh);
  const aliases = extras.targetAliases || {};
  for (const name of [key.name, ...members])
    if (hasOwn(aliases, name) && Number.isInteger(aliases[name]) &&
        aliases[name] >= 0 && aliases[name] < (mesh.morphTargetInfluences || []).length) return aliases[name];
  const keyed = tableTarget(mesh, table, [key.name, ...members]);
  if (keyed >= 0) return keyed;
  for (const vk of extras.visemeKeys || [])
    if (vk && vk.members && vk.targets && vk.targets.length && members.some((m) => vk.members.includes(m))) return vk.targets[0];
  for (const [name, index] of Object.entries(dict))
    if (name.includes('+') && mergedMembersOf(name).some((part) => members.includes(part))) return index;
  // The same Oculus viseme under another spelling.
  const wanted = new Set(members.map(oculusVisemeOf).filter((v) => v));
  if (wanted.size === 0) return -1;
  for (const [name, index] of Object.entries(dict)) {
    const parts = name.split('+').map(oculusVisemeOf);
    if (parts.some((p) => p && wanted.has(p))) return index;
  }
  return -1;
}

export class VisemePlayer {
  // root: the avatar (GLTFLoader's result, or a scene); track: the say track JSON; face: 'full',
  // 'reduced' or 'auto' (reduced when the avatar or face was reduced by VisemeLab, i.e. its extras
  // name keys); table: the key table when root is a scene without it (gltf.userData.visemelab).
  constructor(root, track, { face = 'auto', table = null } = {}) {
    const parts = avatarParts(root, table);
    if (face === 'auto') face = VisemePlayer.isReducedAvatar(root) ? 'reduced' : 'full';
    this.face = face;
    this.curve = curveOfTrack(track, face);
    this.keys = track.playback[face].keys;
    this.bindings = []; // per mesh: {mesh, targets: target index per key, driven: targets to zero}
    for (const mesh of morphMeshes(parts.scene)) {
      const targets = this.keys.map((key) => targetOfKey(mesh, key, parts.table));
      const driven = [...new Set(targets.filter((t) => t >= 0))];
      if (driven.length) this.bindings.push({ mesh, targets, driven });
    }
    this.unbound = this.keys.filter((_, k) => !this.bindings.some((b) => b.targets[k] >= 0)).map((key) => key.name);
  }

  static isReducedAvatar(root) {
    const parts = avatarParts(root, null);
    let reduced = Boolean(parts.table);
    const visit = (o) => {
      const u = o.userData || {};
      if (u.visemelab || u.visemeKeys || u.targetMembers) reduced = true;
      for (const child of o.children || []) visit(child);
    };
    visit(parts.scene);
    return reduced;
  }

  get duration() { return this.curve.endTime; }

  // Sets the influences of every driven target for time t (seconds); returns the key weights.
  update(t) {
    const weights = this.curve.weightsAt(t);
    for (const { mesh, targets, driven } of this.bindings) {
      const influences = mesh.morphTargetInfluences;
      for (const target of driven) influences[target] = 0;
      targets.forEach((target, key) => { if (target >= 0) influences[target] += weights[key]; });
    }
    return weights;
  }
}
