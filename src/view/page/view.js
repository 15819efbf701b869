// The page of `prt view`: asks prt for frames as the user acts and draws them. Every picture is
// prt's own (its rasterizer, on the server); this script only keeps the state of the controls,
// turns mouse moves into a light rotation and a camera, and measures what the frames cost.
'use strict';

// Degrees the light turns per pixel dragged; the camera the same.
const DEGREES_PER_PIXEL = 0.5;
const $ = (id) => document.getElementById(id);

const view = {
  state: null,            // /state: limits and the first frame
  turn: { axis: [0, 1, 0], angle: 0 },  // the light's rotation: degrees about a unit axis
  playing: false,
  camera: null,           // {eye, target, up, fov}
  input: 0,               // the newest input's number (each change of a control or the light)
  inputs: [],             // [number, time, query] of the inputs no frame has answered yet
  posted: 0,              // the newest input sent to the server
  answered: 0,            // the input the picture answers
  stream: null,           // the open stream's name
  streams: 0,             // streams opened (a reconnect opens another)
  opening: null,          // the name of the stream being opened
  frame: 0,               // the number of the frame on the page, in its stream
  shown: 0,               // the same, as told to the server
  outOfOrder: 0,          // frames that came after a later one (never, on one stream)
  still: false,           // the picture is at still quality (what prt render draws)
  stillFrames: 0,         // frames shown at still quality, and at interactive
  interactiveFrames: 0,
  framesDrawn: 0,
  frameTimes: [],         // when each of the last frames was drawn, for the frame rate
  latencies: [],          // input to picture, ms
  lastQuery: '',
  transport: null,        // {basis, mode} drawn: the controls' choice once it is computed
  choice: 0,              // counts the basis and mode choices, the newest wins
};
window.prtView = view;   // for tests and the benchmark

function normalize(v) {
  const n = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / n, v[1] / n, v[2] / n];
}
function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
function quatAbout(axis, degrees) {
  const a = normalize(axis), h = degrees * Math.PI / 360;
  const s = Math.sin(h);
  return [a[0] * s, a[1] * s, a[2] * s, Math.cos(h)];
}
function quatMul(p, q) {  // p then... : the rotation q followed by p
  return [p[3] * q[0] + p[0] * q[3] + p[1] * q[2] - p[2] * q[1],
          p[3] * q[1] - p[0] * q[2] + p[1] * q[3] + p[2] * q[0],
          p[3] * q[2] + p[0] * q[1] - p[1] * q[0] + p[2] * q[3],
          p[3] * q[3] - p[0] * q[0] - p[1] * q[1] - p[2] * q[2]];
}
function rotate(v, axis, degrees) {  // Rodrigues
  const k = normalize(axis), t = degrees * Math.PI / 180, c = Math.cos(t), s = Math.sin(t);
  const d = k[0] * v[0] + k[1] * v[1] + k[2] * v[2], kx = cross(k, v);
  return [0, 1, 2].map((i) => v[i] * c + kx[i] * s + k[i] * d * (1 - c));
}

// The light's rotation as axis and angle in degrees (what prt render's --axis and --start-angle
// take), kept as such: playing and the turn slider change the angle about the same axis, exactly,
// so the server's frame light keeps its axis; a drag composes rotations and finds a new axis.
function axisAngle() { return view.turn; }

function turnFromQuat(q) {
  let [x, y, z, w] = q;
  if (w < 0) { x = -x; y = -y; z = -z; w = -w; }
  const s = Math.hypot(x, y, z);
  if (s < 1e-12) return { axis: view.turn.axis, angle: 0 };
  return { axis: [x / s, y / s, z / s], angle: 2 * Math.atan2(s, w) * 180 / Math.PI };
}

function fmt(v) { return v.map((x) => Number(x.toPrecision(12))).join(','); }

