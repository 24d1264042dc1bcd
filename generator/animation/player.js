// The player of `eomgen run --animate`: draws a model's scene (animation/scene.hpp) at each frame on a canvas,
// in 2-D for planar scenes and with an orbit camera (orthographic) in 3-D. Everything it shows of the model's text
// is set with textContent: a model file is a stranger's text (docs/security.md). URL hash options, for people and
// for the browser test (tests/animation/): #t=1.5 seeks there and pauses; #size=800x500 fixes the canvas; #probe writes the view and the drawn
// positions of the points as JSON into the element #probe; #bench times the drawing of every frame.
(function () {
  'use strict';
  const errors = [];
  window.addEventListener('error', function (e) { errors.push(String(e.message)); });
  const data = JSON.parse(document.getElementById('eomgen-data').textContent);
  const canvas = document.getElementById('view');
  const ctx = canvas.getContext('2d');
  const slider = document.getElementById('scrub');
  const playButton = document.getElementById('play');
  const speedSelect = document.getElementById('speed');
  const timeText = document.getElementById('time');
  const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf'];

  document.title = data.title + ' (eomgen animation)';
  document.getElementById('title').textContent = data.title;
  const equations = document.getElementById('equations');
  for (const [name, text] of data.equations) {
    const li = document.createElement('li');
    li.textContent = name + ' = ' + text;
    equations.appendChild(li);
  }

  const legend = document.getElementById('legend');
  for (const [text, colour] of data.legend) {  // an ensemble's members
    const li = document.createElement('li');
    li.textContent = text;
    li.style.color = colour;
    legend.appendChild(li);
  }

  const n = data.t.length;
  const items = data.items.map(function (item, k) {
    return Object.assign({}, item, { v: Float64Array.from(item.v), colour: item.colour || palette[k % palette.length] });
  });
  const readout = data.readout;
  const readoutCells = [];
  {
    const table = document.getElementById('readout');
    for (let c = 0; c < readout.names.length; ++c) {
      const row = table.insertRow();
      row.insertCell().textContent = readout.names[c] + (readout.units[c] ? ' [' + readout.units[c] + ']' : '');
      readoutCells.push(row.insertCell());
    }
  }

  // Vectors
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const unit = (a) => { const l = Math.hypot(a[0], a[1], a[2]); return l > 0 ? scale(a, 1 / l) : [0, 0, 1]; };

  // An item's numbers at frame f, and its points
  const numbers = (item, f) => item.v.subarray(f * item.stride, (f + 1) * item.stride);
  const pointAt = (v, k) => [v[3 * k], v[3 * k + 1], v[3 * k + 2]];
  // A solid's point ρ (body axes) in space: centre + Aᵀ ρ
  const bodyPoint = (v, r) => [v[0] + v[3] * r[0] + v[4] * r[1] + v[5] * r[2],
                               v[1] + v[6] * r[0] + v[7] * r[1] + v[8] * r[2],
                               v[2] + v[9] * r[0] + v[10] * r[1] + v[11] * r[2]];

  // The scene's extent at each frame and over all: where a scene travels far beyond its own size (a bicycle
  // riding off), the camera follows it, frame by frame; otherwise it holds the whole motion in view.
  const frameLo = [], frameHi = [];
  let lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  let frameRadius = 0;
  const frameExtent = [0, 0, 0];
  for (let f = 0; f < n; ++f) {
    let flo = [Infinity, Infinity, Infinity], fhi = [-Infinity, -Infinity, -Infinity];
    const grow = (p, r) => { for (let i = 0; i < 3; ++i) { flo[i] = Math.min(flo[i], p[i] - r); fhi[i] = Math.max(fhi[i], p[i] + r); } };
    for (const item of items) {
      const v = numbers(item, f);
      if (item.kind === 'point' || item.kind === 'trace') grow(pointAt(v, 0), item.has_radius ? v[3] : 0);
      else if (item.kind === 'polyline' || item.kind === 'spring') for (let k = 0; k < item.stride / 3; ++k) grow(pointAt(v, k), 0);
      else if (item.kind === 'circle') grow(pointAt(v, 0), Math.abs(v[6]));
      else if (item.kind === 'solid') {
        let r = 0;
        for (let k = 12; k < item.stride; ++k) r = Math.max(r, Math.abs(v[k]));
        grow([v[0], v[1], v[2]], item.shape === 'ellipsoid' ? r : item.shape === 'cone' ? 1.75 * r : 0.75 * r);
      }
    }
    if (!isFinite(flo[0])) { flo = [-1, -1, -1]; fhi = [1, 1, 1]; }
    frameLo.push(flo); frameHi.push(fhi);
    for (let i = 0; i < 3; ++i) {
      lo[i] = Math.min(lo[i], flo[i]); hi[i] = Math.max(hi[i], fhi[i]);
      frameExtent[i] = Math.max(frameExtent[i], fhi[i] - flo[i]);
    }
    frameRadius = Math.max(frameRadius, 0.5 * Math.hypot(fhi[0] - flo[0], fhi[1] - flo[1], fhi[2] - flo[2]));
  }
  if (!isFinite(lo[0])) { lo = [-1, -1, -1]; hi = [1, 1, 1]; }
  const wholeExtent = sub(hi, lo);
  const wholeRadius = Math.max(1e-9, 0.5 * Math.hypot(wholeExtent[0], wholeExtent[1], wholeExtent[2]));
  const follow = wholeRadius > 2.5 * Math.max(frameRadius, 1e-12);
  const extent = follow ? frameExtent : wholeExtent;
  const radius = follow ? Math.max(frameRadius, 1e-9) : wholeRadius;
  const centreAt = (f) => follow ? scale(add(frameLo[f], frameHi[f]), 0.5) : scale(add(lo, hi), 0.5);
  let centre = centreAt(0);

  // The camera
  const up = unit(data.up);
  const e1 = unit(Math.abs(up[0]) < 0.9 ? cross(up, [1, 0, 0]) : cross(up, [0, 1, 0]));
  const e2 = cross(up, e1);
  const view = { az: -0.6, el: 0.35, zoom: 1, panX: 0, panY: 0 };
  let right = [1, 0, 0], screenUp = [0, 1, 0], toViewer = [0, 0, 1];
  let W = 0, H = 0, fit = 1;
  function layout() {
    const ratio = window.devicePixelRatio || 1;
    W = Math.max(200, Math.floor(canvas.clientWidth));
    H = Math.max(200, Math.floor(canvas.clientHeight));
    canvas.width = Math.round(W * ratio);
    canvas.height = Math.round(H * ratio);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    if (data.planar) {
      const big = Math.max(extent[0], extent[1], 1e-9);
      const w = Math.max(extent[0], 0.05 * big), h = Math.max(extent[1], 0.05 * big);
      fit = 0.9 * Math.min(W / w, H / h);
    } else {
      fit = 0.45 * Math.min(W, H) / radius;
    }
  }
  function orient() {
    if (data.planar) { right = [1, 0, 0]; screenUp = [0, 1, 0]; toViewer = [0, 0, 1]; return; }
    const horizontal = add(scale(e1, Math.cos(view.az)), scale(e2, Math.sin(view.az)));
    toViewer = add(scale(horizontal, Math.cos(view.el)), scale(up, Math.sin(view.el)));
    right = unit(cross(up, toViewer));
    if (Math.abs(Math.cos(view.el)) < 1e-6) right = unit(cross(e2, toViewer));
    screenUp = cross(toViewer, right);
  }
  const pixelScale = () => fit * view.zoom;
  // Screen position (CSS pixels) and depth (larger: nearer the viewer) of a point
  function project(p) {
    const d = sub(p, centre);
    const s = pixelScale();
    return [W / 2 + view.panX + s * dot(d, right), H / 2 + view.panY - s * dot(d, screenUp), dot(d, toViewer)];
  }

  function polyline(points, close) {
    ctx.beginPath();
    points.forEach(function (p, i) { const s = project(p); if (i === 0) ctx.moveTo(s[0], s[1]); else ctx.lineTo(s[0], s[1]); });
    if (close) ctx.closePath();
  }
  function ring(v, radius, z, count) {  // a circle of a solid, in its x-y plane at height z
    const pts = [];
    for (let k = 0; k < count; ++k) { const a = 2 * Math.PI * k / count; pts.push(bodyPoint(v, [radius * Math.cos(a), radius * Math.sin(a), z])); }
    return pts;
  }
  function label(text, p, colour) {
    if (!text) return;
    const s = project(p);
    ctx.fillStyle = '#222';
    ctx.font = '12px sans-serif';
    ctx.fillText(text, s[0] + 8, s[1] - 8);
  }
  function shade(colour, normal) {  // a face's colour, darker as it turns away from the viewer
    const k = 0.55 + 0.45 * Math.abs(dot(unit(normal), toViewer));
    const c = parseInt(colour.slice(1), 16);
    const r = Math.round(((c >> 16) & 255) * k), g = Math.round(((c >> 8) & 255) * k), b = Math.round((c & 255) * k);
    return 'rgb(' + r + ',' + g + ',' + b + ')';
  }

  function drawGround(item) {
    const h = item.v[0];
    ctx.strokeStyle = '#999';
    ctx.lineWidth = 1;
    if (data.planar) {
      const y = project([0, h, 0])[1];
      ctx.beginPath(); ctx.moveTo(0, y); ctx.lineTo(W, y); ctx.stroke();
      return;
    }
    // Lines fixed in space, a round spacing apart, around the centre: under a following camera they pass by.
    const axis = { x: 0, y: 1, z: 2 }[item.axis];
    const a = (axis + 1) % 3, b = (axis + 2) % 3;
    const half = 1.2 * radius;
    const rough = half / 4, power = Math.pow(10, Math.floor(Math.log10(rough)));
    const step = [1, 2, 5, 10].map(function (m) { return m * power; }).find(function (x) { return x >= rough; });
    for (const [u, w] of [[a, b], [b, a]]) {
      for (let s = Math.ceil((centre[u] - half) / step) * step; s <= centre[u] + half; s += step) {
        const p = [0, 0, 0], q = [0, 0, 0];
        p[axis] = q[axis] = h;
        p[u] = q[u] = s;
        p[w] = centre[w] - half; q[w] = centre[w] + half;
        polyline([p, q]); ctx.stroke();
      }
    }
  }

  function drawSolid(item, v) {
    const d = Array.from(v.subarray(12));
    ctx.strokeStyle = item.colour;
    ctx.fillStyle = item.colour;
    ctx.lineWidth = 2;
    if (item.shape === 'box') {
      const h = [d[0] / 2, d[1] / 2, d[2] / 2];
      const corner = (i, j, k) => bodyPoint(v, [i * h[0], j * h[1], k * h[2]]);
      const faces = [[[1, -1, -1], [1, 1, -1], [1, 1, 1], [1, -1, 1]], [[-1, -1, -1], [-1, -1, 1], [-1, 1, 1], [-1, 1, -1]],
                     [[-1, 1, -1], [-1, 1, 1], [1, 1, 1], [1, 1, -1]], [[-1, -1, -1], [1, -1, -1], [1, -1, 1], [-1, -1, 1]],
                     [[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], [[-1, -1, -1], [-1, 1, -1], [1, 1, -1], [1, -1, -1]]]
        .map(function (face) {
          const pts = face.map(function (c) { return corner(c[0], c[1], c[2]); });
          const depth = pts.reduce(function (s, p) { return s + project(p)[2]; }, 0) / 4;
          return { pts: pts, depth: depth, normal: cross(sub(pts[1], pts[0]), sub(pts[3], pts[0])) };
        })
        .sort(function (x, y) { return x.depth - y.depth; });
      for (const face of faces) {
        polyline(face.pts, true);
        ctx.fillStyle = shade(item.colour, face.normal);
        ctx.globalAlpha = 0.85; ctx.fill(); ctx.globalAlpha = 1;
        ctx.strokeStyle = '#333'; ctx.lineWidth = 1; ctx.stroke();
      }
    } else if (item.shape === 'ellipsoid') {
      // The outline of {c + Aᵀ diag(a) u : |u| ≤ 1} seen along toViewer: the ellipse S = P Aᵀ D² A Pᵀ
      const cols = [0, 1, 2].map(function (k) { return scale([v[3 + k], v[6 + k], v[9 + k]], d[k]); });
      const pr = cols.map(function (c) { return [dot(c, right), dot(c, screenUp)]; });
      let sxx = 0, sxy = 0, syy = 0;
      for (const p of pr) { sxx += p[0] * p[0]; sxy += p[0] * p[1]; syy += p[1] * p[1]; }
      const mean = (sxx + syy) / 2, diff = Math.hypot((sxx - syy) / 2, sxy);
      const angle = 0.5 * Math.atan2(2 * sxy, sxx - syy);
      const c = project([v[0], v[1], v[2]]), s = pixelScale();
      ctx.beginPath();
      ctx.ellipse(c[0], c[1], s * Math.sqrt(Math.max(mean + diff, 0)), s * Math.sqrt(Math.max(mean - diff, 0)), -angle, 0, 2 * Math.PI);
      ctx.globalAlpha = 0.35; ctx.fill(); ctx.globalAlpha = 1; ctx.stroke();
      ctx.lineWidth = 1; ctx.strokeStyle = '#333';
      for (const [i, j] of [[0, 1], [1, 2], [2, 0]]) {  // its principal circles, so its turning shows
        const pts = [];
        for (let k = 0; k < 48; ++k) {
          const a = 2 * Math.PI * k / 48, r = [0, 0, 0];
          r[i] = d[i] * Math.cos(a); r[j] = d[j] * Math.sin(a);
          pts.push(bodyPoint(v, r));
        }
        polyline(pts, true); ctx.stroke();
      }
    } else if (item.shape === 'rod') {
      ctx.lineWidth = 5;
      polyline([bodyPoint(v, [0, 0, -d[0] / 2]), bodyPoint(v, [0, 0, d[0] / 2])]); ctx.stroke();
    } else if (item.shape === 'disk' || item.shape === 'ring') {
      polyline(ring(v, d[0], 0, 48), true);
      if (item.shape === 'disk') { ctx.globalAlpha = 0.3; ctx.fill(); ctx.globalAlpha = 1; }
      ctx.stroke();
      ctx.lineWidth = 1;
      for (let k = 0; k < 4; ++k) {  // spokes: a wheel's turning shows
        const a = Math.PI * k / 2;
        polyline([bodyPoint(v, [0, 0, 0]), bodyPoint(v, [d[0] * Math.cos(a), d[0] * Math.sin(a), 0])]); ctx.stroke();
      }
    } else if (item.shape === 'cylinder' || item.shape === 'cone') {
      const r = d[0], h = d[1];
      const base = item.shape === 'cone' ? -h / 4 : -h / 2, top = item.shape === 'cone' ? 3 * h / 4 : h / 2;
      const bottom = ring(v, r, base, 48);
      polyline(bottom, true); ctx.stroke();
      if (item.shape === 'cylinder') { polyline(ring(v, r, top, 48), true); ctx.stroke(); }
      for (let k = 0; k < 48; k += 8) {
        const to = item.shape === 'cone' ? bodyPoint(v, [0, 0, top]) : ring(v, r, top, 48)[k];
        polyline([bottom[k], to]); ctx.stroke();
      }
    } else if (item.shape === 'triangle') {
      polyline([bodyPoint(v, [-d[0] / 3, -d[1] / 3, 0]), bodyPoint(v, [2 * d[0] / 3, -d[1] / 3, 0]),
                bodyPoint(v, [-d[0] / 3, 2 * d[1] / 3, 0])], true);
      ctx.globalAlpha = 0.6; ctx.fill(); ctx.globalAlpha = 1; ctx.stroke();
    }
    label(item.label, [v[0], v[1], v[2]]);
  }

  const probe = { points: [] };
  function drawItem(item, f) {
    const v = numbers(item, f);
    ctx.strokeStyle = item.colour;
    ctx.fillStyle = item.colour;
    if (item.kind === 'polyline') {
      const pts = [];
      for (let k = 0; k < item.stride / 3; ++k) pts.push(pointAt(v, k));
      ctx.lineWidth = 3; ctx.lineJoin = 'round';
      polyline(pts); ctx.stroke();
      label(item.label, pts[pts.length - 1]);
    } else if (item.kind === 'spring') {
      const a = project(pointAt(v, 0)), b = project(pointAt(v, 1));
      const dx = b[0] - a[0], dy = b[1] - a[1], len = Math.hypot(dx, dy) || 1;
      const nx = -dy / len, ny = dx / len, amp = 6, zig = 2 * item.coils;
      ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.moveTo(a[0], a[1]);
      const s0 = 0.1, s1 = 0.9;
      ctx.lineTo(a[0] + dx * s0, a[1] + dy * s0);
      for (let k = 1; k < zig; ++k) {
        const s = s0 + (s1 - s0) * k / zig, side = k % 2 ? amp : -amp;
        ctx.lineTo(a[0] + dx * s + nx * side, a[1] + dy * s + ny * side);
      }
      ctx.lineTo(a[0] + dx * s1, a[1] + dy * s1); ctx.lineTo(b[0], b[1]); ctx.stroke();
      label(item.label, pointAt(v, 1));
    } else if (item.kind === 'circle') {
      const c = pointAt(v, 0), nrm = unit([v[3], v[4], v[5]]), r = v[6];
      const u = unit(Math.abs(nrm[0]) < 0.9 ? cross(nrm, [1, 0, 0]) : cross(nrm, [0, 1, 0])), w = cross(nrm, u);
      const pts = [];
      for (let k = 0; k < 64; ++k) { const a = 2 * Math.PI * k / 64; pts.push(add(c, add(scale(u, r * Math.cos(a)), scale(w, r * Math.sin(a))))); }
      ctx.lineWidth = 2;
      polyline(pts, true);
      if (item.fill) { ctx.globalAlpha = 0.3; ctx.fill(); ctx.globalAlpha = 1; }
      ctx.stroke();
      label(item.label, add(c, scale(u, r)));
    } else if (item.kind === 'trace') {
      const pts = [];
      for (let g = 0; g <= f; ++g) pts.push(pointAt(numbers(item, g), 0));
      ctx.lineWidth = 1; ctx.globalAlpha = 0.6;
      polyline(pts); ctx.stroke(); ctx.globalAlpha = 1;
    } else if (item.kind === 'point') {
      const p = pointAt(v, 0), s = project(p);
      const r = item.has_radius ? Math.max(2, v[3] * pixelScale()) : 6;
      ctx.beginPath(); ctx.arc(s[0], s[1], r, 0, 2 * Math.PI);
      if (item.has_radius && !data.planar) {  // a ball: what is inside or behind it shows through
        ctx.globalAlpha = 0.55; ctx.fill(); ctx.globalAlpha = 1; ctx.stroke();
      } else {
        ctx.fill();
      }
      label(item.label, p);
      probe.points.push({ label: item.label, x: s[0], y: s[1] });
    } else if (item.kind === 'solid') {
      drawSolid(item, v);
    }
  }

  function depthOf(item, f) {
    const v = numbers(item, f);
    if (item.kind === 'ground') return -Infinity;
    if (item.kind === 'trace') return -1e300;
    if (item.kind === 'circle' || item.kind === 'solid' || item.kind === 'point') return project(pointAt(v, 0))[2];
    let s = 0;
    const k = item.stride / 3;
    for (let i = 0; i < k; ++i) s += project(pointAt(v, i))[2];
    return s / k;
  }

  let frame = 0;
  function draw(f) {
    centre = centreAt(f);
    orient();
    probe.points = [];
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, W, H);
    const order = items.slice();
    if (data.planar) {  // the file's order, points last: they sit on the links
      order.sort(function (a, b) { return (a.kind === 'ground' ? -2 : a.kind === 'point' ? 1 : 0) - (b.kind === 'ground' ? -2 : b.kind === 'point' ? 1 : 0); });
    } else {  // far to near; dots after everything else: a mass sits on the links that end at it
      const depth = new Map(order.map(function (item) { return [item, depthOf(item, f)]; }));
      const dot = (item) => item.kind === 'point' && !item.has_radius;
      order.sort(function (a, b) { return dot(a) - dot(b) || depth.get(a) - depth.get(b); });
    }
    for (const item of order) {
      if (item.kind === 'ground') drawGround(item); else drawItem(item, f);
    }
    timeText.textContent = 't = ' + data.t[f].toFixed(3) + ' s';
    slider.value = String(f);
    for (let c = 0; c < readoutCells.length; ++c) {
      const x = readout.v[f][c];
      readoutCells[c].textContent = Math.abs(x) >= 1e4 || (Math.abs(x) < 1e-3 && x !== 0) ? x.toExponential(4) : x.toFixed(4);
    }
  }

  // Playing: the frame whose time is the last at or before the clock's
  let playing = false, clock = data.t[0], last = null;
  function frameAt(time) {
    let a = 0, b = n - 1;
    if (time >= data.t[b]) return b;
    while (b - a > 1) { const m = (a + b) >> 1; if (data.t[m] <= time) a = m; else b = m; }
    return a;
  }
  function tick(stamp) {
    if (playing) {
      if (last !== null) {
        clock += (stamp - last) / 1000 * Number(speedSelect.value);
        if (clock > data.t[n - 1]) clock = data.t[0];
      }
      last = stamp;
      const f = frameAt(clock);
      if (f !== frame) { frame = f; draw(frame); }
    }
    window.requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on && n > 1;
    last = null;
    playButton.textContent = playing ? 'Pause' : 'Play';
  }
  playButton.addEventListener('click', function () { setPlaying(!playing); });
  slider.max = String(n - 1);
  slider.addEventListener('input', function () { setPlaying(false); frame = Number(slider.value); clock = data.t[frame]; draw(frame); });
  document.getElementById('reset').addEventListener('click', function () {
    view.az = -0.6; view.el = 0.35; view.zoom = 1; view.panX = 0; view.panY = 0; draw(frame);
  });
  window.addEventListener('keydown', function (e) {
    if (e.target !== document.body) return;
    if (e.key === ' ') { e.preventDefault(); setPlaying(!playing); }
    if (e.key === 'ArrowLeft' || e.key === 'ArrowRight') {  // one frame back or on, paused
      e.preventDefault();
      setPlaying(false);
      frame = Math.max(0, Math.min(n - 1, frame + (e.key === 'ArrowRight' ? 1 : -1)));
      clock = data.t[frame];
      draw(frame);
    }
  });
  let drag = null;
  canvas.addEventListener('pointerdown', function (e) { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener('pointerup', function () { drag = null; });
  canvas.addEventListener('pointermove', function (e) {
    if (!drag) return;
    const dx = e.clientX - drag[0], dy = e.clientY - drag[1];
    drag = [e.clientX, e.clientY];
    if (data.planar) { view.panX += dx; view.panY += dy; } else {
      view.az -= dx * 0.01;
      view.el = Math.max(-1.55, Math.min(1.55, view.el + dy * 0.01));
    }
    draw(frame);
  });
  canvas.addEventListener('wheel', function (e) { e.preventDefault(); view.zoom *= Math.exp(-e.deltaY * 0.001); draw(frame); }, { passive: false });
  window.addEventListener('resize', function () { layout(); draw(frame); });

  const options = new Map(window.location.hash.replace(/^#/, '').split('&').filter(Boolean).map(function (kv) {
    const i = kv.indexOf('=');
    return i < 0 ? [kv, ''] : [kv.slice(0, i), kv.slice(i + 1)];
  }));
  if (options.has('size')) {  // WxH: a fixed canvas, the same layout in every window (the browser test)
    const m = /^(\d+)x(\d+)$/.exec(options.get('size'));
    if (m) { canvas.style.flex = 'none'; canvas.style.width = m[1] + 'px'; canvas.style.height = m[2] + 'px'; canvas.style.maxWidth = 'none'; }
  }
  layout();
  if (options.has('t')) { frame = frameAt(Number(options.get('t'))); clock = data.t[frame]; }
  draw(frame);
  let bench = null;
  if (options.has('bench')) {  // every frame drawn, timed
    const times = [];
    // Reading a pixel back makes the canvas rasterize what was drawn: the time is the frame's, not only the script's.
    for (let f = 0; f < n; ++f) { const a = performance.now(); draw(f); ctx.getImageData(0, 0, 1, 1); times.push(performance.now() - a); }
    times.sort(function (a, b) { return a - b; });
    bench = { frames: n, mean_ms: times.reduce(function (s, x) { return s + x; }, 0) / n, p95_ms: times[Math.floor(0.95 * (n - 1))], max_ms: times[n - 1] };
    draw(frame);
  }
  if (options.has('probe')) {
    const box = canvas.getBoundingClientRect();
    document.getElementById('probe').textContent = JSON.stringify({
      frame: frame, t: data.t[frame], planar: data.planar, canvas: { left: box.left + canvas.clientLeft, top: box.top + canvas.clientTop, width: W, height: H },
      view: { scale: pixelScale(), centre: centre, right: right, up: screenUp, pan: [view.panX, view.panY] },
      points: probe.points, bench: bench, errors: errors });
  }
  setPlaying(!options.has('t') && !options.has('probe') && !options.has('bench'));
  window.requestAnimationFrame(tick);
})();
