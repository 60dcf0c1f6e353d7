// ede-view's page script: fetches frames (binary: frame.hpp) from the server and draws them on a canvas,
// with GasLab's colours, histograms against 2D Maxwell-Boltzmann and monitors. One fetch at a time,
// paced by requestAnimationFrame, so the page asks for states at its own display rate and a slow machine
// simply skips frames. window.edeView exposes what was drawn (positions, time, counts) for the tests
// (tests/tools/view/) and for anyone curious, in the browser's console.
// Disks are drawn with WebGL2 where the browser has it (gl_draw.js: one instanced point per disk, the
// circle cut in the fragment shader, from the frame's decoded float32 columns), else with the 2D canvas
// below; the box and wall segments are drawn on a transparent 2D canvas over the WebGL one. The
// histograms and monitors are redrawn at most 10 times a second while frames stream (they are text and
// bars nobody reads at 60 Hz, and their layout cost the main thread as much as the disks). A crater log
// gets the crater view: the server's surface profiles and crater metrics drawn over the disks.
// Rejected: a framework or a plotting library (a build step or a CDN); WebGL only (a browser without it
// would show nothing: the 2D path stays as the fallback, and ?draw=2d forces it for comparison).
'use strict';

const $ = (id) => document.getElementById(id);
const view = { frames: 0, last: null, mode: 'live', errors: [] };
window.edeView = view;

let busy = false, liveRunning = false, liveDirty = false, logInfo = null, logWanted = null, logShown = null;
let play = 0, playFrom = 0, playWall = 0;

function showError(message) {
  $('error').textContent = message || '';
  if (message) view.errors.push(message);
}

async function api(path, options) {
  const res = await fetch(path, options);
  if (!res.ok) {
    let message = res.status + ' ' + res.statusText;
    try { message = (await res.json()).error; } catch (e) { /* not JSON */ }
    const error = new Error(message);
    error.status = res.status;
    throw error;
  }
  return res;
}

// Frame (frame.hpp): "EDEF" | u32 json bytes | JSON | u32 n | u32 0 | the columns JSON "columns" lists,
// each padded to 8 bytes. Compact frames carry x, y (and r when radii differ) as u16 fixed point over the
// box, decoded here into float32 for drawing; exact ones (?exact=1) carry float64, kept in f.exact.
const COLUMN_TYPES = { u8: Uint8Array, u16: Uint16Array, f32: Float32Array, f64: Float64Array };
function parseFrame(buffer) {
  const dv = new DataView(buffer);
  const magic = String.fromCharCode(dv.getUint8(0), dv.getUint8(1), dv.getUint8(2), dv.getUint8(3));
  if (magic !== 'EDEF') throw new Error('not a frame');
  const jsonBytes = dv.getUint32(4, true);
  const info = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 8, jsonBytes)));
  const n = dv.getUint32(8 + jsonBytes, true);
  let at = 16 + jsonBytes;
  const cols = {};
  for (const [name, type] of info.columns) {
    const T = COLUMN_TYPES[type];
    cols[name] = new T(buffer, at, n);
    at += Math.ceil(n * T.BYTES_PER_ELEMENT / 8) * 8;
  }
  const f = { info, n, colour: cols.colour };
  if (info.packing === 'exact') {
    f.exact = { x: cols.x, y: cols.y, r: cols.r };
    f.x = Float32Array.from(cols.x);
    f.y = Float32Array.from(cols.y);
    f.r = Float32Array.from(cols.r);
  } else {
    const decode = (q, scale) => { const v = new Float32Array(n); for (let i = 0; i < n; i++) v[i] = q[i] * scale; return v; };
    f.x = decode(cols.x, info.scale[0]);
    f.y = decode(cols.y, info.scale[1]);
    f.r = cols.r ? decode(cols.r, info.scale[2]) : new Float32Array(n).fill(info.radius);
  }
  return f;
}

