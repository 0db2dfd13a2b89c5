"""The style sheet and the script of the HTML page (:mod:`scanconv.render.mappings.html`), as strings.

Kept as Python strings, not package data files, so the page is built from the installed
package alone (nothing to find on disk) and stays one self-contained file.

Every CSS rule is scoped under ``.scanconv`` (one answer's root element), so the same rules
can sit in a Jupyter notebook next to other output without touching it. The script defines
``window.scanconvStepper`` once (a second answer in the same notebook or document reuses it)
and starts every answer root that is not started yet; each root keeps its own state and finds
its elements by class inside itself, never by a document-wide id.
"""

from __future__ import annotations

CSS = (
    """\
.scanconv{--sc-ink:#1b1b1b;--sc-muted:#555;--sc-rule:#d0d0d0;--sc-px:#9ec5e8;\
--sc-px-edge:#3a6ea5;--sc-mirror:#d6e7f5;--sc-r2:#f6c28b;--sc-r2-edge:#b86b12;\
--sc-r2-mirror:#fbe3c7;--sc-new:#d62728;--sc-cur:#fff3b0;\
color:var(--sc-ink);font-family:"DejaVu Sans",system-ui,-apple-system,"Segoe UI",sans-serif;\
font-size:15px;line-height:1.45;margin:0 0 2.5em 0}
.scanconv math{font-family:"Latin Modern Math","DejaVu Math TeX Gyre","STIX Two Math",math;\
font-size:1.08em}
.scanconv math[display=block]{margin:.15em 0;text-align:left}
.scanconv h2.sc-title{font-size:1.35em;margin:.2em 0 .6em 0;\
border-bottom:2px solid var(--sc-rule);padding-bottom:.2em}
.scanconv h3{font-size:1.05em;margin:1.1em 0 .35em 0}
.scanconv .sc-heading{font-size:1.1em;font-weight:bold;margin:0 0 .3em 0;color:var(--sc-muted)}
.scanconv .sc-layout{display:grid;grid-template-columns:minmax(0,1fr) minmax(0,1fr);gap:1.6em;\
align-items:start}
.scanconv .sc-layout.sc-single{grid-template-columns:minmax(0,1fr)}
@media (max-width:980px){.scanconv .sc-layout{grid-template-columns:minmax(0,1fr)}}
.scanconv .sc-stepper{position:sticky;top:.5em;z-index:2;border:1px solid var(--sc-rule);\
border-radius:6px;padding:.6em .7em;background:#fff}
.scanconv .sc-working,.scanconv .sc-notes{margin:.2em 0;padding-left:1.3em}
.scanconv .sc-working li{margin:.2em 0}
.scanconv .sc-notes li{margin:.25em 0;color:#333}
.scanconv .sc-given math{margin-right:.3em}
.scanconv .sc-scroll{max-height:30em;overflow:auto;border:1px solid var(--sc-rule);\
border-radius:4px}
.scanconv table.sc-table{border-collapse:collapse;font-variant-numeric:tabular-nums;\
font-size:.93em;margin:.2em 0 .8em 0}
.scanconv .sc-scroll table.sc-table{margin:0}
.scanconv .sc-pixbox{max-height:12em;padding:0 .5em;content-visibility:auto;\
contain-intrinsic-size:auto 12em}
.scanconv table.sc-fixed{table-layout:fixed;margin:0}
.scanconv table.sc-fixed td,.scanconv table.sc-fixed th{overflow:hidden;text-overflow:ellipsis}
.scanconv table.sc-fixed[data-head]{position:sticky;top:0;z-index:1}
.scanconv table.sc-fixed[data-head] caption{background:#fff}
.scanconv .sc-chunk{content-visibility:auto;contain-intrinsic-size:auto 1100px}
.scanconv .sc-chunk table.sc-fixed{border-top:none}
.scanconv table.sc-table caption{text-align:left;font-weight:bold;padding:.3em 0}
.scanconv table.sc-table th,.scanconv table.sc-table td{border:1px solid var(--sc-rule);\
padding:.18em .55em;text-align:center;white-space:nowrap}
.scanconv table.sc-table th{background:#f3f3f3}
.scanconv .sc-scroll table.sc-table th{position:sticky;top:0;z-index:1}
.scanconv .sc-tablebox{overflow-x:auto;max-width:100%}
.scanconv .sc-working math,.scanconv .sc-given math{max-width:100%;overflow-x:auto;overflow-y:hidden;vertical-align:middle}
.scanconv math.sc-clip{box-shadow:inset -16px 0 10px -10px rgba(0,0,0,.5);\
border-right:2px dotted var(--sc-px-edge)}
.scanconv math.sc-clipl{box-shadow:inset 16px 0 10px -10px rgba(0,0,0,.5)}
.scanconv math.sc-clip.sc-clipl{box-shadow:inset -16px 0 10px -10px rgba(0,0,0,.5),\
inset 16px 0 10px -10px rgba(0,0,0,.5)}
.scanconv table.sc-table td.sc-num{text-align:right}
.scanconv tr[data-pos]{cursor:pointer}
.scanconv tr[data-pos]:hover td{background:#f2f7fc}
.scanconv tr.sc-cur td{background:var(--sc-cur)!important;font-weight:bold}
.scanconv tr.sc-r2 td:first-child{box-shadow:inset 4px 0 0 var(--sc-r2-edge)}
.scanconv .sc-more{color:var(--sc-muted);font-style:italic;margin:.2em 0 .8em 0}
.scanconv .sc-pixels{font-family:"DejaVu Sans Mono",monospace;font-size:.88em;\
word-spacing:-.1em}
.scanconv .sc-controls{display:flex;flex-wrap:wrap;gap:.35em;align-items:center;margin:.4em 0}
.scanconv .sc-controls button{font:inherit;font-size:.92em;padding:.2em .6em;\
border:1px solid #999;border-radius:4px;background:#f7f7f7;cursor:pointer}
.scanconv .sc-controls button:hover{background:#eaeaea}
.scanconv .sc-controls button:focus-visible,.scanconv .sc-slider:focus-visible{\
outline:2px solid var(--sc-px-edge);outline-offset:1px}
.scanconv .sc-slider{flex:1 1 10em;min-width:8em}
.scanconv .sc-pos{font-variant-numeric:tabular-nums;color:var(--sc-muted);min-width:5.5em;\
text-align:right}
.scanconv .sc-caption{min-height:3em;margin:.3em 0;padding:.35em .5em;background:#f7f7f2;\
border-left:3px solid var(--sc-new)}
.scanconv .sc-hover{min-height:1.3em;margin:.2em 0;color:var(--sc-muted);font-size:.9em}
.scanconv .sc-keys{color:var(--sc-muted);font-size:.82em;margin:.2em 0}
.scanconv .sc-legend{color:var(--sc-muted);font-size:.85em;margin:.3em 0}
.scanconv .sc-legend span{display:inline-block;margin-right:1em;white-space:nowrap}
.scanconv .sc-legend i{display:inline-block;width:.9em;height:.9em;vertical-align:-.1em;\
border:1px solid #555;margin-right:.3em}
.scanconv svg.sc-grid{display:block;max-width:100%;height:auto;background:#fff}
.scanconv svg.sc-stepgrid{max-height:66vh;width:auto}
.scanconv svg .sc-cells{stroke:#c8c8c8;stroke-width:1;fill:none}
.scanconv svg .sc-axis{stroke:#333;stroke-width:1.5}
.scanconv svg .sc-px{fill:var(--sc-px);stroke:var(--sc-px-edge);stroke-width:1}
.scanconv svg .sc-px.sc-m{fill:var(--sc-mirror)}
.scanconv svg .sc-px.sc-r2{fill:var(--sc-r2);stroke:var(--sc-r2-edge)}
.scanconv svg .sc-px.sc-r2.sc-m{fill:var(--sc-r2-mirror)}
.scanconv svg .sc-px.sc-edge,.scanconv svg .sc-fpx.sc-edge{stroke:#8c4a12;stroke-width:3}
.scanconv svg .sc-fpx{fill:var(--sc-px);stroke:var(--sc-px-edge);stroke-width:1}
.scanconv svg .sc-outline{fill:#f4b183;stroke:#8c4a12;stroke-width:1}
.scanconv svg.sc-stepgrid .sc-px:not(.on){fill:none!important;stroke:none}
.scanconv svg.sc-stepgrid .sc-lb:not(.on){display:none}
.scanconv svg .sc-px.sc-new{stroke:var(--sc-new);stroke-width:3}
.scanconv svg .sc-ideal{fill:none;stroke:#d62728;stroke-width:2;stroke-linejoin:round}
.scanconv svg .sc-control{fill:none;stroke:#2ca02c;stroke-width:1.5;stroke-dasharray:6 4}
.scanconv svg .sc-cpoint{fill:none;stroke:#2ca02c;stroke-width:2}
.scanconv svg .sc-mark{stroke:#7b3294;stroke-width:2}
.scanconv svg .sc-level{fill:#fff;stroke:#7b3294;stroke-width:1.5}
.scanconv svg .sc-levelline{fill:none;stroke:#7b3294;stroke-width:1;stroke-dasharray:3 3}
.scanconv svg text{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;fill:#333}
.scanconv svg .sc-lb{fill:#111;stroke:#fff;stroke-width:3;paint-order:stroke;\
pointer-events:none}
.scanconv svg .sc-ftitle{font-weight:bold;fill:#111}
.scanconv .sc-figures{display:flex;flex-wrap:wrap;gap:1.2em;align-items:flex-start}
.scanconv .sc-figures figure{margin:.3em 0}
.scanconv .sc-figures figcaption{font-size:.9em;color:var(--sc-muted);max-width:36em}
@media print{
"""
    + "{PLAIN}"
    + """.scanconv .sc-layout{display:block}
.scanconv svg.sc-stepgrid{max-height:none}
.scanconv .sc-stepper{position:static;border:none;padding:0;break-inside:avoid}
.scanconv .sc-scroll{max-height:none;overflow:visible;border:none}
.scanconv .sc-scroll table.sc-table th{position:static}
.scanconv .sc-tablebox{overflow:visible}
.scanconv tr.sc-cur td{background:none!important;font-weight:normal}
}
"""
)
"""The page's style sheet (every rule under ``.scanconv``)."""

