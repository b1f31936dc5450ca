// The visibility playground: the scene in the page as its file's JSON, the engine (the same C++
// as camcov, compiled to WebAssembly: src/wasm/engine.cpp) asked for everything at every change,
// and SVG drawn from its answer. Nothing is computed here but where things go on screen.
// DOM contract for tests: body[data-ready|data-busy], #message, #terms [data-term], #cameras
// tr[data-camera] [data-term], svg#world (g.camera[data-camera], .handle[data-ring|data-vertex],
// .segment.selected[data-segment]: a click on an edge selects its segment), #edge, #sweep (#sweep-back, #sweep-forward, #sweep-step), #time,
// #fov, #export, #export-scene, #export-poses, #export-command.
"use strict";
(async () => {
  const data = JSON.parse(document.getElementById("camcov-data").textContent);
  const P = data.palette;
  const engine = await createCamcovEngine();
  const SVG = "http://www.w3.org/2000/svg";

  // ---- the scene as a file says it ---------------------------------------------------------
  const scene = data.scene;  // edited in place: what export writes
  let poses = data.poses.map((p) => ({...p}));  // {x, y, yaw_deg}, one per camera
  let time = data.time;
  // A link may say the instant and the poses (the explorer's "open this step"):
  // #t=SECONDS&poses=[{"x":..,"y":..,"yaw_deg":..}, ...], one per camera.
  const asked = new URLSearchParams(location.hash.slice(1));
  if (asked.has("t") && Number.isFinite(Number(asked.get("t")))) time = Number(asked.get("t"));
  if (asked.has("poses")) {
    try {
      const given = JSON.parse(asked.get("poses"));
      if (Array.isArray(given) && given.length === poses.length) poses = given;
    } catch (error) {
      // A link that is not ours: the page's own poses.
    }
  }
  let result = null;         // the engine's last answer for a valid state
  // The camera whose sweep is shown, the edge explained, the vertex and the object chosen.
  let selected = {camera: 0, edge: null, handle: null, object: null};
  let sweepStep = -1;        // the event shown of the selected camera's sweep; -1: none
  const stats = {explains: 0, lastMs: 0, totalMs: 0};

  const parseRing = (wkt) => {
    const inner = wkt.slice(wkt.indexOf("((") + 2, wkt.lastIndexOf("))"));
    const points = inner.split(",").map((p) => p.trim().split(/\s+/).map(Number));
    const [f, l] = [points[0], points[points.length - 1]];
    if (points.length > 1 && f[0] === l[0] && f[1] === l[1]) points.pop();
    return points;
  };
  const writeRing = (points) => `POLYGON((${points.map((p) => `${p[0]} ${p[1]}`).join(",")}))`;
  const signedArea = (points) => points.reduce((sum, p, i) => {
    const q = points[(i + 1) % points.length];
    return sum + p[0] * q[1] - q[0] * p[1];
  }, 0) / 2;
  const round = (v) => Math.round(v * 1e6) / 1e6;  // a micrometre: files stay short

  // Ring k of the engine's answer (normalised, counter-clockwise) is written vertex
  // `written(k)` in the file: the file's order is kept for its edgeWeights and keyframes.
  function ringOf(kind, id) {
    if (kind === "boundary") {
      const points = parseRing(scene.boundary);
      return {points, cw: signedArea(points) < 0, set: (p) => { scene.boundary = writeRing(p); }};
    }
    const object = scene[kind === "target" ? "targets" : "obstacles"][id];
    const points = parseRing(object.shape);
    return {points, cw: signedArea(points) < 0, object,
            set: (p) => { object.shape = writeRing(p); }};
  }
  const writtenIndex = (ring, k) => (ring.cw ? ring.points.length - 1 - k : k);
  // World point -> the object's own frame at the present time (its reference and turn).
  function toLocal(placed, point) {
    if (!placed) return point;
    const dx = point[0] - placed.reference[0], dy = point[1] - placed.reference[1];
    const c = Math.cos(-placed.angle), s = Math.sin(-placed.angle);
    return [dx * c - dy * s, dx * s + dy * c];
  }
  const placedOf = (kind, id) => kind === "boundary" ? null
      : result[kind === "target" ? "targets" : "obstacles"].find((o) => o.id === id);

  // A camera's pose is also its entry in the scene: the validator then judges where it stands
  // (inside an object, outside the boundary) in its own words, and the exported scene starts
  // the cameras where the page shows them.
  function placeCamera(j) {
    scene.cameras[j].pos = `POINT(${poses[j].x} ${poses[j].y})`;
    scene.cameras[j].angle = poses[j].yaw_deg;
  }
  poses.forEach((_, j) => placeCamera(j));

  // ---- asking the engine -------------------------------------------------------------------
  function explain() {
    const t0 = performance.now();
    const text = JSON.stringify(scene);
    const answer = JSON.parse(engine.explain(text, data.file, time, JSON.stringify(poses),
                                             selected.camera === null ? -1 : selected.camera,
                                             selected.edge === null ? -1 : selected.edge));
    const ms = performance.now() - t0;
    stats.explains += 1;
    stats.lastMs = ms;
    stats.totalMs += ms;
    const message = document.getElementById("message");
    if (answer.error) {
      // The validator's own words; the picture stays the last valid one.
      message.textContent = answer.error;
      message.hidden = false;
      document.body.dataset.valid = "0";
      drawPending();
      return false;
    }
    message.hidden = true;
    message.textContent = "";
    document.body.dataset.valid = "1";
    // S arrives by columns; the page keeps it as one object a segment.
    const c = answer.segments;
    answer.segments = c.target.map((target, i) => ({
      target, edge: c.edge[i], visibleBy: c.visibleBy[i],
      a: [c.ends[4 * i], c.ends[4 * i + 1]], b: [c.ends[4 * i + 2], c.ends[4 * i + 3]],
      reasons: answer.reasons && answer.reasons.segment === i ? answer.reasons.why : null}));
    result = answer;
    if (result.trace && sweepStep >= result.trace.events.length) sweepStep = -1;
    draw();
    return true;
  }
  // Drags ask once a frame, whatever the pointer's rate.
  let queued = false;
  function explainSoon() {
    if (queued) return;
    queued = true;
    document.body.dataset.busy = "1";
    requestAnimationFrame(() => {
      queued = false;
      explain();
      document.body.dataset.busy = "0";
    });
  }

  // ---- drawing -----------------------------------------------------------------------------
  const world = document.getElementById("world");
  const el = (tag, attributes, parent) => {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
    if (parent) parent.appendChild(e);
    return e;
  };
  const pts = (ring) => ring.map((p) => `${p[0]},${-p[1]}`).join(" ");
  const bounds = (() => {
    const b = parseRing(scene.boundary);
    const xs = b.map((p) => p[0]), ys = b.map((p) => p[1]);
    const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    const pad = 0.05 * Math.max(x1 - x0, y1 - y0);
    return {x0: x0 - pad, y0: y0 - pad, w: x1 - x0 + 2 * pad, h: y1 - y0 + 2 * pad};
  })();
  // Zoom and pan (world_view.js, shared with the run explorer): handles and markers are a
  // fortieth of what is in view, and an object smaller than minObject() is drawn enlarged.
  const view = camcovWorldView.create({
    home: {x: bounds.x0, y: -bounds.y0 - bounds.h, w: bounds.w, h: bounds.h}, svgs: [world],
    reset: document.getElementById("zoom-reset"),
    onChange: () => {
      em = view.em();
      if (result) draw();
    }});
  let em = view.em();
  const minObject = () => 0.6 * em;

  function drawPending() {
    // The invalid edit, outlined over the last valid picture.
    world.querySelectorAll(".pending").forEach((e) => e.remove());
    if (selected.handle) {
      const ring = ringOf(selected.handle.kind, selected.handle.id);
      const placed = result && placedOf(selected.handle.kind, selected.handle.id);
      const worldPoints = ring.points.map((p) => placed ? toWorld(placed, p) : p);
      el("polygon", {points: pts(worldPoints), fill: "none", stroke: P.seenBy[0],
                     "stroke-dasharray": "4 3", "vector-effect": "non-scaling-stroke",
                     class: "pending"}, world);
    }
  }
  function toWorld(placed, p) {
    const c = Math.cos(placed.angle), s = Math.sin(placed.angle);
    return [placed.reference[0] + p[0] * c - p[1] * s, placed.reference[1] + p[0] * s + p[1] * c];
  }

  function draw() {
    world.replaceChildren();
    el("polygon", {points: pts(result.boundary), fill: P.floor, stroke: P.wall, "stroke-width": 3,
                   "vector-effect": "non-scaling-stroke", class: "boundary"}, world);
    result.cameras.forEach((c, j) => {
      if (c.view.length > 2) {
        el("polygon", {points: pts(c.view), fill: P.view, "fill-opacity": P.viewAlpha,
                       class: "view", "data-camera": String(j)}, world);
      }
    });
    // A small object (a pedestrian in a plaza) is drawn enlarged about its centre and ringed
    // with dots, as the frames and the explorer draw it, unless it is the one being edited.
    const chosen = selected.handle || selected.object;
    const shapes = new Map();  // "kind id" -> its enlargement
    const enlarged = [];
    const object = (kind, o, fill) => {
      const editing = chosen && chosen.kind === kind && chosen.id === o.id;
      const e = camcovWorldView.enlargement(o.ring, editing ? 0 : minObject());
      shapes.set(`${kind} ${o.id}`, e);
      if (e.factor !== 1) enlarged.push(e);
      const shape = el("polygon", {points: pts(o.ring.map(e.at)), fill, class: "object",
                                   "data-kind": kind, "data-id": String(o.id)}, world);
      shape.addEventListener("click", () => {
        selected.object = {kind, id: o.id};
        draw();
      });
    };
    for (const o of result.obstacles) object("obstacle", o, P.obstacle);
    for (const t of result.targets) object("target", t, data.colors[t.id] || P.target);
    for (const e of enlarged) {
      el("circle", {cx: e.c[0], cy: -e.c[1], r: 0.5 * minObject() + 0.2 * em, fill: "none",
                    stroke: P.text, "stroke-width": 1.2, "stroke-dasharray": "0.5 3",
                    "stroke-linecap": "round", "vector-effect": "non-scaling-stroke",
                    class: "enlarged"}, world);
    }
    // Each segment where it is drawn (on its target, enlarged or not): clicks pick it there.
    for (const s of result.segments) {
      const e = shapes.get(`target ${s.target}`);
      [s.drawnA, s.drawnB] = e ? [e.at(s.a), e.at(s.b)] : [s.a, s.b];
    }
    // Every edge coloured by how many cameras see it; a weighted one as wide as important.
    const weightOf = (s) => {
      const t = result.targets.find((o) => o.id === s.target);
      return t && t.weights ? t.weights[s.edge] : null;
    };
    // One path per colour and width (a large target's thousands of segments as elements cost a
    // drag most of its time); a click finds its segment by position (pick()).
    const groups = new Map();
    for (const s of result.segments) {
      const w = weightOf(s);
      const key = `${P.seenBy[Math.min(s.visibleBy.length, 3)]} ${
          w === null ? 5 : 5 * (P.widthAtZero + P.widthPerWeight * w)}`;
      const [a, b] = [s.drawnA, s.drawnB];
      groups.set(key, (groups.get(key) || "") + `M${a[0]},${-a[1]}L${b[0]},${-b[1]}`);
    }
    for (const [key, d] of groups) {
      const [stroke, width] = key.split(" ");
      el("path", {d, stroke, "stroke-width": width, fill: "none", "stroke-linecap": "round",
                  "vector-effect": "non-scaling-stroke", class: "segments"}, world);
    }
    const edge = selected.edge === null ? null : result.segments[selected.edge];
    if (edge) {
      el("line", {x1: edge.drawnA[0], y1: -edge.drawnA[1], x2: edge.drawnB[0], y2: -edge.drawnB[1],
                  stroke: P.seenBy[Math.min(edge.visibleBy.length, 3)], "stroke-width": 10,
                  "stroke-linecap": "round", "vector-effect": "non-scaling-stroke",
                  class: "segment selected", "data-segment": String(selected.edge)}, world);
    }
    drawSweep();
    result.cameras.forEach((c, j) => drawCamera(c, j));
    drawHandles();
    drawPanel();
  }

  function drawCamera(c, j) {
    const [x, y, yaw] = c.pose;
    const g = el("g", {class: "camera", "data-camera": String(j),
                       transform: `translate(${x},${-y})`}, world);
    if (selected.camera === j) g.classList.add("selected");
    // The field-of-view wedge: its two edges out to the room's size.
    const reach = Math.max(bounds.w, bounds.h);
    for (const side of [-1, 1]) {
      const a = yaw + side * c.halfFov;
      el("line", {x1: 0, y1: 0, x2: reach * Math.cos(a), y2: -reach * Math.sin(a),
                  stroke: P.camera, "stroke-opacity": 0.35, "stroke-dasharray": "3 4",
                  "vector-effect": "non-scaling-stroke", class: "wedge"}, g);
    }
    el("circle", {r: 0.6 * em, fill: P.camera, class: "body"}, g);
    el("line", {x1: 0, y1: 0, x2: 1.4 * em * Math.cos(yaw), y2: -1.4 * em * Math.sin(yaw),
                stroke: P.camera, "stroke-width": 3, "vector-effect": "non-scaling-stroke",
                class: "heading"}, g);
    const label = el("text", {x: 0, y: 0.3 * em, "font-size": 0.8 * em, fill: "#fff",
                              "text-anchor": "middle", class: "label"}, g);
    label.textContent = String(j);
    g.addEventListener("pointerdown", (e) => startDrag(e, {camera: j}));
    g.addEventListener("click", (e) => e.stopPropagation());
    g.addEventListener("wheel", (e) => {
      e.preventDefault();
      turn(j, (e.deltaY < 0 ? 1 : -1) * (e.shiftKey ? 0.1 : 2));
    }, {passive: false});
  }

  const kHandlesShown = 200;
  const handleRadius = () => 0.3 * em;
  // Its vertices at least two handles apart in view: each handle then stands clear of the next
  // rather than merge into a blob (a pedestrian's 12-gon at plaza scale; zoom in for them).
  const handlesFit = (ring) => ring.every((p, k) => {
    const q = ring[(k + 1) % ring.length];
    return Math.hypot(q[0] - p[0], q[1] - p[1]) >= 4 * handleRadius();
  });
  function drawHandles() {
    const rings = [{kind: "boundary", id: 0, ring: result.boundary}]
        .concat(result.targets.map((t) => ({kind: "target", id: t.id, ring: t.ring})))
        .concat(result.obstacles.map((o) => ({kind: "obstacle", id: o.id, ring: o.ring})));
    // A ring gets its handles when one of its vertices or its fill is selected, else when they
    // fit apart in view and are not hundreds: thousands of handles would hide the ring and slow
    // every redraw.
    const chosen = selected.handle || selected.object;
    const shown = (r) => (chosen && chosen.kind === r.kind && chosen.id === r.id) ||
                         (r.ring.length <= kHandlesShown && handlesFit(r.ring));
    for (const r of rings.filter(shown)) {
      r.ring.forEach((p, k) => {
        const h = el("circle", {cx: p[0], cy: -p[1], r: handleRadius(), class: "handle",
                                "data-ring": `${r.kind} ${r.id}`, "data-vertex": String(k)}, world);
        const s = selected.handle;
        if (s && s.kind === r.kind && s.id === r.id && s.vertex === k) h.classList.add("selected");
        h.addEventListener("pointerdown", (e) => startDrag(e, {kind: r.kind, id: r.id, vertex: k}));
        h.addEventListener("click", (e) => e.stopPropagation());
      });
    }
  }

  function drawSweep() {
    const trace = result.trace;
    if (!trace || sweepStep < 0) return;
    const e = trace.events[sweepStep];
    const [x, y] = result.cameras[trace.camera].pose;
    el("line", {x1: x, y1: -y, x2: e.point[0], y2: -e.point[1], stroke: P.plan,
                "stroke-width": 2, "vector-effect": "non-scaling-stroke", class: "sweep-ray"}, world);
    if (e.front && e.front.a) {
      el("line", {x1: e.front.a[0], y1: -e.front.a[1], x2: e.front.b[0], y2: -e.front.b[1],
                  stroke: P.plan, "stroke-width": 8, "stroke-opacity": 0.5,
                  "vector-effect": "non-scaling-stroke", class: "sweep-front"}, world);
    }
    el("circle", {cx: e.hit[0], cy: -e.hit[1], r: 0.35 * em, fill: P.plan, class: "sweep-hit"},
       world);
  }

  // ---- the panel ---------------------------------------------------------------------------
  const number = (v) => v.toPrecision(12);  // as the batch computes it: compare to 1e-9
  function termRow(parent, terms) {
    for (const key of ["coverage", "weightedCoverage", "utilization", "repulsion", "reward"]) {
      if (!(key in terms)) continue;
      const cell = parent.querySelector(`[data-term="${key}"]`);
      if (cell) cell.textContent = number(terms[key]);
    }
  }
  function drawPanel() {
    const team = document.getElementById("terms");
    team.querySelector('[data-term="weightedCoverage"]').parentElement.hidden =
        !("weightedCoverage" in result.terms);
    termRow(team, result.terms);
    const body = document.querySelector("#cameras tbody");
    body.replaceChildren();
    result.cameras.forEach((c, j) => {
      const tr = document.createElement("tr");
      tr.dataset.camera = String(j);
      if (selected.camera === j) tr.classList.add("selected");
      const cells = [`${j}`, `${c.pose[0].toFixed(3)}, ${c.pose[1].toFixed(3)}`,
                     `${(c.pose[2] * 180 / Math.PI).toFixed(2)}°`,
                     `${(c.halfFov * 180 / Math.PI).toFixed(1)}°`];
      for (const text of cells) tr.appendChild(document.createElement("td")).textContent = text;
      for (const key of ["coverage", "utilization", "reward"]) {
        const td = tr.appendChild(document.createElement("td"));
        td.dataset.term = key;
        td.textContent = c.terms[key].toFixed(4);
      }
      tr.addEventListener("click", () => selectCamera(j));
      body.appendChild(tr);
    });
    const fov = document.getElementById("fov");
    if (selected.camera !== null && result.cameras[selected.camera]) {
      fov.disabled = false;
      fov.value = String(result.cameras[selected.camera].halfFov * 180 / Math.PI);
      document.getElementById("fov-value").textContent = `${Number(fov.value).toFixed(1)}°`;
    }
    drawEdge();
    drawSweepPanel();
  }
  function drawEdge() {
    const box = document.getElementById("edge");
    box.replaceChildren();
    const s = selected.edge === null ? null : result.segments[selected.edge];
    if (!s) {
      box.appendChild(document.createElement("p")).textContent =
          "Click an edge: who sees it, and why each other camera does not.";
      return;
    }
    const h = box.appendChild(document.createElement("h3"));
    h.textContent = `target ${s.target}, edge ${s.edge}`;
    const seen = box.appendChild(document.createElement("p"));
    seen.dataset.field = "visibleBy";
    seen.textContent = s.visibleBy.length ? `seen by camera ${s.visibleBy.join(", ")}` : "seen by none";
    const list = box.appendChild(document.createElement("ul"));
    (s.reasons || []).forEach((reason, j) => {
      if (reason === null) return;
      const li = list.appendChild(document.createElement("li"));
      li.dataset.camera = String(j);
      li.textContent = `camera ${j}: ${reason}`;
    });
  }
  function drawSweepPanel() {
    const trace = result.trace;
    const step = document.getElementById("sweep-step");
    const count = trace ? trace.events.length : 0;
    step.textContent = !trace ? "select a camera"
        : trace.blind ? `camera ${trace.camera} sees nothing (inside an object or outside)`
        : sweepStep < 0 ? `camera ${trace.camera}: ${count} events; step through them`
        : describeEvent(trace.events[sweepStep], sweepStep, count);
    document.body.dataset.sweepStep = String(sweepStep);
  }
  function describeEvent(e, k, count) {
    const front = !e.front ? "nothing in front"
        : e.front.wedge ? "the camera's own ring in front"
        : `front: ${e.front.ring}${e.front.ring === "boundary" ? "" : " " + e.front.owner}, edge ${e.front.edge}`;
    const inserted = e.inserted ? `+${e.inserted}` : "", removed = e.removed ? `−${e.removed}` : "";
    return `event ${k + 1} of ${count} at ${(e.angle * 180 / Math.PI).toFixed(3)}° ` +
           `(${[inserted, removed].filter(Boolean).join(" ") || "field of view"}); ${front}` +
           `${e.inFov ? "" : "; outside the field of view"}`;
  }

  // ---- acting ------------------------------------------------------------------------------
  function worldPoint(event) {
    const m = world.getScreenCTM().inverse();
    const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(m);
    return [p.x, -p.y];
  }
  let drag = null, dragged = false;
  function startDrag(event, what) {
    event.preventDefault();
    event.stopPropagation();
    drag = what;
    dragged = false;
    if ("camera" in what) selectCamera(what.camera, false);
    else selected.handle = what;
    world.setPointerCapture(event.pointerId);
  }
  world.addEventListener("pointermove", (event) => {
    if (!drag) return;
    dragged = true;
    const p = worldPoint(event);
    if ("camera" in drag) {
      poses[drag.camera].x = round(p[0]);
      poses[drag.camera].y = round(p[1]);
      placeCamera(drag.camera);
    } else {
      moveVertex(drag, p);
    }
    explainSoon();
  });
  const endDrag = () => { drag = null; };
  world.addEventListener("pointerup", endDrag);
  world.addEventListener("pointercancel", endDrag);

  function moveVertex(handle, point) {
    const ring = ringOf(handle.kind, handle.id);
    const placed = result && placedOf(handle.kind, handle.id);
    const local = toLocal(placed, point);
    ring.points[writtenIndex(ring, handle.vertex)] = [round(local[0]), round(local[1])];
    ring.set(ring.points);
  }
  // A click on a target's edge explains the segment there: who sees it, why the others do not.
  world.addEventListener("click", (event) => {
    if (!result || dragged) {  // the end of a drag is not a click
      dragged = false;
      return;
    }
    const i = pick(worldPoint(event));
    if (i === null) return;
    selected.edge = i;
    explain();
  });
  function pick(p) {
    let best = null, bestDistance = 0.5 * em;
    result.segments.forEach((s, i) => {
      const d = distanceToSegment(p, s.drawnA, s.drawnB);
      if (d <= bestDistance) [best, bestDistance] = [i, d];
    });
    return best;
  }
  function distanceToSegment(p, a, b) {
    const dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    const u = len2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2)) : 0;
    return Math.hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy);
  }
  // Double-click an edge of any ring: a vertex there. Edge weights and keyframes follow.
  world.addEventListener("dblclick", (event) => {
    const p = worldPoint(event);
    const hit = nearestEdge(p);
    if (!hit) return;
    const ring = ringOf(hit.kind, hit.id);
    const placed = placedOf(hit.kind, hit.id);
    const n = ring.points.length;
    // Edge k (from vertex k to k + 1 of the engine's ring) is written edge i, between written
    // vertices i and i + 1: the new vertex goes after i.
    const i = ring.cw ? (n - 2 - hit.edge + n) % n : hit.edge;
    const local = toLocal(placed, p);
    ring.points.splice(i + 1, 0, [round(local[0]), round(local[1])]);
    ring.set(ring.points);
    if (ring.object && ring.object.edgeWeights) ring.object.edgeWeights.splice(i + 1, 0, ring.object.edgeWeights[i]);
    if (ring.object && ring.object.deformation) {
      for (const frame of ring.object.deformation.keyframes) {
        const q = parseRing(frame.shape), a = q[i], b = q[(i + 1) % q.length];
        q.splice(i + 1, 0, [round((a[0] + b[0]) / 2), round((a[1] + b[1]) / 2)]);
        frame.shape = writeRing(q);
      }
    }
    selected.handle = {kind: hit.kind, id: hit.id, vertex: ring.cw ? n - i - 1 : i + 1};
    explain();
  });
  function nearestEdge(p) {
    let best = null;
    const consider = (kind, id, ring) => ring.forEach((a, k) => {
      const d = distanceToSegment(p, a, ring[(k + 1) % ring.length]);
      if (d < em && (!best || d < best.d)) best = {kind, id, edge: k, d};
    });
    consider("boundary", 0, result.boundary);
    result.targets.forEach((t) => consider("target", t.id, t.ring));
    result.obstacles.forEach((o) => consider("obstacle", o.id, o.ring));
    return best;
  }
  function deleteVertex() {
    const h = selected.handle;
    if (!h) return;
    const ring = ringOf(h.kind, h.id);
    const i = writtenIndex(ring, h.vertex);
    ring.points.splice(i, 1);
    ring.set(ring.points);
    const o = ring.object;
    if (o && o.edgeWeights) o.edgeWeights.splice(i, 1);
    if (o && o.deformation) {
      for (const frame of o.deformation.keyframes) {
        const q = parseRing(frame.shape);
        q.splice(i, 1);
        frame.shape = writeRing(q);
      }
    }
    selected.handle = null;
    explain();
  }
  function turn(j, degrees) {
    poses[j].yaw_deg = round(poses[j].yaw_deg + degrees);
    placeCamera(j);
    explainSoon();
  }
  function selectCamera(j, redraw = true) {
    if (selected.camera !== j) sweepStep = -1;
    selected.camera = j;
    if (redraw) explain();
  }
  function centre() {
    const b = result.boundary;
    return [b.reduce((s, p) => s + p[0], 0) / b.length, b.reduce((s, p) => s + p[1], 0) / b.length];
  }
  function addObject(kind) {
    const [x, y] = centre();
    const r = round(em);
    scene[kind].push({shape: writeRing([[-r, -r], [r, -r], [r, r], [-r, r]]),
                      path: `POINT(${round(x)} ${round(y)})`});
    explain();
  }
  function removeSelectedObject() {
    const h = selected.handle || selected.object;
    if (!h || h.kind === "boundary") return;
    scene[h.kind === "target" ? "targets" : "obstacles"].splice(h.id, 1);
    selected.handle = selected.object = null;
    explain();
  }
  function addCamera() {
    const [x, y] = centre();
    const template = scene.cameras[0] || {maxVelocity: 1, maxAngularVelocity: 1};
    scene.cameras.push({pos: `POINT(${round(x)} ${round(y)})`, angle: 0,
                        maxVelocity: template.maxVelocity,
                        maxAngularVelocity: template.maxAngularVelocity});
    poses.push({x: round(x), y: round(y), yaw_deg: 0});
    selectCamera(scene.cameras.length - 1);
  }
  function removeCamera() {
    if (selected.camera === null || scene.cameras.length <= 1) return;
    scene.cameras.splice(selected.camera, 1);
    poses.splice(selected.camera, 1);
    selected.camera = 0;
    sweepStep = -1;
    explain();
  }

  document.getElementById("fov").addEventListener("input", (event) => {
    if (selected.camera === null) return;
    const degrees = Number(event.target.value);
    scene.cameras[selected.camera].cameraFoV = degrees;
    document.getElementById("fov-value").textContent = `${degrees.toFixed(1)}°`;
    explainSoon();
  });
  const timeInput = document.getElementById("time");
  timeInput.max = String(data.duration);
  timeInput.value = String(time);
  document.getElementById("time-value").textContent = `t = ${time.toFixed(2)} s`;
  timeInput.addEventListener("input", () => {
    time = Number(timeInput.value);
    document.getElementById("time-value").textContent = `t = ${time.toFixed(2)} s`;
    explainSoon();
  });
  document.getElementById("sweep-back").addEventListener("click", () => {
    sweepStep = Math.max(-1, sweepStep - 1);
    draw();
  });
  document.getElementById("sweep-forward").addEventListener("click", () => {
    if (result.trace) sweepStep = Math.min(result.trace.events.length - 1, sweepStep + 1);
    draw();
  });
  const buttons = {"add-target": () => addObject("targets"), "add-obstacle": () => addObject("obstacles"),
                   "add-camera": addCamera, "remove-camera": removeCamera,
                   "remove-object": removeSelectedObject, "delete-vertex": deleteVertex,
                   "export": exportFiles};
  for (const [id, act] of Object.entries(buttons)) document.getElementById(id).addEventListener("click", act);
  document.addEventListener("keydown", (event) => {
    if (event.key === "Delete" || event.key === "Backspace") deleteVertex();
  });

  // ---- from a picture to a test ------------------------------------------------------------
  function exportFiles() {
    const sceneText = JSON.stringify(scene, null, 2) + "\n";
    const posesText = JSON.stringify(poses) + "\n";
    const stem = data.file.replace(/\.json$/, "");
    const link = (id, text, name) => {
      const a = document.getElementById(id);
      a.href = URL.createObjectURL(new Blob([text], {type: "application/json"}));
      a.download = name;
      a.textContent = name;
      a.dataset.content = text;
    };
    link("export-scene", sceneText, `${stem}-edited.json`);
    link("export-poses", posesText, `${stem}-poses.json`);
    // All three in one file: tests/data/visibility_cases/ takes it as a regression test.
    link("export-case", JSON.stringify({scene, time, poses}, null, 2) + "\n", `${stem}-case.json`);
    document.getElementById("export-command").textContent =
        `camcov inspect ${stem}-edited.json --time ${time} --cameras ${stem}-poses.json --json`;
    document.getElementById("exported").hidden = false;
  }

  window.camcovPlayground = {stats, explain: () => explain(), poses: () => poses, scene: () => scene};
  explain();
  document.body.dataset.ready = "1";
})();
