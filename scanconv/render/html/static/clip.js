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