// The frames the page asks for: coloured as the page colours, exact when the page's address says
// ?exact=1 (or edeView.exact is set: the tests compare exact positions with ede-replay --at).
const pageParams = new URLSearchParams(location.search);
view.exact = pageParams.get('exact') === '1';
function frameParams() { return 'colour=' + $('colour').value + (view.exact ? '&exact=1' : ''); }

const SPECIES = ['#4fc3f7', '#ffb74d', '#81c784', '#e57373', '#ba68c8', '#fff176', '#a1887f', '#90a4ae'];
const CLASSES = ['#2962ff', '#00c853', '#ff1744'];  // GasLab: slow blue, medium green, fast red
// Bonded clusters (frame.hpp): grey for a disk alone, then 15 colours by the cluster's rank (1: the
// largest), repeating; the same state always gets the same colours.
const CLUSTERS = ['#5a5a5a', '#e6194b', '#3cb44b', '#ffe119', '#4363d8', '#f58231', '#911eb4', '#46f0f0', '#f032e6',
  '#bcf60c', '#fabebe', '#008080', '#e6beff', '#9a6324', '#fffac8', '#aaffc3'];
const RAMP = ['#313695', '#4575b4', '#74add1', '#abd9e9', '#fee090', '#fdae61', '#f46d43', '#d73027', '#a50026'];

// The colour group of every disk (an index into the palette returned), from the frame's colour byte: the
// speed class, the species, the displacement in 255ths of the frame's largest, or the bonded cluster
// (0 alone, else 1 + (rank - 1) mod 255: frame.hpp).
function colourGroups(f) {
  const by = f.info.colour.by, c = f.colour;
  if (by === 'clusters') {
    const g = new Uint8Array(f.n), k = CLUSTERS.length - 1;
    for (let i = 0; i < f.n; i++) g[i] = c[i] ? 1 + (c[i] - 1) % k : 0;
    return { groups: g, palette: CLUSTERS };
  }
  if (by === 'species') {
    const g = new Uint8Array(f.n);
    for (let i = 0; i < f.n; i++) g[i] = c[i] % SPECIES.length;
    return { groups: g, palette: SPECIES };
  }
  if (by === 'displacement') {
    const g = new Uint8Array(f.n), k = (RAMP.length - 1) / 255;
    for (let i = 0; i < f.n; i++) g[i] = Math.round(c[i] * k);
    return { groups: g, palette: RAMP };
  }
  return { groups: c, palette: CLASSES };
}

// Colours as the canvas's pixels hold them (RGBA bytes read as one little-endian uint32).
const pixelCache = new Map();
function pixel(hex) {
  if (!pixelCache.has(hex)) {
    const v = parseInt(hex.slice(1), 16);
    pixelCache.set(hex, (0xff000000 | ((v & 0xff) << 16) | (v & 0xff00) | ((v >> 16) & 0xff)) >>> 0);
  }
  return pixelCache.get(hex);
}

let image = null;
// The WebGL2 disk layer (gl_draw.js), or null: then the 2D canvas draws the disks too.
// ?draw=2d or ?draw=webgl force a path (for the benchmark); by default WebGL unless it is software-rendered
// and the disks are small enough for the 2D pixel path (gl_draw.js says why).
const drawMode = pageParams.get('draw') || 'auto';
const gl = drawMode === '2d' ? null : makeGlDisks($('disks-gl'));
view.renderer = gl ? gl.renderer : 'none (2D canvas)';

