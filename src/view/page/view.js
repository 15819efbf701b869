// The page of `prt view`: asks prt for frames as the user acts and draws them. Every picture is
// prt's own (its rasterizer, on the server); this script only keeps the state of the controls,
// turns mouse moves into a light rotation and a camera, and measures what the frames cost.
'use strict';

// Degrees the light turns per pixel dragged; the camera the same.
const DEGREES_PER_PIXEL = 0.5;
const $ = (id) => document.getElementById(id);

// The run's token (src/view/request_guard.h): the server writes it into the page it serves, as
// <meta name="prt-token">, and every request but the page's own files and /state carries it.
// Another origin cannot read the page, so only this page can ask for frames. Read once.
const TOKEN = document.querySelector('meta[name="prt-token"]')?.content ?? null;
/// `path` (with or without a query) as the page requests it: with token=TOKEN when the run has one.
function api(path) {
  if (TOKEN === null) return path;
  return path + (path.includes('?') ? '&' : '?') + 'token=' + encodeURIComponent(TOKEN);
}

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
    ['fov', String(view.camera.fov)], ['size', $('size').value], ['ssaa', $('ssaa').value],
    ['terms', String(lightTerms())]];
  return params.map(([k, v]) => k + '=' + encodeURIComponent(v)).join('&');
}

/// The wavelet light's terms the page asks for: the box's whole number within the run's limit (0: all).
function lightTerms() {
  return Math.min(view.state.limits.light_terms, Math.max(0, Math.floor(Number($('terms').value) || 0)));
}

function status(text) { $('status').textContent = text; }

// A figure measured against a reference of noise n is sqrt(e^2 + n^2) for a setting's own error e
// (independent errors add in quadrature): up to sqrt(2) n it says no more than e <= n, so the page
// says the setting cannot be told from the reference there.
const WITHIN_NOISE = Math.SQRT2;

/// The error label of /error's answer `e` for transport {basis, mode} at `terms` light terms.
function errorText(e, transport, terms) {
  const { basis, mode } = transport;
  const setting = basis + (BANDED.has(basis) ? ' lmax ' + e.lmax : '') +
    (TERMED.has(basis) ? ', ' + (terms > 0 ? terms + ' light terms' : 'all light terms') : '') + ', ' + mode;
  let text = 'error against prt reference: ' + (100 * e.error).toFixed(2) + ' % RMS over ' + e.vertices +
    ' vertices (' + setting + ', the light unturned); the reference\'s own error ' + (100 * e.reference_error).toFixed(2) +
    ' % at ' + e.samples + ' directions a vertex';
  if (e.error <= WITHIN_NOISE * e.reference_error)
    text += ': within the reference\'s own noise, so this setting cannot be told from it (more --reference-samples can)';
  return text;
}

// The setting's error against prt reference, when the run has measured that reference (the
// light unturned: the figure belongs to the setting, not to the frame). A setting is the mode,
// the environment, the basis, lmax and the light terms: each changes the figure, the environment
// as much as any (each has a reference of its own). An answer that comes after the setting
// changed is dropped: the newer setting's own call says what to show.
async function updateError() {
  const key = view.transport.mode + ' ' + $('env').value;
  const setting = key + ' ' + view.transport.basis + ' ' + $('lmax').value + ' ' + lightTerms();
  if (setting === view.errorSetting) return;
  view.errorSetting = setting;
  const transport = view.transport, terms = lightTerms(), q = query();
  const state = await (await fetch(api('/state'))).json();
  if (view.errorSetting !== setting) return;
  const ref = state.references.find((x) => x.key === key);
  const t = state.transports.find((x) => x.key === transport.basis + ' ' + transport.mode);
  if (!ref || ref.state !== 'ready' || !t || t.state !== 'ready') {
    $('error').textContent = 'error against prt reference: ' +
      (ref && ref.state === 'measuring' ? 'measuring ...' : ref && ref.error ? ref.error : 'not measured for this mode and environment');
    view.error = null;
    view.errorSetting = null;
    return;
  }
  const e = await (await fetch(api('/error?' + q))).json();
  if (view.errorSetting !== setting) return;
  $('error').textContent = errorText(e, transport, terms);
  view.error = e;
}

