"""The MCP App view: the step-through page, for hosts that render MCP Apps.

The ``ui://`` resource is scanconv's ``--format html`` page (the stepper, the grid, the test
yourself mode) of the VTU line (5, 5) to (13, 9), so that it is a whole answer by itself, with
a short bridge script added (:data:`BRIDGE`). In a host, the bridge speaks the MCP Apps
protocol over ``postMessage`` (JSON-RPC 2.0, SEP-1865): it introduces itself
(``ui/initialize``), learns the question of the ``solve`` call it is shown for
(``ui/notifications/tool-input``), asks the server for that question's page through the host
(``tools/call answer_page``, a tool only the view sees) and shows it in place of its own. It
asks for nothing outside the page: no script, style, font or image is fetched, and the only
messages go to the host that framed it.
"""

from __future__ import annotations

from .answers import page

URI = "ui://scanconv/stepper.html"
"""The view's address, which the ``solve`` tool points to (``_meta.ui.resourceUri``)."""

EXAMPLE = "line 5 5 13 9 --algo bresenham"
"""The question the view shows before (or without) a host's tool result."""

PAGE_TOOL = "answer_page"
"""The tool the view calls for a question's page (visible to the view only)."""

BRIDGE = """<script>
(function () {
  "use strict";
  if (window.parent === window) { return; }  /* opened as a page: it is the example's answer */
  var host = window.parent, next = 1, waiting = {}, asked = null;
  function send(message) { host.postMessage(message, "*"); }
  function request(method, params) {
    var id = next++;
    send({jsonrpc: "2.0", id: id, method: method, params: params});
    return new Promise(function (done) { waiting[id] = done; });
  }
  function show(html) {
    document.open();
    document.write(html);
    document.close();
  }
  function ask(question) {
    if (typeof question !== "string" || question === asked) { return; }
    asked = question;
    request("tools/call", {name: "@TOOL@", arguments: {question: question}}).then(
      function (reply) {
        var result = reply && reply.result, text = result && result.content && result.content[0];
        if (result && !result.isError && text && typeof text.text === "string") {
          show(text.text);
        }
      });
  }
  window.addEventListener("message", function (event) {
    if (event.source !== host) { return; }
    var m = event.data;
    if (!m || m.jsonrpc !== "2.0") { return; }
    if (m.id !== undefined && waiting[m.id] && m.method === undefined) {
      var done = waiting[m.id];
      delete waiting[m.id];
      done(m);
      return;
    }
    if (m.method === "ui/notifications/tool-input" && m.params && m.params.arguments) {
      ask(m.params.arguments.question);
    }
  });
  request("ui/initialize", {
    protocolVersion: "2026-01-26",
    appInfo: {name: "scanconv", version: "1"},
    appCapabilities: {}
  }).then(function () {
    send({jsonrpc: "2.0", method: "ui/notifications/initialized", params: {}});
    var size = document.documentElement;
    send({jsonrpc: "2.0", method: "ui/notifications/size-changed",
          params: {width: size.scrollWidth, height: size.scrollHeight}});
  });
}());
</script>
""".replace("@TOOL@", PAGE_TOOL)
"""The view's side of the MCP Apps protocol, hand-written (no SDK on the page)."""


def view_html() -> str:
    """The view: the example's step-through page with :data:`BRIDGE` before ``</body>``.

    >>> html = view_html()
    >>> html.startswith("<!DOCTYPE html>"), "ui/initialize" in html, "Test yourself" in html
    (True, True, True)
    """
    html = page(EXAMPLE)
    head, body_end, tail = html.rpartition("</body>")
    return head + BRIDGE + body_end + tail