PLAIN = """\
.scanconv .sc-controls,.scanconv .sc-caption,.scanconv .sc-hover,.scanconv .sc-keys{display:none}
.scanconv svg.sc-stepgrid .sc-px:not(.on){fill:var(--sc-px)!important;stroke:var(--sc-px-edge)}
.scanconv svg.sc-stepgrid .sc-px.sc-m:not(.on){fill:var(--sc-mirror)!important}
.scanconv svg.sc-stepgrid .sc-px.sc-r2:not(.on){fill:var(--sc-r2)!important;stroke:var(--sc-r2-edge)}
.scanconv svg.sc-stepgrid .sc-lb:not(.on){display:inline}
.scanconv svg .sc-px.sc-new{stroke:var(--sc-px-edge);stroke-width:1}
.scanconv .sc-chunk{content-visibility:visible}
"""
"""The answer without its stepper: every pixel shown, no controls (printing; no script)."""

CSS = CSS.replace("{PLAIN}", PLAIN)

PAGE_CSS = """\
body{margin:1.2em auto;max-width:1400px;padding:0 1.2em;background:#fff}
.sc-doc-title{font-family:"DejaVu Sans",system-ui,sans-serif;font-size:1.6em;margin:.2em 0 .8em 0}
@media print{body{margin:0;max-width:none}}
"""
"""Rules for a whole page only (never put into a notebook)."""

