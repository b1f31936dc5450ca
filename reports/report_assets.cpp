#include "reports/report_assets.h"

#include <fmt/format.h>

#include "reports/markup.h"

namespace camcov::reports {
std::string documentHead(std::string_view title, std::string_view toolVersion,
                         std::string_view style, std::string_view contentSecurityPolicy) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"{}\">\n"
      "<meta name=\"generator\" content=\"camcov {}\">\n"
      "<title>{}</title>\n<style>{}</style>\n</head>\n<body>\n",
      contentSecurityPolicy, escapeXml(toolVersion), escapeXml(title), style);
}

std::string_view reportStyle() {
  return R"css(
:root { --ink: #1f2328; --muted: #5f6670; --line: #d8dbe0; --panel: #f5f6f8; --accent: #1f6fd1; }
* { box-sizing: border-box; }
html { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", "DejaVu Sans",
       Arial, sans-serif; font-size: 15px; line-height: 1.45; color: var(--ink); background: #fff; }
body { margin: 0; }
.page { max-width: 1180px; margin: 0 auto; padding: 28px 28px 48px; }
h1 { font-size: 1.9rem; margin: 0 0 .4rem; letter-spacing: -.01em; }
h2 { font-size: 1.35rem; margin: 2.4rem 0 .7rem; padding-bottom: .3rem;
     border-bottom: 2px solid var(--line); }
h3 { font-size: 1.05rem; margin: 1.5rem 0 .5rem; }
p { max-width: 86ch; }
a { color: var(--accent); text-decoration: none; }
a:hover { text-decoration: underline; }
code { font-family: ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; font-size: .86em;
       background: var(--panel); padding: .05em .3em; border-radius: 3px; }
.muted { color: var(--muted); font-weight: 400; }
.lede { color: var(--muted); font-size: 1.05rem; margin-top: 0; }
.verdict { background: var(--panel); border-left: 4px solid var(--accent); padding: .6rem .9rem;
           border-radius: 4px; }
.facts { display: grid; grid-template-columns: max-content 1fr; gap: .25rem 1.2rem;
         margin: 1.1rem 0 0; }
dt { color: var(--muted); font-weight: 600; }
dd { margin: 0; overflow-wrap: anywhere; }
nav.toc { position: sticky; top: 0; z-index: 2; background: rgba(255, 255, 255, .96);
          border-bottom: 1px solid var(--line); }
nav.toc ul { display: flex; flex-wrap: wrap; gap: .2rem 1.4rem; list-style: none; margin: 0 auto;
             padding: .55rem 28px; max-width: 1180px; font-weight: 500; }
.table-wrap { overflow-x: auto; }
table { border-collapse: collapse; font-size: .86rem; }
th, td { padding: .3rem .55rem; border-bottom: 1px solid var(--line); text-align: left;
         vertical-align: top; }
thead th { background: var(--panel); font-weight: 600; vertical-align: bottom; white-space: nowrap; }
thead th[colspan] { text-align: center; border-bottom: 1px solid #c3c8cf; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.near-optimum { color: #1a7f37; font-weight: 600; }
p.scene-warning { color: #9a6700; }
.out-of-reach { color: #9a6700; font-size: 0.85em; white-space: nowrap; }
table.summary tbody { border-top: 1px solid #b4bac3; }
table.summary tbody th { font-weight: 600; }
/* Fourteen columns in the page's width (1124 px in a 1400 px window): narrower padding, and the
   column titles wrap (the numbers below them do not); a scene's name may break after '_'. */
table.summary th, table.summary td { padding: .3rem .45rem; }
table.summary thead th:not([colspan]) { white-space: normal; }
/* A weighted or resolved line under a mean wraps after its word rather than push the table's
   last columns (the winner) out of sight. */
table.summary td.num .extra { white-space: normal; }
table.summary td.num .extra .value { white-space: nowrap; }
th button { font: inherit; font-weight: 600; color: inherit; background: none; border: 0;
            padding: 0; cursor: pointer; }
/* A no-break space: the arrow stays with the title's last word when the title wraps. */
th button::after { content: "\a0\2195"; color: var(--muted); font-weight: 400; }
th[data-dir="asc"] button::after { content: "\a0\25B2"; }
th[data-dir="desc"] button::after { content: "\a0\25BC"; }
.badge { display: inline-block; padding: .02rem .5rem; border-radius: 999px; color: #fff;
         background: var(--c, #8a8f98); font-size: .78rem; font-weight: 600; }
.method-mark { white-space: nowrap; }
.method-dot { display: inline-block; width: .7em; height: .7em; border-radius: 50%;
              background: var(--c); margin-right: .4em; }
.swatch { display: inline-block; width: 1.1em; height: .8em; margin: 0 .3em 0 .15em;
          vertical-align: -.05em; border-radius: 2px; background: var(--c); opacity: .7; }
.swatch.line { height: 3px; vertical-align: .2em; opacity: 1; }
figure { margin: 1rem 0; }
figcaption { font-size: .88rem; }
svg.chart, svg.scene { display: block; max-width: 100%; height: auto; }
svg text { font-family: inherit; }
figure.panel figcaption { color: var(--muted); }
figure.series { border-top: 1px solid var(--line); padding-top: .55rem; margin: .9rem 0; }
.pair { display: flex; flex-wrap: wrap; gap: 4px 28px; margin-top: .3rem; }
.gallery { display: grid; grid-template-columns: repeat(auto-fill, minmax(340px, 1fr)); gap: 16px; }
.scene-card { margin: 0; padding: 10px 12px; border: 1px solid var(--line); border-radius: 6px; }
.scene-card svg { margin: 0 auto 8px; }
.note { color: #9a3412; font-size: .85rem; margin: .3rem 0 0; }
.left-out { color: var(--muted); }
table.parameters tr.group th, table.settings-scenes tr.group th { background: #eceef2; }
tr.override td { background: #fff3dc; }
td.symbol { font-style: italic; white-space: nowrap; }
.videos { display: grid; grid-template-columns: repeat(auto-fill, minmax(360px, 1fr)); gap: 16px; }
video { width: 100%; background: #000; border-radius: 4px; }
footer { margin-top: 3rem; padding-top: .6rem; border-top: 1px solid var(--line);
         color: var(--muted); font-size: .82rem; }
@media (max-width: 720px) { .page { padding: 14px; } nav.toc ul { padding: .5rem 14px; } }
@media print {
  @page { size: A4 landscape; margin: 12mm; }
  html { font-size: 10.5pt; }
  * { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
  nav.toc { display: none; }
  .page { max-width: none; padding: 0; }
  #box-plots, #time-series, #scenes, #parameters { break-before: page; }
  h2, h3 { break-after: avoid; }
  figure, .scene-card, tr, thead, .verdict { break-inside: avoid; }
  .table-wrap { overflow: visible; }
  th button::after { content: none; }
  video { display: none; }
  a { color: inherit; }
}
)css";
}

std::string_view reportScript() {
  return R"js(
document.querySelectorAll("table.sortable").forEach((table) => {
  const headers = table.querySelectorAll("th[data-key]");
  headers.forEach((th) => {
    th.querySelector("button").addEventListener("click", () => {
      const key = th.dataset.key;
      const dir = th.dataset.dir === "asc" ? "desc" : "asc";
      headers.forEach((h) => h.removeAttribute("data-dir"));
      th.dataset.dir = dir;
      const bodies = Array.from(table.tBodies);
      bodies.sort((a, b) => {
        const x = a.dataset[key], y = b.dataset[key];
        const nx = Number(x), ny = Number(y);
        const c = Number.isNaN(nx) || Number.isNaN(ny) ? x.localeCompare(y) : nx - ny;
        return dir === "asc" ? c : -c;
      });
      bodies.forEach((body) => table.appendChild(body));
    });
  });
});
)js";
}

}  // namespace camcov::reports