// Disks of a few pixels or less are written straight into the image's pixels (each the pixels whose
// centres lie inside it, at least one): ~10x faster than canvas arcs at 10^4-10^5 disks, and it is the
// density view when disks are below a pixel. Larger disks are drawn as arcs, antialiased.
function drawDisks(f) {
  const c = $('disks'), ctx = c.getContext('2d'), W = c.width, H = c.height;
  const { lx, ly } = f.info;
  const scale = Math.min(W / lx, H / ly);
  const { groups, palette } = colourGroups(f);
  let rmax = 0;
  for (let i = 0; i < f.n; i++) rmax = Math.max(rmax, f.r[i]);
  const preferGl = gl && (drawMode === 'webgl' || !gl.software || rmax * scale >= 4);
  if (preferGl && gl.draw(f, groups, palette, scale, rmax)) {
    view.drawer = 'webgl';
    ctx.clearRect(0, 0, W, H);  // the overlay: only the box and the segments
  } else if (rmax * scale < 4) {
    view.drawer = '2d-pixels';
    if (gl) gl.clear();
    if (!image || image.width !== W || image.height !== H) image = ctx.createImageData(W, H);
    const buf = new Uint32Array(image.data.buffer), colours = palette.map(pixel);
    buf.fill(0xff000000);
    // Each disk is a stamp: the pixels whose centres lie within its radius of the centre of the pixel
    // holding its centre (at least that pixel), one stamp per pixel radius (a frame has few).
    const stamps = new Map();
    const stampOf = (pr) => {
      const key = Math.round(pr * 16);
      let st = stamps.get(key);
      if (!st) {
        const q = key / 16, e = Math.ceil(q), offsets = [0];
        for (let dy = -e; dy <= e; dy++)
          for (let dx = -e; dx <= e; dx++) if ((dx || dy) && dx * dx + dy * dy <= q * q) offsets.push(dy * W + dx);
        st = { extent: e, offsets: Int32Array.from(offsets) };
        stamps.set(key, st);
      }
      return st;
    };
    let st = stampOf(f.r[0] * scale), stampR = f.r[0];
    for (let i = 0; i < f.n; i++) {
      if (f.r[i] !== stampR) st = stampOf(f.r[i] * scale), stampR = f.r[i];
      const cx = Math.floor(f.x[i] * scale), cy = Math.floor((ly - f.y[i]) * scale), colour = colours[groups[i]];
      const e = st.extent, off = st.offsets, base = cy * W + cx;
      if (cx >= e && cx < W - e && cy >= e && cy < H - e) {
        for (let k = 0; k < off.length; k++) buf[base + off[k]] = colour;
      } else {  // near the edge: each pixel checked
        for (let k = 0; k < off.length; k++) {
          const o = off[k], dy = Math.round(o / W), dx = o - dy * W, x = cx + dx, y = cy + dy;
          if (x >= 0 && x < W && y >= 0 && y < H) buf[y * W + x] = colour;
        }
      }
    }
    ctx.putImageData(image, 0, 0);
  } else {
    view.drawer = '2d-arcs';
    if (gl) gl.clear();
    ctx.fillStyle = '#000';
    ctx.fillRect(0, 0, W, H);
    for (let p = 0; p < palette.length; p++) {
      ctx.fillStyle = palette[p];
      ctx.beginPath();
      for (let i = 0; i < f.n; i++) {
        if (groups[i] !== p) continue;
        const px = f.x[i] * scale, py = (ly - f.y[i]) * scale, pr = f.r[i] * scale;
        ctx.moveTo(px + pr, py);
        ctx.arc(px, py, pr, 0, 2 * Math.PI);
      }
      ctx.fill();
    }
  }
  ctx.strokeStyle = '#666';
  ctx.strokeRect(0.5, 0.5, lx * scale - 1, ly * scale - 1);
  if (f.info.crater && !f.info.crater.error) drawCrater(ctx, f.info.crater, scale, ly);
  if (f.info.segments) {  // the scene's wall segments
    ctx.strokeStyle = '#ddd';
    ctx.lineWidth = 2;
    ctx.lineCap = 'round';
    ctx.beginPath();
    for (const [ax, ay, bx, by] of f.info.segments) {
      ctx.moveTo(ax * scale, (ly - ay) * scale);
      ctx.lineTo(bx * scale, (ly - by) * scale);
    }
    ctx.stroke();
    ctx.lineWidth = 1;
  }
}

