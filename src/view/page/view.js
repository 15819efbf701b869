// The page of `prt view`: asks prt for frames as the user acts and draws them. Every picture is
// prt's own (its rasterizer, on the server); this script only keeps the state of the controls,
// turns mouse moves into a light rotation and a camera, and measures what the frames cost.
'use strict';

// Degrees the light turns per pixel dragged; the camera the same.
const DEGREES_PER_PIXEL = 0.5;
const $ = (id) => document.getElementById(id);

const view = {
  state: null,            // /state: limits and the first frame
  q: [0, 0, 0, 1],        // the light's rotation as a unit quaternion (x, y, z, w)
  axis: [0, 1, 0],        // the rotation's axis, kept when the rotation is the identity
  playing: false,
  camera: null,           // {eye, target, up, fov}
  dirty: true,            // the picture is not the one the controls ask for
  inflight: false,
  pendingInput: null,     // time of the oldest input the next frame answers
  framesDrawn: 0,
  frameTimes: [],         // when each of the last frames was drawn, for the frame rate
  latencies: [],          // input to picture, ms
  lastQuery: '',
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

// The light's rotation as axis and angle in degrees (what prt render's --axis and --start-angle take).
function axisAngle() {
  let [x, y, z, w] = view.q;
  if (w < 0) { x = -x; y = -y; z = -z; w = -w; }
  const s = Math.hypot(x, y, z);
  if (s < 1e-12) return { axis: view.axis, angle: 0 };
  view.axis = [x / s, y / s, z / s];
  return { axis: view.axis, angle: 2 * Math.atan2(s, w) * 180 / Math.PI };
}

function fmt(v) { return v.map((x) => Number(x.toPrecision(12))).join(','); }

function query() {
  const { axis, angle } = axisAngle();
  const s = view.state, d = s.defaults;
  let viewName = $('view').value;
  if (viewName === 'transport') viewName = 'transport:' + Math.max(0, Math.floor(Number($('coef').value) || 0));
  const params = [
    ['axis', fmt(axis)], ['angle', String(Number(angle.toPrecision(12)))], ['lmax', $('lmax').value],
    ['basis', $('basis').value], ['mode', $('mode').value], ['env', $('env').value], ['view', viewName],
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
  const key = $('mode').value + ' ' + $('env').value;
  const setting = key + ' ' + $('basis').value + ' ' + $('lmax').value + ' ' + $('terms').value;
  if (setting === view.errorSetting) return;
  view.errorSetting = setting;
  const state = await (await fetch('/state')).json();
  const ref = state.references.find((x) => x.key === key);
  const t = state.transports.find((x) => x.key === $('basis').value + ' ' + $('mode').value);
  if (!ref || ref.state !== 'ready' || !t || t.state !== 'ready') {
    $('error').textContent = 'error against prt reference: ' +
      (ref && ref.state === 'measuring' ? 'measuring ...' : ref && ref.error ? ref.error : 'not measured for this mode and environment');
    view.errorSetting = null;
    return;
  }
  const e = await (await fetch('/error?' + query())).json();
  $('error').textContent = 'error against prt reference: ' + (100 * e.error).toFixed(2) + ' % RMS over ' + e.vertices +
    ' vertices (' + $('basis').value + (($('basis').value === 'sh') ? ' lmax ' + e.lmax : '') + ', ' + $('mode').value +
    ', the light unturned); the reference\'s own error ' + (100 * e.reference_error).toFixed(2) + ' % at ' + e.samples +
    ' directions a vertex';
  view.error = e;
}

async function measure() {
  const mode = $('mode').value, env = $('env').value;
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
  view.dirty = true;
  if (view.pendingInput === null) view.pendingInput = performance.now();
  const { axis, angle } = axisAngle();
  $('angletext').textContent = angle.toFixed(1);
  $('axistext').textContent = axis.map((x) => x.toFixed(3)).join(',');
  $('lmaxtext').textContent = $('lmax').value;
  $('exposuretext').textContent = Number($('exposure').value).toFixed(1);
  $('save').href = '/frame.png?' + query();
  updateError();
}

function median(xs) {
  const s = xs.slice().sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : NaN;
}

async function drawFrame() {
  view.inflight = true;
  view.dirty = false;
  const input = view.pendingInput;
  view.pendingInput = null;
  const q = query();
  const t0 = performance.now();
  try {
    const res = await fetch('/frame?' + q);
    if (!res.ok) {
      status('frame: ' + (await res.text()).trim());
      return;
    }
    const [w, h] = res.headers.get('X-Prt-Size').split('x').map(Number);
    const rgb = new Uint8Array(await res.arrayBuffer());
    const canvas = $('frame');
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    const ctx = canvas.getContext('2d');
    const image = ctx.createImageData(w, h);
    const out = image.data;
    for (let i = 0, j = 0; i < rgb.length; i += 3, j += 4) {
      out[j] = rgb[i]; out[j + 1] = rgb[i + 1]; out[j + 2] = rgb[i + 2]; out[j + 3] = 255;
    }
    ctx.putImageData(image, 0, 0);
    const now = performance.now();
    view.lastQuery = q;
    view.framesDrawn++;
    view.frameTimes.push(now);
    while (view.frameTimes.length && now - view.frameTimes[0] > 1000) view.frameTimes.shift();
    if (input !== null) {
      view.latencies.push(now - input);
      if (view.latencies.length > 50) view.latencies.shift();
    }
    $('drawms').textContent = Number(res.headers.get('X-Prt-Draw-Ms')).toFixed(1);
    $('tripms').textContent = (now - t0).toFixed(1);
    $('inputms').textContent = view.latencies.length ? median(view.latencies).toFixed(1) : '-';
    if (!status.busy) status('');
  } catch (e) {
    status('frame: ' + e);
  } finally {
    view.inflight = false;
  }
}

function tick(now) {
  if (view.playing) {
    const dt = view.lastTick ? now - view.lastTick : 0;
    view.q = quatMul(quatAbout(view.axis, dt * 0.045), view.q);  // 45 degrees a second
    changed();
  }
  view.lastTick = now;
  const times = view.frameTimes;
  $('fps').textContent = times.length > 1 && now - times[times.length - 1] < 1000
    ? ((times.length - 1) * 1000 / (times[times.length - 1] - times[0])).toFixed(1) : '-';
  if (!view.inflight && view.dirty) drawFrame();
  requestAnimationFrame(tick);
}

// A transport not computed yet: asks for it, shows the progress, then draws.
async function ensureTransport() {
  const key = $('basis').value + ' ' + $('mode').value;
  for (;;) {
    const state = await (await fetch('/state')).json();
    const t = state.transports.find((x) => x.key === key);
    if (t && t.state === 'ready') { status.busy = false; status(''); changed(); return; }
    if (t && t.state === 'failed') { status.busy = false; status(t.error); return; }
    if (!t) await fetch('/compute?basis=' + encodeURIComponent($('basis').value) + '&mode=' + $('mode').value, { method: 'POST' });
    const p = state.progress;
    status.busy = true;
    status('computing the ' + key + ' transport' + (p.active ? ': ' + p.label + ' ' + Math.round(100 * p.fraction) + ' %' : '') + ' ...');
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
  view.axis = normalize(d.axis);
  view.q = quatAbout(view.axis, Number(initial.get('angle')));
  $('frame').width = d.width;
  $('frame').height = d.height;
  for (const id of ['lmax', 'terms', 'view', 'coef', 'exposure', 'tonemap', 'env']) $(id).addEventListener('input', changed);
  for (const id of ['basis', 'mode']) $(id).addEventListener('change', ensureTransport);
  $('angle').addEventListener('input', () => {
    view.q = quatAbout(view.axis, Number($('angle').value));
    changed();
  });
  $('play').addEventListener('click', () => {
    view.playing = !view.playing;
    $('play').textContent = view.playing ? 'pause' : 'play';
  });
  $('reset').addEventListener('click', () => { view.q = [0, 0, 0, 1]; changed(); });
  $('measure').addEventListener('click', measure);
  $('showcommand').addEventListener('click', async () => {
    $('command').value = (await (await fetch('/command?' + query())).text()).trim();
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
      let q = view.q;
      if (dx) q = quatMul(quatAbout(c.up, dx * DEGREES_PER_PIXEL), q);
      if (dy) q = quatMul(quatAbout(right, dy * DEGREES_PER_PIXEL), q);
      view.q = q;
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
  view.state = await (await fetch('/state')).json();
  setupControls();
  changed();
  requestAnimationFrame(tick);
}
start();
