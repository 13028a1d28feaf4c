// The HTML player's script. viz/html_player.hpp writes it into every page through assets.hpp:
// run scripts/embed_player_assets.py after editing this file (tests/viz/player_assets.cpp fails
// until then, and runs `node --check` on it where Node.js is installed).
// It reads the page data, the JSON in the script element "gaitsynth-data" (keys: data.hpp), and
// draws on the canvases of player_body.html. No library, no module, nothing fetched: the page
// has to work opened from disk. After a few frames it checks its own pixels and writes the result
// into the element with id "status", which tests/viz/player_chromium.cpp reads from headless
// Chromium. That element is hidden (its `hidden` attribute): people see it only when the page is
// opened with ?selftest in its address, or when a script error happened (the page then does not
// work, and the message says why).
(function () {
'use strict';
var statusEl = document.getElementById('status');
if (new URLSearchParams(location.search).has('selftest')) statusEl.hidden = false;
var errors = [];
function reportError(msg) {
  errors.push(String(msg));
  statusEl.textContent = 'error: ' + errors.join(' | ');
  statusEl.className = 'err';
  statusEl.hidden = false;
}
window.onerror = function (msg, src, line, col) { reportError(msg + ' (line ' + line + ':' + col + ')'); return false; };
window.addEventListener('unhandledrejection', function (e) { reportError('unhandled rejection: ' + e.reason); });

var D = JSON.parse(document.getElementById('gaitsynth-data').textContent);
var NF = D.t.length, NB = D.bodies.length, NC = D.contacts.length;
var NJ = D.joint_names.length, NO = D.obj_names.length;
var SIDE_RGB = { l: [95, 139, 212], r: [221, 132, 82], c: [160, 164, 170] };
var PALETTE = ['#0072B2', '#D55E00', '#009E73', '#CC79A7', '#E69F00', '#56B4E9', '#000000', '#8c564b', '#7f7f7f', '#bcbd22'];

// ---- small vector helpers ------------------------------------------------
function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function add(a, b) { return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]; }
function scl(a, s) { return [a[0] * s, a[1] * s, a[2] * s]; }
function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function norm(a) { var n = Math.sqrt(dot(a, a)); return n > 0 ? scl(a, 1 / n) : [0, 0, 0]; }
// rotate v by unit quaternion (w, x, y, z)
function qrot(q, v) {
  var u = [q[1], q[2], q[3]], w = q[0];
  var t = scl(cross(u, v), 2);
  return add(add(v, scl(t, w)), cross(u, t));
}
function bodyPos(f, b) { var i = (f * NB + b) * 3; return [D.bp[i], D.bp[i + 1], D.bp[i + 2]]; }
function bodyQuat(f, b) { var i = (f * NB + b) * 4; return [D.bq[i], D.bq[i + 1], D.bq[i + 2], D.bq[i + 3]]; }
function toWorld(f, b, p) { return add(bodyPos(f, b), qrot(bodyQuat(f, b), p)); }
function vec3(arr, f, k, n) { var i = (f * n + k) * 3; return [arr[i], arr[i + 1], arr[i + 2]]; }
function terrainHeight(x, y) {
  var T = D.terrain;
  if (!T || !T.nx || !T.ny) return 0;
  function cell(u, n) { if (n === 1 || !(u > 0)) return [0, 0]; if (u >= n - 1) return [n - 2, 1]; var i = Math.floor(u); return [i, u - i]; }
  var cx = cell((x - T.x0) / T.dx, T.nx), cy = cell((y - T.y0) / T.dy, T.ny);
  function h(i, j) { i = Math.max(0, Math.min(T.nx - 1, i)); j = Math.max(0, Math.min(T.ny - 1, j)); return T.h[j * T.nx + i]; }
  var ix = cx[0], wx = cx[1], iy = cy[0], wy = cy[1];
  return (1 - wy) * ((1 - wx) * h(ix, iy) + wx * h(ix + 1, iy)) + wy * ((1 - wx) * h(ix, iy + 1) + wx * h(ix + 1, iy + 1));
}

// ---- camera --------------------------------------------------------------
var cam = {
  az: D.planar ? -Math.PI / 2 : -Math.PI / 2 + 0.7,
  el: D.planar ? 0.05 : 0.28,
  dist: Math.max(1.2, D.size * 2.6),
  target: [D.cm[0], D.cm[1], D.cm[2]],
  ortho: !!D.planar,
  fov: 40 * Math.PI / 180
};
function camera(W, H, target) {
  var ce = Math.cos(cam.el), se = Math.sin(cam.el), ca = Math.cos(cam.az), sa = Math.sin(cam.az);
  var off = [ce * ca, ce * sa, se];
  var eye = add(target, scl(off, cam.dist));
  var f = scl(off, -1);
  var r = norm(cross(f, [0, 0, 1]));
  var u = cross(r, f);
  var focal = H / (2 * Math.tan(cam.fov / 2));
  return { eye: eye, f: f, r: r, u: u, W: W, H: H, focal: focal, ortho: cam.ortho, oscale: focal / cam.dist };
}
// world point -> [sx, sy, depth, px_per_m] or null when behind the camera
function project(C, p) {
  var d = sub(p, C.eye);
  var x = dot(d, C.r), y = dot(d, C.u), z = dot(d, C.f);
  if (C.ortho) return [C.W / 2 + x * C.oscale, C.H / 2 - y * C.oscale, z, C.oscale];
  if (z < 0.05) return null;
  var s = C.focal / z;
  return [C.W / 2 + x * s, C.H / 2 - y * s, z, s];
}
function shade(rgb, k, a) {
  return 'rgba(' + Math.round(rgb[0] * k) + ',' + Math.round(rgb[1] * k) + ',' + Math.round(rgb[2] * k) + ',' + (a === undefined ? 1 : a) + ')';
}
var LIGHT = norm([0.35, -0.55, 0.75]);
var BOX_FACES = [[0, 1, 3, 2], [4, 5, 7, 6], [0, 1, 5, 4], [2, 3, 7, 6], [0, 2, 6, 4], [1, 3, 7, 5]];

// ---- scene drawing -------------------------------------------------------
// flags: {ground, overlays, hud, background}
function drawScene(ctx, W, H, fi, flags) {
  var target = cam.target;
  var C = camera(W, H, target);
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  if (flags.background) {
    var g = ctx.createLinearGradient(0, 0, 0, H);
    g.addColorStop(0, '#eef3f8'); g.addColorStop(1, '#cfd9e3');
    ctx.fillStyle = g; ctx.fillRect(0, 0, W, H);
  } else {
    ctx.clearRect(0, 0, W, H);
  }
  if (flags.ground) drawGround(ctx, C, target);
  var prims = [];
  for (var b = 0; b < NB; b++) addBody(prims, C, fi, b);
  prims.sort(function (a, b) { return b.z - a.z; });
  for (var i = 0; i < prims.length; i++) prims[i].draw(ctx);
  if (flags.overlays) drawOverlays(ctx, C, fi);
  if (flags.hud) drawHud(ctx, fi);
}

function drawGround(ctx, C, target) {
  var T = D.terrain, quads = [];
  var R = Math.max(4, D.size * 4), step;
  if (T && T.nx > 1 && T.ny > 1) {
    var hmin = Infinity, hmax = -Infinity;
    for (var k = 0; k < T.h.length; k++) { hmin = Math.min(hmin, T.h[k]); hmax = Math.max(hmax, T.h[k]); }
    for (var j = 0; j + 1 < T.ny; j++) for (var i = 0; i + 1 < T.nx; i++) {
      var x0 = T.x0 + i * T.dx, y0 = T.y0 + j * T.dy;
      var pts = [[x0, y0, T.h[j * T.nx + i]], [x0 + T.dx, y0, T.h[j * T.nx + i + 1]],
                 [x0 + T.dx, y0 + T.dy, T.h[(j + 1) * T.nx + i + 1]], [x0, y0 + T.dy, T.h[(j + 1) * T.nx + i]]];
      var hm = (pts[0][2] + pts[1][2] + pts[2][2] + pts[3][2]) / 4;
      var k2 = hmax > hmin ? (hm - hmin) / (hmax - hmin) : 0.5;
      quads.push({ p: pts, fill: shade([150, 170, 135], 0.8 + 0.25 * k2), line: 'rgba(60,70,50,0.35)' });
    }
  } else {
    step = R > 8 ? 1.0 : 0.5;
    var cx = Math.round(target[0] / step) * step, cy = Math.round(target[1] / step) * step;
    // Planar characters live in the x-z plane: a narrow strip of ground reads best side on.
    var n = Math.ceil(R / step), ny = D.planar ? 1 : n;
    for (var a = -n; a < n; a++) for (var c = -ny; c < ny; c++) {
      var xa = cx + a * step, ya = cy + c * step;
      var odd = ((Math.round(xa / step) + Math.round(ya / step)) & 1) !== 0;
      quads.push({ p: [[xa, ya, 0], [xa + step, ya, 0], [xa + step, ya + step, 0], [xa, ya + step, 0]],
                   fill: odd ? '#c9cfc4' : '#d9ded4', line: null });
    }
  }
  var drawn = [];
  for (var q = 0; q < quads.length; q++) {
    var P = [], z = 0, ok = true;
    for (var v = 0; v < 4; v++) { var s = project(C, quads[q].p[v]); if (!s) { ok = false; break; } P.push(s); z += s[2]; }
    if (ok) drawn.push({ P: P, z: z / 4, fill: quads[q].fill, line: quads[q].line });
  }
  drawn.sort(function (a, b) { return b.z - a.z; });
  for (var d = 0; d < drawn.length; d++) {
    var Q = drawn[d];
    ctx.beginPath(); ctx.moveTo(Q.P[0][0], Q.P[0][1]);
    for (var w = 1; w < 4; w++) ctx.lineTo(Q.P[w][0], Q.P[w][1]);
    ctx.closePath(); ctx.fillStyle = Q.fill; ctx.fill();
    if (Q.line) { ctx.strokeStyle = Q.line; ctx.lineWidth = 0.5; ctx.stroke(); }
  }
}

function addBody(prims, C, fi, b) {
  var B = D.bodies[b], rgb = SIDE_RGB[B.side] || SIDE_RGB.c;
  var shapes = B.shapes;
  for (var s = 0; s < shapes.length; s++) {
    var S = shapes[s];
    if (S.k === 'box') addBox(prims, C, fi, b, S, rgb);
    else if (S.k === 'cap') addCapsule(prims, C, toWorld(fi, b, S.a), toWorld(fi, b, S.b), S.r, rgb);
    else addSphere(prims, C, toWorld(fi, b, S.c), S.r, rgb);
  }
  if (shapes.length === 0) {
    var o = bodyPos(fi, b);
    for (var e = 0; e < B.ends.length; e++) addCapsule(prims, C, o, toWorld(fi, b, B.ends[e]), 0.018, rgb);
    addSphere(prims, C, o, 0.025, [60, 60, 60]);
  }
}
function addBox(prims, C, fi, b, S, rgb) {
  var W = [];
  for (var c = 0; c < 8; c++) {
    var l = [S.c[0] + ((c & 1) ? S.h[0] : -S.h[0]), S.c[1] + ((c & 2) ? S.h[1] : -S.h[1]), S.c[2] + ((c & 4) ? S.h[2] : -S.h[2])];
    W.push(toWorld(fi, b, l));
  }
  var centre = toWorld(fi, b, S.c);
  for (var f = 0; f < 6; f++) {
    var idx = BOX_FACES[f];
    var a = W[idx[0]], bb = W[idx[1]], cc = W[idx[2]], dd = W[idx[3]];
    var fc = scl(add(add(a, bb), add(cc, dd)), 0.25);
    var n = norm(cross(sub(bb, a), sub(dd, a)));
    if (dot(n, sub(fc, centre)) < 0) n = scl(n, -1);
    var toEye = C.ortho ? scl(C.f, -1) : sub(C.eye, fc);
    if (dot(n, toEye) <= 0) continue;
    var P = [], z = 0, ok = true;
    for (var v = 0; v < 4; v++) { var p = project(C, W[idx[v]]); if (!p) { ok = false; break; } P.push(p); z += p[2]; }
    if (!ok) continue;
    var k = 0.55 + 0.45 * Math.max(0, dot(n, LIGHT));
    prims.push({ z: z / 4, draw: (function (P, k) { return function (ctx) {
      ctx.beginPath(); ctx.moveTo(P[0][0], P[0][1]);
      for (var i = 1; i < 4; i++) ctx.lineTo(P[i][0], P[i][1]);
      ctx.closePath(); ctx.fillStyle = shade(rgb, k); ctx.fill();
      ctx.strokeStyle = shade(rgb, 0.45); ctx.lineWidth = 0.8; ctx.stroke();
    }; })(P, k) });
  }
}
function addCapsule(prims, C, a, b, r, rgb) {
  var pa = project(C, a), pb = project(C, b);
  if (!pa || !pb) return;
  var w = Math.max(1.5, r * (pa[3] + pb[3]));
  prims.push({ z: (pa[2] + pb[2]) / 2, draw: function (ctx) {
    ctx.lineCap = 'round';
    ctx.beginPath(); ctx.moveTo(pa[0], pa[1]); ctx.lineTo(pb[0], pb[1]);
    ctx.strokeStyle = shade(rgb, 0.45); ctx.lineWidth = w + 2; ctx.stroke();
    ctx.strokeStyle = shade(rgb, 1); ctx.lineWidth = w; ctx.stroke();
    ctx.beginPath(); ctx.moveTo(pa[0] - w * 0.15, pa[1] - w * 0.15); ctx.lineTo(pb[0] - w * 0.15, pb[1] - w * 0.15);
    ctx.strokeStyle = 'rgba(255,255,255,0.25)'; ctx.lineWidth = w * 0.3; ctx.stroke();
  } });
}
function addSphere(prims, C, c, r, rgb) {
  var p = project(C, c);
  if (!p) return;
  var rad = Math.max(1.5, r * p[3]);
  prims.push({ z: p[2], draw: function (ctx) {
    ctx.beginPath(); ctx.arc(p[0], p[1], rad, 0, 2 * Math.PI);
    ctx.fillStyle = shade(rgb, 1); ctx.fill();
    ctx.strokeStyle = shade(rgb, 0.45); ctx.lineWidth = 1; ctx.stroke();
  } });
}

function arrow(ctx, C, from, to, colour, width) {
  var a = project(C, from), b = project(C, to);
  if (!a || !b) return;
  var dx = b[0] - a[0], dy = b[1] - a[1], L = Math.sqrt(dx * dx + dy * dy);
  if (L < 1) return;
  ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = width; ctx.lineCap = 'round';
  ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.stroke();
  var ux = dx / L, uy = dy / L, hl = Math.min(10, L * 0.4);
  ctx.beginPath(); ctx.moveTo(b[0], b[1]);
  ctx.lineTo(b[0] - ux * hl - uy * hl * 0.5, b[1] - uy * hl + ux * hl * 0.5);
  ctx.lineTo(b[0] - ux * hl + uy * hl * 0.5, b[1] - uy * hl - ux * hl * 0.5);
  ctx.closePath(); ctx.fill();
}
function drawOverlays(ctx, C, fi) {
  var showF = document.getElementById('forces').checked;
  for (var k = 0; k < NC; k++) {
    var p = vec3(D.cp, fi, k, NC), on = D.ca[fi * NC + k] === 1;
    var s = project(C, p);
    if (!s) continue;
    ctx.beginPath(); ctx.arc(s[0], s[1], on ? 4 : 2.5, 0, 2 * Math.PI);
    if (on) { ctx.fillStyle = '#d62728'; ctx.fill(); } else { ctx.strokeStyle = 'rgba(60,60,60,0.7)'; ctx.lineWidth = 1; ctx.stroke(); }
    if (showF && on) {
      var F = vec3(D.cf, fi, k, NC);
      arrow(ctx, C, p, add(p, scl(F, D.force_scale)), 'rgba(20,150,40,0.9)', 2);
    }
  }
  if (showF) {
    var pu = D.pushes[fi] || [];
    for (var j = 0; j < pu.length; j++) {
      var o = bodyPos(fi, pu[j][0]), F2 = [pu[j][1], pu[j][2], pu[j][3]];
      arrow(ctx, C, sub(o, scl(F2, D.force_scale)), o, 'rgba(245,130,0,0.95)', 3.5);
    }
  }
  if (document.getElementById('com').checked) {
    var c = vec3(D.cm, fi, 0, 1), g = [c[0], c[1], terrainHeight(c[0], c[1])];
    var sc = project(C, c), sg = project(C, g);
    if (sc && sg) {
      ctx.setLineDash([4, 3]); ctx.strokeStyle = 'rgba(40,40,40,0.6)'; ctx.lineWidth = 1;
      ctx.beginPath(); ctx.moveTo(sc[0], sc[1]); ctx.lineTo(sg[0], sg[1]); ctx.stroke(); ctx.setLineDash([]);
      ctx.beginPath(); ctx.arc(sc[0], sc[1], 5, 0, 2 * Math.PI); ctx.fillStyle = '#ffd400'; ctx.fill();
      ctx.strokeStyle = '#222'; ctx.lineWidth = 1.5; ctx.stroke();
      ctx.beginPath(); ctx.moveTo(sc[0] - 5, sc[1]); ctx.lineTo(sc[0] + 5, sc[1]); ctx.moveTo(sc[0], sc[1] - 5); ctx.lineTo(sc[0], sc[1] + 5); ctx.stroke();
    }
  }
}
function drawHud(ctx, fi) {
  ctx.font = '13px sans-serif'; ctx.fillStyle = 'rgba(20,20,20,0.85)';
  ctx.fillText(D.name + '   t = ' + D.t[fi].toFixed(3) + ' s   frame ' + (fi + 1) + '/' + NF +
               (D.cs[fi] >= 0 ? '   state ' + D.cs[fi] : ''), 10, 18);
}

// ---- plots ---------------------------------------------------------------
function niceTicks(lo, hi, n) {
  var t = []; if (!(hi > lo)) return t;
  var raw = (hi - lo) / n, mag = Math.pow(10, Math.floor(Math.log10(raw))), step = mag;
  var m = [1, 2, 5, 10];
  for (var i = 0; i < m.length; i++) if (m[i] * mag >= raw) { step = m[i] * mag; break; }
  for (var v = Math.ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) t.push(Math.abs(v) < 1e-12 * step ? 0 : v);
  return t;
}
function fmt(v) { var a = Math.abs(v); return a >= 100 ? v.toFixed(0) : a >= 1 ? (+v.toFixed(2)).toString() : (+v.toPrecision(2)).toString(); }
function setupCanvas(cv) {
  var dpr = window.devicePixelRatio || 1, w = cv.clientWidth || cv.width, h = cv.clientHeight || cv.height;
  if (cv.width !== Math.round(w * dpr) || cv.height !== Math.round(h * dpr)) { cv.width = Math.round(w * dpr); cv.height = Math.round(h * dpr); }
  var ctx = cv.getContext('2d'); ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx: ctx, W: w, H: h };
}
// series: [{name, colour, segs: [[x[], y[]], ...]}], cursor: {x} or {pts: [[x, y, colour]]}
function drawPlot(cv, xlab, ylab, xlo, xhi, series, cursor, note) {
  var S = setupCanvas(cv), ctx = S.ctx, W = S.W, H = S.H;
  var L = 46, R = 8, T = 8, B = 30;
  ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, W, H);
  var ylo = Infinity, yhi = -Infinity;
  series.forEach(function (s) { s.segs.forEach(function (g) { g[1].forEach(function (y) { if (isFinite(y) && y !== null) { ylo = Math.min(ylo, y); yhi = Math.max(yhi, y); } }); }); });
  if (!(yhi >= ylo)) { ylo = 0; yhi = 1; }
  if (yhi - ylo < 1e-9) { ylo -= 1; yhi += 1; }
  var pad = (yhi - ylo) * 0.06; ylo -= pad; yhi += pad;
  if (!(xhi > xlo)) xhi = xlo + 1;
  function X(x) { return L + (x - xlo) / (xhi - xlo) * (W - L - R); }
  function Y(y) { return T + (yhi - y) / (yhi - ylo) * (H - T - B); }
  ctx.font = '10px sans-serif'; ctx.strokeStyle = '#e5e7eb'; ctx.fillStyle = '#444'; ctx.lineWidth = 1;
  niceTicks(xlo, xhi, 5).forEach(function (v) { ctx.beginPath(); ctx.moveTo(X(v), T); ctx.lineTo(X(v), H - B); ctx.stroke(); ctx.textAlign = 'center'; ctx.fillText(fmt(v), X(v), H - B + 12); });
  niceTicks(ylo, yhi, 4).forEach(function (v) { ctx.beginPath(); ctx.moveTo(L, Y(v)); ctx.lineTo(W - R, Y(v)); ctx.stroke(); ctx.textAlign = 'right'; ctx.fillText(fmt(v), L - 4, Y(v) + 3); });
  ctx.strokeStyle = '#9ca3af'; ctx.strokeRect(L, T, W - L - R, H - T - B);
  ctx.textAlign = 'center'; ctx.fillText(xlab, L + (W - L - R) / 2, H - 4);
  ctx.save(); ctx.translate(10, T + (H - T - B) / 2); ctx.rotate(-Math.PI / 2); ctx.fillText(ylab, 0, 0); ctx.restore();
  ctx.save(); ctx.beginPath(); ctx.rect(L, T, W - L - R, H - T - B); ctx.clip();
  series.forEach(function (s) {
    ctx.strokeStyle = s.colour; ctx.lineWidth = s.width || 1.5; ctx.globalAlpha = s.alpha || 1;
    s.segs.forEach(function (g) {
      ctx.beginPath(); var pen = false;
      for (var i = 0; i < g[0].length; i++) {
        var y = g[1][i];
        if (y === null || !isFinite(y)) { pen = false; continue; }
        if (pen) ctx.lineTo(X(g[0][i]), Y(y)); else { ctx.moveTo(X(g[0][i]), Y(y)); pen = true; }
      }
      ctx.stroke();
    });
  });
  ctx.globalAlpha = 1;
  if (cursor && cursor.x !== undefined) { ctx.strokeStyle = '#111'; ctx.lineWidth = 1; ctx.beginPath(); ctx.moveTo(X(cursor.x), T); ctx.lineTo(X(cursor.x), H - B); ctx.stroke(); }
  if (cursor && cursor.pts) cursor.pts.forEach(function (p) { if (p[1] === null || !isFinite(p[1])) return; ctx.beginPath(); ctx.arc(X(p[0]), Y(p[1]), 3.5, 0, 2 * Math.PI); ctx.fillStyle = p[2]; ctx.fill(); });
  ctx.restore();
  // Legend: as many rows as the plot is tall, then further columns to the right (the objective
  // plot's dozen terms overflowed a single column), on a white backing over the curves.
  var items = series.filter(function (s) { return !!s.legend; });
  if (items.length) {
    var rowH = 12, rows = Math.max(1, Math.floor((H - T - B - 6) / rowH)), colW = [];
    items.forEach(function (s, i) { var c = Math.floor(i / rows); colW[c] = Math.max(colW[c] || 0, 24 + ctx.measureText(s.legend).width); });
    var colX = [L + 6];
    for (var c = 1; c < colW.length; c++) colX.push(colX[c - 1] + colW[c - 1]);
    ctx.fillStyle = 'rgba(255,255,255,0.85)';
    ctx.fillRect(L + 2, T + 2, colX[colW.length - 1] + colW[colW.length - 1] - L - 6, Math.min(items.length, rows) * rowH + 4);
    items.forEach(function (s, i) {
      var lx = colX[Math.floor(i / rows)], ly = T + 12 + (i % rows) * rowH;
      ctx.fillStyle = s.colour; ctx.fillRect(lx, ly - 7, 10, 3);
      ctx.fillStyle = '#222'; ctx.textAlign = 'left'; ctx.fillText(s.legend, lx + 14, ly - 3);
    });
  }
  if (note) { ctx.fillStyle = '#a00'; ctx.textAlign = 'center'; ctx.fillText(note, L + (W - L - R) / 2, T + (H - T - B) / 2); }
}
var selected = [];
function jointValue(f, j) { return D.q[f * NJ + j] * 180 / Math.PI; }
function drawJointPlot(fi) {
  var cv = document.getElementById('jplot');
  var mode = document.getElementById('xmode').value, series = [], note = '';
  var cyc = D.cycles;
  if (mode === 'cycle' && cyc.length >= 2) {
    var pts = [];
    selected.forEach(function (j, n) {
      var col = PALETTE[n % PALETTE.length], segs = [];
      for (var k = 0; k + 1 < cyc.length; k++) {
        var xs = [], ys = [];
        for (var f = 0; f < NF; f++) if (D.t[f] >= cyc[k] && D.t[f] <= cyc[k + 1]) { xs.push(100 * (D.t[f] - cyc[k]) / (cyc[k + 1] - cyc[k])); ys.push(jointValue(f, j)); }
        segs.push([xs, ys]);
      }
      series.push({ colour: col, segs: segs, legend: D.joint_names[j], width: 1.2, alpha: 0.8 });
      for (var k2 = 0; k2 + 1 < cyc.length; k2++) if (D.t[fi] >= cyc[k2] && D.t[fi] <= cyc[k2 + 1]) pts.push([100 * (D.t[fi] - cyc[k2]) / (cyc[k2 + 1] - cyc[k2]), jointValue(fi, j), col]);
    });
    drawPlot(cv, '% gait cycle (' + (cyc.length - 1) + ' cycles, ' + D.foot + ' heel strikes)', 'deg', 0, 100, series, { pts: pts }, '');
    return;
  }
  if (mode === 'cycle') note = 'fewer than two heel strikes: showing time';
  selected.forEach(function (j, n) {
    var ys = new Array(NF);
    for (var f = 0; f < NF; f++) ys[f] = jointValue(f, j);
    series.push({ colour: PALETTE[n % PALETTE.length], segs: [[D.t, ys]], legend: D.joint_names[j] });
  });
  drawPlot(cv, 'time (s)', 'deg', D.t[0], D.t[NF - 1], series, { x: D.t[fi] }, note);
}
var objMax = [];
for (var o = 0; o < NO; o++) { var m = 0; for (var f0 = 0; f0 < NF; f0++) { var v0 = D.obj[f0 * NO + o]; if (v0 !== null && isFinite(v0)) m = Math.max(m, Math.abs(v0)); } objMax.push(m > 0 ? m : 1); }
function drawObjectivePlot(fi) {
  var cv = document.getElementById('oplot'), normalize = document.getElementById('normalize').checked, series = [];
  for (var o = 0; o < NO; o++) {
    var ys = new Array(NF);
    for (var f = 0; f < NF; f++) { var v = D.obj[f * NO + o]; ys[f] = v === null ? null : (normalize ? v / objMax[o] : v); }
    series.push({ colour: PALETTE[o % PALETTE.length], segs: [[D.t, ys]], legend: D.obj_names[o] + (normalize ? ' (max ' + fmt(objMax[o]) + ')' : '') });
  }
  drawPlot(cv, 'time (s)', normalize ? 'value / max' : 'value', D.t[0], D.t[NF - 1], series, { x: D.t[fi] }, NO === 0 ? 'no objective terms recorded' : '');
}