JS = r"""
(function () {
  "use strict";
  var S = window.scanconvStepper;
  if (!S || S.version !== 1) {
    S = window.scanconvStepper = { version: 1, roots: [], active: null, keysBound: false };
    S.init = function (root) {
      if (root.getAttribute("data-ready")) { return; }
      root.setAttribute("data-ready", "1");
      var holder = root.querySelector("script.sc-data");
      if (!holder) { return; }
      var data = JSON.parse(holder.textContent);
      var n = data.n, pos = data.pos, kind = data.kind;
      var rects = root.querySelectorAll("svg.sc-stepgrid .sc-px");
      var labels = {};
      root.querySelectorAll(".sc-lb").forEach(function (el) { labels[el.getAttribute("data-i")] = el; });
      var byPos = [];
      var q, i;
      for (q = 0; q <= n; q++) { byPos.push([]); }
      for (i = 0; i < pos.length && i < rects.length; i++) { byPos[pos[i]].push(i); }
      var rows = {};
      root.querySelectorAll("tr[data-pos]").forEach(function (tr) { rows[+tr.getAttribute("data-pos")] = tr; });
      var slider = root.querySelector(".sc-slider");
      var out = root.querySelector(".sc-pos");
      var caption = root.querySelector(".sc-caption");
      var hover = root.querySelector(".sc-hover");
      var playBtn = root.querySelector("[data-act=play]");
      // The page is written at a step (lit pixels, row, slider, caption): nothing to redraw.
      var cur = +(root.getAttribute("data-pos") || 0);
      var newOnes = byPos[cur] || [], curRow = rows[cur] || null, timer = null;
      function light(i, on) {
        rects[i].classList.toggle("on", on);
        var l = labels[i];
        if (l) { l.classList.toggle("on", on); }
      }
      function go(p) {
        p = Math.max(0, Math.min(n, p | 0));
        if (p > cur) {
          for (q = cur + 1; q <= p; q++) { byPos[q].forEach(function (j) { light(j, true); }); }
        } else if (p < cur) {
          for (q = p + 1; q <= cur; q++) { byPos[q].forEach(function (j) { light(j, false); }); }
        }
        newOnes.forEach(function (j) { rects[j].classList.remove("sc-new"); });
        newOnes = byPos[p];
        newOnes.forEach(function (j) { rects[j].classList.add("sc-new"); });
        if (curRow) { curRow.classList.remove("sc-cur"); }
        curRow = rows[p] || null;
        if (curRow) {
          curRow.classList.add("sc-cur");
          var box = curRow.closest(".sc-scroll");
          if (box) {
            var r = curRow.getBoundingClientRect(), b = box.getBoundingClientRect();
            if (r.top < b.top + 40 || r.bottom > b.bottom - 8) { box.scrollTop += r.top - b.top - b.height / 2; }
          }
        }
        cur = p;
        root.setAttribute("data-pos", String(p));
        if (slider) { slider.value = String(p); }
        if (out) { out.textContent = "step " + p + " / " + n; }
        if (caption) { caption.textContent = data.captions[p]; }
      }
      function stop() {
        if (timer !== null) { clearInterval(timer); timer = null; }
        if (playBtn) { playBtn.textContent = "\u25B6 Play"; playBtn.setAttribute("aria-pressed", "false"); }
      }
      function play() {
        if (timer !== null) { stop(); return; }
        if (cur >= n) { go(0); }
        if (playBtn) { playBtn.textContent = "\u275A\u275A Pause"; playBtn.setAttribute("aria-pressed", "true"); }
        timer = setInterval(function () { if (cur >= n) { stop(); } else { go(cur + 1); } }, data.ms);
      }
      var acts = {
        reset: function () { stop(); go(0); },
        prev: function () { stop(); go(cur - 1); },
        next: function () { stop(); go(cur + 1); },
        end: function () { stop(); go(n); },
        play: play
      };
      root.querySelectorAll("button[data-act]").forEach(function (b) {
        b.addEventListener("click", function () { S.active = root; acts[b.getAttribute("data-act")](); });
      });
      if (slider) { slider.addEventListener("input", function () { stop(); go(+slider.value); }); }
      root.addEventListener("click", function (e) {
        var tr = e.target.closest ? e.target.closest("tr[data-pos]") : null;
        if (tr && root.contains(tr)) { stop(); go(+tr.getAttribute("data-pos")); }
      });
      root.addEventListener("pointerdown", function () { S.active = root; });
      root.addEventListener("focusin", function () { S.active = root; });
      var svg = root.querySelector("svg.sc-stepgrid");
      if (svg && hover) {
        svg.addEventListener("mouseover", function (e) {
          var t = e.target, at = t.getAttribute ? t.getAttribute("data-i") : null;
          if (at === null || !t.classList.contains("sc-px")) { return; }
          var j = +at, p = pos[j];
          hover.textContent = "(" + t.getAttribute("data-x") + ", " + t.getAttribute("data-y") + "): plotted at step " +
            p + " (" + data.heads[p] + ")" + (kind[j] === 1 ? ", a mirror image" : "") + (p > cur ? "; not plotted yet" : "");
        });
        svg.addEventListener("mouseleave", function () { hover.textContent = ""; });
      }
      root.scanconvKey = function (e) {
        var t = e.target, tag = t && t.tagName ? t.tagName.toLowerCase() : "";
        if (tag === "input" || tag === "textarea" || tag === "select") { return; }
        var k = e.key;
        if (k === "ArrowRight") { acts.next(); }
        else if (k === "ArrowLeft") { acts.prev(); }
        else if (k === "Home") { acts.reset(); }
        else if (k === "End") { acts.end(); }
        else if (k === " " || k === "Spacebar") { if (tag === "button") { return; } play(); }
        else { return; }
        e.preventDefault();
      };
      if (root.getAttribute("data-keys") === "root") {
        root.addEventListener("keydown", root.scanconvKey);
      } else if (!S.keysBound) {
        S.keysBound = true;
        document.addEventListener("keydown", function (e) {
          var r = S.active || S.roots.find(function (x) { return x.getAttribute("data-keys") !== "root"; });
          if (r && r.getAttribute("data-keys") !== "root") { r.scanconvKey(e); }
        });
      }
      S.roots.push(root);
      root.classList.add("sc-js");
    };
  }
  document.querySelectorAll(".scanconv[data-stepper]").forEach(function (r) { S.init(r); });
})();
"""
"""The stepper: one script for every answer on the page (see the module)."""

