// The run explorer's page script. It decodes the data camcov embedded
// (reports/explorer/explorer_data.h says the format) and draws; every piece of geometry and
// every "why not seen" was computed by camcov, so nothing here decides visibility.
"use strict";
(() => {
  const data = JSON.parse(document.getElementById("camcov-data").textContent);
  const P = data.palette;
  const U = data.units;
  const SVG = "http://www.w3.org/2000/svg";

  // ---- decoding -----------------------------------------------------------------------------
  class PackedReader {
    constructor(base64) {
      const text = atob(base64);
      this.bytes = new Uint8Array(text.length);
      for (let i = 0; i < text.length; ++i) this.bytes[i] = text.charCodeAt(i);
      this.at = 0;
    }
    u() {  // LEB128
      let value = 0, scale = 1, byte;
      do {
        byte = this.bytes[this.at++];
        value += (byte & 0x7f) * scale;
        scale *= 128;
      } while (byte & 0x80);
      return value;
    }
    s() {  // zigzag
      const z = this.u();
      return z % 2 === 0 ? z / 2 : -(z + 1) / 2;
    }
    bits() {  // a varint mask as the list of its set bits (any number of cameras, beyond 2^53)
      const set = [];
      let shift = 0, byte;
      do {
        byte = this.bytes[this.at++];
        for (let b = 0; b < 7; ++b) if (byte & (1 << b)) set.push(shift + b);
        shift += 7;
      } while (byte & 0x80);
      return set;
    }
    points(units, x0, y0) {  // count, then differences from the previous point
      const n = this.u(), out = [];
      let x = x0, y = y0;
      for (let i = 0; i < n; ++i) {
        x += this.s();
        y += this.s();
        out.push([x / units, y / units]);
      }
      return out;
    }
  }

  function decodeRun(run) {
    const r = new PackedReader(run.steps);
    const M = run.cameras.length, objects = run.targets + run.obstacles;  // in the scene
    const previous = new Array(objects).fill(null);
    const pose = Array.from({length: M}, () => [0, 0, 0]);
    const goal = new Array(M).fill(null);
    const steps = [];
    for (let k = 0; k < run.series.time.length; ++k) {
      // Targets, then obstacles: those present, each with its scene index.
      const present = [];
      for (let group = 0; group < 2; ++group) {
        const count = r.u(), list = [];
        for (let o = 0; o < count; ++o) {
          const id = r.u(), key = group * run.targets + id;
          const n = r.u(), before = previous[key], same = before && before.length === 2 * n;
          const q = new Array(2 * n);
          let x = 0, y = 0;
          for (let i = 0; i < n; ++i) {
            x = (same ? before[2 * i] : x) + r.s();
            y = (same ? before[2 * i + 1] : y) + r.s();
            q[2 * i] = x;
            q[2 * i + 1] = y;
          }
          previous[key] = q;
          const ring = [];
          for (let i = 0; i < n; ++i) ring.push([q[2 * i] / U.millimetres, q[2 * i + 1] / U.millimetres]);
          list.push({id, ring});
        }
        present.push(list);
      }
      const targetRing = new Map(present[0].map((t) => [t.id, t.ring]));
      const cameras = [];
      for (let j = 0; j < M; ++j) {
        for (let c = 0; c < 3; ++c) pose[j][c] += r.s();
        const g = r.u();
        if (g === 0) goal[j] = null;
        else if (g === 2) goal[j] = [r.s(), r.s(), r.s()];
        const plan = r.points(U.millimetres, pose[j][0], pose[j][1]);
        const view = r.points(U.centimetres, 0, 0);
        const objectDistance = r.u() / U.millimetres, object = r.u();
        const other = r.u(), cameraDistance = r.u() / U.millimetres;
        const coverage = r.u() / U.terms, utilization = r.u() / U.terms;
        cameras.push({
          x: pose[j][0] / U.millimetres, y: pose[j][1] / U.millimetres, yaw: pose[j][2] / U.yaw,
          goal: goal[j] && {x: goal[j][0] / U.millimetres, y: goal[j][1] / U.millimetres,
                            yaw: goal[j][2] / U.yaw},
          plan, view, object, objectDistance, other, cameraDistance, coverage, utilization,
        });
      }
      const segments = [];
      const count = r.u();
      for (let i = 0; i < count; ++i) {
        const target = r.u(), edge = r.u(), ta = r.u() / U.alongEdge, tb = r.u() / U.alongEdge;
        const visibleBy = r.bits();
        const weight = run.weighted ? r.u() / U.weight : null;  // a weighted scene's
        const reasons = new Array(M).fill(null);
        for (let j = 0; j < M; ++j) if (!visibleBy.includes(j)) reasons[j] = r.u();
        const ring = targetRing.get(target), a = ring[edge], b = ring[(edge + 1) % ring.length];
        const at = (t) => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
        segments.push({target, edge, ta, tb, a: at(ta), b: at(tb), visibleBy, reasons, weight});
      }
      // A scene with a resolution: the pieces of seen boundary no camera resolves.
      const unresolved = [];
      for (let i = 0, n = run.resolved ? r.u() : 0; i < n; ++i) {
        const target = r.u(), edge = r.u(), ta = r.u() / U.alongEdge, tb = r.u() / U.alongEdge;
        const ring = targetRing.get(target), a = ring[edge], b = ring[(edge + 1) % ring.length];
        const at = (t) => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
        unresolved.push({target, edge, a: at(ta), b: at(tb)});
      }
      steps.push({targets: present[0], obstacles: present[1], cameras, segments, unresolved});
    }
    return steps;
  }

  const runs = data.runs.map((run) => ({...run, decoded: decodeRun(run)}));
  const stepCount = Math.max(...runs.map((r) => r.decoded.length));

  // ---- helpers ------------------------------------------------------------------------------
  const el = (tag, attributes = {}, parent = null) => {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
    if (parent) parent.appendChild(e);
    return e;
  };
  const html = (tag, attributes = {}, text = null, parent = null) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
    if (text !== null) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  };
  const pts = (ring) => ring.map(([x, y]) => `${x.toFixed(3)},${(-y).toFixed(3)}`).join(" ");
  const deg = (rad) => (rad * 180 / Math.PI).toFixed(1);
  // A target edge's stroke: as wide as important, as frames draw them (viz/palette.h
  // importanceWidthFactor); 5 px in a scene without weights.
  const edgeWidth = (weight) => weight == null ? 5 : 5 * (P.widthAtZero + P.widthPerWeight * weight);
  const length = (s) => Math.hypot(s.b[0] - s.a[0], s.b[1] - s.a[1]);
  const objectName = (code) => code === 0 ? "none"
      : code % 2 === 1 ? `target ${(code - 1) / 2}` : `obstacle ${(code - 2) / 2}`;
  const blockerName = (kind, index) =>
      kind === 1 ? "the boundary" : kind === 2 ? `target ${index}` : `obstacle ${index}`;
  // The words of visibility::unseenPhrase, by UnseenKind, from the palette.
  function reasonText(code) {
    const kind = code % 8, rest = Math.floor(code / 8), blocker = rest % 4, index = Math.floor(rest / 4);
    return P.unseen[kind].replace("{blocker}", blockerName(blocker, index));
  }

  // ---- layout -------------------------------------------------------------------------------
  const boundary = data.scene.boundary;
  const xs = boundary.map((p) => p[0]), ys = boundary.map((p) => p[1]);
  const minX = Math.min(...xs), maxX = Math.max(...xs), minY = Math.min(...ys), maxY = Math.max(...ys);
  const pad = 0.04 * Math.max(maxX - minX, maxY - minY);
  const home = {x: minX - pad, y: -maxY - pad, w: maxX - minX + 2 * pad, h: maxY - minY + 2 * pad};
  const viewBox = `${home.x} ${home.y} ${home.w} ${home.h}`;

  const container = document.getElementById("runs");
  const panels = runs.map((run, i) => {
    const section = html("section", {class: "run", "data-run": String(i)}, null, container);
    const head = html("header", {}, null, section);
    const swatch = html("span", {class: "swatch"}, null, head);
    swatch.style.background = run.color;
    html("h2", {}, run.label, head);
    const numbers = html("p", {class: "numbers"}, null, section);
    html("span", {}, "coverage ", numbers);
    const coverage = html("b", {class: "coverage"}, "", numbers);
    const weighted = run.weighted ? html("b", {class: "weighted-coverage"}, "", null) : null;
    if (weighted) {
      html("span", {}, " · weighted coverage ", numbers);
      numbers.appendChild(weighted);
    }
    const resolved = run.resolved ? html("b", {class: "resolution-coverage"}, "", null) : null;
    if (resolved) {
      html("span", {}, " · resolved coverage ", numbers);
      numbers.appendChild(resolved);
    }
    html("span", {}, " · utilization ", numbers);
    const utilization = html("b", {class: "utilization"}, "", numbers);
    html("span", {}, " · reward ", numbers);
    const reward = html("b", {class: "reward"}, "", numbers);
    // This step in the visibility playground (camcov explore --playground), if there is one.
    if (data.playground) html("span", {}, " · ", numbers);
    const playground = data.playground
        ? html("a", {class: "playground"}, "open this step in the playground", numbers) : null;
    const world = el("svg", {class: "world", viewBox, role: "img",
                             "aria-label": `${data.scene.name}, ${run.label}`}, section);
    const info = html("div", {class: "info", "aria-live": "polite"}, null, section);
    html("p", {class: "hint"}, "Click an edge or a camera for its details.", info);
    return {run, section, coverage, weighted, resolved, utilization, reward, playground, world,
            info, selection: null};
  });

  // One zoom and pan for every run's world (world_view.js); a redraw per frame at most.
  let redrawQueued = false;
  const view = camcovWorldView.create({
    home, svgs: panels.map((panel) => panel.world), reset: document.getElementById("zoom-reset"),
    onChange: () => {
      if (redrawQueued) return;
      redrawQueued = true;
      requestAnimationFrame(() => {
        redrawQueued = false;
        for (const panel of panels) drawWorld(panel, current);
      });
    }});

  // The legend, from the palette the frames use (viz/palette.h).
  const legend = document.getElementById("legend");
  const legendSwatches = [P.seenBy[1], P.seenBy[0], P.target, P.obstacle, P.view, P.plan, P.objectPath];
  P.legend.forEach((text, i) => {
    const item = html("span", {class: "item"}, null, legend);
    const s = html("span", {class: "swatch"}, null, item);
    s.style.background = legendSwatches[i] || P.text;
    item.appendChild(document.createTextNode(text));
  });
  [2, 3].forEach((n) => {
    const item = html("span", {class: "item"}, null, legend);
    html("span", {class: "swatch"}, null, item).style.background = P.seenBy[n];
    item.appendChild(document.createTextNode(`seen by ${n}${n === 3 ? " or more" : ""} cameras`));
  });
  // A weighted scene's edges are as wide as they are important.
  if (runs.some((run) => run.weighted)) {
    const item = html("span", {class: "item importance"}, null, legend);
    html("span", {class: "swatch"}, null, item).style.background = P.seenBy[1];
    item.appendChild(document.createTextNode(P.importance));
  }
  // A scene with a resolution draws seen boundary no camera resolves in its own colour.
  if (runs.some((run) => run.resolved)) {
    const item = html("span", {class: "item unresolved"}, null, legend);
    html("span", {class: "swatch"}, null, item).style.background = P.unresolved;
    item.appendChild(document.createTextNode(P.unresolvedText));
  }
  // The timeline's marks, as the report's plots mark the same events (control/event_kind.h).
  for (const [name, mark] of Object.entries(data.marks)) {
    const item = html("span", {class: `item mark-${name}`}, null, legend);
    item.appendChild(document.createTextNode(`${mark.glyph} ${mark.label}`));
  }

  // ---- drawing one step ---------------------------------------------------------------------
  function drawWorld(panel, k) {
    const step = panel.run.decoded[Math.min(k, panel.run.decoded.length - 1)];
    const svg = panel.world;
    // Marker sizes follow what is in view; an object less than minObject across (a player on
    // a pitch) is drawn enlarged and ringed with dots, which says it is drawn larger than life.
    const em = view.em(), minObject = 0.6 * em;
    svg.textContent = "";
    el("rect", {x: minX - pad, y: -maxY - pad, width: maxX - minX + 2 * pad,
                height: maxY - minY + 2 * pad, fill: P.page}, svg);
    el("polygon", {points: pts(boundary), fill: P.floor, stroke: P.wall,
                   "stroke-width": 2, "vector-effect": "non-scaling-stroke"}, svg);
    for (const line of data.scene.markings) {
      el("polyline", {points: pts(line), fill: "none", stroke: P.pitchLine, "stroke-width": 1.2,
                      "vector-effect": "non-scaling-stroke", class: "marking"}, svg);
    }
    for (const path of data.scene.paths) {
      const loop = el("polygon", {points: pts(path.loop), fill: "none", stroke: P.objectPath,
                                  "stroke-width": 1.2, "stroke-dasharray": "6 4",
                                  "vector-effect": "non-scaling-stroke", class: "object-path"}, svg);
      el("title", {}, loop).textContent = path.speed;
    }
    // Under limited knowledge: a dashed line from each camera heard to each that heard it now.
    const heard = panel.run.series.heard;
    for (const [from, to] of heard ? heard[Math.min(k, heard.length - 1)] : []) {
      const a = step.cameras[from], b = step.cameras[to];
      el("line", {class: "heard", "data-from": String(from), "data-to": String(to),
                  x1: a.x, y1: -a.y, x2: b.x, y2: -b.y, stroke: P.text, "stroke-opacity": 0.45,
                  "stroke-width": 1.2, "stroke-dasharray": "3 3",
                  "vector-effect": "non-scaling-stroke"}, svg);
    }
    for (const c of step.cameras) {
      if (c.view.length > 2) {
        el("polygon", {points: pts(c.view), fill: P.view, "fill-opacity": panel.run.viewAlpha,
                       class: "view"}, svg);
      }
    }
    const enlarged = [];  // rings drawn larger than life, to ring with dots
    const drawn = (ring) => {
      const e = camcovWorldView.enlargement(ring, minObject);
      if (e.factor !== 1) enlarged.push(e);
      return e;
    };
    for (const o of step.obstacles) {
      el("polygon", {points: pts(o.ring.map(drawn(o.ring).at)),
                     fill: data.scene.colors.obstacles[o.id] || P.obstacle,
                     "data-obstacle": String(o.id)}, svg);
    }
    const targetShape = new Map();  // scene target id -> its enlargement
    for (const t of step.targets) {
      const e = drawn(t.ring);
      targetShape.set(t.id, e);
      el("polygon", {points: pts(t.ring.map(e.at)),
                     fill: data.scene.colors.targets[t.id] || P.target,
                     "data-target": String(t.id)}, svg);
    }
    for (const e of enlarged) {
      el("circle", {cx: e.c[0], cy: -e.c[1], r: 0.5 * minObject + 0.2 * em, fill: "none",
                    stroke: P.text, "stroke-width": 1.2, "stroke-dasharray": "0.5 3",
                    "stroke-linecap": "round", "vector-effect": "non-scaling-stroke",
                    class: "enlarged"}, svg);
    }
    step.segments.forEach((s, i) => {
      const e = targetShape.get(s.target), a = e ? e.at(s.a) : s.a, b = e ? e.at(s.b) : s.b;
      const line = el("line", {
        class: "segment", "data-segment": String(i), "data-target": String(s.target),
        "data-edge": String(s.edge), x1: a[0], y1: -a[1], x2: b[0], y2: -b[1],
        stroke: P.seenBy[Math.min(s.visibleBy.length, 3)],
        "stroke-width": edgeWidth(s.weight),
        "stroke-linecap": "round", "vector-effect": "non-scaling-stroke"}, svg);
      if (panel.selection && panel.selection.segment === i) line.classList.add("selected");
      line.addEventListener("click", (e) => {
        e.stopPropagation();
        select(panel, {segment: i, target: s.target, edge: s.edge, along: (s.ta + s.tb) / 2});
      });
    });
    // Over the seen: what no camera resolves, as wide, letting clicks through to the edge.
    for (const u of step.unresolved) {
      const e = targetShape.get(u.target), a = e ? e.at(u.a) : u.a, b = e ? e.at(u.b) : u.b;
      const weight = step.segments.find((s) => s.target === u.target && s.edge === u.edge)?.weight;
      el("line", {class: "unresolved", "data-target": String(u.target), x1: a[0], y1: -a[1],
                  x2: b[0], y2: -b[1], stroke: P.unresolved,
                  "stroke-width": edgeWidth(weight),
                  "stroke-linecap": "round", "pointer-events": "none",
                  "vector-effect": "non-scaling-stroke"}, svg);
    }
    step.cameras.forEach((c, j) => {
      if (c.plan.length > 1) {
        el("polyline", {points: pts(c.plan), fill: "none", stroke: P.plan, "stroke-width": 2,
                        "vector-effect": "non-scaling-stroke", class: "plan"}, svg);
      }
      if (c.goal) {
        const g = el("g", {class: "goal", transform:
            `translate(${c.goal.x} ${-c.goal.y}) rotate(${-deg(c.goal.yaw)})`}, svg);
        el("path", {d: `M${-0.5 * em} ${-0.5 * em}L${0.6 * em} 0L${-0.5 * em} ${0.5 * em}`,
                    fill: "none", stroke: P.plan, "stroke-width": 2,
                    "vector-effect": "non-scaling-stroke"}, g);
      }
      const g = el("g", {class: "camera", "data-camera": String(j),
                         transform: `translate(${c.x} ${-c.y})`}, svg);
      const nose = el("g", {transform: `rotate(${-deg(c.yaw)})`}, g);
      el("path", {d: `M0 ${-0.55 * em}L${1.6 * em} 0L0 ${0.55 * em}Z`, fill: P.camera}, nose);
      el("circle", {r: 0.75 * em, fill: P.camera, stroke: "#fff", "stroke-width": 1.5,
                    "vector-effect": "non-scaling-stroke"}, g);
      const label = el("text", {"font-size": 0.95 * em, fill: "#fff", "text-anchor": "middle",
                                "dominant-baseline": "central"}, g);
      label.textContent = String(j);
      if (panel.selection && panel.selection.camera === j) g.classList.add("selected");
      g.addEventListener("click", (e) => {
        e.stopPropagation();
        select(panel, {camera: j});
      });
    });
  }

  function field(parent, name, label, value) {
    const row = html("div", {class: "field"}, null, parent);
    html("span", {class: "label"}, label, row);
    html("span", {"data-field": name}, value, row);
  }

  function showInfo(panel, k) {
    const run = panel.run, step = run.decoded[Math.min(k, run.decoded.length - 1)];
    const info = panel.info, sel = panel.selection;
    info.textContent = "";
    if (!sel) {
      html("p", {class: "hint"}, "Click an edge or a camera for its details.", info);
      return;
    }
    if (sel.camera !== undefined) {
      const c = step.cameras[sel.camera], limits = run.cameras[sel.camera];
      html("h3", {}, `Camera ${sel.camera}`, info);
      field(info, "pose", "pose", `(${c.x.toFixed(3)}, ${c.y.toFixed(3)}) m, ${deg(c.yaw)}°`);
      // The camera as the scene file describes it (scene::describeCamera): the limits in
      // words; any further property of its lens (sensingRange, …) by the file's own key.
      const theta = limits.cameraFoV;
      field(info, "limits", "limits",
            `v ≤ ${limits.maxVelocity} m/s, ω ≤ ${limits.maxAngularVelocity.toFixed(3)} rad/s, ` +
            `half-angle θ = ${theta.toFixed(1)}° (field of view ${(2 * theta).toFixed(1)}°)`);
      const shown = new Set(["x", "y", "angle", "maxVelocity", "maxAngularVelocity", "cameraFoV"]);
      for (const [key, value] of Object.entries(limits))
        if (!shown.has(key)) field(info, key, key, String(value));
      let sees = 0, total = 0;
      for (const s of step.segments) {
        total += length(s);
        if (s.visibleBy.includes(sel.camera)) sees += length(s);
      }
      field(info, "sees", "sees", `${sees.toFixed(3)} m of ${total.toFixed(3)} m of target boundary`);
      // Its own terms of the reward, eq. (3) and (5), as camcov computed them.
      field(info, "coverage", "its coverage", c.coverage.toFixed(4));
      field(info, "utilization", "its utilization", c.utilization.toFixed(4));
      field(info, "nearest-object", "nearest object", c.object === 0 ? "none"
            : `${objectName(c.object)} at ${c.objectDistance.toFixed(3)} m`);
      field(info, "nearest-camera", "nearest camera", c.other === 0 ? "none"
            : `camera ${c.other - 1} at ${c.cameraDistance.toFixed(3)} m`);
      const heard = run.series.heard;
      if (heard) {
        const from = heard[Math.min(k, heard.length - 1)]
            .filter(([, to]) => to === sel.camera).map(([f]) => f);
        field(info, "heard", "heard now from",
              from.length ? `camera${from.length > 1 ? "s" : ""} ${from.join(", ")}` : "nobody");
      }
      field(info, "goal", "goal", c.goal
            ? `(${c.goal.x.toFixed(2)}, ${c.goal.y.toFixed(2)}) m, ${deg(c.goal.yaw)}°, ` +
              `${c.plan.length - 1} waypoints ahead` : "none");
      return;
    }
    // A segment: the one on the same edge that holds the selected point at this step.
    let i = step.segments.findIndex((s) => s.target === sel.target && s.edge === sel.edge &&
                                           s.ta <= sel.along && sel.along <= s.tb);
    if (i < 0) {
      html("p", {class: "hint"}, "The selected edge is not part of this step.", info);
      return;
    }
    sel.segment = i;
    const s = step.segments[i];
    html("h3", {}, `Target ${s.target}, edge ${s.edge}`, info);
    field(info, "length", "length (m)", length(s).toFixed(3));
    if (s.weight !== null) field(info, "weight", "importance weight (of 1)", s.weight.toFixed(3));
    field(info, "visibleBy", "visibleBy", s.visibleBy.length ? s.visibleBy.join(", ") : "none");
    const list = html("ul", {class: "reasons"}, null, info);
    s.reasons.forEach((code, j) => {
      if (code === null) return;
      html("li", {"data-camera": String(j)}, `camera ${j}: ${reasonText(code)}`, list);
    });
  }

  function select(panel, selection) {
    panel.selection = selection;
    render();
  }

  // ---- timeline -----------------------------------------------------------------------------
  const timeline = document.getElementById("timeline");
  // In the timeline's own px (as wide as the page shows it, so text is not scaled), and low:
  // the scene below it stays in view.
  const T = {width: Math.max(600, Math.round(timeline.getBoundingClientRect().width)), height: 112,
             left: 44, right: 12, top: 8, bottom: 30};
  const times = runs.reduce((a, r) => (r.series.time.length > a.length ? r.series.time : a), []);
  const t0 = times[0], t1 = times[times.length - 1] > t0 ? times[times.length - 1] : t0 + 1;
  const tx = (t) => T.left + (t - t0) / (t1 - t0) * (T.width - T.left - T.right);
  const ty = (v) => T.top + (1 - v) * (T.height - T.top - T.bottom);
  timeline.setAttribute("viewBox", `0 0 ${T.width} ${T.height}`);
  for (const v of [0, 0.5, 1]) {
    el("line", {x1: T.left, x2: T.width - T.right, y1: ty(v), y2: ty(v), stroke: "#e3e5e8"}, timeline);
    el("text", {x: T.left - 6, y: ty(v), "text-anchor": "end", "dominant-baseline": "central",
                class: "tick"}, timeline).textContent = v.toFixed(1);
  }
  for (let t = Math.ceil(t0); t <= t1; t += Math.max(1, Math.round((t1 - t0) / 10))) {
    el("text", {x: tx(t), y: T.height - T.bottom + 14, "text-anchor": "middle", class: "tick"},
       timeline).textContent = `${t} s`;
  }
  const curves = [["coverage", "", "coverage"], ["utilization", "5 3", "utilization"]];
  // Where nobody is present (recorded tracks) coverage and utilization are 0 by definition:
  // the curve leaves a gap there rather than plunge, which would read as a collapse.
  const curvePath = (run, key) => {
    const present = run.series.targetsPresent;
    let d = "", open = false;
    run.series.time.forEach((t, k) => {
      if (present && present[k] === 0) {
        open = false;
        return;
      }
      d += `${open ? "L" : "M"}${tx(t).toFixed(1)} ${ty(run.series[key][k]).toFixed(1)}`;
      open = true;
    });
    return d;
  };
  // Runs drawn later lie on top and thinner: where two runs' curves coincide, each earlier one
  // shows as a rim around the later, so no run hides behind another.
  const curveWidth = (i) => 1.5 + 2 * Math.min(2, runs.length - 1 - i);
  runs.forEach((run, i) => {
    for (const [key, dash] of curves) {
      el("path", {d: curvePath(run, key), fill: "none", stroke: run.color,
                  "stroke-width": curveWidth(i), "stroke-dasharray": dash,
                  "stroke-linejoin": "round", class: `curve ${key}`, "data-run": String(i)},
         timeline);
    }
    for (const e of run.events) {
      const mark = data.marks[e.mark];  // which events get marks: control/event_kind.h
      if (!mark) continue;
      const m = el("text", {x: tx(e.time), y: T.height - T.bottom - 3 - 9 * i, "text-anchor": "middle",
                            class: `event ${e.kind} mark-${e.mark}`, fill: run.color}, timeline);
      m.textContent = mark.glyph;
      const title = el("title", {}, m);
      title.textContent = `${run.label}, t = ${e.time.toFixed(2)} s: ${e.kind}` +
                          `${e.camera >= 0 ? ` (camera ${e.camera})` : ""} — ${e.detail}`;
    }
  });
  // What the curves are: their dashes, and the gap where nobody is present.
  const curveLegend = document.getElementById("curve-legend");
  for (const [key, dash, text] of curves) {
    const item = html("span", {class: `item ${key}`}, null, curveLegend);
    const sample = el("svg", {width: 30, height: 10, class: "sample"}, item);
    el("line", {x1: 1, x2: 29, y1: 5, y2: 5, stroke: P.text, "stroke-width": 1.6,
                "stroke-dasharray": dash}, sample);
    item.appendChild(document.createTextNode(text));
  }
  html("span", {class: "item colours"}, "one colour per run, as its panel's", curveLegend);
  if (runs.some((run) => run.series.targetsPresent)) {
    html("span", {class: "item gap"}, "a gap: nobody present", curveLegend);
  }
  const cursor = el("line", {y1: T.top, y2: T.height - T.bottom, stroke: "#1f2328",
                             "stroke-width": 1.2, class: "cursor"}, timeline);
  timeline.addEventListener("click", (e) => {
    const box = timeline.getBoundingClientRect();
    const x = (e.clientX - box.left) / box.width * T.width;
    const t = t0 + (x - T.left) / (T.width - T.left - T.right) * (t1 - t0);
    let best = 0;
    times.forEach((time, k) => { if (Math.abs(time - t) < Math.abs(times[best] - t)) best = k; });
    seek(best);
  });

  // ---- controls -----------------------------------------------------------------------------
  const slider = document.getElementById("slider");
  const play = document.getElementById("play");
  const timeText = document.getElementById("time");
  slider.max = String(stepCount - 1);
  let current = 0, timer = null;

  function render() {
    const k = current;
    document.body.dataset.step = String(k);
    slider.value = String(k);
    const t = times[Math.min(k, times.length - 1)];
    timeText.textContent = `t = ${t.toFixed(2)} s`;
    cursor.setAttribute("x1", tx(t));
    cursor.setAttribute("x2", tx(t));
    for (const panel of panels) {
      const series = panel.run.series, at = Math.min(k, series.time.length - 1);
      panel.coverage.textContent = series.coverage[at].toFixed(4);
      if (panel.weighted) panel.weighted.textContent = series.weightedCoverage[at].toFixed(4);
      if (panel.resolved) panel.resolved.textContent = series.resolutionCoverage[at].toFixed(4);
      if (panel.playground) {
        const step = panel.run.decoded[Math.min(k, panel.run.decoded.length - 1)];
        const poses = step.cameras.map((c) => ({x: c.x, y: c.y, yaw_deg: c.yaw * 180 / Math.PI}));
        panel.playground.href = `${data.playground}#t=${series.time[at]}` +
                                `&poses=${encodeURIComponent(JSON.stringify(poses))}`;
      }
      panel.utilization.textContent = series.utilization[at].toFixed(4);
      panel.reward.textContent = series.reward[at].toFixed(4);
      drawWorld(panel, k);
      showInfo(panel, k);
    }
  }
  function seek(k) {
    current = Math.max(0, Math.min(stepCount - 1, k));
    render();
  }
  function setPlaying(on) {
    if (timer) clearInterval(timer);
    timer = null;
    if (on) {
      if (current >= stepCount - 1) seek(0);
      timer = setInterval(() => {
        if (current >= stepCount - 1) setPlaying(false);
        else seek(current + 1);
      }, 1000 * (runs[0].dt || 0.1));
    }
    play.textContent = on ? "Pause" : "Play";
    play.setAttribute("aria-pressed", on ? "true" : "false");
  }
  play.addEventListener("click", () => setPlaying(!timer));
  document.getElementById("step-back").addEventListener("click", () => seek(current - 1));
  document.getElementById("step-forward").addEventListener("click", () => seek(current + 1));
  slider.addEventListener("input", () => seek(Number(slider.value)));
  document.addEventListener("keydown", (e) => {
    if (e.target === slider && e.key !== " ") return;  // the slider moves itself
    const keys = {ArrowLeft: () => seek(current - 1), ArrowRight: () => seek(current + 1),
                  Home: () => seek(0), End: () => seek(stepCount - 1),
                  " ": () => setPlaying(!timer)};
    const action = keys[e.key];
    if (!action) return;
    e.preventDefault();
    action();
  });

  view.fit();  // again, now that the timeline and its legend above the worlds are drawn
  render();
  document.body.dataset.ready = "1";
})();