function query() {
  const { axis, angle } = axisAngle();
  const s = view.state, d = s.defaults;
  let viewName = $('view').value;
  if (viewName === 'transport') viewName = 'transport:' + Math.max(0, Math.floor(Number($('coef').value) || 0));
  const params = [
    ['axis', fmt(axis)], ['angle', String(Number(angle.toPrecision(12)))], ['lmax', $('lmax').value],
    ['basis', view.transport.basis], ['mode', view.transport.mode], ['env', $('env').value], ['view', viewName],
    ['exposure', $('exposure').value], ['tonemap', $('tonemap').value],
    ['eye', fmt(view.camera.eye)], ['target', fmt(view.camera.target)], ['up', fmt(view.camera.up)],
    ['fov', String(view.camera.fov)], ['size', d.width + 'x' + d.height],
    ['terms', String(Math.min(s.limits.light_terms, Math.max(0, Math.floor(Number($('terms').value) || 0))))]];
  return params.map(([k, v]) => k + '=' + encodeURIComponent(v)).join('&');
}

function status(text) { $('status').textContent = text; }

// The setting's error against prt reference, when the run has measured that reference (the
// light unturned: the figure belongs to the setting, not to the frame).
async function updateError() {
  const key = view.transport.mode + ' ' + $('env').value;
  const setting = key + ' ' + view.transport.basis + ' ' + $('lmax').value + ' ' + $('terms').value;
  if (setting === view.errorSetting) return;
  view.errorSetting = setting;
  const state = await (await fetch('/state')).json();
  const ref = state.references.find((x) => x.key === key);
  const t = state.transports.find((x) => x.key === view.transport.basis + ' ' + view.transport.mode);
  if (!ref || ref.state !== 'ready' || !t || t.state !== 'ready') {
    $('error').textContent = 'error against prt reference: ' +
      (ref && ref.state === 'measuring' ? 'measuring ...' : ref && ref.error ? ref.error : 'not measured for this mode and environment');
    view.errorSetting = null;
    return;
  }
  const e = await (await fetch('/error?' + query())).json();
  $('error').textContent = 'error against prt reference: ' + (100 * e.error).toFixed(2) + ' % RMS over ' + e.vertices +
    ' vertices (' + view.transport.basis + ((view.transport.basis === 'sh') ? ' lmax ' + e.lmax : '') + ', ' + view.transport.mode +
    ', the light unturned); the reference\'s own error ' + (100 * e.reference_error).toFixed(2) + ' % at ' + e.samples +
    ' directions a vertex';
  view.error = e;
}

async function measure() {
  const mode = view.transport.mode, env = $('env').value;
  await fetch('/reference?mode=' + mode + '&env=' + env, { method: 'POST' });
  for (;;) {
    const state = await (await fetch('/state')).json();
    const ref = state.references.find((x) => x.key === mode + ' ' + env);
    if (ref && ref.state !== 'measuring') break;
    const p = state.progress;
    $('error').textContent = 'measuring prt reference' + (p.active ? ': ' + p.label + ' ' + Math.round(100 * p.fraction) + ' %' : '') + ' ...';
    await new Promise((r) => setTimeout(r, 250));
  }
  view.errorSetting = null;
  updateError();
}

function changed() {
  view.input++;
  view.inputs.push([view.input, performance.now(), query()]);
  if (view.inputs.length > 200) view.inputs.shift();
  const { axis, angle } = axisAngle();
  $('angletext').textContent = angle.toFixed(1);
  if (document.activeElement !== $('angle')) $('angle').value = String(((angle % 360) + 360) % 360);
  $('axistext').textContent = axis.map((x) => x.toFixed(3)).join(',');
  $('lmaxtext').textContent = $('lmax').value;
  $('exposuretext').textContent = Number($('exposure').value).toFixed(1);
  $('save').href = '/frame.png?' + query();
  $('command').classList.add('stale');
  sendInput();
  updateError();
}

function median(xs) {
  const s = xs.slice().sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : NaN;
}

// The frame stream (GET /stream, src/view/frame_stream.h): the server pushes each frame as soon
// as it is drawn, the next drawn while the last travels; the page says what it wants (POST
// /input, one at a time, the newest) and which frame it has shown, so the server never draws
// more than two frames ahead of the picture. Records: src/view/stream_record.h.
const HEADER = 32;