// ---- playback and controls ----------------------------------------------
var view = document.getElementById('view');
var playing = !!D.autoplay, speed = D.speed, playT = D.t[0], frame = 0, framesRendered = 0, lastStamp = null;
var scrub = document.getElementById('scrub');
scrub.max = String(NF - 1);
var speedSel = document.getElementById('speed');
speedSel.value = String(speed);
if (speedSel.value !== String(speed)) { var opt = document.createElement('option'); opt.value = String(speed); opt.textContent = speed + 'x'; speedSel.appendChild(opt); speedSel.value = String(speed); }
document.getElementById('ortho').checked = cam.ortho;
function frameAt(t) { var lo = 0, hi = NF - 1; while (lo < hi) { var mid = (lo + hi + 1) >> 1; if (D.t[mid] <= t) lo = mid; else hi = mid - 1; } return lo; }
function setFrame(f) { frame = Math.max(0, Math.min(NF - 1, f)); playT = D.t[frame]; }
function updateCamera(fi) { if (document.getElementById('follow').checked) { var c = vec3(D.cm, fi, 0, 1); cam.target = [c[0], c[1], Math.max(c[2] * 0.8, 0.3 * D.size)]; } }
function render() {
  var S = setupCanvas(view);
  updateCamera(frame);
  drawScene(S.ctx, S.W, S.H, frame, { ground: true, overlays: true, hud: true, background: true });
  drawJointPlot(frame);
  drawObjectivePlot(frame);
  scrub.value = String(frame);
  document.getElementById('time').textContent = 't = ' + D.t[frame].toFixed(3) + ' / ' + D.t[NF - 1].toFixed(3) + ' s';
  document.getElementById('play').textContent = playing ? 'Pause' : 'Play';
  framesRendered++;
}
function tick(stamp) {
  try {
    if (lastStamp !== null && playing) {
      playT += Math.min(0.1, (stamp - lastStamp) / 1000) * speed;
      if (playT > D.t[NF - 1]) playT = D.t[0] + (playT - D.t[NF - 1]) % Math.max(1e-9, D.t[NF - 1] - D.t[0] + 1e-9);
      frame = frameAt(playT);
    }
    lastStamp = stamp;
    render();
    if (framesRendered >= 3) selfCheck();
  } catch (e) { reportError(e && e.stack ? e.stack.split('\n')[0] : e); }
  requestAnimationFrame(tick);
}
document.getElementById('play').onclick = function () { playing = !playing; };
document.getElementById('prev').onclick = function () { playing = false; setFrame(frame - 1); };
document.getElementById('next').onclick = function () { playing = false; setFrame(frame + 1); };
speedSel.onchange = function () { speed = parseFloat(speedSel.value); };
scrub.oninput = function () { playing = false; setFrame(parseInt(scrub.value, 10)); };
document.getElementById('ortho').onchange = function (e) { cam.ortho = e.target.checked; };
document.getElementById('side').onclick = function () { cam.az = -Math.PI / 2; cam.el = 0.05; };
document.getElementById('persp').onclick = function () { cam.az = -Math.PI / 2 + 0.7; cam.el = 0.28; cam.ortho = false; document.getElementById('ortho').checked = false; };
window.addEventListener('keydown', function (e) {
  if (e.target && e.target.tagName === 'SELECT') return;
  if (e.key === ' ') { playing = !playing; e.preventDefault(); }
  else if (e.key === 'ArrowLeft') { playing = false; setFrame(frame - 1); e.preventDefault(); }
  else if (e.key === 'ArrowRight') { playing = false; setFrame(frame + 1); e.preventDefault(); }
});
var drag = null;
view.addEventListener('pointerdown', function (e) { drag = [e.clientX, e.clientY]; view.setPointerCapture(e.pointerId); view.style.cursor = 'grabbing'; });
view.addEventListener('pointermove', function (e) {
  if (!drag) return;
  cam.az -= (e.clientX - drag[0]) * 0.008;
  cam.el = Math.max(-0.3, Math.min(1.5, cam.el + (e.clientY - drag[1]) * 0.008));
  drag = [e.clientX, e.clientY];
});
view.addEventListener('pointerup', function () { drag = null; view.style.cursor = 'grab'; });
view.addEventListener('wheel', function (e) { cam.dist = Math.max(0.3, Math.min(200, cam.dist * Math.exp(e.deltaY * 0.001))); e.preventDefault(); }, { passive: false });
// joint checkboxes
var jointsDiv = document.getElementById('joints');
D.joint_names.forEach(function (n, j) {
  var lab = document.createElement('label'), cb = document.createElement('input');
  cb.type = 'checkbox'; cb.checked = D.plot_joints.indexOf(j) >= 0;
  cb.onchange = function () { selected = []; jointsDiv.querySelectorAll('input').forEach(function (c, k) { if (c.checked) selected.push(k); }); };
  lab.appendChild(cb); lab.appendChild(document.createTextNode(' ' + n)); jointsDiv.appendChild(lab);
});
selected = D.plot_joints.slice();

