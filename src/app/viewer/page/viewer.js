'use strict';
// The viewer's page. It holds the camera, the lights and the choices; the server renders.
// Each pane keeps one WebSocket to the frame stream and one request in flight on it: a change
// made meanwhile is sent, as the newest state, when that request's frame arrives.
// Camera and lights are in the scene's world coordinates, with scene-format keys
// (docs/scene-format.md), so a frame's request is also a scene file's camera and lights.

const $ = (id) => document.getElementById(id);

// ---- Vectors -------------------------------------------------------------------------------

const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) =>
  [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => scale(a, 1 / Math.hypot(a[0], a[1], a[2]));

// The camera's pixel convention, as Camera::pixel_grid in the C++ code: the ray through the
// centre of pixel (c, w) is f + (x0 + c step) r + (y0 - w step) u.
function cameraFrame(camera) {
  const f = norm(sub(camera.look_at, camera.position));
  const r = norm(cross(f, camera.up));
  const u = cross(r, f);
  const t = Math.tan(camera.fov_y_deg * Math.PI / 360);
  const step = 2 * t / camera.height;
  return { f, r, u, step, x0: -t * camera.width / camera.height + 0.5 * step, y0: t - 0.5 * step };
}

// The image position (pixel units, 0 at the left and top edges) of world point p, or null
// when p is behind the camera.
function project(camera, p) {
  const k = cameraFrame(camera);
  const d = sub(p, camera.position);
  const z = dot(d, k.f);
  if (z <= 1e-9) return null;
  return [(dot(d, k.r) / z - k.x0) / k.step + 0.5, (k.y0 - dot(d, k.u) / z) / k.step + 0.5];
}

// The ray through image position (x, y), as project() gives them.
function pixelRay(camera, x, y) {
  const k = cameraFrame(camera);
  const a = k.x0 + (x - 0.5) * k.step, b = k.y0 - (y - 0.5) * k.step;
  return norm(add(k.f, add(scale(k.r, a), scale(k.u, b))));
}

// ---- State ---------------------------------------------------------------------------------

const state = {
  scene: null,
  camera: null,
  lights: [],  // {light: scene-format light, enabled}
  selected: 0,
  layout: 'one',
  methods: ['volume', 'raytrace'],
  view: 'shaded',
  settings: {},  // method -> {key: value}
  sun: { on: false, light: null, text: '' },
  mismatch: false,
};

// What the page's tests and latency measurement read.
const stats = { latencies: [], drawn: 0 };
window.shadowkitViewer = { state, stats, panes: [], project };

function enabledLights() {
  if (state.sun.on) return state.sun.light ? [state.sun.light] : [];
  return state.lights.filter((l) => l.enabled).map((l) => l.light);
}

// The index, among the frame's lights, of the light the mask and difference views show.
function shownLight() {
  if (state.sun.on) return 0;
  const chosen = state.lights[state.selected];
  if (chosen && chosen.enabled) return state.lights.slice(0, state.selected).filter((l) => l.enabled).length;
  return 0;
}

function frameRequest(pane, id) {
  const method = state.methods[pane];
  const lights = enabledLights();
  const request = {
    id, camera: state.camera, lights, method,
    settings: state.settings[method] || {},
    view: lights.length ? state.view : 'shaded',
  };
  if (request.view !== 'shaded') request.light = shownLight();
  if (state.mismatch) request.mismatch = true;
  return request;
}

// ---- Panes: one stream each ----------------------------------------------------------------

class Pane {
  constructor(index) {
    this.index = index;
    this.nextId = 1;
    this.drawnId = 0;
    this.sent = new Map();  // id -> time of the change it shows
    this.pendingSince = null;  // time of the oldest change not yet sent
    this.inFlight = null;  // the id of the request sent and not yet answered
    this.recent = [];  // paint times of the last second's frames
    this.element = document.createElement('div');
    this.element.className = 'pane';
    this.element.innerHTML = '<div class="frame"><canvas class="image"></canvas>' +
      '<canvas class="overlay"></canvas></div><div class="caption"></div>';
    this.canvas = this.element.querySelector('canvas.image');
    this.overlay = this.element.querySelector('canvas.overlay');
    this.caption = this.element.querySelector('.caption');
    this.info = null;
    $('panes').appendChild(this.element);
    attachPointer(this);
    this.connect();
  }

  connect() {
    this.socket = new WebSocket(state.scene.stream);
    this.socket.binaryType = 'arraybuffer';
    this.socket.onopen = () => {
      setStatus('connected');
      this.inFlight = null;  // what a closed socket had in flight will not come
      this.pendingSince ??= performance.now();
      this.send();
    };
    this.socket.onmessage = (event) => this.received(event.data);
    this.socket.onclose = () => {
      setStatus('disconnected; retrying', true);
      setTimeout(() => this.connect(), 1000);
    };
  }

  // Something the frame shows changed at time t: send the state now, or when the frame in
  // flight arrives. (Chromium already delivers pointer moves once an animation frame.)
  changed(t) {
    if (this.pendingSince !== null) return;
    this.pendingSince = t;
    this.send();
  }

  send() {
    if (this.socket.readyState !== WebSocket.OPEN || this.inFlight !== null) return;
    const id = this.nextId++;
    this.sent.set(id, this.pendingSince);
    this.pendingSince = null;
    this.inFlight = id;
    this.socket.send(JSON.stringify(frameRequest(this.index, id)));
  }

  // The request in flight was answered: the newest change, if any, goes now.
  answered() {
    this.inFlight = null;
    if (this.pendingSince !== null) this.send();
  }

  async received(data) {
    const length = new DataView(data).getUint32(0, true);
    const info = JSON.parse(new TextDecoder().decode(new Uint8Array(data, 4, length)));
    this.answered();
    if (info.error) {
      this.caption.innerHTML = '';
      this.caption.append(Object.assign(document.createElement('span'),
        { className: 'error', textContent: info.error }));
      return;
    }
    const png = new Blob([new Uint8Array(data, 4 + length)], { type: 'image/png' });
    const bitmap = await createImageBitmap(png,
      { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
    if (info.id < this.drawnId) return;  // a newer frame is already on screen
    this.draw(bitmap, info);
  }

  draw(bitmap, info) {
    this.drawnId = info.id;
    this.canvas.width = bitmap.width;
    this.canvas.height = bitmap.height;
    this.canvas.getContext('2d').drawImage(bitmap, 0, 0);
    this.info = info;
    const changedAt = this.sent.get(info.id);
    this.sent.delete(info.id);
    requestAnimationFrame((paint) => {
      if (changedAt !== undefined) stats.latencies.push(paint - changedAt);
      this.recent.push(paint);
      while (this.recent.length && this.recent[0] < paint - 1000) this.recent.shift();
      stats.drawn++;
      this.latency = changedAt === undefined ? null : paint - changedAt;
      showFigures();
    });
    this.caption.textContent = `${info.method}, ${info.view}` +
      (info.warnings.length ? ` — ${info.warnings.join('; ')}` : '');
    drawGizmos(this);
  }

  // An image that is not a frame (the sun hours), drawn until the next frame.
  showImage(bitmap, caption) {
    this.drawnId = this.nextId;
    this.canvas.width = bitmap.width;
    this.canvas.height = bitmap.height;
    this.canvas.getContext('2d').drawImage(bitmap, 0, 0);
    this.caption.textContent = caption;
    this.overlay.width = bitmap.width;
    this.overlay.height = bitmap.height;
  }

  remove() {
    this.socket.onclose = null;
    this.socket.close();
    this.element.remove();
  }
}

function changed(event) {
  const t = event && event.timeStamp !== undefined ? event.timeStamp : performance.now();
  for (const pane of window.shadowkitViewer.panes) pane.changed(t);
  for (const pane of window.shadowkitViewer.panes) drawGizmos(pane);
}

function setStatus(text, error = false) {
  $('connection').textContent = text;
  $('connection').classList.toggle('error', error);
}

// ---- Gizmos and the pointer ----------------------------------------------------------------

const GIZMO_RADIUS = 9;  // CSS pixels

function cssToImage(pane) {
  return pane.canvas.width / pane.canvas.getBoundingClientRect().width;
}

function drawGizmos(pane) {
  const o = pane.overlay;
  o.width = pane.canvas.width || state.camera.width;
  o.height = pane.canvas.height || state.camera.height;
  const g = o.getContext('2d');
  const px = cssToImage(pane) || 1;
  const groundY = state.scene.bounds.lo[1];
  if (state.sun.on) return;
  state.lights.forEach((entry, i) => {
    if (!entry.enabled || entry.light.type !== 'point') return;
    const p = entry.light.position;
    const at = project(state.camera, p);
    const foot = project(state.camera, [p[0], groundY, p[2]]);
    if (!at) return;
    const colour = i === state.selected ? '#f2b84b' : '#cdd0d6';
    g.strokeStyle = colour;
    g.lineWidth = 1.5 * px;
    if (foot) {
      g.setLineDash([4 * px, 3 * px]);
      g.beginPath(); g.moveTo(at[0], at[1]); g.lineTo(foot[0], foot[1]); g.stroke();
      g.setLineDash([]);
      g.beginPath(); g.ellipse(foot[0], foot[1], 6 * px, 3 * px, 0, 0, 2 * Math.PI); g.stroke();
    }
    g.fillStyle = colour;
    g.beginPath(); g.arc(at[0], at[1], GIZMO_RADIUS * px * 0.6, 0, 2 * Math.PI); g.fill();
    g.beginPath(); g.arc(at[0], at[1], GIZMO_RADIUS * px, 0, 2 * Math.PI); g.stroke();
  });
}

// The point light whose handle is under image position (x, y), or -1.
function lightAt(pane, x, y) {
  const reach = GIZMO_RADIUS * 1.5 * cssToImage(pane);
  let best = -1, bestDistance = reach;
  state.lights.forEach((entry, i) => {
    if (!entry.enabled || entry.light.type !== 'point' || state.sun.on) return;
    const at = project(state.camera, entry.light.position);
    if (!at) return;
    const d = Math.hypot(at[0] - x, at[1] - y);
    if (d <= bestDistance) { best = i; bestDistance = d; }
  });
  return best;
}

// A point light dragged across the horizontal plane through it, or with Shift up and down.
function dragLight(entry, from, to, shift) {
  const p = entry.light.position;
  if (shift) {
    const depth = dot(sub(p, state.camera.position), cameraFrame(state.camera).f);
    const perPixel = depth * cameraFrame(state.camera).step;
    entry.light.position = [p[0], p[1] - (to[1] - from[1]) * perPixel, p[2]];
    return;
  }
  const ray = pixelRay(state.camera, to[0], to[1]);
  const up = [0, 1, 0];
  const denominator = dot(ray, up);
  if (Math.abs(denominator) < 1e-6) return;
  const t = dot(sub(p, state.camera.position), up) / denominator;
  if (t <= 0) return;
  const hit = add(state.camera.position, scale(ray, t));
  entry.light.position = [hit[0], p[1], hit[2]];
}

function orbit(dx, dy) {
  const c = state.camera;
  const axis = norm(c.up);
  let offset = sub(c.position, c.look_at);
  const turn = (v, k, angle) =>  // Rodrigues: v turned by angle around unit k
    add(add(scale(v, Math.cos(angle)), scale(cross(k, v), Math.sin(angle))),
      scale(k, dot(k, v) * (1 - Math.cos(angle))));
  offset = turn(offset, axis, -dx * 0.006);
  const right = norm(cross(sub(c.look_at, c.position), axis));
  const tilted = turn(offset, right, -dy * 0.006);
  const elevation = Math.asin(dot(norm(tilted), axis));
  if (Math.abs(elevation) < 1.45) offset = tilted;
  c.position = add(c.look_at, offset);
}

function pan(dx, dy) {
  const c = state.camera;
  const k = cameraFrame(c);
  const distance = Math.hypot(...sub(c.position, c.look_at));
  const move = add(scale(k.r, -dx * k.step * distance), scale(k.u, dy * k.step * distance));
  c.position = add(c.position, move);
  c.look_at = add(c.look_at, move);
}

function zoom(amount) {
  const c = state.camera;
  const offset = scale(sub(c.position, c.look_at), Math.exp(amount * 0.001));
  if (Math.hypot(...offset) > 1e-6 * state.scene.diagonal) c.position = add(c.look_at, offset);
}

function attachPointer(pane) {
  const o = pane.overlay;
  let drag = null;
  const imagePoint = (event) => {
    const rect = o.getBoundingClientRect();
    const s = cssToImage(pane);
    return [(event.clientX - rect.left) * s, (event.clientY - rect.top) * s];
  };
  o.addEventListener('contextmenu', (event) => event.preventDefault());
  o.addEventListener('pointerdown', (event) => {
    const at = imagePoint(event);
    const light = event.button === 0 ? lightAt(pane, at[0], at[1]) : -1;
    if (light >= 0) selectLight(light);
    drag = { kind: light >= 0 ? 'light' : event.button === 0 ? 'orbit' : 'pan', last: at,
      client: [event.clientX, event.clientY] };
    o.setPointerCapture(event.pointerId);
  });
  o.addEventListener('pointermove', (event) => {
    if (!drag) return;
    const at = imagePoint(event);
    const client = [event.clientX, event.clientY];
    if (drag.kind === 'light') {
      dragLight(state.lights[state.selected], drag.last, at, event.shiftKey);
      showLights();
    } else if (drag.kind === 'orbit') {
      orbit(client[0] - drag.client[0], client[1] - drag.client[1]);
    } else {
      pan(at[0] - drag.last[0], at[1] - drag.last[1]);
    }
    drag.last = at;
    drag.client = client;
    changed(event);
  });
  o.addEventListener('pointerup', () => { drag = null; });
  o.addEventListener('wheel', (event) => {
    event.preventDefault();
    zoom(event.deltaY);
    changed(event);
  }, { passive: false });
}

// ---- Controls ------------------------------------------------------------------------------

function selectLight(i) {
  state.selected = i;
  showLights();
}

function numberInput(value, onInput) {
  const input = Object.assign(document.createElement('input'),
    { type: 'number', step: 'any', value: String(+value.toPrecision(6)) });
  input.addEventListener('change', (event) => {
    if (Number.isFinite(+input.value) && input.value !== '') { onInput(+input.value); changed(event); }
  });
  return input;
}

// Azimuth (degrees clockwise from -Z seen from above) and elevation of the way toward a
// directional light, as the sun study orients the sun with north at 0.
function anglesOf(direction) {
  const toward = scale(norm(direction), -1);
  const elevation = Math.asin(Math.max(-1, Math.min(1, toward[1]))) * 180 / Math.PI;
  const azimuth = (Math.atan2(toward[0], -toward[2]) * 180 / Math.PI + 360) % 360;
  return { azimuth, elevation };
}

function directionOf(azimuth, elevation) {
  const a = azimuth * Math.PI / 180, e = elevation * Math.PI / 180;
  return [-Math.cos(e) * Math.sin(a), -Math.sin(e), Math.cos(e) * Math.cos(a)];
}

function showLights() {
  const box = $('lights');
  box.innerHTML = '';
  state.lights.forEach((entry, i) => {
    const div = document.createElement('div');
    div.className = 'light' + (i === state.selected ? ' selected' : '');
    const head = document.createElement('label');
    head.className = 'inline';
    const enabled = Object.assign(document.createElement('input'),
      { type: 'checkbox', checked: entry.enabled });
    enabled.addEventListener('change', (event) => { entry.enabled = enabled.checked; changed(event); });
    const pick = Object.assign(document.createElement('input'),
      { type: 'radio', name: 'selected-light', checked: i === state.selected, title: 'select' });
    pick.addEventListener('change', (event) => { selectLight(i); changed(event); });
    head.append(enabled, ` L${i} ${entry.light.type} `, pick, ' selected');
    div.append(head);
    if (entry.light.type === 'point') {
      const row = document.createElement('div');
      row.className = 'xyz';
      [0, 1, 2].forEach((axis) => row.append(numberInput(entry.light.position[axis], (v) => {
        entry.light.position[axis] = v;
      })));
      div.append(row);
    } else {
      const angles = anglesOf(entry.light.direction);
      for (const [name, lo, hi] of [['azimuth', 0, 360], ['elevation', 1, 89.9]]) {
        const label = document.createElement('label');
        const slider = Object.assign(document.createElement('input'),
          { type: 'range', min: lo, max: hi, step: 0.1, value: angles[name] });
        slider.addEventListener('input', (event) => {
          const a = anglesOf(entry.light.direction);
          a[name] = +slider.value;
          entry.light.direction = directionOf(a.azimuth, a.elevation);
          changed(event);
        });
        label.append(`${name} `, slider);
        div.append(label);
      }
    }
    box.append(div);
  });
  for (const pane of window.shadowkitViewer.panes) drawGizmos(pane);
}

function showSettings() {
  const box = $('settings');
  box.innerHTML = '';
  const shown = state.layout === 'two' ? state.methods : [state.methods[0]];
  for (const name of new Set(shown)) {
    const method = state.scene.methods.find((m) => m.name === name);
    const values = state.settings[name] || (state.settings[name] = {});
    if (!method.settings.length) box.append(Object.assign(document.createElement('p'),
      { className: 'hint', textContent: `${name} has no settings` }));
    for (const s of method.settings) {
      const label = document.createElement('label');
      let input;
      if (s.choices.length) {
        input = document.createElement('select');
        if (!s.default) input.append(new Option('(default)', ''));
        for (const c of s.choices) input.append(new Option(c + (c === s.default ? ' (default)' : ''), c));
        input.value = values[s.key] ?? s.default;
      } else {
        input = Object.assign(document.createElement('input'),
          { type: 'text', placeholder: s.default || 'automatic', value: values[s.key] ?? '', title: s.range });
      }
      input.addEventListener('change', (event) => {
        if (input.value === '' || input.value === s.default) delete values[s.key];
        else values[s.key] = input.value;
        changed(event);
      });
      label.append(`${name}.${s.key}`, input);
      box.append(label);
    }
  }
}

function showPanes() {
  const panes = window.shadowkitViewer.panes;
  const wanted = state.layout === 'two' ? 2 : 1;
  while (panes.length > wanted) panes.pop().remove();
  while (panes.length < wanted) panes.push(new Pane(panes.length));
  document.body.classList.toggle('two', state.layout === 'two');
  showSettings();
}

function showFigures() {
  const rows = [];
  const ms = (v) => (v === undefined ? '–' : v.toFixed(1) + ' ms');
  const sum = (lights, key) => lights.reduce((s, l) => s + l[key], 0);
  for (const pane of window.shadowkitViewer.panes) {
    const info = pane.info;
    if (!info) continue;
    const lights = info.lights || [];
    rows.push([`<b>${info.method}</b>`, `${info.width}×${info.height}`]);
    rows.push(['scan conversion', ms(info.scan_ms)]);
    rows.push(['build, all lights', ms(sum(lights, 'build_ms'))]);
    rows.push(['shade, all lights', ms(sum(lights, 'shade_ms'))]);
    rows.push(['image and PNG', ms(info.image_ms + info.encode_ms)]);
    rows.push(['move to screen', pane.latency == null ? '–' : ms(pane.latency)]);
    rows.push(['frames per second', String(pane.recent.length)]);
    for (const l of lights) {
      if (l.mismatch_interior_pct !== undefined) {
        rows.push([`L${l.light} interior mismatch`, l.mismatch_interior_pct.toFixed(4) + ' %']);
      }
    }
  }
  $('figures').innerHTML = rows.map((r) => `<tr><td>${r[0]}</td><td>${r[1]}</td></tr>`).join('');
}

// ---- Sun mode ------------------------------------------------------------------------------

function site() {
  return { latitude: +$('sun-lat').value, longitude: +$('sun-lon').value,
    utc_offset: +$('sun-offset').value, north: +$('sun-north').value };
}

function sunTime() {
  const minutes = +$('sun-time').value;
  const hhmm = `${String(Math.floor(minutes / 60)).padStart(2, '0')}:${String(minutes % 60).padStart(2, '0')}`;
  $('sun-time-text').textContent = hhmm;
  return `${$('sun-date').value}T${hhmm}`;
}

async function post(path, body) {
  const response = await fetch(path, { method: 'POST', body: JSON.stringify(body) });
  if (!response.ok) throw new Error((await response.text()).trim());
  return response;
}

async function moveSun(event) {
  if (!state.sun.on) { changed(event); return; }
  try {
    const sun = await (await post('/api/sun', { site: site(), time: sunTime() })).json();
    state.sun.light = sun.elevation_deg > 0 ? { type: 'directional', direction: sun.direction } : null;
    $('sun-position').textContent = `azimuth ${sun.azimuth_deg.toFixed(1)}°, elevation ` +
      `${sun.elevation_deg.toFixed(1)}°` + (state.sun.light ? '' : ': below the horizon');
  } catch (error) {
    $('sun-position').textContent = error.message;
    state.sun.light = null;
  }
  changed(event);
}

async function showSunHours() {
  const pane = window.shadowkitViewer.panes[0];
  pane.caption.textContent = 'computing the day\'s sun hours…';
  try {
    const response = await post('/api/sun-hours',
      { site: site(), time: sunTime(), step_minutes: 15, camera: state.camera });
    const bitmap = await createImageBitmap(await response.blob(),
      { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
    pane.showImage(bitmap, `sun hours on ${$('sun-date').value}, every 15 minutes`);
  } catch (error) {
    pane.caption.textContent = error.message;
  }
}

// ---- Start ---------------------------------------------------------------------------------

function fillMethods() {
  for (const [i, select] of [$('method-0'), $('method-1')].entries()) {
    for (const m of state.scene.methods) select.append(new Option(m.name, m.name));
    select.value = state.methods[i];
    select.addEventListener('change', (event) => {
      state.methods[i] = select.value;
      showSettings();
      changed(event);
    });
  }
}

function bindControls() {
  $('layout').addEventListener('change', (event) => {
    state.layout = $('layout').value;
    showPanes();
    changed(event);
  });
  $('view').addEventListener('change', (event) => { state.view = $('view').value; changed(event); });
  $('size').addEventListener('change', (event) => {
    const [w, h] = $('size').value.split('x').map(Number);
    state.camera.width = w;
    state.camera.height = h;
    changed(event);
  });
  $('mismatch').addEventListener('click', (event) => {
    state.mismatch = !state.mismatch;
    $('mismatch').textContent = state.mismatch ? 'Stop comparing' : 'Compare with raytrace';
    changed(event);
  });
  $('sun-mode').addEventListener('change', (event) => {
    state.sun.on = $('sun-mode').checked;
    document.body.classList.toggle('sun', state.sun.on);
    moveSun(event);
  });
  for (const id of ['sun-lat', 'sun-lon', 'sun-offset', 'sun-north', 'sun-date']) {
    $(id).addEventListener('change', moveSun);
  }
  $('sun-time').addEventListener('input', moveSun);
  $('sun-hours').addEventListener('click', showSunHours);
}

async function start() {
  const scene = await (await fetch('/api/scene')).json();
  const lo = scene.bounds.lo, hi = scene.bounds.hi;
  scene.diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
  state.scene = scene;
  state.camera = scene.camera;
  state.lights = scene.lights.map((light) => ({ light, enabled: true }));
  if (scene.site) {
    $('sun-lat').value = scene.site.latitude;
    $('sun-lon').value = scene.site.longitude;
    $('sun-offset').value = scene.site.utc_offset;
    $('sun-north').value = scene.site.north;
  }
  $('scene-name').textContent = `${scene.name}: ${scene.polygons.toLocaleString()} polygons`;
  const size = `${scene.camera.width}x${scene.camera.height}`;
  if (![...$('size').options].some((o) => o.value === size)) $('size').add(new Option(size.replace('x', ' × '), size));
  $('size').value = size;
  fillMethods();
  bindControls();
  showLights();
  showPanes();
  sunTime();
}

start().catch((error) => setStatus(`cannot start: ${error.message}`, true));
