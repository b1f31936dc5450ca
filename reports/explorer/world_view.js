// The world as both pages show it (the run explorer and the visibility playground): zoom and
// pan, and small objects drawn larger than life as the frames draw them
// (viz/cairo_drawing.h). The wheel zooms about the pointer, a drag on the background pans, a
// reset button shows the whole scene again; marker sizes follow the part of the scene in view,
// so zooming in on a crowd shows each person at true size.
"use strict";
window.camcovWorldView = (() => {
  const kMaxZoom = 400;   // a pedestrian in a stadium: still a few hundred px across
  const kPanSlop = 3;     // px a press may wander and still be a click
  const kWheelRate = 0.0015;  // per wheel delta unit: a notch (100) zooms about 16%

  // home: {x, y, w, h}, the box of SVG user units (y down) the whole scene fills. Every svg of
  // `svgs` shows the same box; onChange(view) redraws after each zoom or pan.
  function create({home, svgs, reset, onChange}) {
    const view = {box: {...home}};
    view.zoom = () => home.w / view.box.w;
    // A fortieth of what is in view: markers, handles and the size below which an object is
    // drawn enlarged.
    view.em = () => 0.025 * Math.max(view.box.w, view.box.h);
    const apply = () => {
      const b = view.box;
      for (const svg of svgs) svg.setAttribute("viewBox", `${b.x} ${b.y} ${b.w} ${b.h}`);
      document.body.dataset.zoom = String(view.zoom());
    };
    // The box scaled by `factor` about the user point p, kept overlapping the home box.
    const setBox = (w, about) => {
      const b = view.box, s = Math.min(home.w, Math.max(home.w / kMaxZoom, w)) / b.w;
      const x = about[0] - (about[0] - b.x) * s, y = about[1] - (about[1] - b.y) * s;
      const nw = b.w * s, nh = b.h * s;
      view.box = {x: Math.min(home.x + home.w - 0.1 * nw, Math.max(home.x - 0.9 * nw, x)),
                  y: Math.min(home.y + home.h - 0.1 * nh, Math.max(home.y - 0.9 * nh, y)), w: nw, h: nh};
      apply();
      onChange(view);
    };
    view.reset = () => {
      view.box = {...home};
      apply();
      onChange(view);
    };
    // Zoom by `factor` about a client point of svg (its centre if none).
    view.zoomBy = (svg, factor, clientX, clientY) => {
      const r = svg.getBoundingClientRect();
      const p = userPoint(svg, clientX ?? r.left + r.width / 2, clientY ?? r.top + r.height / 2);
      setBox(view.box.w / factor, p);
    };
    for (const svg of svgs) {
      svg.addEventListener("wheel", (e) => {
        if (e.defaultPrevented) return;  // a camera turned by the wheel (playground)
        e.preventDefault();
        view.zoomBy(svg, Math.exp(-e.deltaY * kWheelRate), e.clientX, e.clientY);
      }, {passive: false});
      let press = null;
      svg.addEventListener("pointerdown", (e) => {
        if (e.button !== 0) return;
        press = {id: e.pointerId, x: e.clientX, y: e.clientY, box: {...view.box}, panning: false,
                 scale: view.box.w / svg.getBoundingClientRect().width};
      });
      svg.addEventListener("pointermove", (e) => {
        if (!press || e.pointerId !== press.id) return;
        const dx = e.clientX - press.x, dy = e.clientY - press.y;
        if (!press.panning && Math.hypot(dx, dy) < kPanSlop) return;
        if (!press.panning) svg.setPointerCapture(e.pointerId);
        press.panning = true;
        view.box = {...press.box, x: press.box.x - dx * press.scale, y: press.box.y - dy * press.scale};
        apply();
        onChange(view);
      });
      // The end of a pan is not a click on what lies under the pointer.
      let panEnded = -Infinity;
      svg.addEventListener("click", (c) => {
        if (performance.now() - panEnded > 300) return;
        c.stopImmediatePropagation();  // create() runs before the page adds its own listeners
        c.preventDefault();
      }, {capture: true});
      const release = () => {
        if (press && press.panning) panEnded = performance.now();
        press = null;
      };
      svg.addEventListener("pointerup", release);
      svg.addEventListener("pointercancel", release);
    }
    if (reset) reset.addEventListener("click", () => view.reset());
    // The svgs as tall as the window leaves below their top (CSS max-height:
    // var(--world-room)), so the whole scene is in view without scrolling; at least 240 px, so
    // a very short window scrolls instead.
    const fit = view.fit = () => {
      const top = svgs[0].getBoundingClientRect().top + window.scrollY;
      document.documentElement.style.setProperty(
          "--world-room", `${Math.max(240, Math.floor(window.innerHeight - top - 8))}px`);
    };
    window.addEventListener("resize", fit);
    fit();
    apply();
    return view;
  }

  function userPoint(svg, clientX, clientY) {
    const p = new DOMPoint(clientX, clientY).matrixTransform(svg.getScreenCTM().inverse());
    return [p.x, p.y];
  }

  // An object less than `minObject` across (a player on a pitch) is drawn enlarged about the
  // mean of its vertices, its edges with it: {c, factor, at(point)}.
  function enlargement(ring, minObject) {
    let cx = 0, cy = 0, x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const [x, y] of ring) {
      cx += x; cy += y;
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
    const across = Math.max(x1 - x0, y1 - y0);
    const factor = across >= minObject ? 1 : minObject / Math.max(across, 1e-9);
    const c = [cx / ring.length, cy / ring.length];
    return {c, factor, at: (p) => factor === 1 ? p
                              : [c[0] + (p[0] - c[0]) * factor, c[1] + (p[1] - c[1]) * factor]};
  }

  return {create, enlargement};
})();