async function measure() {
  const mode = view.transport.mode, env = $('env').value;
  await fetch(api('/reference?mode=' + mode + '&env=' + env), { method: 'POST' });
  for (;;) {
    const state = await (await fetch(api('/state'))).json();
    const ref = state.references.find((x) => x.key === mode + ' ' + env);
    if (ref && ref.state !== 'measuring') break;
    const p = state.progress;
    $('error').textContent = 'measuring prt reference' + (p.active ? ': ' + p.label + ' ' + Math.round(100 * p.fraction) + ' %' : '') + ' ...';
    await new Promise((r) => setTimeout(r, 250));
  }
  view.errorSetting = null;
  updateError();
}

// Every change of a control or of the light: a new input, the page's text, the frame asked for.
// `fromSlider`: the turn slider itself moved, which keeps its own place (a full turn would set
// it from 360 back to 0 under the hand); every other change (a drag, play, reset) moves it to
// the light's angle, whatever has the focus (a touch drag on the canvas leaves it on the slider).
function changed(fromSlider) {
  view.input++;
  view.inputs.push([view.input, performance.now(), query()]);
  if (view.inputs.length > 200) view.inputs.shift();
  const { axis, angle } = axisAngle();
  $('angletext').textContent = angle.toFixed(1);
  if (fromSlider !== true) $('angle').value = String(((angle % 360) + 360) % 360);
  $('axistext').textContent = axis.map((x) => x.toFixed(3)).join(',');
  $('lmaxtext').textContent = $('lmax').value;
  $('exposuretext').textContent = Number($('exposure').value).toFixed(1);
  $('save').href = api('/frame.png?' + query());
  updateControls();
  sendInput();
  updateError();
  updateCommand();
}