// The crater view (crater_view.hpp): the bed's surface at the log's start (grey, dashed) and now (yellow),
// as steps over the profile's bins, and the crater's extent [left, right) marked above the old surface.
function drawCrater(ctx, c, scale, ly) {
  const profile = (heights) => {
    ctx.beginPath();
    heights.forEach((h, k) => {
      const x0 = k * c.bin_width * scale, x1 = (k + 1) * c.bin_width * scale, y = (ly - h) * scale;
      k ? ctx.lineTo(x0, y) : ctx.moveTo(x0, y);
      ctx.lineTo(x1, y);
    });
    ctx.stroke();
  };
  ctx.lineWidth = 2;
  ctx.setLineDash([6, 4]);
  ctx.strokeStyle = '#bbb';
  profile(c.before);
  ctx.setLineDash([]);
  ctx.strokeStyle = '#ffd600';
  profile(c.after);
  if (c.has_crater) {
    const top = Math.max(...c.before), y = (ly - top) * scale - 8;
    ctx.strokeStyle = '#ff5252';
    ctx.beginPath();
    ctx.moveTo(c.left * scale, y); ctx.lineTo(c.right * scale, y);
    ctx.moveTo(c.left * scale, y - 5); ctx.lineTo(c.left * scale, y + 5);
    ctx.moveTo(c.right * scale, y - 5); ctx.lineTo(c.right * scale, y + 5);
    ctx.stroke();
  }
  ctx.lineWidth = 1;
}

function drawHistogram(canvasId, h, curve, means) {
  const c = $(canvasId), ctx = c.getContext('2d'), W = c.width, H = c.height, pad = 18;
  ctx.clearRect(0, 0, W, H);
  const bins = h.counts.length, width = (h.hi - h.lo) / bins;
  const total = h.counts.reduce((a, b) => a + b, 0) + h.outside;
  const expected = [];
  for (let k = 0; k <= 100; k++) {
    const v = h.lo + (h.hi - h.lo) * k / 100;
    expected.push(curve ? curve(v) * total * width : 0);
  }
  const top = Math.max(1, ...h.counts, ...expected) * 1.1;
  const X = (v) => pad + (W - 2 * pad) * (v - h.lo) / (h.hi - h.lo), Y = (n) => H - pad - (H - 2 * pad) * n / top;
  ctx.fillStyle = '#90caf9';
  for (let k = 0; k < bins; k++) ctx.fillRect(X(h.lo + k * width), Y(h.counts[k]), X(width) - X(0) - 1, Y(0) - Y(h.counts[k]));
  if (curve) {
    ctx.strokeStyle = '#c62828';
    ctx.lineWidth = 2;
    ctx.beginPath();
    expected.forEach((e, k) => { const x = X(h.lo + (h.hi - h.lo) * k / 100); k ? ctx.lineTo(x, Y(e)) : ctx.moveTo(x, Y(e)); });
    ctx.stroke();
  }
  ctx.lineWidth = 1;
  ctx.setLineDash([4, 3]);
  means.forEach(([v, colour]) => { if (!(v > 0)) return; ctx.strokeStyle = colour; ctx.beginPath(); ctx.moveTo(X(v), Y(0)); ctx.lineTo(X(v), pad); ctx.stroke(); });
  ctx.setLineDash([]);
  ctx.fillStyle = '#333';
  ctx.fillText('0', pad, H - 4);
  ctx.fillText(h.hi.toPrecision(3), W - pad - 24, H - 4);
}

function drawPlots(f) {
  const i = f.info, kT = i.kT, m = i.mass;
  const mbSpeed = kT > 0 && m ? (v) => (m * v / kT) * Math.exp(-m * v * v / (2 * kT)) : null;
  drawHistogram('speed-hist', i.speed_hist, mbSpeed, [[i.mean_speed0, '#999'], [i.mean_speed, '#000']]);
  const mbEnergy = kT > 0 ? (e) => Math.exp(-e / kT) / kT : null;
  drawHistogram('energy-hist', i.energy_hist, mbEnergy, [[i.kT0, '#999'], [i.kT, '#000']]);
}

