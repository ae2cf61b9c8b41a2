#include "core/speech/SpeechPage.h"

#include "core/common/JsonParse.h"
#include "core/common/MarkupEscape.h"

#include <array>

namespace vl {

namespace {

// JSON inside a <script> element: "</" would end the element, so it is written "<\/" (the same
// string in JSON).
std::string scriptSafe(std::string_view json) {
    std::string out;
    out.reserve(json.size());
    for (std::size_t i = 0; i < json.size(); ++i) {
        out += json[i];
        if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') out += '\\';
    }
    return out;
}

// The page's own script, after the player's source in the same module.
constexpr std::string_view kPageScript = R"JS(
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

const statusLine = document.getElementById('status');
const bytesOf = (id) => Uint8Array.from(atob(document.getElementById(id).textContent.trim()), (c) => c.charCodeAt(0));
const track = JSON.parse(document.getElementById('track').textContent);
const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x303236);
scene.add(new THREE.HemisphereLight(0xffffff, 0x404040, 2.2));
const light = new THREE.DirectionalLight(0xffffff, 1.8);
light.position.set(0.4, 0.6, 1.0);
scene.add(light);
const camera = new THREE.PerspectiveCamera(25, 1, 0.001, 1000);

function resize() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}

// A front view of the meshes that speak (the head), not the whole body.
function frame(objects) {
  const box = new THREE.Box3();
  for (const o of objects) box.expandByObject(o);
  const center = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
  const radius = Math.max(size.x, size.y) * 0.5 || 1;
  const distance = radius / Math.tan(THREE.MathUtils.degToRad(camera.fov * 0.5)) * 1.25;
  camera.position.set(center.x, center.y, center.z + size.z * 0.5 + distance);
  camera.near = distance / 100;
  camera.far = distance * 100;
  camera.lookAt(center);
  camera.updateProjectionMatrix();
}

const loader = new GLTFLoader();
loader.setMeshoptDecoder(MeshoptDecoder);
loader.parse(bytesOf('avatar').buffer, '', (gltf) => {
  scene.add(gltf.scene);
  gltf.scene.updateMatrixWorld(true);
  const player = new VisemePlayer(gltf, track); // the result: its userData holds the key table
  frame(player.bindings.length ? player.bindings.map((b) => b.mesh) : [gltf.scene]);
  resize();
  const fixed = new URLSearchParams(location.hash.slice(1)).get('t');
  const describe = (t) => `${player.face} face, ${track.playback.interpolation}, ${t.toFixed(2)} of ${player.duration.toFixed(2)} s`;
  if (fixed !== null) {
    if (fixed !== 'rest') player.update(Number(fixed));
    renderer.render(scene, camera);
    statusLine.textContent = fixed === 'rest' ? 'rest pose' : describe(Number(fixed));
    document.title = 'ready';
    return;
  }
  const audioData = document.getElementById('audio').textContent.trim();
  const audio = audioData ? new Audio('data:audio/wav;base64,' + audioData) : null;
  let start = null;
  const now = () => (audio ? audio.currentTime : start === null ? 0 : (performance.now() - start) / 1000);
  document.getElementById('play').onclick = () => {
    start = performance.now();
    if (audio) { audio.currentTime = 0; audio.play(); }
  };
  renderer.setAnimationLoop(() => {
    const t = now();
    if (start !== null) player.update(t);
    renderer.render(scene, camera);
    statusLine.textContent = describe(t);
  });
  window.addEventListener('resize', resize);
  document.title = 'ready';
}, (error) => { statusLine.textContent = 'Cannot load the avatar: ' + error; });
)JS";

} // namespace

std::string base64Encode(std::string_view bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const auto b = [&](std::size_t k) { return static_cast<unsigned char>(bytes[i + k]); };
        const unsigned v = (b(0) << 16) | (b(1) << 8) | b(2);
        out += {kAlphabet[v >> 18], kAlphabet[(v >> 12) & 63], kAlphabet[(v >> 6) & 63], kAlphabet[v & 63]};
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += kAlphabet[v >> 18];
        out += kAlphabet[(v >> 12) & 63];
        out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

std::string speechPageHtml(const SpeechPageInputs& in) {
    std::string base = in.threeBase;
    if (!base.empty() && base.back() != '/') base += '/';
    const Json imports = {
        {"imports", {{"three", base + "build/three.module.js"}, {"three/addons/", base + "examples/jsm/"}}}};
    std::string html =
        "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>VisemeLab: " +
        escapeMarkup(in.title.substr(0, 200)) + "</title>\n";
    html += "<style>html,body{margin:0;height:100%;background:#303236;color:#e8eaed;font:14px sans-serif}"
            "canvas{display:block;width:100%;height:100%}"
            "#bar{position:fixed;left:0;right:0;bottom:0;padding:8px;background:#0009;display:flex;gap:12px;"
            "align-items:center}</style>\n";
    html += "<script type=\"importmap\">" + scriptSafe(imports.dump()) + "</script>\n</head>\n<body>\n";
    html +=
        "<canvas id=\"view\"></canvas>\n<div id=\"bar\"><button id=\"play\">Play</button><span id=\"status\">"
        "loading&hellip;</span></div>\n";
    html += "<script type=\"application/json\" id=\"track\">" + scriptSafe(in.trackJson) + "</script>\n";
    html += "<script type=\"text/plain\" id=\"avatar\">" + base64Encode(in.glb) + "</script>\n";
    html += "<script type=\"text/plain\" id=\"audio\">" + base64Encode(in.wav) + "</script>\n";
    html += "<script type=\"module\">\n" + std::string(in.playerModule) + std::string(kPageScript) +
            "</script>\n";
    return html + "</body>\n</html>\n";
}

} // namespace vl