CLIP_JS = r"""
(function () {
  "use strict";
  // A working formula too wide for its line scrolls inside its own box: it is marked
  // (sc-clip: a shadow and a dotted edge on the right; sc-clipl: a shadow on the left once it
  // is scrolled) only while some of it is out of sight.
  var mark = function (m) {
    var more = m.scrollWidth > m.clientWidth + 1;
    m.classList.toggle("sc-clip", more && m.scrollLeft + m.clientWidth < m.scrollWidth - 1);
    m.classList.toggle("sc-clipl", more && m.scrollLeft > 1);
  };
  var all = [];
  var watch = window.ResizeObserver && new ResizeObserver(function (es) { es.forEach(function (e) { mark(e.target); }); });
  document.querySelectorAll(".scanconv").forEach(function (root) {
    if (root.getAttribute("data-clipcue")) { return; }
    root.setAttribute("data-clipcue", "1");
    root.querySelectorAll(".sc-working math, .sc-given math").forEach(function (m) {
      all.push(m);
      mark(m);
      m.addEventListener("scroll", function () { mark(m); }, { passive: true });
      if (watch) { watch.observe(m); }
    });
  });
  var again = function () { all.forEach(mark); };
  window.addEventListener("load", again);
  if (document.fonts && document.fonts.ready) { document.fonts.ready.then(again); }
})();
"""
"""Marks the working formulas that are cut at the edge of their box (see the script)."""

# The "Test yourself" mode (issue 31): its own module, appended to every page's style and script.
from .selftest_assets import SELFTEST_CSS, SELFTEST_JS  # noqa: E402

CSS += SELFTEST_CSS
JS += CLIP_JS + SELFTEST_JS