// ---- self check (read by tests through --dump-dom; hidden from people) -----
var checked = false;
function countPixels(ctx, W, H, bg) {
  var px = ctx.getImageData(0, 0, W, H).data, n = 0;
  for (var i = 0; i < px.length; i += 4) {
    if (bg) { if (Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]) > 30) n++; }
    else if (px[i + 3] > 0) n++;
  }
  return n;
}
function selfCheck() {
  if (checked) return;
  checked = true;
  try {
    // Whole view: anything but a uniform colour?
    var ctx = view.getContext('2d'), w = view.width, h = view.height;
    var data = ctx.getImageData(0, 0, w, h).data, first = [data[0], data[1], data[2]], differ = 0;
    for (var i = 0; i < data.length; i += 4) if (Math.abs(data[i] - first[0]) + Math.abs(data[i + 1] - first[1]) + Math.abs(data[i + 2] - first[2]) > 30) differ++;
    // The character alone (no ground, no overlays) at the first, middle and last frame.
    var off = document.createElement('canvas'); off.width = 320; off.height = 240;
    var octx = off.getContext('2d'), counts = [], saved = cam.target;
    [0, NF >> 1, NF - 1].forEach(function (f) {
      var c = vec3(D.cm, f, 0, 1); cam.target = [c[0], c[1], c[2]];
      drawScene(octx, 320, 240, f, { ground: false, overlays: false, hud: false, background: false });
      counts.push(countPixels(octx, 320, 240, null));
    });
    cam.target = saved;
    var nonblank = differ > 200 ? 1 : 0, character = Math.min.apply(null, counts) > 50;
    if (errors.length) return;
    // shown=1 when the line takes space on the page (shown to people), 0 while it is hidden.
    var shown = statusEl.getClientRects().length > 0 ? 1 : 0;
    statusEl.textContent = (nonblank && character ? 'ok' : 'blank') + ' frames=' + framesRendered + ' nonblank=' + nonblank +
                           ' character_px=' + counts.join('/') + ' data_frames=' + NF + ' shown=' + shown;
    statusEl.className = nonblank && character ? '' : 'err';
  } catch (e) { reportError('self check: ' + e); }
}
setTimeout(selfCheck, 1500);
try { render(); } catch (e) { reportError(e && e.stack ? e.stack.split('\n')[0] : e); }
requestAnimationFrame(tick);
})();