function randomName() {
  const bytes = new Uint8Array(16);
  crypto.getRandomValues(bytes);
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

// The page's stream requests carry this header: only the page itself can send it (the server
// refuses them without), so no other page, even of the same site, can open a stream.
const STREAM_HEADERS = { 'X-Prt-Stream': '1' };

async function sendInput() {
  if (!view.stream) return;
  if (view.posting) { view.postAgain = true; return; }
  view.posting = true;
  const name = view.stream;  // this stream's inputs only: a reconnect sends its own
  try {
    do {
      view.postAgain = false;
      const fresh = view.input > view.posted;
      const url = '/input?stream=' + name + '&shown=' + view.shown +
        (fresh ? '&input=' + view.input + '&' + query() : '');
      const sentInput = view.input;
      const res = await fetch(url, { method: 'POST', headers: STREAM_HEADERS });
      if (view.stream !== name) return;  // the stream ended meanwhile: its successor has the input
      if (res.status === 404) { reopenStream(name); return; }
      if (!res.ok) {  // refused (a query the scene cannot take): said, and sent again with the next
        status('input: ' + (await res.text()).trim());  // message to the server, not in a loop
        break;
      }
      if (fresh) view.posted = Math.max(view.posted, sentInput);
    } while (view.postAgain || view.input > view.posted);
  } catch (e) {
    status('input: ' + e);
  } finally {
    view.posting = false;
    if (view.stream && view.stream !== name) sendInput();  // what came meanwhile goes to the new stream
  }
}

function fieldsOf(bytes) {
  const d = new DataView(bytes.buffer, bytes.byteOffset, HEADER);
  const f = [];
  for (let i = 4; i < HEADER; i += 4) f.push(d.getUint32(i, true));
  return { kind: String.fromCharCode(bytes[0], bytes[1], bytes[2], bytes[3]), f };
}

function showFrame(h, pixels) {
  const [frame, input, w, hgt, drawUs, flags] = h.f;
  const canvas = $('frame');
  if (canvas.width !== w || canvas.height !== hgt) { canvas.width = w; canvas.height = hgt; }
  canvas.getContext('2d').putImageData(new ImageData(pixels, w, hgt), 0, 0);
  const now = performance.now();
  if (frame <= view.frame) view.outOfOrder++;
  view.frame = frame;
  view.answered = input;
  view.still = (flags & 1) === 1;
  if (view.still) view.stillFrames++; else view.interactiveFrames++;
  view.framesDrawn++;
  view.frameTimes.push(now);
  while (view.frameTimes.length && now - view.frameTimes[0] > 1000) view.frameTimes.shift();
  let first = null;
  while (view.inputs.length && view.inputs[0][0] <= input) first = first || view.inputs[0], view.lastQuery = view.inputs.shift()[2];
  if (first) {
    view.latencies.push(now - first[1]);
    if (view.latencies.length > 50) view.latencies.shift();
  }
  const times = view.frameTimes;
  $('fps').textContent = times.length > 1 ? ((times.length - 1) * 1000 / (times[times.length - 1] - times[0])).toFixed(1) : '-';
  $('drawms').textContent = (drawUs / 1000).toFixed(1);
  $('inputms').textContent = view.latencies.length ? median(view.latencies).toFixed(1) : '-';
  $('quality').textContent = view.still ? 'still' : 'interactive';
  if (!status.busy) status('');
  view.shown = frame;
  sendInput();
}

// Opens the page's one stream; a stream that ends (the server dropped it, the connection broke)
// is replaced once, by reopenStream, never twice.
async function openStream() {
  const name = randomName();
  view.stream = null;
  view.opening = name;
  let res;
  try {
    res = await fetch('/stream?stream=' + name + '&input=' + view.input + '&' + query(), { headers: STREAM_HEADERS });
  } catch (e) {
    status('stream: ' + e + ' (trying again)');
    setTimeout(() => reopenStream(name), 1000);
    return;
  }
  if (view.opening !== name) { res.body && res.body.cancel(); return; }
  if (!res.ok) { status('stream: ' + (await res.text()).trim()); setTimeout(() => reopenStream(name), 1000); return; }
  view.stream = name;
  view.frame = 0;
  view.shown = 0;
  view.posted = Math.max(view.posted, view.input);  // the stream starts with the newest input
  view.streams++;
  const reader = res.body.getReader();
  const header = new Uint8Array(HEADER);
  let have = 0, h = null, body = null, at = 0;
  try {
    for (;;) {
      const { value, done } = await reader.read();
      if (done || view.stream !== name) break;
      let i = 0;
      while (i < value.length) {
        if (!h) {
          const n = Math.min(HEADER - have, value.length - i);
          header.set(value.subarray(i, i + n), have);
          have += n; i += n;
          if (have < HEADER) break;
          h = fieldsOf(header);
          have = 0;
          const size = h.kind === 'PRTF' ? h.f[2] * h.f[3] * 4 : h.kind === 'PRTE' ? h.f[2] : 0;
          body = h.kind === 'PRTF' ? new Uint8ClampedArray(size) : new Uint8Array(size);
          at = 0;
        }
        const n = Math.min(body.length - at, value.length - i);
        body.set(value.subarray(i, i + n), at);
        at += n; i += n;
        if (at < body.length) break;
        if (h.kind === 'PRTF') showFrame(h, body);
        else if (h.kind === 'PRTE') {
          status('frame: ' + new TextDecoder().decode(body).trim());
          view.answered = h.f[1];
          view.shown = h.f[0];
          sendInput();
        }
        h = null;
      }
    }
  } catch (e) {
    // the connection broke: another stream below
  }
  reader.cancel().catch(() => {});
  reopenStream(name);
}

// Replaces stream `name` once it has ended, if it is still the page's stream (or the one being
// opened): a late 404 of an old stream, or a second end, opens nothing more.
function reopenStream(name) {
  if (view.stream !== name && view.opening !== name) return;
  view.stream = null;
  view.opening = null;
  setTimeout(openStream, 250);
}

// The page's text changes only when a frame arrives (showFrame); this only clears the frame
// rate once frames have stopped coming.
setInterval(() => {
  const times = view.frameTimes;
  if (times.length && performance.now() - times[times.length - 1] > 1000) { times.length = 0; $('fps').textContent = '-'; }
}, 1000);

// While playing, the light turns with the display's frames; an idle page asks for none (it
// would cost the server's machine a share of a core for nothing).
function tick(now) {
  if (!view.playing) { view.lastTick = null; view.ticking = false; return; }
  const dt = view.lastTick ? now - view.lastTick : 0;
  view.turn = { axis: view.turn.axis, angle: (view.turn.angle + dt * 0.045) % 360 };  // 45 degrees a second
  changed();
  view.lastTick = now;
  requestAnimationFrame(tick);
}

// The transport the controls ask for, computed on first use: until it is ready the page keeps
// drawing (and turning) the one it shows, and says so. A later choice takes over from an earlier
// one still waiting.
async function ensureTransport() {
  const generation = ++view.choice;
  for (;;) {
    const basis = $('basis').value, mode = $('mode').value, key = basis + ' ' + mode;
    const state = await (await fetch('/state')).json();
    if (generation !== view.choice) return;
    const t = state.transports.find((x) => x.key === key);
    const shown = view.transport.basis + ' ' + view.transport.mode;
    if (t && t.state === 'ready') {
      view.transport = { basis, mode };
      status.busy = false; status(''); view.errorSetting = null; changed(); return;
    }
    if (t && t.state === 'failed') { status.busy = false; status(t.error + ' (showing ' + shown + ')'); return; }
    if (!t) await fetch('/compute?basis=' + encodeURIComponent(basis) + '&mode=' + encodeURIComponent(mode), { method: 'POST' });
    if (generation !== view.choice) return;
    const p = state.progress;
    status.busy = true;
    status('computing the ' + key + ' transport' + (p.active ? ': ' + p.label + ' ' + Math.round(100 * p.fraction) + ' %' : '') +
      ' ... (showing ' + shown + ')');
    await new Promise((r) => setTimeout(r, 250));
  }
}

function setupControls() {
  const s = view.state, d = s.defaults;
  const fill = (id, values, labels) => {
    $(id).innerHTML = '';
    values.forEach((v, i) => { const o = document.createElement('option'); o.value = v; o.textContent = labels ? labels[i] : v; $(id).appendChild(o); });
  };
  fill('basis', s.limits.bases);
  fill('mode', s.limits.modes);
  fill('env', s.limits.environments.map((_, i) => String(i)), s.limits.environments);
  const initial = new URLSearchParams(d.query);
  view.transport = { basis: initial.get('basis'), mode: initial.get('mode') };
  $('mode').value = initial.get('mode');
  $('lmax').max = String(s.limits.lmax);
  $('lmax').value = initial.get('lmax');
  $('coef').max = String(s.limits.coefficients - 1);
  $('terms').max = String(s.limits.light_terms);
  $('terms').value = initial.get('terms');
  const v = initial.get('view');
  $('view').value = v.startsWith('transport:') ? 'transport' : v;
  if (v.startsWith('transport:')) $('coef').value = v.slice(10);
  $('exposure').value = String(d.exposure);
  $('tonemap').value = initial.get('tonemap');
  view.camera = { eye: d.eye.slice(), target: d.target.slice(), up: d.up.slice(), fov: d.fov };
  view.home = { camera: JSON.parse(JSON.stringify(view.camera)) };
  view.turn = { axis: normalize(d.axis), angle: Number(initial.get('angle')) };
  $('frame').width = d.width;
  $('frame').height = d.height;
  for (const id of ['lmax', 'terms', 'view', 'coef', 'exposure', 'tonemap', 'env']) $(id).addEventListener('input', changed);
  for (const id of ['basis', 'mode']) $(id).addEventListener('change', ensureTransport);
  $('angle').addEventListener('input', () => {
    view.turn = { axis: view.turn.axis, angle: Number($('angle').value) };
    changed();
  });
  $('play').addEventListener('click', () => {
    view.playing = !view.playing;
    $('play').textContent = view.playing ? 'pause' : 'play';
    if (view.playing && !view.ticking) { view.ticking = true; requestAnimationFrame(tick); }
  });
  $('reset').addEventListener('click', () => { view.turn = { axis: view.turn.axis, angle: 0 }; changed(); });
  $('measure').addEventListener('click', measure);
  $('showcommand').addEventListener('click', async () => {
    $('command').value = (await (await fetch('/command?' + query())).text()).trim();
    $('command').classList.remove('stale');
  });
  setupPointer();
}

function setupPointer() {
  const canvas = $('frame');
  let last = null, orbit = false;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (e) => {
    last = [e.clientX, e.clientY];
    orbit = e.button === 2 || e.shiftKey;
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointerup', () => { last = null; });
  canvas.addEventListener('pointermove', (e) => {
    if (!last) return;
    const dx = e.clientX - last[0], dy = e.clientY - last[1];
    last = [e.clientX, e.clientY];
    if (dx === 0 && dy === 0) return;
    const c = view.camera;
    const forward = normalize([c.target[0] - c.eye[0], c.target[1] - c.eye[1], c.target[2] - c.eye[2]]);
    const right = normalize(cross(forward, c.up));
    if (orbit) {
      if (!view.state.limits.camera_moves) { status('the camera stays: the glossy transfer was computed for its eye'); return; }
      let offset = [0, 1, 2].map((i) => c.eye[i] - c.target[i]);
      offset = rotate(offset, c.up, -dx * DEGREES_PER_PIXEL);
      offset = rotate(offset, right, -dy * DEGREES_PER_PIXEL);
      c.eye = [0, 1, 2].map((i) => c.target[i] + offset[i]);
    } else {
      // Dragging right turns the light about the camera's up (the world's, unless --up says
      // otherwise), dragging down about the camera's right: together, about any axis.
      let q = quatAbout(view.turn.axis, view.turn.angle);
      if (dx) q = quatMul(quatAbout(c.up, dx * DEGREES_PER_PIXEL), q);
      if (dy) q = quatMul(quatAbout(right, dy * DEGREES_PER_PIXEL), q);
      view.turn = turnFromQuat(q);
    }
    changed();
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    if (!view.state.limits.camera_moves) return;
    const c = view.camera, k = Math.exp(e.deltaY * 0.001);
    c.eye = [0, 1, 2].map((i) => c.target[i] + (c.eye[i] - c.target[i]) * k);
    changed();
  }, { passive: false });
}

async function start() {
  // The server answers at once; its scene once the first transport is computed.
  for (;;) {
    view.state = await (await fetch('/state')).json();
    if (!view.state.starting) break;
    const p = view.state.progress;
    status('starting: computing the first transport' + (p.active ? ': ' + p.label + ' ' + Math.round(100 * p.fraction) + ' %' : '') + ' ...');
    await new Promise((r) => setTimeout(r, 250));
  }
  status('');
  setupControls();
  changed();
  openStream();
}
start();
