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
