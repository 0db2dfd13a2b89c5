// scanconv's site: the Python worker. Loads the Pyodide runtime and the wheels from this
// site's own folder (nothing from anywhere else), then answers each question it is sent with
// scanconv.site.page.answer (scanconv's own question parser and renderers).
import { loadPyodide } from "./pyodide/pyodide.mjs";

let page = null;
const waiting = [];

async function start() {
  const phases = {};
  const mark = (name) => (phases[name] = Math.round(performance.now()));
  const site = await (await fetch("site.json")).json();
  const pyodide = await loadPyodide({ indexURL: new URL("./pyodide/", import.meta.url).href });
  mark("python");
  for (const wheel of site.wheels) {
    const response = await fetch("wheels/" + wheel);
    if (!response.ok) throw new Error(`wheels/${wheel}: HTTP ${response.status}`);
    pyodide.unpackArchive(new Uint8Array(await response.arrayBuffer()), "wheel");
  }
  mark("wheels");
  page = pyodide.pyimport("scanconv.site.page");
  page.warm();
  mark("scanconv");
  postMessage({ type: "ready", phases });
  while (waiting.length) answer(waiting.shift());
}

// The last line of an error that says something: a Python error's text is its traceback,
// which ends with a line end (its last line, the one a split on "\n" gives, is empty).
function lastLine(err) {
  const lines = String(err)
    .split("\n")
    .map((line) => line.trim())
    .filter(Boolean);
  return lines.length ? lines[lines.length - 1] : "an error with no message";
}

function answer(message) {
  if (message.steps !== undefined) return judge(message);
  let result;
  try {
    result = JSON.parse(page.answer(message.question));
  } catch (err) {
    result = { ok: false, error: "scanconv failed: " + lastLine(err) };
  }
  postMessage({ type: "answer", id: message.id, ...result });
}

// "Test yourself" in the answer's frame: the steps typed so far, judged by the library's
// marking (check's follow-through), scanconv.site.page.judge
function judge(message) {
  let result;
  try {
    result = JSON.parse(page.judge(message.question, JSON.stringify(message.steps)));
  } catch (err) {
    result = { error: "scanconv failed: " + lastLine(err) };
  }
  postMessage({ type: "judged", id: message.id, result });
}

onmessage = (event) => (page ? answer(event.data) : waiting.push(event.data));

start().catch((err) => postMessage({ type: "failed", error: lastLine(err) }));