// Pressure of a live run from its impulse sums (Simulation::impulses): differences between the newest
// frame and the oldest one seen in the last 3 s of wall time (at least the two latest), so the value is
// a window average that follows the run. With walls, the walls' pressure
//   P = sum |dp_n| / (perimeter * dt);
// in a periodic box the virial pressure P = (N kT + W / (2 dt)) / A, W = sum r_ij . dp_i over the pair
// collisions (ede/pressure.hpp; kT the frame's). Units: force per unit length, the scene's mass / time^2.
let pressureHistory = [];
function pressure(f) {
  const p = f.info.impulses;
  if (!p) return null;
  const now = performance.now();
  const last = pressureHistory[pressureHistory.length - 1];
  if (last && p.time < last.time) pressureHistory = [];
  if (!last || p.time > last.time) pressureHistory.push({ ...p, wallClock: now });
  while (pressureHistory.length > 2 && now - pressureHistory[0].wallClock > 3000) pressureHistory.shift();
  if (pressureHistory.length < 2) return null;
  const a = pressureHistory[0], b = pressureHistory[pressureHistory.length - 1], dt = b.time - a.time;
  const i = f.info, area = i.lx * i.ly;
  let value, formula;
  if (!i.periodic) {
    const impulse = b.wall.reduce((s, v) => s + v, 0) - a.wall.reduce((s, v) => s + v, 0);
    value = impulse / (2 * (i.lx + i.ly) * dt);
    formula = 'walls';
  } else {
    value = (i.disks * i.kT + (b.virial - a.virial) / (2 * dt)) / area;
    formula = 'virial';
  }
  return { value, z: value * area / (i.disks * i.kT), dt, formula };
}

function monitors(f) {
  const i = f.info, rows = [
    ['time', i.time.toPrecision(6)],
    ['events', i.events.toLocaleString('en')],
  ];
  if (i.events_per_second !== undefined) rows.push(['events / s', Math.round(i.events_per_second).toLocaleString('en')]);
  rows.push(['collisions per disk', (view.mode === 'log' ? '≈ ' : '') + i.collisions_per_disk.toFixed(2)],
    ['kT (initial)', i.kT.toPrecision(4) + ' (' + i.kT0.toPrecision(4) + ')'],
    ['% slow / medium / fast', i.percent.map((p) => p.toFixed(1)).join(' / ')],
    ...(view.pressure ? [['pressure, ' + view.pressure.formula + ' (Δt ' + view.pressure.dt.toPrecision(3) + ')',
      view.pressure.value.toPrecision(4) + ' (Z ' + view.pressure.z.toPrecision(4) + ')']] : []),
    ['disks drawn', f.n.toLocaleString('en') + (i.stride > 1 ? ' (every ' + i.stride + 'th of ' + i.disks.toLocaleString('en') + ')' : '')]);
  if (i.colour.by === 'clusters') {  // the legend: bonded when closer than the outermost well
    const c = i.colour;
    rows.push(['clusters (bonded: r < ' + c.bond_radius.toPrecision(3) + ')', c.clusters.toLocaleString('en') +
      ', largest ' + c.largest.toLocaleString('en') + ' disks, ' + c.alone.toLocaleString('en') + ' alone (grey)']);
  }
  if (i.crater && i.crater.error) rows.push(['crater', i.crater.error]);
  else if (i.crater) {
    const c = i.crater;
    rows.push(['crater depth, width', c.has_crater ? c.depth.toPrecision(4) + ', ' + c.width.toPrecision(4) + ' (x ' +
      c.left.toPrecision(3) + '–' + c.right.toPrecision(3) + ')' : 'none yet (largest drop ' + c.depth.toPrecision(3) + ')'],
    ['crater area', c.area.toPrecision(4)],
    ['bed disks displaced', c.displaced + ' of ' + c.bed_disks + (c.detached ? ' (' + c.detached + ' ejecta)' : '')]);
  }
  if (i.status) rows.push(['run', i.status]);
  if (i.message) rows.push(['message', i.message]);  // e.g. why a reversal could not be placed
  if (i.log) rows.push(['log', i.log]);
  $('monitors').replaceChildren(...rows.map(([k, v]) => {
    const tr = document.createElement('tr');
    for (const text of [k, String(v)]) tr.insertCell().textContent = text;
    return tr;
  }));
}