// The `prt render` command line of the settings, kept up to date: asked again after every change
// (one request at a time; the newest settings are asked for when it answers). Until the line of
// the current settings has come, the box is greyed and says it is stale.
async function updateCommand() {
  const q = query();
  if (q === view.commandQuery) return;  // the box shows this line
  $('command').classList.add('stale');
  $('commandstate').textContent = 'stale: updating to the settings now ...';
  if (view.commandBusy) return;  // asked for when the request in flight answers
  view.commandBusy = true;
  let text, ok = false;
  try {
    const res = await fetch(api('/command?' + q));
    text = (await res.text()).trim();
    ok = res.ok;
  } catch (e) {
    text = String(e);
  }
  view.commandBusy = false;
  if (ok) {
    $('command').value = text;
    view.commandQuery = q;
  }
  if (query() !== q) return updateCommand();
  if (!ok) { $('commandstate').textContent = 'stale: ' + text; return; }  // asked again at the next change
  $('command').classList.remove('stale');
  $('commandstate').textContent = 'the command line of these settings';
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
      const res = await fetch(api(url), { method: 'POST', headers: STREAM_HEADERS });
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
    res = await fetch(api('/stream?stream=' + name + '&input=' + view.input + '&' + query()), { headers: STREAM_HEADERS });
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
// one still waiting. Each round reads the controls once: the key waited for is the key asked
// for. A request the server refuses, or that cannot be sent, ends the wait with its reason
// (never "computing" for ever).
async function ensureTransport() {
  const generation = ++view.choice;
  const shown = () => view.transport.basis + ' ' + view.transport.mode;
  try {
    for (;;) {
      const basis = $('basis').value, mode = $('mode').value, key = basis + ' ' + mode;
      const state = await (await fetch(api('/state'))).json();
      if (generation !== view.choice) return;
      const t = state.transports.find((x) => x.key === key);
      if (t && t.state === 'ready') {
        view.transport = { basis, mode };
        status.busy = false; status(''); view.errorSetting = null; changed(); return;
      }
      if (t && t.state === 'failed') { status.busy = false; status(t.error + ' (showing ' + shown() + ')'); return; }
      if (!t) {
        const res = await fetch(api('/compute?basis=' + encodeURIComponent(basis) + '&mode=' + encodeURIComponent(mode)),
                                { method: 'POST' });
        if (generation !== view.choice) return;
        if (!res.ok) {
          status.busy = false;
          status(key + ': ' + (await res.text()).trim() + ' (showing ' + shown() + ')');
          return;
        }
      }
      const p = state.progress;
      status.busy = true;
      status('computing the ' + key + ' transport' + (p.active ? ': ' + p.label + ' ' + Math.round(100 * p.fraction) + ' %' : '') +
        ' ... (showing ' + shown() + ')');
      await new Promise((r) => setTimeout(r, 250));
    }
  } catch (e) {
    if (generation !== view.choice) return;
    status.busy = false;
    status('transport: ' + e + ' (showing ' + shown() + ')');
  }
}

// What changes the picture, for the transport shown (the server takes every control, but some
// change nothing for some bases or scenes): those that would not are disabled, and their title
// says why. /state names the bases, not their traits, so the page knows them by name (a basis
// added to src/bases/ takes its place here): BANDED cuts its light at lmax (its Traits()
// light_bands), TERMED keeps a number of light terms (MaxLightTerms), COEFFICIENTS keeps SH
// transfer coefficients per vertex (coefficient_view: the transport:K view).
const BANDED = new Set(['sh']);
const TERMED = new Set(['wavelet']);
const COEFFICIENTS = new Set(['sh']);

function setEnabled(control, enabled, why) {
  control.disabled = !enabled;
  control.title = enabled ? '' : why;
  const label = control.closest('label');
  if (label && label.contains(control) && control.tagName !== 'OPTION') label.title = control.title;
}

function updateControls() {
  const s = view.state, basis = view.transport.basis;
  setEnabled($('lmax'), BANDED.has(basis),
    'lmax cuts the SH light\'s bands: the ' + basis + ' basis keeps its light whole, so lmax changes nothing here' +
    ' (its bounces, if any, stay at the command line\'s --lmax ' + s.limits.lmax + ')');
  setEnabled($('terms'), TERMED.has(basis) && s.limits.light_terms > 0,
    'light terms are the wavelet light\'s: the ' + basis + ' basis keeps every coefficient of its bands (lmax cuts them)');
  // A diffuse scene has no glossy term (the glossy view would be black): its camera moves, which
  // a glossy scene's cannot (its transfer was computed for one eye, ViewLimits::camera_moves).
  setEnabled($('view').querySelector('option[value="glossy"]'), !s.limits.camera_moves,
    'the scene is diffuse: it has no glossy term to show (prt view --material phong:... gives one)');
  setEnabled($('view').querySelector('option[value="transport"]'), COEFFICIENTS.has(basis),
    'the ' + basis + ' basis keeps no SH transfer coefficients (basis sh does)');
  setEnabled($('coef'), $('view').value === 'transport', 'K is the coefficient the transport:K view shows');
  setEnabled($('resetcamera'), s.limits.camera_moves, 'the camera stays: the glossy transfer was computed for its eye');
}

function setupControls() {
  const s = view.state, d = s.defaults;
  const initial = new URLSearchParams(d.query);
  const fill = (id, values, labels) => {
    $(id).innerHTML = '';
    values.forEach((v, i) => { const o = document.createElement('option'); o.value = v; o.textContent = labels ? labels[i] : v; $(id).appendChild(o); });
  };
  fill('basis', s.limits.bases);
  fill('mode', s.limits.modes);
  // Each environment by its file (or built-in) name; the whole path in the option's title.
  fill('env', s.limits.environments.map((_, i) => String(i)), s.limits.environments.map(shortName));
  Array.from($('env').options).forEach((o, i) => { o.title = s.limits.environments[i]; });
  // The frame's size: the command line's, and a few more of 4:3; supersampling 1..MAX_SSAA, each
  // within MAX_SAMPLES at the size chosen (updateSsaa).
  const sizes = [d.width + 'x' + d.height];
  for (const w of [160, 320, 640, 800, 1024, 1280]) if (!sizes.includes(w + 'x' + w * 3 / 4)) sizes.push(w + 'x' + w * 3 / 4);
  fill('size', sizes, sizes.map((x, i) => x.replace('x', ' x ') + (i === 0 ? ' (the command line\'s)' : '')));
  fill('ssaa', Array.from({ length: MAX_SSAA }, (_, k) => String(k + 1)), Array.from({ length: MAX_SSAA }, (_, k) => (k + 1) + ' x ' + (k + 1)));
  $('ssaa').value = initial.get('ssaa');
  updateSsaa();
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
  for (const id of ['lmax', 'terms', 'view', 'coef', 'exposure', 'tonemap', 'env', 'ssaa']) $(id).addEventListener('input', changed);
  $('size').addEventListener('input', () => { updateSsaa(); changed(); });
  for (const id of ['basis', 'mode']) $(id).addEventListener('change', ensureTransport);
  $('angle').addEventListener('input', () => {
    view.turn = { axis: view.turn.axis, angle: Number($('angle').value) };
    changed(true);
  });
  $('play').addEventListener('click', () => {
    view.playing = !view.playing;
    $('play').textContent = view.playing ? 'pause' : 'play';
    if (view.playing && !view.ticking) { view.ticking = true; requestAnimationFrame(tick); }
  });
  $('reset').addEventListener('click', () => { view.turn = { axis: view.turn.axis, angle: 0 }; changed(); });
  $('measure').addEventListener('click', measure);
  $('resetcamera').addEventListener('click', () => { view.camera = JSON.parse(JSON.stringify(view.home.camera)); changed(); });
  $('showcommand').addEventListener('click', () => { view.commandQuery = null; updateCommand(); });
  setupPointer();
}

/// The last part of an environment's path (a file's or a cubemap folder's name); a built-in
/// (sky, sky:sun=3,..., furnace) as it is.
function shortName(path) {
  const parts = path.replace(/[\\/]+$/, '').split(/[\\/]/);
  return parts[parts.length - 1] || path;
}

// The most supersampling a frame takes, and the most samples (width x height x ssaa^2) a frame of
// prt view draws: render/frame_limits.h's kMaxSsaa and kMaxViewSamples, which the server checks.
const MAX_SSAA = 8;
const MAX_SAMPLES = 4096 * 4096;

/// Disables the supersampling that the size chosen cannot take, saying why; a choice over the
/// limit comes down to the most it takes.
function updateSsaa() {
  const [w, h] = $('size').value.split('x').map(Number);
  let most = 1;
  for (const o of $('ssaa').options) {
    const k = Number(o.value), fits = w * h * k * k <= MAX_SAMPLES;
    o.disabled = !fits;
    o.title = fits ? '' : w + ' x ' + h + ' at ' + k + ' x ' + k + ' samples a pixel is over 4096 x 4096 samples, the most a frame of prt view draws';
    if (fits) most = Math.max(most, k);
  }
  if (Number($('ssaa').value) > most) $('ssaa').value = String(most);
}

// The camera orbits its target on a sphere: dragging right turns the eye about the camera's up
// (azimuth), dragging down raises it (elevation, measured from the plane through the target
// across up). The elevation stays within [lowestElevation(), MAX_ELEVATION]:
// - MAX_ELEVATION, 85 degrees, short of the pole: at the pole the eye looks along up, the
//   picture's right (forward x up) has no direction, and a drag past it turned the picture over
//   (every few pixels, as the eye crossed the pole back and forth). A drag past 85 stops there.
// - the ground: the page does not know the mesh, so it takes the plane across up through the
//   target as the ground, and the orbit stops there (elevation 0), or at the command line's own
//   eye if that was lower (the camera can go back where it began). For the embedded scene this
//   keeps the eye above its ground at any distance: the 12 x 12 ground is at y = 0 and the
//   camera's target at y = 1.5 (--target 0,1.5,0). A mesh without --target is looked at from
//   its fitted view's middle, which can lie a little below a wide ground (the tests' small
//   scene: 0.2 below its 12 x 12 ground, 20 away): there the eye stops that little under it.
const MAX_ELEVATION = 85;

function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// The camera's elevation in degrees: the angle of eye - target above the plane across up.
function elevation(c) {
  const offset = [0, 1, 2].map((i) => c.eye[i] - c.target[i]);
  return Math.asin(Math.max(-1, Math.min(1, dot(offset, normalize(c.up)) / Math.hypot(...offset)))) * 180 / Math.PI;
}

function lowestElevation() { return Math.min(0, elevation(view.home.camera)); }

/// The eye of camera `c` after a drag of (dx, dy) pixels, at the same distance from the target.
function orbitEye(c, dx, dy) {
  const up = normalize(c.up);
  const offset = [0, 1, 2].map((i) => c.eye[i] - c.target[i]);
  const r = Math.hypot(...offset);
  let across = offset.map((x, i) => x - dot(offset, up) * up[i]);  // the eye's direction across up
  if (Math.hypot(...across) < 1e-9 * r) across = normalize(cross(up, Math.abs(up[0]) < 0.9 ? [1, 0, 0] : [0, 0, 1]));
  across = normalize(rotate(across, up, -dx * DEGREES_PER_PIXEL));
  const highest = Math.max(MAX_ELEVATION, elevation(view.home.camera));
  const e = Math.max(lowestElevation(), Math.min(highest, elevation(c) + dy * DEGREES_PER_PIXEL)) * Math.PI / 180;
  return [0, 1, 2].map((i) => c.target[i] + r * (Math.cos(e) * across[i] + Math.sin(e) * up[i]));
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
      c.eye = orbitEye(c, dx, dy);
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
    view.state = await (await fetch(api('/state'))).json();
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
