(function () {
  "use strict";
  var S = window.scanconvStepper;
  if (!S) { return; }
  var T = window.scanconvSelftest;
  if (!T || T.version !== 1) {
    T = window.scanconvSelftest = { version: 1 };
    var B0 = BigInt(0), B1 = BigInt(1), B2 = BigInt(2), B10 = BigInt(10);
    var abs = function (a) { return a < B0 ? -a : a; };
    var gcd = function (a, b) { a = abs(a); b = abs(b); while (b !== B0) { var t = a % b; a = b; b = t; } return a; };
    var mk = function (n, d) { if (d < B0) { n = -n; d = -d; } var g = gcd(n, d) || B1; return { n: n / g, d: d / g, places: 0 }; };
    // An exact value written as "-5/4", "3", "-1.25" (or with a real minus sign).
    T.num = function (text) {
      var t = String(text).trim().replace(/\u2212/g, "-").replace(/\s+/g, "");
      var m = /^([+-]?\d+)\/(\d+)$/.exec(t);
      if (m) { return BigInt(m[2]) === B0 ? null : mk(BigInt(m[1]), BigInt(m[2])); }
      m = /^([+-]?)(\d*)(?:\.(\d*))?$/.exec(t);
      if (!m || (m[2] + (m[3] || "")) === "") { return null; }
      var frac = m[3] || "", r = mk(BigInt((m[1] === "-" ? "-" : "") + (m[2] || "0") + frac), B10 ** BigInt(frac.length));
      r.places = Math.min(frac.length, 12);
      return r;
    };
    // A written number equals an exact value: exactly, or to 2 or more decimals within one unit
    // of the last (as check marks it).
    T.same = function (got, want) {
      if (!got || !want) { return false; }
      var diff = abs(got.n * want.d - want.n * got.d);
      if (diff === B0) { return true; }
      return got.places >= 2 && diff * B10 ** BigInt(got.places) <= got.d * want.d;
    };
    T.sign = function (r) { return r.n < B0 ? "neg" : r.n > B0 ? "pos" : "zero"; };
    T.show = function (r) { return (r.d === B1 ? String(r.n) : r.n + "/" + r.d).replace(/-/g, "\u2212"); };
    var floorDiv = function (n, d) { var q = n / d; return (n % d !== B0 && (n < B0) !== (d < B0)) ? q - B1 : q; };
    T.round = function (r, how) {
      var n = r.n, d = r.d;
      if (how === "trunc") { return n / d; }
      if (how === "c-cast") { return (B2 * n + d) / (B2 * d); }
      if (how === "half-away") { var u = floorDiv(B2 * abs(n) + d, B2 * d); return n < B0 ? -u : u; }
      if (how === "half-even") {
        var f = floorDiv(n, d), rest = n - f * d;
        if (B2 * rest > d || (B2 * rest === d && f % B2 !== B0)) { f += B1; }
        return f;
      }
      return floorDiv(B2 * n + d, B2 * d);
    };
    // A pixel written "5, 3", "(5, 3)" or "5 3".
    T.pixel = function (text) {
      var m = /^\(?\s*([+\-\u2212]?\d+)\s*[,;\s]\s*([+\-\u2212]?\d+)\s*\)?$/.exec(String(text).trim());
      return m ? [+m[1].replace("\u2212", "-"), +m[2].replace("\u2212", "-")] : null;
    };
    var pt = function (p) { return ("(" + p[0] + ", " + p[1] + ")").replace(/-/g, "\u2212"); };
    var el = function (tag, cls, text) {
      var e = document.createElement(tag);
      if (cls) { e.className = cls; }
      if (text !== undefined) { e.textContent = text; }
      return e;
    };
    var CMP = { neg: " < 0", zero: "", pos: " > 0" };
    // A page shown by the site (in its frame) asks the site to judge each step with the
    // library's own marking (check's follow-through across steps), once the site has said it
    // can (scanconvHost: the page itself never writes to a host first, whatever embeds it).
    // Elsewhere the script judges each step itself.
    var pending = {}, asks = 0;
    T.host = null;
    if (window.parent !== window) {
      window.addEventListener("message", function (e) {
        var m = e.source === window.parent && e.data;
        if (!m) { return; }
        if (m.scanconvHost === "judge") { T.host = window.parent; }
        var j = m.scanconvJudged;
        if (j && pending[j.id]) { var f = pending[j.id]; delete pending[j.id]; f(j.result || {}); }
      });
    }
    T.judged = function (steps, done) {
      var id = "st" + (++asks);
      pending[id] = done;
      T.host.postMessage({ scanconvJudge: { id: id, steps: steps } }, "*");
    };
    T.minus = function (text) { return String(text).replace(/-(?=[\d(])/g, "\u2212"); };

    T.init = function (root) {
      if (root.getAttribute("data-st-ready")) { return; }
      root.setAttribute("data-st-ready", "1");
      var holder = root.querySelector("script.sc-testdata");
      var btn = root.querySelector("[data-selftest]");
      var panel = root.querySelector(".sc-testpanel");
      var slider = root.querySelector(".sc-slider");
      if (!holder || !btn || !panel || !slider) { return; }
      var data = JSON.parse(holder.textContent), rows = data.rows, dda = data.kind === "dda";
      var trs = root.querySelectorAll("tr[data-pos]");
      var svg = root.querySelector("svg.sc-stepgrid");
      var i = 0, got = 0, asked = 0, testing = false, waiting = false, typed = [], byHost = false;
      // the student's own state after their last step (check's follow-through): the pixel they
      // reached, their next p or exact values; null: the answer's own row
      var own = null;
      var stepped = [];
      trs.forEach(function (tr) { stepped.push(tr.closest(".sc-tablebox, .sc-scroll")); });
      root.querySelectorAll(".sc-tablebox, .sc-scroll").forEach(function (box) {
        if (stepped.indexOf(box) < 0) { box.classList.add("sc-testhide"); }  // it would tell
      });
      var listed = root.querySelector(".sc-pixels");
      var heading = listed && (listed.closest(".sc-pixbox") || listed).previousElementSibling;
      if (heading && heading.tagName === "H3") { heading.classList.add("sc-testhide"); }
      function goTo(p) { slider.value = String(p); slider.dispatchEvent(new Event("input")); }
      function hideFrom(p) {
        trs.forEach(function (tr) {
          var at = +tr.getAttribute("data-pos"), cell = data.next === null ? null : tr.children[data.next];
          tr.classList.toggle("sc-hid", at >= p);
          if (cell) { cell.classList.toggle("sc-hidcell", at === p - 1); }
        });
      }
      // the panel: the question, the form, the feedback, the score
      var q = el("p", "sc-tq"), form = el("form", "sc-tform"), feed = el("div", "sc-tfeed");
      var score = el("p", "sc-tscore"), bar = el("div", "sc-tbar");
      form.setAttribute("novalidate", "");
      feed.setAttribute("aria-live", "polite");
      score.setAttribute("aria-live", "polite");
      var pIn = el("input"), dIn = el("select"), xyIn = el("input");
      var pLab = el("label"), dLab = el("label"), xyLab = el("label");
      var pName = el("span"), check = el("button", "", "Check");
      [pIn, xyIn].forEach(function (x) { x.type = "text"; x.autocomplete = "off"; x.spellcheck = false; });
      pIn.name = "p"; dIn.name = "decision"; xyIn.name = "pixel";
      xyIn.placeholder = "x, y";
      pIn.placeholder = dda ? "x, y (exact)" : "exact value";
      pLab.append(pName, pIn);
      dLab.append(el("span", "", "decision"), dIn);
      xyLab.append(el("span", "", dda ? "pixel" : "next pixel"), xyIn);
      check.type = "button";  // no form submission: a sandboxed frame (the site's) blocks it
      form.append(pLab, dLab, xyLab, check);
      var next = el("button", "", "Next step"), stop = el("button", "", "Stop");
      next.type = "button"; stop.type = "button";
      next.setAttribute("data-tact", "next"); stop.setAttribute("data-tact", "stop");
      bar.append(next, stop);
      panel.append(q, form, feed, score, bar);

      // a grid wider than its box (its cells kept large): the step's pixel scrolled into sight
      function inSight(at) {
        var box = gridBox, c = data.centre || [0, 0];
        if (!box || box.scrollWidth <= box.clientWidth) { return; }
        var px = root.querySelector('svg.sc-stepgrid rect.sc-px[data-x="' + (at[0] + c[0]) + '"][data-y="' + (at[1] + c[1]) + '"]');
        if (!px) { return; }
        var b = px.getBoundingClientRect(), o = box.getBoundingClientRect();
        box.scrollLeft += b.left + b.width / 2 - (o.left + o.width / 2);
      }
      function ask() {
        var r = rows[i];
        waiting = true;
        hideFrom(r.row);
        goTo(r.lit);
        inSight(r.at);
        var last = typed.length && T.pixel(typed[typed.length - 1].pixel);
        var yours = last && (last[0] !== r.at[0] || last[1] !== r.at[1]) ? " (or from your own " + pt(last) + ")" : "";
        q.textContent = "Step " + (i + 1) + " of " + rows.length + ": from " + (dda ? "(" + r.xyt.join(", ") + ")" : pt(r.at)) + yours +
          (dda ? "" : r.p === null ? ", the pixel only" : ", what are " + r.name + ", the decision and the next pixel?");
        if (dda) { q.textContent += ", what are " + r.name + " and the pixel?"; }
        pName.textContent = r.name + " =";
        var rule = dda ? null : data.rules[r.rule];
        var one = dda || r.p === null;
        pLab.hidden = !dda && r.p === null;
        dLab.hidden = one;
        dIn.textContent = "";
        dIn.append(el("option", "", "choose"));
        dIn.firstChild.value = "";
        if (rule) { Object.keys(rule.moves).forEach(function (m) { var o = el("option", "", m); o.value = m; dIn.append(o); }); }
        pIn.value = ""; dIn.value = ""; xyIn.value = "";
        feed.textContent = "";
        form.hidden = false; next.hidden = true;
        (pLab.hidden ? xyIn : pIn).focus();
      }
      function line(ok, text) { var p = el("p", ok ? "sc-ok" : "sc-no", (ok ? "\u2713 " : "\u2717 ") + text); feed.append(p); }
      function add(a, b) { return mk(a.n * b.d + b.n * a.d, a.d * b.d); }
      function sub(a, b) { return mk(a.n * b.d - b.n * a.d, a.d * b.d); }
      function judgeDda(r) {
        var parts = pIn.value.replace(/^\s*\(|\)\s*$/g, "").split(/\s*[,;]\s*|\s+/);
        var gx = parts.length === 2 ? T.num(parts[0]) : null, gy = parts.length === 2 ? T.num(parts[1]) : null;
        var ax = T.num(r.nxy[0]), ay = T.num(r.nxy[1]);
        // follow-through: the increments added to the student's own values of the row before
        var wx = own ? add(own.xy[0], sub(ax, T.num(r.xy[0]))) : ax;
        var wy = own ? add(own.xy[1], sub(ay, T.num(r.xy[1]))) : ay;
        var okXY = (T.same(gx, wx) && T.same(gy, wy)) || (T.same(gx, ax) && T.same(gy, ay));
        if (!(T.same(gx, wx) && T.same(gy, wy)) && okXY) { wx = ax; wy = ay; }
        var ux = gx && gy ? gx : wx, uy = gx && gy ? gy : wy;  // follow-through: the pixel of your own values
        var want = [Number(T.round(ux, data.rounding)), Number(T.round(uy, data.rounding))];
        var px = T.pixel(xyIn.value), okPx = !!px && px[0] === want[0] && px[1] === want[1];
        var right = "(" + r.nxyt.join(", ") + ")";
        line(okXY, r.name + " = " + right + (okXY ? "" : ", not " + (pIn.value.trim() || "blank") + " (the row before plus the increments)"));
        line(okPx, okPx ? "pixel " + pt(want) + (okXY ? "" : ", rounded from your values: follow-through") :
          "pixel: " + data.rounding + " rounding of " + (gx && gy ? "your (" + T.show(gx) + ", " + T.show(gy) + ")" : right) + " gives " + pt(want));
        feed.append(el("p", "", r.name + " = " + right + ", so the pixel is " + pt(r.to) + "."));
        own = { xy: gx && gy ? [gx, gy] : [wx, wy] };
        return (okXY ? 1 : 0) + (okPx ? 1 : 0);
      }
      // one reading of the student's step, as check reads it: taken from ``base`` (where the
      // step starts and the p it should have), deciding on their own p (``ownP``) or on the
      // base's; its marks, and what it expects
      function reading(r, base, ownP) {
        var rule = data.rules[r.rule], moves = rule.moves;
        var gp = T.num(pIn.value), px = T.pixel(xyIn.value), dv = dIn.value;
        var want = r.p === null ? null : base.p, okP = want === null || T.same(gp, want);
        var used = want === null ? null : ownP && gp ? gp : want;
        var dWant = used === null ? Object.keys(moves)[0] : rule[T.sign(used)];
        var okD = want === null || dv === dWant, move = moves[dv] ? dv : dWant;
        var to = [base.at[0] + moves[move][0], base.at[1] + moves[move][1]];
        var ruled = [base.at[0] + moves[dWant][0], base.at[1] + moves[dWant][1]];
        var okX = !!px && px[0] === to[0] && px[1] === to[1], slip = false;
        if (!okX && px && px[0] === ruled[0] && px[1] === ruled[1]) {
          // the pixel the rule's own step reaches: the decision word was the one slip (as check
          // judges it: a right cell is never called wrong)
          okX = true; to = ruled; slip = true;
        }
        var marks = (want === null ? 0 : (okP ? 1 : 0) + (okD ? 1 : 0)) + (okX ? 1 : 0);
        return { r: r, base: base, want: want, okP: okP, gp: gp, used: used, dWant: dWant, okD: okD,
          move: slip ? dWant : move, to: to, okX: okX, slip: slip, px: px, marks: marks };
      }
      // where the next step starts after a reading (check's bases): the student's own pixel
      // (else the move's), p moved on from the p they decided by, by their move and by the
      // rule's (the row's increments; none known: the answer's next p)
      function after(rd) {
        var out = [], at = rd.base.at;
        [rd.move, rd.dWant].forEach(function (m) {
          var inc = rd.r.inc && rd.used !== null && rd.r.inc[m], moves = data.rules[rd.r.rule].moves;
          var p = inc ? add(rd.used, add(T.num(inc[0]), add(mk(T.num(inc[1]).n * BigInt(at[0]), T.num(inc[1]).d),
            mk(T.num(inc[2]).n * BigInt(at[1]), T.num(inc[2]).d)))) : null;
          var b = { at: rd.px || [at[0] + moves[m][0], at[1] + moves[m][1]], p: p, from: rd.used };
          if (!out.some(function (o) { return o.at[0] === b.at[0] && o.at[1] === b.at[1] && T.same(o.p, b.p); })) { out.push(b); }
        });
        return out;
      }
      function judge(r) {
        var answer = { at: r.at, p: r.p === null ? null : T.num(r.p) };
        var best = reading(r, answer, true);
        if (best.marks < parts(r)) {  // not the answer's own step: the best reading from hers
          best = null;
          (own || [answer]).forEach(function (b) {
            if (b.p === null && r.p !== null) { b = { at: b.at, p: answer.p, from: b.from }; }
            [true, false].forEach(function (ownP) {
              var rd = reading(r, b, ownP);
              if (!best || rd.marks > best.marks) { best = rd; }
            });
          });
        }
        own = after(best);
        show(r, best);
        return best.marks;
      }
      function show(r, rd) {
        var mine = rd.base.at !== r.at || (rd.want !== null && !T.same(rd.want, T.num(r.p)));
        if (rd.want !== null) {
          var prev = rows[i - 1], why = "", want = rd.want;
          if (prev && prev.p !== null && prev.rule === r.rule) {
            var a = rd.base.from !== undefined && rd.base.from !== null ? rd.base.from : T.num(prev.p);
            var inc = mk(want.n * a.d - a.n * want.d, want.d * a.d);
            why = " (" + r.name + " = " + prev.name + (inc.n < B0 ? " \u2212 " + T.show(mk(-inc.n, inc.d)) : " + " + T.show(inc)) +
              " = " + T.show(a) + (inc.n < B0 ? " \u2212 " : " + ") + T.show(mk(abs(inc.n), inc.d)) + " = " + T.show(want) + ")";
          } else if (!rd.okP) { why = " (see the working)"; }
          var shown = mine ? T.show(want) + (T.same(want, T.num(r.p)) ? "" : " (follow-through: from your own answers)") : r.pt.replace(/-/g, "\u2212");
          line(rd.okP, rd.okP ? r.name + " = " + shown : r.name + " = " + shown + ", not " + (pIn.value.trim() || "blank") + why);
          var on = r.name + " = " + T.show(rd.used) + CMP[T.sign(rd.used)];
          line(rd.okD, rd.okD ? "decision " + rd.dWant + (rd.okP ? "" : ": it follows from your " + on + " (follow-through)") :
            "decision: " + (dIn.value ? dIn.value : "none chosen") + "; " + (rd.okP ? "" : "your ") + on + " chooses " + rd.dWant);
        }
        var from = rd.slip ? " (the rule's step: the decision was the slip)" :
          rd.move === r.d && !mine ? "" : " (follow-through from your decision)";
        line(rd.okX, rd.okX ? "next pixel " + pt(rd.to) + from : "next pixel: " + rd.move + " from " + pt(rd.base.at) + " goes to " + pt(rd.to) + (rd.px ? ", not " + pt(rd.px) : ""));
        var tail = rd.want === null && r.p === null ? "the next pixel is " + r.d + ": " + pt(r.to) :
          r.name + " = " + r.pt.replace(/-/g, "\u2212") + CMP[T.sign(T.num(r.p))] + ", so the next pixel is " + r.d + ": " + pt(r.to);
        feed.append(el("p", "", tail + "."));
      }
      function parts(r) { return dda ? 2 : r.p === null ? 1 : 3; }
      // the library's verdict (the site's): each answer right or wrong against the value
      // check judges it by, the reason in check's words, the expected step as check writes it
      var NAMES = { decision: "decision", pixel: dda ? "pixel" : "next pixel" };
      function ownValue(part, r) {
        if (part.field === "p") { return r.p !== null && T.same(T.num(part.want), T.num(r.p)); }
        if (part.field === "decision") { return part.want === r.d; }
        if (part.field === "pixel") { var w = T.pixel(part.want); return !!w && w[0] === r.to[0] && w[1] === r.to[1]; }
        return part.want === "x = " + r.nxy[0] + ", y = " + r.nxy[1];
      }
      function showJudged(r, res) {
        res.parts.forEach(function (part) {
          var name = NAMES[part.field] || r.name, eq = NAMES[part.field] ? " " : " = ";
          if (part.field === "exact") { eq = ": "; }
          var follows = part.ok && !ownValue(part, r) ? " (follow-through: it follows from your own answers)" : "";
          line(part.ok, T.minus(part.ok ? name + eq + part.got + follows : name + eq + part.want + ", not " + part.got));
        });
        if (res.why) { feed.append(el("p", "sc-twhy", T.minus("Why: " + res.why))); }
        feed.append(el("p", "sc-texp", T.minus("Expected (as check marks it): " + res.expected)));
        var tail = dda ? r.name + " = (" + r.nxyt.join(", ") + "), so the pixel is " + pt(r.to) :
          r.p === null ? "the next pixel is " + r.d + ": " + pt(r.to) :
          r.name + " = " + T.minus(r.pt) + CMP[T.sign(T.num(r.p))] + ", so the next pixel is " + r.d + ": " + pt(r.to);
        feed.append(el("p", "", "The answer's own step: " + tail + "."));
      }
      function judged(r, marks, steps) {
        got = marks; asked = steps;
        hideFrom(r.row + 1);
        goTo(r.lit + 1);
        var unit = " steps right";
        score.textContent = "Score so far: " + got + " / " + asked + unit;
        i += 1;
        if (i >= rows.length) {
          score.textContent = "Score: " + got + " / " + asked + unit + " (" + Math.round(100 * got / Math.max(asked, 1)) + " %)";
          next.textContent = "Again";
        } else { next.textContent = "Next step"; }
        next.hidden = false;
        next.focus();
      }
      form.addEventListener("submit", function (e) { e.preventDefault(); });
      root.addEventListener("keydown", function (e) {  // on the root: the stepper's keys stop there
        if (e.key === "Enter" && !e.isComposing && form.contains(e.target)) { e.preventDefault(); checkStep(); }
      }, true);
      check.addEventListener("click", checkStep);
      function checkStep() {
        if (!waiting) { return; }
        waiting = false;
        var r = rows[i];
        feed.textContent = "";
        form.hidden = true;
        typed.push(dda ? { exact: pIn.value, pixel: xyIn.value } : { p: pLab.hidden ? "" : pIn.value, decision: dIn.value, pixel: xyIn.value });
        if (T.host) {
          byHost = true;
          feed.textContent = "Checking\u2026";
          T.judged(typed.slice(), function (res) {
            feed.textContent = "";
            if (res.error || !res.parts) {  // the site cannot mark this answer: judged here, from now on
              T.host = null; byHost = false;
              judged(r, got + stepRight(r), asked + 1);
              return;
            }
            showJudged(r, res);
            judged(r, res.score[0], res.score[1]);
          });
          return;
        }
        judged(r, got + stepRight(r), asked + 1);
      }
      // a step is right when each of its answers is (the score in steps, as check counts it)
      function stepRight(r) { return (dda ? judgeDda(r) : judge(r)) === parts(r) ? 1 : 0; }
      next.addEventListener("click", function () {
        if (i >= rows.length) { i = 0; got = 0; asked = 0; typed = []; own = null; score.textContent = ""; }
        ask();
      });
      // a grid cell is a target to tap: at least 26 CSS px while testing (WCAG 2.2's 24 px
      // minimum), the grid scrolling sideways in its box if the screen is narrower
      var cell = root.querySelector("svg.sc-stepgrid rect.sc-px"), gridBox = null;
      function targets(on) {
        if (!svg || !cell || !svg.viewBox || !svg.viewBox.baseVal) { return; }
        if (!gridBox) {  // the grid alone scrolls sideways, in a box of its own
          gridBox = el("div", "sc-gridbox");
          svg.parentNode.insertBefore(gridBox, svg);
          gridBox.appendChild(svg);
        }
        var units = svg.viewBox.baseVal.width, size = +cell.getAttribute("width");
        svg.style.minWidth = on && size > 0 ? Math.ceil(units * 26 / size) + "px" : "";
      }
      function start() {
        targets(true);
        testing = true; i = 0; got = 0; asked = 0; typed = []; own = null;
        root.classList.add("sc-testing");
        panel.hidden = false;
        btn.setAttribute("aria-expanded", "true");
        btn.textContent = "Stop the test";
        score.textContent = "";
        ask();
      }
      function end() {
        targets(false);
        testing = false; waiting = false;
        root.classList.remove("sc-testing");
        hideFrom(Infinity);
        panel.hidden = true;
        btn.setAttribute("aria-expanded", "false");
        btn.textContent = "Test yourself";
        btn.focus();
      }
      btn.addEventListener("click", function () { if (testing) { end(); } else { start(); } });
      stop.addEventListener("click", end);
      // while testing, the stepper's keys and row clicks would give the answer away
      var key = root.scanconvKey;
      if (key) { root.scanconvKey = function (e) { if (!testing) { key(e); } }; }
      root.addEventListener("keydown", function (e) { if (testing) { e.stopPropagation(); } }, true);
      root.addEventListener("click", function (e) {
        if (testing && e.target.closest && e.target.closest("tr[data-pos]")) { e.stopPropagation(); }
      }, true);
      // a click on the grid names the pixel (relative to the centre, as the table writes it)
      if (svg && data.centre) {
        var ref = root.querySelector("svg.sc-stepgrid rect.sc-px");
        svg.addEventListener("click", function (e) {
          if (!testing || !waiting || !ref || !svg.getScreenCTM()) { return; }
          var m = svg.getScreenCTM().inverse(), s = +ref.getAttribute("width");
          var ux = m.a * e.clientX + m.c * e.clientY + m.e, uy = m.b * e.clientX + m.d * e.clientY + m.f;
          var cx = Math.floor((ux - +ref.getAttribute("x")) / s), cy = Math.floor((uy - +ref.getAttribute("y")) / s);
          var x = +ref.getAttribute("data-x") + cx, y = +ref.getAttribute("data-y") + (data.down ? cy : -cy);
          xyIn.value = (x - data.centre[0]) + ", " + (y - data.centre[1]);
          xyIn.focus();
        });
      }
    };
  }
  S.roots.forEach(function (r) { T.init(r); });
})();