let statsWall = 0;

// `streaming`: one of a stream of frames (a running run, a playing log): the histograms and monitors
// then wait 100 ms since they were last drawn; any other frame draws them.
function show(f, streaming) {
  const t0 = performance.now();
  view.pressure = pressure(f);
  drawDisks(f);
  if (!streaming || t0 - statsWall >= 100) {
    drawPlots(f);
    monitors(f);
    statsWall = t0;
  }
  view.drawMs = performance.now() - t0;
  view.frames++;
  const drawn = f.exact || f;
  view.last = { time: f.info.time, t_request: f.info.t_request, events: f.info.events, n: f.n,
    stride: f.info.stride, x: drawn.x, y: drawn.y, r: drawn.r, packing: f.info.packing, info: f.info };
}

async function fetchFrame(path, streaming) {
  let res;
  try {
    res = await api(path);
  } catch (e) {
    if (e.status === 503) return;  // the server is busy sending frames to other pages: the next tick asks again
    throw e;
  }
  show(parseFrame(await res.arrayBuffer()), streaming);
}

// --- live runs ---------------------------------------------------------------------------------------

function paceValue() { return $('fastest').checked ? 0 : Math.pow(10, Number($('pace').value)); }

async function sendPace() {
  $('pace-text').textContent = $('fastest').checked ? 'max' : paceValue().toPrecision(2) + ' / s';
  try { await api('/api/run/pace?pace=' + paceValue(), { method: 'POST' }); } catch (e) { /* no run yet */ }
}

// The clusters colouring only where the scene has a square well: otherwise disabled, with the reason as
// its tooltip, and the speed classes instead if it was chosen. Why not, per mode (the live scene, the log).
const clustersWhy = { live: '', log: '' };
function offerClusters(unavailable) {
  const option = $('colour').querySelector('option[value=clusters]');
  option.disabled = !!unavailable;
  option.title = unavailable || 'disks bonded (closer than their outermost square well) share a colour';
  if (unavailable && $('colour').value === 'clusters') $('colour').value = 'speed';
}

async function loadScene() {
  const s = await (await api('/api/scene?name=' + encodeURIComponent($('scene').value))).json();
  offerClusters(clustersWhy.live = s.clusters_unavailable);
  $('count').value = s.count;
  $('radius').value = s.radius ?? '';
  $('radius').placeholder = s.radius === null ? 'from the scene' : '';
  $('restitution').value = s.restitution;
  $('tc').value = s.tc;
  $('gravity').value = -s.gravity[1];
  $('boundary').value = s.boundary;
}

async function setup() {
  showError('');
  const scene = await (await api('/api/scene?name=' + encodeURIComponent($('scene').value))).json();
  const set = [];
  const changed = (id, now) => $(id).value !== '' && Number($(id).value) !== now;
  if (changed('count', scene.count)) set.push('species[0].count=' + Math.round(Number($('count').value)));
  if (changed('radius', scene.radius)) set.push('species[0].radius=' + Number($('radius').value));
  if (changed('restitution', scene.restitution)) set.push('physics.restitution=' + Number($('restitution').value));
  if (changed('tc', scene.tc)) set.push('physics.tc=' + Number($('tc').value));
  if (changed('gravity', -scene.gravity[1])) set.push('physics.gravity=[0,' + (-Number($('gravity').value)) + ']');
  if ($('boundary').value !== scene.boundary) set.push('box.boundary="' + $('boundary').value + '"');
  try {
    const status = await (await api('/api/run/setup', { method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ scene: $('scene').value, set, until: Number($('until').value) || 100 }) })).json();
    offerClusters(clustersWhy.live = status.clusters_unavailable);
    liveRunning = false;
    $('go').textContent = 'GO';
    $('go').disabled = $('reverse').disabled = $('finish').disabled = false;
    pressureHistory = [];
    await sendPace();
    liveDirty = true;
  } catch (e) { showError(e.message); }
}

