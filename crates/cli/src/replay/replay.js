// The vorrt replay page: draws one closed-loop run from the inline JSON
// of the element #vorrt-data (crates/cli/src/replay/data.rs, decision 35).
// Plain JavaScript and canvas, no library, no network. Everything drawn is
// read from the data; nothing here judges the run.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("vorrt-data").textContent);
  const NM = 1852;
  const times = data.times_s;
  const T0 = times.length ? times[0] : 0;
  const T1 = times.length ? times[times.length - 1] : 0;
  // Tableau 10, the colours of the static plots (crates/cli/src/plot).
  const PALETTE = ["#d62728", "#1f77b4", "#2ca02c", "#ff7f0e", "#9467bd",
    "#17becf", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f"];
  const OWN_FILL = "#1b3fbf";
  const DTH_COLOUR = "#c80000";
  const MIN_HULL_PX = 14;
  const ENCOUNTER_SHORT = {
    head_on: "head-on", crossing_give_way: "crossing, give way",
    crossing_stand_on: "crossing, stand on", overtaking: "overtaking",
    being_overtaken: "being overtaken", none: "no risk",
  };

  function decode(column, scale) {
    const out = new Array(column.length);
    let sum = 0;
    for (let i = 0; i < column.length; i++) { sum += column[i]; out[i] = sum / scale; }
    return out;
  }
  const vessels = data.vessels.map(function (v, index) {
    const track = v.track;
    return {
      index: index, name: v.name, role: v.role, length_m: v.length_m, beam_m: v.beam_m,
      encounter: v.encounter,
      east: decode(track.east_dm, 10), north: decode(track.north_dm, 10),
      course: decode(track.course_ddeg, 10).map(function (c) { return ((c % 360) + 360) % 360; }),
      speed: decode(track.speed_ckn, 100),
      n: track.east_dm.length,
      colour: index === 0 ? OWN_FILL : PALETTE[(index - 1) % PALETTE.length],
    };
  });
  const own = vessels[0];
  const targets = vessels.slice(1);

  // ---- time ----
  function locate(t) {
    const last = times.length - 1;
    if (last <= 0 || t <= times[0]) return [0, 0];
    if (t >= times[last]) return [last, 0];
    let lo = 0, hi = last;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid; else hi = mid;
    }
    return [lo, (t - times[lo]) / (times[lo + 1] - times[lo])];
  }
  // The state of vessel v at time t, linear between the kept samples
  // (courses the short way round); null after its track ends.
  function stateAt(v, t) {
    if (v.n === 0) return null;
    let [i, f] = locate(t);
    if (i >= v.n - 1) {
      if (i > v.n - 1 || f > 0) return null;
      i = v.n - 1; f = 0;
    }
    const j = Math.min(i + 1, v.n - 1);
    const lerp = function (a) { return a[i] + (a[j] - a[i]) * f; };
    const turn = ((v.course[j] - v.course[i] + 540) % 360) - 180;
    return {
      east_m: lerp(v.east), north_m: lerp(v.north),
      course_deg: ((v.course[i] + turn * f) % 360 + 360) % 360, speed_kn: lerp(v.speed),
    };
  }
  function clock(t) {
    const s = Math.max(0, Math.round(t));
    const m = Math.floor(s / 60);
    return m + ":" + String(s % 60).padStart(2, "0");
  }
  function minutes(t) { return (t / 60).toFixed(1) + " min"; }

  // ---- elements ----
  const $ = function (id) { return document.getElementById(id); };
  const chart = $("chart"), timeline = $("timeline"), plots = $("plots");
  const slider = $("slider"), playButton = $("play"), speedSelect = $("speed");
  let current = T0, playing = false, lastWall = null, selected = -1, follow = false;
  let view = { cx: 0, cy: 0, s: 1 };
  let lastDrawn = null;

  function sizeCanvas(canvas) {
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(50, canvas.clientWidth), h = Math.max(40, canvas.clientHeight);
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
    }
    const ctx = canvas.getContext("2d");
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    return { ctx: ctx, w: w, h: h };
  }

  // ---- the chart: world (east, north metres) to screen ----
  let W = 100, H = 100;
  function sx(x) { return W / 2 + (x - view.cx) * view.s; }
  function sy(y) { return H / 2 - (y - view.cy) * view.s; }
  function fit() {
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (const v of vessels) for (let i = 0; i < v.n; i++) {
      lo = [Math.min(lo[0], v.east[i]), Math.min(lo[1], v.north[i])];
      hi = [Math.max(hi[0], v.east[i]), Math.max(hi[1], v.north[i])];
    }
    if (data.goal_m) {
      lo = [Math.min(lo[0], data.goal_m[0]), Math.min(lo[1], data.goal_m[1])];
      hi = [Math.max(hi[0], data.goal_m[0]), Math.max(hi[1], data.goal_m[1])];
    }
    if (!isFinite(lo[0])) { lo = [-1000, -1000]; hi = [1000, 1000]; }
    const spanX = Math.max(hi[0] - lo[0], 500), spanY = Math.max(hi[1] - lo[1], 500);
    view.cx = (lo[0] + hi[0]) / 2; view.cy = (lo[1] + hi[1]) / 2;
    view.s = Math.min((W - 40) / spanX, (H - 40) / spanY) * 0.95;
  }
  function niceStep(target) {
    const p = Math.pow(10, Math.floor(Math.log10(target)));
    for (const k of [1, 2, 5, 10]) if (k * p >= target) return k * p;
    return 10 * p;
  }
  function distanceLabel(m) {
    return m >= NM ? +(m / NM).toFixed(2) + " nm" : Math.round(m) + " m";
  }

  function drawGrid(ctx) {
    ctx.save();
    ctx.strokeStyle = "#dde6ee"; ctx.fillStyle = "#6b7b88"; ctx.lineWidth = 1;
    ctx.font = "11px sans-serif";
    if (data.geo) {
      const maxStep = { lat: 0, lon: 0 };
      for (const line of data.geo.graticule) maxStep[line.kind] = Math.max(maxStep[line.kind], line.step_deg);
      for (const line of data.geo.graticule) {
        // A finer grid's line only when its lines are 70 px apart or more
        // (a minute of latitude is 1852 m; of longitude, less).
        const spacing_px = line.step_deg * 60 * NM * view.s * (line.kind === "lon" ? Math.cos(data.geo.origin_lat_deg * Math.PI / 180) : 1);
        const coarsest = line.step_deg >= maxStep[line.kind];
        if (!coarsest && spacing_px < 70) continue;
        ctx.strokeStyle = coarsest ? "#d3dee8" : "#e6edf3";
        ctx.beginPath();
        line.points_m.forEach(function (p, k) {
          if (k === 0) ctx.moveTo(sx(p[0]), sy(p[1])); else ctx.lineTo(sx(p[0]), sy(p[1]));
        });
        ctx.stroke();
        const spot = edgeCrossing(line.points_m, line.kind === "lat");
        if (spot) ctx.fillText(line.label, spot[0], spot[1]);
      }
    } else {
      const step = niceStep(90 / view.s / NM) * NM;
      const x0 = Math.floor((view.cx - W / 2 / view.s) / step) * step;
      const y0 = Math.floor((view.cy - H / 2 / view.s) / step) * step;
      for (let x = x0; sx(x) < W; x += step) {
        ctx.beginPath(); ctx.moveTo(sx(x), 0); ctx.lineTo(sx(x), H); ctx.stroke();
        ctx.fillText(+(x / NM).toFixed(2) + " nm E", sx(x) + 2, H - 4);
      }
      for (let y = y0; sy(y) > 0; y += step) {
        ctx.beginPath(); ctx.moveTo(0, sy(y)); ctx.lineTo(W, sy(y)); ctx.stroke();
        ctx.fillText(+(y / NM).toFixed(2) + " nm N", 4, sy(y) - 3);
      }
    }
    ctx.restore();
  }
  // Where a grid line meets the left edge (parallels) or the bottom edge
  // (meridians), for its label.
  function edgeCrossing(points, parallel) {
    for (let k = 1; k < points.length; k++) {
      const a = [sx(points[k - 1][0]), sy(points[k - 1][1])];
      const b = [sx(points[k][0]), sy(points[k][1])];
      const edge = parallel ? 4 : H - 4;
      const ia = parallel ? 0 : 1;
      if ((a[ia] - edge) * (b[ia] - edge) <= 0 && a[ia] !== b[ia]) {
        const f = (edge - a[ia]) / (b[ia] - a[ia]);
        const x = a[0] + (b[0] - a[0]) * f, y = a[1] + (b[1] - a[1]) * f;
        if (x >= 0 && x <= W && y >= 12 && y <= H) return parallel ? [x + 2, y - 3] : [x + 3, y];
      }
    }
    return null;
  }

  // Polygons: outer ring first, then holes (a bare ring is taken as one).
  function drawPolygons(ctx, polygons, fill, stroke) {
    if (!polygons || !polygons.length) return;
    ctx.save(); ctx.fillStyle = fill; ctx.strokeStyle = stroke; ctx.lineWidth = 1;
    for (let polygon of polygons) {
      if (polygon.length && typeof polygon[0][0] === "number") polygon = [polygon];
      ctx.beginPath();
      for (const ring of polygon) ring.forEach(function (p, k) {
        if (k === 0) ctx.moveTo(sx(p[0]), sy(p[1])); else ctx.lineTo(sx(p[0]), sy(p[1]));
      });
      ctx.closePath(); ctx.fill("evenodd"); ctx.stroke();
    }
    ctx.restore();
  }

  function drawLanes(ctx) {
    ctx.save();
    for (const lane of data.lanes) {
      const dx = lane.to_m[0] - lane.from_m[0], dy = lane.to_m[1] - lane.from_m[1];
      const len = Math.hypot(dx, dy) || 1, ux = dx / len, uy = dy / len;
      const nx = -uy * lane.width_m / 2, ny = ux * lane.width_m / 2;
      ctx.beginPath();
      ctx.moveTo(sx(lane.from_m[0] + nx), sy(lane.from_m[1] + ny));
      ctx.lineTo(sx(lane.to_m[0] + nx), sy(lane.to_m[1] + ny));
      ctx.lineTo(sx(lane.to_m[0] - nx), sy(lane.to_m[1] - ny));
      ctx.lineTo(sx(lane.from_m[0] - nx), sy(lane.from_m[1] - ny));
      ctx.closePath();
      ctx.fillStyle = "rgba(150,110,200,0.13)"; ctx.fill();
      ctx.strokeStyle = "rgba(120,80,180,0.7)"; ctx.lineWidth = 1; ctx.stroke();
      ctx.setLineDash([8, 6]); ctx.beginPath();
      ctx.moveTo(sx(lane.from_m[0]), sy(lane.from_m[1])); ctx.lineTo(sx(lane.to_m[0]), sy(lane.to_m[1]));
      ctx.stroke(); ctx.setLineDash([]);
      // Arrows of the traffic direction every 180 px along the centre line.
      const every = 180 / view.s;
      ctx.fillStyle = "rgba(120,80,180,0.8)";
      for (let d = every / 2; d < len; d += every) {
        const x = sx(lane.from_m[0] + ux * d), y = sy(lane.from_m[1] + uy * d);
        const ax = ux, ay = -uy;
        ctx.beginPath();
        ctx.moveTo(x + ax * 9, y + ay * 9);
        ctx.lineTo(x - ax * 6 - ay * 6, y - ay * 6 + ax * 6);
        ctx.lineTo(x - ax * 6 + ay * 6, y - ay * 6 - ax * 6);
        ctx.closePath(); ctx.fill();
      }
      const mid = [sx(lane.from_m[0] + ux * len / 2 + nx), sy(lane.from_m[1] + uy * len / 2 + ny)];
      ctx.font = "12px sans-serif";
      ctx.fillText("lane " + lane.name, Math.min(Math.max(mid[0], 8), W - 120), mid[1] - 4);
    }
    ctx.restore();
  }

  function trackPath(ctx, v, upto) {
    ctx.beginPath();
    const end = Math.min(v.n - 1, upto);
    for (let i = 0; i <= end; i++) {
      if (i === 0) ctx.moveTo(sx(v.east[i]), sy(v.north[i])); else ctx.lineTo(sx(v.east[i]), sy(v.north[i]));
    }
  }
  function drawTracks(ctx, index, frac) {
    ctx.save(); ctx.lineJoin = "round";
    for (const v of vessels) {
      const strong = v === own || v.index === selected;
      ctx.strokeStyle = v.colour; ctx.globalAlpha = strong ? 0.35 : 0.18; ctx.lineWidth = 1;
      trackPath(ctx, v, v.n - 1); ctx.stroke();
      ctx.globalAlpha = strong ? 1 : 0.75; ctx.lineWidth = v === own ? 2.5 : (strong ? 2.5 : 1.4);
      trackPath(ctx, v, index);
      const st = stateAt(v, current);
      if (st && index < v.n) ctx.lineTo(sx(st.east_m), sy(st.north_m));
      ctx.stroke();
    }
    ctx.restore();
  }
  // Targets named on the chart: all of a small encounter; in a crowd, the
  // selected one, any that broke d_th and the five closest passes of those
  // with risk of collision (the list beside names every one).
  const named = new Set();
  (function () {
    const risky = targets.filter(function (v) { return v.encounter && v.encounter.risk_time_s !== null; });
    if (targets.length <= 8) { for (const v of targets) named.add(v.index); return; }
    for (const v of targets) if (v.encounter && !v.encounter.clearance_kept) named.add(v.index);
    risky.sort(function (a, b) { return a.encounter.min_distance_m - b.encounter.min_distance_m; });
    for (const v of risky.slice(0, 5)) named.add(v.index);
  })();
  function showsLabel(v) { return v.index === selected || named.has(v.index); }
  function showsApproach(v) {
    const e = v.encounter;
    return v.index === selected || (e && (e.risk_time_s !== null || !e.clearance_kept) && (targets.length <= 25 || named.has(v.index)));
  }
  function drawClosestApproaches(ctx) {
    ctx.save(); ctx.font = "11px sans-serif";
    for (const v of targets) {
      const e = v.encounter;
      if (!e || !showsApproach(v)) continue;
      const a = stateAt(own, e.time_of_min_s), b = stateAt(v, e.time_of_min_s);
      if (!a || !b) continue;
      ctx.strokeStyle = v.colour; ctx.fillStyle = v.colour; ctx.lineWidth = v.index === selected ? 2 : 1;
      ctx.globalAlpha = current >= e.time_of_min_s ? 0.95 : 0.55;
      ctx.setLineDash([4, 3]);
      ctx.beginPath(); ctx.moveTo(sx(a.east_m), sy(a.north_m)); ctx.lineTo(sx(b.east_m), sy(b.north_m)); ctx.stroke();
      ctx.setLineDash([]);
      for (const p of [a, b]) { ctx.beginPath(); ctx.arc(sx(p.east_m), sy(p.north_m), 2.5, 0, 2 * Math.PI); ctx.fill(); }
      if (showsLabel(v)) {
        const x = (sx(a.east_m) + sx(b.east_m)) / 2 + 4, y = (sy(a.north_m) + sy(b.north_m)) / 2 - 4;
        ctx.fillStyle = e.clearance_kept ? "#333" : DTH_COLOUR;
        ctx.fillText("CPA " + v.name + " " + Math.round(e.min_distance_m) + " m @ " + minutes(e.time_of_min_s), x, y);
      }
    }
    ctx.restore();
  }
  // The hull outline (length to scale, beam as the data gives it) at st.
  function hullPoints(st, L, B) {
    const c = st.course_deg * Math.PI / 180;
    const fx = Math.sin(c), fy = Math.cos(c), rx = Math.cos(c), ry = -Math.sin(c);
    const shape = [[0.5, 0], [0.22, 0.5], [-0.5, 0.45], [-0.5, -0.45], [0.22, -0.5]];
    return shape.map(function (p) {
      const along = p[0] * L, across = p[1] * B;
      return [sx(st.east_m + fx * along + rx * across), sy(st.north_m + fy * along + ry * across)];
    });
  }
  function drawHull(ctx, v, st) {
    const isOwn = v === own;
    const pts = hullPoints(st, v.length_m, v.beam_m);
    const poly = function (p) {
      ctx.beginPath(); p.forEach(function (q, k) { if (k === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]); }); ctx.closePath();
    };
    ctx.fillStyle = v.colour; ctx.strokeStyle = isOwn ? "#000" : "#222"; ctx.lineWidth = isOwn ? 1.5 : 1;
    poly(pts); ctx.fill(); ctx.stroke();
    // A hull smaller than MIN_HULL_PX on screen is outlined at that size too.
    const px = v.length_m * view.s;
    if (px < MIN_HULL_PX) {
      const k = MIN_HULL_PX / px;
      const big = hullPoints(st, v.length_m * k, v.beam_m * k * 1.3);
      ctx.lineWidth = isOwn ? 2.5 : 1.5; ctx.strokeStyle = v.colour;
      poly(big); ctx.stroke();
      if (isOwn) { ctx.globalAlpha = 0.35; ctx.fill(); ctx.globalAlpha = 1; }
    }
    // One minute of travel ahead of the bow.
    const c = st.course_deg * Math.PI / 180, ahead = st.speed_kn * NM / 60;
    ctx.strokeStyle = v.colour; ctx.lineWidth = isOwn ? 2 : 1;
    ctx.beginPath(); ctx.moveTo(sx(st.east_m), sy(st.north_m));
    ctx.lineTo(sx(st.east_m + Math.sin(c) * ahead), sy(st.north_m + Math.cos(c) * ahead)); ctx.stroke();
  }
  function drawScaleBar(ctx) {
    const want = 110 / view.s;
    const m = want > NM / 2 ? niceStep(want / NM) * NM : niceStep(want);
    const px = m * view.s, x = 14, y = H - 22;
    ctx.save(); ctx.fillStyle = "rgba(255,255,255,0.85)"; ctx.fillRect(x - 6, y - 16, px + 70, 26);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + px, y); ctx.lineTo(x + px, y - 5); ctx.stroke();
    ctx.fillStyle = "#000"; ctx.font = "12px sans-serif";
    ctx.fillText(distanceLabel(m) + (m >= NM ? " (" + Math.round(m) + " m)" : " (" + +(m / NM).toFixed(3) + " nm)"), x + 4, y - 5);
    ctx.restore();
  }
  function drawNorth(ctx) {
    ctx.save(); ctx.fillStyle = "#333"; ctx.font = "bold 12px sans-serif";
    ctx.beginPath(); ctx.moveTo(W - 24, 44); ctx.lineTo(W - 30, 60); ctx.lineTo(W - 18, 60); ctx.closePath(); ctx.fill();
    ctx.fillText("N", W - 28, 74); ctx.restore();
  }

  function drawChart() {
    const c = sizeCanvas(chart), ctx = c.ctx;
    W = c.w; H = c.h;
    if (follow) { const st = stateAt(own, current); if (st) { view.cx = st.east_m; view.cy = st.north_m; } }
    ctx.fillStyle = "#f3f8fc"; ctx.fillRect(0, 0, W, H);
    drawGrid(ctx);
    drawPolygons(ctx, data.separation_zones, "rgba(230,120,200,0.25)", "rgba(190,60,160,0.8)");
    drawLanes(ctx);
    drawPolygons(ctx, data.no_go, "rgba(220,40,40,0.18)", "rgba(200,0,0,0.8)");
    drawPolygons(ctx, data.land, "#e9dcb5", "#9a8655");
    const [index, frac] = locate(current);
    drawTracks(ctx, index, frac);
    if (data.goal_m) {
      const gx = sx(data.goal_m[0]), gy = sy(data.goal_m[1]);
      ctx.save(); ctx.strokeStyle = "#000"; ctx.lineWidth = 2; ctx.beginPath();
      ctx.moveTo(gx - 6, gy - 6); ctx.lineTo(gx + 6, gy + 6); ctx.moveTo(gx + 6, gy - 6); ctx.lineTo(gx - 6, gy + 6);
      ctx.stroke(); ctx.font = "12px sans-serif"; ctx.fillStyle = "#000"; ctx.fillText("goal", gx + 8, gy + 4); ctx.restore();
    }
    drawClosestApproaches(ctx);
    const drawn = [];
    ctx.save(); ctx.font = "12px sans-serif";
    for (const v of targets.concat([own])) {
      const st = stateAt(v, current);
      if (!st) continue;
      drawHull(ctx, v, st);
      drawn.push({ name: v.name, role: v.role, east_m: st.east_m, north_m: st.north_m,
        course_deg: st.course_deg, speed_kn: st.speed_kn, x_px: sx(st.east_m), y_px: sy(st.north_m) });
      if (v !== own && showsLabel(v)) {
        const e = v.encounter;
        const label = v.name + (e && e.risk_time_s !== null && current >= e.risk_time_s ? " (" + ENCOUNTER_SHORT[e.encounter] + ")" : "");
        ctx.font = v.index === selected ? "bold 12px sans-serif" : "11px sans-serif";
        ctx.fillStyle = "rgba(255,255,255,0.8)";
        const w = ctx.measureText(label).width;
        ctx.fillRect(sx(st.east_m) + 8, sy(st.north_m) - 20, w + 4, 15);
        ctx.fillStyle = "#111"; ctx.fillText(label, sx(st.east_m) + 10, sy(st.north_m) - 8);
      }
    }
    const o = stateAt(own, current);
    if (o) {
      ctx.strokeStyle = DTH_COLOUR; ctx.lineWidth = 1.5; ctx.setLineDash([6, 4]);
      ctx.beginPath(); ctx.arc(sx(o.east_m), sy(o.north_m), data.d_th_m * view.s, 0, 2 * Math.PI); ctx.stroke();
      ctx.setLineDash([]);
      const ring = data.d_th_m * view.s;
      if (ring > 30) { ctx.fillStyle = DTH_COLOUR; ctx.fillText("d_th " + Math.round(data.d_th_m) + " m", sx(o.east_m) + ring * 0.72 + 3, sy(o.north_m) + ring * 0.72 + 12); }
      ctx.fillStyle = "#000"; ctx.font = "bold 12px sans-serif";
      ctx.fillText(own.name, sx(o.east_m) + 10, sy(o.north_m) + 16);
    }
    ctx.restore();
    drawScaleBar(ctx); drawNorth(ctx);
    ctx.save(); ctx.fillStyle = "rgba(255,255,255,0.85)"; ctx.fillRect(6, 6, 250, 22);
    ctx.fillStyle = "#000"; ctx.font = "bold 14px sans-serif";
    ctx.fillText("t = " + clock(current) + "  (" + current.toFixed(1) + " s)", 12, 22); ctx.restore();
    lastDrawn = { time_s: current, vessels: drawn, view: { cx: view.cx, cy: view.cy, px_per_m: view.s },
      timeline_findings: timelineMarks.filter(function (m) { return m.finding; }).length };
  }

  // ---- timeline and plots: time on x ----
  const MARGIN_L = 92, MARGIN_R = 12;
  function tx(t, w) { return MARGIN_L + (T1 > T0 ? (t - T0) / (T1 - T0) : 0) * (w - MARGIN_L - MARGIN_R); }
  function timeAt(x, w) { return T0 + Math.min(1, Math.max(0, (x - MARGIN_L) / (w - MARGIN_L - MARGIN_R))) * (T1 - T0); }
  let timelineMarks = [];
  let timelineCache = null, plotsCache = null;

  function timeAxis(ctx, w, y0, y1, labels) {
    ctx.strokeStyle = "#eee"; ctx.fillStyle = "#666"; ctx.font = "10px sans-serif"; ctx.lineWidth = 1;
    const step = niceStep((T1 - T0) / 60 / 10 || 1) * 60;
    for (let t = Math.ceil(T0 / step) * step; t <= T1; t += step) {
      ctx.beginPath(); ctx.moveTo(tx(t, w), y0); ctx.lineTo(tx(t, w), y1); ctx.stroke();
      if (labels) ctx.fillText(+(t / 60).toFixed(1) + " min", tx(t, w) + 2, y1 - 2);
    }
  }
  function renderTimeline() {
    const canvas = document.createElement("canvas");
    const w = timeline.clientWidth, h = timeline.clientHeight, dpr = window.devicePixelRatio || 1;
    canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
    const ctx = canvas.getContext("2d"); ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, w, h);
    timeAxis(ctx, w, 0, h, true);
    const rows = [["findings", 10], ["risk / CPA", 28], ["plans", 57]];
    ctx.fillStyle = "#333"; ctx.font = "11px sans-serif";
    for (const [name, y] of rows) ctx.fillText(name, 4, y + 4);
    timelineMarks = [];
    for (const p of data.plans) {
      const x = tx(p.time_s, w);
      ctx.strokeStyle = p.succeeded ? "#2a8a2a" : "#e07b00"; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(x, 51); ctx.lineTo(x, 63); ctx.stroke();
      timelineMarks.push({ x: x, y: 57, time_s: p.time_s, vessel: -1,
        text: minutes(p.time_s) + ": planner call (" + p.trigger + ")" + (p.succeeded ? "" : ", no plan") });
    }
    let labelEnd = -Infinity;
    const labels = [];
    ctx.font = "10px sans-serif";
    for (const v of targets) {
      const e = v.encounter;
      if (!e || e.risk_time_s === null) continue;
      ctx.fillStyle = v.colour; ctx.strokeStyle = v.colour;
      const x = tx(e.risk_time_s, w);
      ctx.beginPath(); ctx.moveTo(x, 22); ctx.lineTo(x - 5, 33); ctx.lineTo(x + 5, 33); ctx.closePath(); ctx.fill();
      timelineMarks.push({ x: x, y: 28, time_s: e.risk_time_s, vessel: v.index,
        text: minutes(e.risk_time_s) + ": risk of collision with " + v.name + ", " + ENCOUNTER_SHORT[e.encounter] });
      // The classification beside its triangle where there is room; risks
      // that arose together share one label.
      const label = v.name + " " + ENCOUNTER_SHORT[e.encounter];
      if (x + 7 > labelEnd) {
        const together = targets.filter(function (u) {
          return u !== v && u.encounter && u.encounter.risk_time_s !== null && Math.abs(tx(u.encounter.risk_time_s, w) - x) < 3;
        }).map(function (u) { return u.name + " " + ENCOUNTER_SHORT[u.encounter.encounter]; });
        const text = [label].concat(together.slice(0, 3)).join("; ") + (together.length > 3 ? "; +" + (together.length - 3) : "");
        labels.push([text, x + 7, v.colour]); labelEnd = x + 7 + ctx.measureText(text).width + 6;
      }
      const x2 = tx(e.time_of_min_s, w);
      ctx.lineWidth = 2; ctx.beginPath(); ctx.moveTo(x2, 22); ctx.lineTo(x2, 34); ctx.stroke();
      timelineMarks.push({ x: x2, y: 28, time_s: e.time_of_min_s, vessel: v.index,
        text: minutes(e.time_of_min_s) + ": closest approach of " + v.name + ", " + Math.round(e.min_distance_m) + " m" });
    }
    // The classifications on a line of their own under the marks.
    for (const [text, x, colour] of labels) { ctx.fillStyle = colour; ctx.fillText(text, x - 9, 45); }
    data.findings.forEach(function (f) {
      if (f.time_s === null) return;
      const x = tx(f.time_s, w);
      ctx.fillStyle = DTH_COLOUR;
      ctx.beginPath(); ctx.moveTo(x, 3); ctx.lineTo(x + 5, 9); ctx.lineTo(x, 15); ctx.lineTo(x - 5, 9); ctx.closePath(); ctx.fill();
      timelineMarks.push({ x: x, y: 9, time_s: f.time_s, vessel: vesselIndex(f.vessel), finding: true,
        text: minutes(f.time_s) + ": " + (f.vessel === null ? "" : f.vessel + ": ") + f.text });
    });
    timelineCache = canvas;
  }
  function vesselIndex(name) {
    for (const v of vessels) if (v.name === name) return v.index;
    return -1;
  }
  function drawCursor(ctx, w, h) {
    const x = tx(current, w);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(x, 0); ctx.lineTo(x, h); ctx.stroke();
  }
  function drawTimeline() {
    const c = sizeCanvas(timeline);
    if (!timelineCache || timelineCache.width !== timeline.width) renderTimeline();
    c.ctx.drawImage(timelineCache, 0, 0, c.w, c.h);
    drawCursor(c.ctx, c.w, c.h);
  }

  // Distance of every target from ownship at the kept samples.
  const distances = targets.map(function (v) {
    const n = Math.min(v.n, own.n), d = new Array(n);
    for (let i = 0; i < n; i++) d[i] = Math.hypot(v.east[i] - own.east[i], v.north[i] - own.north[i]);
    return d;
  });
  function panels(h) {
    const gap = 8, top = 6, each = (h - top - 18 - 2 * gap) / 3;
    return [0, 1, 2].map(function (k) { return [top + k * (each + gap), top + k * (each + gap) + each]; });
  }
  function series(ctx, w, y0, y1, lo, hi, values, count) {
    ctx.beginPath();
    for (let i = 0; i < count; i++) {
      const x = tx(times[i], w), y = y1 - (values(i) - lo) / (hi - lo) * (y1 - y0);
      if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
    }
    ctx.stroke();
  }
  function yAxis(ctx, w, y0, y1, lo, hi, unit) {
    ctx.strokeStyle = "#eee"; ctx.fillStyle = "#666"; ctx.font = "10px sans-serif";
    const step = niceStep((hi - lo) / 4);
    for (let v = Math.ceil(lo / step) * step; v <= hi; v += step) {
      const y = y1 - (v - lo) / (hi - lo) * (y1 - y0);
      ctx.beginPath(); ctx.moveTo(MARGIN_L, y); ctx.lineTo(w - MARGIN_R, y); ctx.stroke();
      ctx.fillText(+v.toFixed(1) + " " + unit, MARGIN_L - 50, y + 3);
    }
  }
  function distanceRange() {
    // Up to twice the farthest close pass of a target with risk of
    // collision (at least 5 d_th): the passes show, not the far starts.
    let top = data.d_th_m * 5, far = 0;
    for (const v of targets) if (v.encounter && v.encounter.risk_time_s !== null) top = Math.max(top, v.encounter.min_distance_m * 2);
    for (const d of distances) for (const x of d) far = Math.max(far, x);
    return Math.max(Math.min(top, far), data.d_th_m * 1.5);
  }
  function renderPlots() {
    const canvas = document.createElement("canvas");
    const w = plots.clientWidth, h = plots.clientHeight, dpr = window.devicePixelRatio || 1;
    canvas.width = Math.round(w * dpr); canvas.height = Math.round(h * dpr);
    const ctx = canvas.getContext("2d"); ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, w, h);
    const [pd, ps, pc] = panels(h);
    for (const [y0, y1] of [pd, ps, pc]) timeAxis(ctx, w, y0, y1, false);
    timeAxis(ctx, w, pc[1], h, true);
    // Distance, clipped to the range that shows the close passes.
    const dmax = distanceRange();
    yAxis(ctx, w, pd[0], pd[1], 0, dmax, "m");
    ctx.save(); ctx.beginPath(); ctx.rect(MARGIN_L, pd[0], w - MARGIN_L - MARGIN_R, pd[1] - pd[0]); ctx.clip();
    targets.forEach(function (v, k) {
      ctx.strokeStyle = v.colour; ctx.lineWidth = v.index === selected ? 2.5 : 1; ctx.globalAlpha = selected < 0 || v.index === selected ? 0.9 : 0.35;
      series(ctx, w, pd[0], pd[1], 0, dmax, function (i) { return distances[k][i]; }, distances[k].length);
    });
    ctx.globalAlpha = 1; ctx.strokeStyle = DTH_COLOUR; ctx.setLineDash([6, 4]); ctx.lineWidth = 1.5;
    const yd = pd[1] - data.d_th_m / dmax * (pd[1] - pd[0]);
    ctx.beginPath(); ctx.moveTo(MARGIN_L, yd); ctx.lineTo(w - MARGIN_R, yd); ctx.stroke(); ctx.setLineDash([]);
    ctx.restore();
    // Speed and course of ownship, and of the selected target dashed.
    const shown = selected > 0 ? [own, vessels[selected]] : [own];
    let smax = 1;
    for (const v of shown) for (const s of v.speed) smax = Math.max(smax, s * 1.15);
    yAxis(ctx, w, ps[0], ps[1], 0, smax, "kn");
    yAxis(ctx, w, pc[0], pc[1], 0, 360, "°");
    for (const v of shown) {
      ctx.strokeStyle = v.colour; ctx.lineWidth = 2; ctx.setLineDash(v === own ? [] : [5, 3]);
      series(ctx, w, ps[0], ps[1], 0, smax, function (i) { return v.speed[i]; }, v.n);
      ctx.beginPath();
      for (let i = 0; i < v.n; i++) {
        const x = tx(times[i], w), y = pc[1] - v.course[i] / 360 * (pc[1] - pc[0]);
        // No line across the 0/360 wrap.
        if (i === 0 || Math.abs(v.course[i] - v.course[i - 1]) > 180) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.stroke();
    }
    ctx.setLineDash([]);
    ctx.fillStyle = "#222"; ctx.font = "bold 11px sans-serif";
    ctx.fillText("distance", 4, pd[0] + 12); ctx.fillText("speed", 4, ps[0] + 12); ctx.fillText("course", 4, pc[0] + 12);
    plotsCache = canvas;
  }
  function drawPlots() {
    const c = sizeCanvas(plots), ctx = c.ctx;
    if (!plotsCache || plotsCache.width !== plots.width) renderPlots();
    ctx.drawImage(plotsCache, 0, 0, c.w, c.h);
    drawCursor(ctx, c.w, c.h);
    const o = stateAt(own, current);
    const parts = [];
    if (o) parts.push(own.name + " " + o.speed_kn.toFixed(1) + " kn, " + o.course_deg.toFixed(1) + "°");
    let nearest = null;
    for (const v of targets) {
      const st = stateAt(v, current);
      if (!o || !st) continue;
      const d = Math.hypot(st.east_m - o.east_m, st.north_m - o.north_m);
      if (v.index === selected || (selected < 0 && (!nearest || d < nearest[1]))) nearest = [v, d, st];
    }
    if (nearest) parts.push((selected > 0 ? "" : "nearest ") + nearest[0].name + " " + Math.round(nearest[1]) + " m away (d_th " + Math.round(data.d_th_m) + " m), " + nearest[2].speed_kn.toFixed(1) + " kn, " + nearest[2].course_deg.toFixed(1) + "°");
    $("readout").textContent = "at t = " + clock(current) + ": " + parts.join("; ");
  }

  // ---- side panel ----
  function buildLegend() {
    const rows = ["<table><tr><th></th><th>vessel</th><th>encounter (risk at)</th><th>CPA</th></tr>"];
    for (const v of vessels) {
      const e = v.encounter;
      const enc = e ? (e.risk_time_s === null ? "no risk" : ENCOUNTER_SHORT[e.encounter] + " (" + minutes(e.risk_time_s) + ")") : "ownship, " + Math.round(v.length_m) + " m";
      const title = e ? "ownship " + e.colregs_role.replace("_", " ") + ", score " + e.score.toFixed(2) + (e.compliant ? "" : ", not compliant") : "";
      rows.push("<tr class=\"vessel\" data-index=\"" + v.index + "\" title=\"" + escapeHtml(title) + "\"><td><span class=\"swatch\" style=\"background:" + v.colour + "\"></span></td><td>" +
        escapeHtml(v.name) + "</td><td>" + escapeHtml(enc) + "</td><td class=\"num" + (e && !e.clearance_kept ? " bad" : "") + "\">" +
        (e ? Math.round(e.min_distance_m) + " m, " + minutes(e.time_of_min_s) : "") + "</td></tr>");
    }
    rows.push("</table>");
    $("legend").innerHTML = rows.join("");
    $("vessel-count").textContent = "(" + vessels.length + ")";
    $("legend").addEventListener("click", function (event) {
      const row = event.target.closest("tr.vessel");
      if (!row) return;
      const index = Number(row.dataset.index);
      select(selected === index ? -1 : index);
    });
  }
  function escapeHtml(text) {
    return String(text).replace(/[&<>"']/g, function (c) {
      return { "&": "&amp;", "<": "&lt;", ">": "&gt;", "\"": "&quot;", "'": "&#39;" }[c];
    });
  }
  const AT_TEXT = { action: "when the action began", risk: "when risk arose", closest_approach: "at the closest approach", track: "the whole track" };
  function buildFindings() {
    const list = $("findings");
    list.textContent = "";
    $("finding-count").textContent = "(" + data.findings.length + ")";
    if (!data.findings.length) {
      const li = document.createElement("li"); li.className = "none"; li.textContent = "no findings: safe and compliant";
      list.appendChild(li);
    }
    data.findings.forEach(function (f, k) {
      const li = document.createElement("li");
      li.className = "finding";
      li.dataset.index = k; li.dataset.name = f.name; li.dataset.vessel = f.vessel === null ? "" : f.vessel;
      li.dataset.time = f.time_s === null ? "" : f.time_s;
      const when = document.createElement("span"); when.className = "when";
      when.textContent = f.time_s === null ? "track " : minutes(f.time_s) + " ";
      li.appendChild(when);
      li.appendChild(document.createTextNode((f.vessel === null ? "" : f.vessel + ": ") + f.text + " (" + AT_TEXT[f.at] + ")"));
      list.appendChild(li);
    });
    list.addEventListener("click", function (event) {
      const li = event.target.closest("li.finding");
      if (!li) return;
      const f = data.findings[Number(li.dataset.index)];
      if (f.vessel !== null) select(vesselIndex(f.vessel));
      if (f.time_s !== null) { pause(); setTime(f.time_s); }
    });
  }
  function markFindings() {
    for (const li of $("findings").querySelectorAll("li.finding")) {
      const f = data.findings[Number(li.dataset.index)];
      const past = f.time_s !== null && f.time_s <= current;
      li.classList.toggle("past", past && Math.abs(f.time_s - current) > data.time_step_s);
      li.classList.toggle("current", f.time_s !== null && Math.abs(f.time_s - current) <= data.time_step_s);
    }
  }
  function select(index) {
    selected = index;
    for (const row of $("legend").querySelectorAll("tr.vessel")) row.classList.toggle("selected", Number(row.dataset.index) === selected);
    plotsCache = null;
    redraw();
  }

  // ---- control ----
  function redraw() { drawChart(); drawTimeline(); drawPlots(); markFindings(); }
  function setTime(t, fromSlider) {
    current = Math.min(T1, Math.max(T0, Number(t)));
    if (!fromSlider) slider.value = current;
    $("clock").textContent = "t = " + clock(current) + " / " + clock(T1);
    redraw();
  }
  function pause() { playing = false; playButton.innerHTML = "&#9654; play"; }
  function play() {
    if (current >= T1) setTime(T0);
    playing = true; lastWall = null; playButton.innerHTML = "&#10074;&#10074; pause";
    requestAnimationFrame(tick);
  }
  function tick(now) {
    if (!playing) return;
    if (lastWall !== null) setTime(current + (now - lastWall) / 1000 * Number(speedSelect.value));
    lastWall = now;
    if (current >= T1) { pause(); return; }
    requestAnimationFrame(tick);
  }
  playButton.addEventListener("click", function () { if (playing) pause(); else play(); });
  slider.addEventListener("input", function () { setTime(slider.value, true); });
  document.addEventListener("keydown", function (event) {
    if (event.target.tagName === "SELECT") return;
    if (event.key === " ") { event.preventDefault(); if (playing) pause(); else play(); }
    if (event.key === "ArrowRight" && event.target !== slider) setTime(current + data.time_step_s);
    if (event.key === "ArrowLeft" && event.target !== slider) setTime(current - data.time_step_s);
  });
  function nearestMark(marks, x, y) {
    let best = null;
    for (const m of marks || []) {
      const d = Math.hypot(m.x - x, m.y - y);
      if (d < 8 && (!best || d < best[1])) best = [m, d];
    }
    return best ? best[0] : null;
  }
  function clickTime(canvas, event, marks) {
    const rect = canvas.getBoundingClientRect();
    const x = event.clientX - rect.left, y = event.clientY - rect.top;
    const best = nearestMark(marks, x, y);
    pause();
    if (best) { if (best.vessel > 0) select(best.vessel); setTime(best.time_s); } else setTime(timeAt(x, rect.width));
  }
  timeline.addEventListener("click", function (event) { clickTime(timeline, event, timelineMarks); });
  timeline.addEventListener("mousemove", function (event) {
    const rect = timeline.getBoundingClientRect();
    const hit = nearestMark(timelineMarks, event.clientX - rect.left, event.clientY - rect.top);
    timeline.title = hit ? hit.text : "click: go to this time";
  });
  plots.addEventListener("click", function (event) { clickTime(plots, event, null); });
  // Pan by dragging, zoom with the wheel about the pointer.
  let drag = null;
  chart.addEventListener("pointerdown", function (event) {
    drag = { x: event.clientX, y: event.clientY }; chart.setPointerCapture(event.pointerId); chart.classList.add("dragging");
  });
  chart.addEventListener("pointermove", function (event) {
    if (!drag) return;
    view.cx -= (event.clientX - drag.x) / view.s; view.cy += (event.clientY - drag.y) / view.s;
    drag = { x: event.clientX, y: event.clientY };
    if (follow) { follow = false; $("follow").checked = false; }
    drawChart();
  });
  chart.addEventListener("pointerup", function () { drag = null; chart.classList.remove("dragging"); });
  function zoom(factor, px, py) {
    const wx = view.cx + (px - W / 2) / view.s, wy = view.cy - (py - H / 2) / view.s;
    view.s = Math.min(50, Math.max(1e-4, view.s * factor));
    view.cx = wx - (px - W / 2) / view.s; view.cy = wy + (py - H / 2) / view.s;
    drawChart();
  }
  chart.addEventListener("wheel", function (event) {
    event.preventDefault();
    const rect = chart.getBoundingClientRect();
    zoom(Math.pow(1.0015, -event.deltaY), event.clientX - rect.left, event.clientY - rect.top);
  }, { passive: false });
  chart.addEventListener("dblclick", function () { fit(); drawChart(); });
  $("zoom-in").addEventListener("click", function () { zoom(1.5, W / 2, H / 2); });
  $("zoom-out").addEventListener("click", function () { zoom(1 / 1.5, W / 2, H / 2); });
  $("fit").addEventListener("click", function () { fit(); drawChart(); });
  $("follow").addEventListener("change", function (event) { follow = event.target.checked; drawChart(); });
  window.addEventListener("resize", function () { timelineCache = null; plotsCache = null; redraw(); });

  // ---- start ----
  $("title").textContent = data.scenario + " - vorrt replay";
  const v = data.verdict;
  const mark = function (ok, yes, no) { return "<span class=\"" + (ok ? "good" : "bad") + "\">" + (ok ? yes : no) + "</span>"; };
  $("verdict").innerHTML = "goal " + mark(v.reached_goal, "reached", "not reached") + " · collision " + mark(!v.collision, "none", "YES") +
    " · d_th " + Math.round(data.d_th_m) + " m " + mark(v.clearance_kept, "kept", "broken") +
    (v.min_distance_m === null ? "" : " (min " + v.min_distance_m.toFixed(1) + " m)") + " · COLREGs " + mark(v.compliant, "no finding", "findings") +
    " · seed " + data.seed + " · " + escapeHtml(data.scenario_file) +
    (data.step_stride > 1 ? " · every " + data.step_stride + "th step of " + data.time_step_s + " s shown" : "");
  $("description").textContent = data.description || "";
  $("key").innerHTML = "<span>hulls to scale (beam = length/6); a hull under " + MIN_HULL_PX + " px is outlined at " + MIN_HULL_PX + " px</span>" +
    "<span>line ahead of a bow: 1 min of travel</span><span style=\"color:" + DTH_COLOUR + "\">dashed ring: d_th</span>" +
    "<span>dashed lines: closest approaches</span><span>drag: pan, wheel: zoom, double-click: fit, space: play</span>" +
    (data.geo ? "<span>grid: latitude and longitude (frame about " + data.geo.origin_lat_deg.toFixed(4) + ", " + data.geo.origin_lon_deg.toFixed(4) + ")</span>" : "<span>grid: nm east and north of the frame's origin</span>");
  slider.min = T0; slider.max = T1; slider.step = 0.1;
  buildLegend(); buildFindings();
  const box = sizeCanvas(chart); W = box.w; H = box.h;
  fit();
  setTime(T0);

  // A read-only hook for tests and scripts: what the last frame drew.
  window.vorrtReplay = Object.freeze({
    state: function () { return JSON.parse(JSON.stringify(Object.assign({ playing: playing, selected: selected }, lastDrawn))); },
    data: function () { return JSON.parse(JSON.stringify(data)); },
  });
})();
