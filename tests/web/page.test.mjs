// The page `visemelab say --html` writes, in headless chromium: screenshots with the face frozen at
// the middle of an open vowel, at the middle of a pause, and at rest (every weight 0). At the pause
// the face must look like the rest pose and at the vowel it must not (the mouth opens): judged on the
// pixels (PNG decoded here) of the region where the two differ at all.
//   node page.test.mjs PAGE.html TRACK.json OUT_DIR
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, existsSync } from 'node:fs';
import { inflateSync } from 'node:zlib';
import path from 'node:path';

const [page, trackPath, outDir] = process.argv.slice(2);
const chromium = ['chromium', 'chromium-browser'].find((c) => {
  try { execFileSync('sh', ['-c', `command -v ${c}`]); return true; } catch { return false; }
});
if (!chromium) { console.log('SKIPPED: chromium not found (apt-get install chromium)'); process.exit(77); }
mkdirSync(outDir, { recursive: true });

function screenshot(hash, file) {
  const out = path.join(outDir, file);
  execFileSync(chromium, ['--headless=new', '--no-sandbox', '--disable-gpu-sandbox', '--use-angle=swiftshader',
    '--enable-unsafe-swiftshader', '--allow-file-access-from-files', '--hide-scrollbars', '--window-size=640,640',
    '--virtual-time-budget=5000', `--screenshot=${out}`, `file://${path.resolve(page)}#${hash}`],
    { stdio: ['ignore', 'ignore', 'ignore'], timeout: 120000 });
  if (!existsSync(out)) throw new Error(`chromium wrote no screenshot for #${hash}`);
  return decodePng(readFileSync(out));
}

// 8-bit RGB/RGBA, non-interlaced PNG (what chromium writes) -> {width, height, channels, data}.
function decodePng(bytes) {
  let offset = 8, width = 0, height = 0, channels = 0;
  const idat = [];
  while (offset < bytes.length) {
    const length = bytes.readUInt32BE(offset), type = bytes.toString('latin1', offset + 4, offset + 8);
    const body = bytes.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0); height = body.readUInt32BE(4);
      if (body[8] !== 8 || body[12] !== 0) throw new Error('unsupported PNG');
      channels = { 2: 3, 6: 4 }[body[9]];
      if (!channels) throw new Error('unsupported PNG colour type');
    } else if (type === 'IDAT') idat.push(body);
    offset += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat)), stride = width * channels;
  const data = Buffer.alloc(height * stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? data[y * stride + x - channels] : 0, b = y > 0 ? data[(y - 1) * stride + x] : 0;
      const c = x >= channels && y > 0 ? data[(y - 1) * stride + x - channels] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const predictor = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
      data[y * stride + x] = (line[x] + predictor) & 255;
    }
  }
  return { width, height, channels, data };
}

// Pixels of the view (above the page's status bar, which shows the time) whose colour differs by
// more than 24 (of 255) in any channel.
function changedPixels(a, b) {
  let changed = 0;
  for (let i = 0; i < a.width * (a.height - 48); ++i) {
    let d = 0;
    for (let c = 0; c < 3; ++c) d = Math.max(d, Math.abs(a.data[i * a.channels + c] - b.data[i * b.channels + c]));
    if (d > 24) changed++;
  }
  return changed;
}

const track = JSON.parse(readFileSync(trackPath, 'utf8'));
const open = ['AA', 'AE', 'AO', 'AW', 'AY', 'EH', 'OW'];
const longest = (names) => track.phonemes.filter((p) => names.includes(p.value))
  .reduce((best, p) => (!best || p.end - p.start > best.end - best.start ? p : best), null);
const vowel = longest(open), pause = longest(['sil']);
if (!vowel || !pause) { console.log('FAIL: the sentence needs an open vowel and a pause'); process.exit(1); }
const mid = (p) => ((p.start + p.end) / 2).toFixed(4);
const rest = screenshot('t=rest', 'rest.png');
const atVowel = screenshot(`t=${mid(vowel)}`, 'vowel.png');
const atPause = screenshot(`t=${mid(pause)}`, 'pause.png');
const blank = rest.data.every((v, i) => i % rest.channels === 3 || v === rest.data[i % rest.channels]);
const vowelChange = changedPixels(atVowel, rest), pauseChange = changedPixels(atPause, rest);
console.log(`${vowel.value} at ${mid(vowel)} s: ${vowelChange} pixels differ from rest; pause at ${mid(pause)} s: ${pauseChange}`);
let failures = 0;
if (blank) { console.log('FAIL: the rest screenshot is one colour (nothing drawn)'); failures++; }
if (vowelChange < 200) { console.log('FAIL: the mouth does not open at the vowel'); failures++; }
if (pauseChange > vowelChange / 10) { console.log('FAIL: the face at the pause is not the rest pose'); failures++; }
console.log(`${3 - failures} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);