async function goPause() {
  try {
    await api(liveRunning ? '/api/run/pause' : '/api/run/go', { method: 'POST' });
    liveRunning = !liveRunning;
    $('go').textContent = liveRunning ? 'PAUSE' : 'GO';
    liveDirty = true;
    if (!liveRunning) setTimeout(() => { liveDirty = true; }, 300);  // the state the worker stopped at
  } catch (e) { showError(e.message); }
}

// FINISH: the run ends here and its log is complete at this time (Simulation::finish in the server).
async function finishRun() {
  try {
    await api('/api/run/finish', { method: 'POST' });
    liveRunning = false;
    $('go').textContent = 'GO';
    $('go').disabled = $('reverse').disabled = $('finish').disabled = true;
    liveDirty = true;
    setTimeout(() => { liveDirty = true; }, 300);  // the state the run finished at
  } catch (e) { showError(e.message); }
}

// --- logs --------------------------------------------------------------------------------------------

async function openLog() {
  showError('');
  try {
    logInfo = await (await api('/api/log/info?name=' + encodeURIComponent($('log').value))).json();
    // A crater scene (a bed and a projectile): the crater view on, coloured by displacement.
    $('crater-view').hidden = $('crater-before-label').hidden = !logInfo.crater;
    $('crater').checked = !!logInfo.crater;
    offerClusters(clustersWhy.log = logInfo.clusters_unavailable);
    if (logInfo.crater) $('colour').value = 'displacement';
    play = 0;
    setLogTime(logInfo.start);
  } catch (e) { logInfo = null; showError(e.message); }
}

// Asks for the state at t (a number, or the exact text typed).
function setLogTime(t, text) {
  if (!logInfo) return;
  if (text === 'end') t = logInfo.end;
  t = Math.min(Math.max(t, logInfo.start), logInfo.end);
  logWanted = text !== undefined ? text : String(t);
  $('time').value = Math.round(100000 * (t - logInfo.start) / ((logInfo.end - logInfo.start) || 1));
  $('time-text').value = logWanted;
}

// Plays forward (1) or backward (-1) at the chosen speed (simulated time per second of wall time), from
// the time shown ('end' is the log's end time).
function startPlay(direction) {
  if (!logInfo) return;
  const from = logWanted === 'end' ? logInfo.end : Number(logWanted ?? logInfo.start);
  play = direction;
  playFrom = Number.isFinite(from) ? from : logInfo.start;
  playWall = performance.now();
}

// The crater view's request: on for a crater log with the box ticked, against the "before" time if given.
function craterParams() {
  if (!logInfo || !logInfo.crater || !$('crater').checked) return '';
  const before = $('crater-before').value.trim();
  return '&crater=1' + (before ? '&before=' + encodeURIComponent(before) : '');
}

// --- the loop ----------------------------------------------------------------------------------------

// One request in flight at a time; in a live run the next frame is fetched while this one is drawn.
let pending = null;

function liveFetch() {
  return api('/api/run/frame?' + frameParams()).then((res) => res.arrayBuffer());
}

async function tick() {
  requestAnimationFrame(tick);
  if (busy) return;
  busy = true;
  try {
    if (view.mode === 'live' && (liveRunning || liveDirty || pending)) {
      liveDirty = false;
      const prefetched = pending !== null;
      const buffer = await (pending || liveFetch());
      pending = liveRunning ? liveFetch() : null;
      if (prefetched && !liveRunning) liveDirty = true;  // fetched before PAUSE: fetch the paused state too
      show(parseFrame(buffer), liveRunning);
    } else if (view.mode === 'log' && logInfo) {
      if (play) {
        const t = playFrom + play * Number($('play-speed').value) * (performance.now() - playWall) / 1000;
        setLogTime(t);
        if (t <= logInfo.start || t >= logInfo.end) play = 0;
      }
      if (logWanted !== null && logWanted !== logShown) {
        const want = logWanted;
        await fetchFrame('/api/log/frame?name=' + encodeURIComponent($('log').value) + '&t=' + encodeURIComponent(want) +
          '&' + frameParams() + craterParams(), play !== 0);
        logShown = want;
      }
    }
  } catch (e) {
    showError(e.message);
    play = 0;
    pending = null;
    logShown = logWanted;
  }
  busy = false;
}

async function init() {
  document.querySelectorAll('input[name=mode]').forEach((r) => r.addEventListener('change', () => {
    view.mode = r.value;
    $('live').hidden = view.mode !== 'live';
    $('logs').hidden = view.mode !== 'log';
    offerClusters(clustersWhy[view.mode]);
    if (view.mode === 'log') refreshLogs(); else liveDirty = true;
  }));
  $('colour').addEventListener('change', () => { liveDirty = true; logShown = null; });
  $('crater').addEventListener('change', () => { logShown = null; });
  $('crater-before').addEventListener('change', () => { logShown = null; });
  $('scene').addEventListener('change', () => loadScene().catch((e) => showError(e.message)));
  $('setup').addEventListener('click', setup);
  $('go').addEventListener('click', goPause);
  $('finish').addEventListener('click', finishRun);
  $('reverse').addEventListener('click', () => api('/api/run/reverse', { method: 'POST' }).catch((e) => showError(e.message)));
  $('pace').addEventListener('input', sendPace);
  $('fastest').addEventListener('change', sendPace);
  $('log').addEventListener('change', openLog);
  $('time').addEventListener('input', () => { play = 0; setLogTime(logInfo.start + (logInfo.end - logInfo.start) * Number($('time').value) / 100000); });
  $('time-text').addEventListener('change', () => { play = 0; setLogTime(Number($('time-text').value), $('time-text').value.trim()); });
  $('fwd').addEventListener('click', () => startPlay(1));
  $('back').addEventListener('click', () => startPlay(-1));
  $('stop').addEventListener('click', () => { play = 0; });
  try {
    const scenes = (await (await api('/api/scenes')).json()).scenes;
    $('scene').replaceChildren(...scenes.map((s) => new Option(s, s)));  // file names as text, never as HTML
    const gas = scenes.find((s) => s.endsWith(':gas.toml'));
    if (gas) $('scene').value = gas;
    if (scenes.length) await loadScene();
  } catch (e) { showError(e.message); }
  $('pace-text').textContent = paceValue().toPrecision(2) + ' / s';
  view.ready = true;
  requestAnimationFrame(tick);
}

async function refreshLogs() {
  try {
    const logs = (await (await api('/api/logs')).json()).logs, was = $('log').value;
    $('log').replaceChildren(...logs.map((s) => new Option(s, s)));
    if (logs.includes(was)) $('log').value = was;
    if (!logInfo || $('log').value !== logInfo.name) await openLog();
  } catch (e) { showError(e.message); }
}

// What was drawn last, as plain arrays (for the DevTools protocol, which passes typed arrays as objects).
view.drawn = () => ({ ...view.last, x: Array.from(view.last.x), y: Array.from(view.last.y), r: Array.from(view.last.r) });

// For tests and the console: open a log and show the state at the exact time text t.
view.openLog = async (name, t) => {
  document.querySelector('input[name=mode][value=log]').click();
  await refreshLogs();
  if (![...$('log').options].some((o) => o.value === name)) $('log').add(new Option(name, name));
  $('log').value = name;
  await openLog();
  if (t !== undefined) setLogTime(Number(t), String(t));
};

init();
