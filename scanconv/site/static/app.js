// scanconv's site: the page. Sends the question to the Python worker, shows the answer (the
// step-through page in a frame, its data as JSON), keeps the question in the URL (#q=...)
// so that the link reopens it, and turns a filled form into a question.
const $ = (id) => document.getElementById(id);
const box = $("q");
const status = $("status");
const started = performance.now();
const timings = { ready: null, answers: [] };
window.scanconvTimings = timings;

let worker = null;
let ready = false;
let asked = null; // { id, question, at }
let nextId = 1;
let shownQuestion = null; // the question whose answer the frame shows (test yourself asks on it)
const judging = new Map(); // a judge request's id -> [the frame's window, the frame's own id]

function setStatus(text, state) {
  status.textContent = text;
  document.body.dataset.state = state;
  $("stop").hidden = state !== "working";
}

// A question that takes long (a huge circle) can be stopped: the worker is ended and a new
// one started (Python loads again).
$("stop").addEventListener("click", () => {
  worker.terminate();
  asked = null;
  startWorker();
});

function startWorker() {
  ready = false;
  worker = new Worker("worker.mjs", { type: "module" });
  worker.onmessage = (event) => received(event.data);
  worker.onerror = (event) => setStatus("Python could not start: " + event.message, "failed");
  setStatus("Loading Python and scanconv (the first time takes a few seconds)…", "loading");
}

function received(m) {
  if (m.type === "ready") {
    ready = true;
    timings.ready = performance.now() - started;
    timings.phases = m.phases; // ms since the worker started: Python up, wheels in, scanconv imported
    setStatus(`Ready (loaded in ${(timings.ready / 1000).toFixed(1)} s).`, "ready");
    if (asked) {
      asked.at = performance.now(); // the answer's own time, not the loading's
      worker.postMessage({ id: asked.id, question: asked.question });
      setStatus("Working…", "working");
    }
  } else if (m.type === "failed") {
    setStatus("Python could not start: " + m.error, "failed");
  } else if (m.type === "judged" && judging.has(m.id)) {
    const [target, id] = judging.get(m.id);
    judging.delete(m.id);
    if (target === $("answer").contentWindow) target.postMessage({ scanconvJudged: { id, result: m.result } }, "*");
  } else if (m.type === "answer" && asked && m.id === asked.id) {
    const ms = performance.now() - asked.at;
    timings.answers.push({ question: asked.question, ms, sinceLoad: performance.now() - started });
    asked = null;
    show(m, ms);
  }
}

function show(m, ms) {
  $("error").hidden = m.ok;
  $("notes").hidden = true;
  $("data").hidden = !m.ok;
  $("answer").hidden = !m.ok;
  if (!m.ok) {
    $("error").textContent = m.error;
    $("share-row").hidden = true; // no link to share for a question that has an error
    setStatus("That question has an error.", "error");
    return;
  }
  $("notes").textContent = m.notes.join("; ");
  $("notes").hidden = !m.notes.length;
  shownQuestion = m.question;
  scrollPending = true;
  showPage(m.html);
  $("json").textContent = m.json;
  setStatus(`${m.title} (answered in ${Math.round(ms)} ms)`, "answered");
  intoView();
}

// On a small screen the answer starts below the question box, the examples and the forms
// (on a 390 x 844 phone, below the fold): once shown, an answer whose top is not in the upper
// quarter of the screen is scrolled up to the top of it; again when its frame has reported
// its height (until then the page may be too short to scroll that far).
let scrollPending = false;
function intoView() {
  const top = $("answer").getBoundingClientRect().top;
  if (top < 0 || top > window.innerHeight / 4) $("answer").scrollIntoView({ block: "start" });
}

// The answer's page runs in a sandboxed frame (sandbox="allow-scripts", no same origin: its
// scripts cannot reach this page), so this page cannot read its height: the frame's page
// reports it with postMessage, and only a number from that frame is read. Each answer gets
// a new frame (Chromium left a sandboxed frame shown again after an error blank).
const HEIGHT_REPORT =
  "<script>(function () { var report = function () { parent.postMessage(" +
  "{ scanconvHeight: document.documentElement.getBoundingClientRect().height }, '*'); };" +
  " addEventListener('load', report); new ResizeObserver(report)" +
  ".observe(document.documentElement); })();</" + "script>";

function showPage(html) {
  const old = $("answer");
  const frame = old.cloneNode(false);
  frame.removeAttribute("style");
  frame.removeAttribute("data-host"); // a new page, told again that it may ask for judgements
  const end = html.lastIndexOf("</body>");
  frame.srcdoc =
    end < 0 ? html + HEIGHT_REPORT : html.slice(0, end) + HEIGHT_REPORT + html.slice(end);
  old.replaceWith(frame);
}

// The frame's "Test yourself" asks this page to judge each step with the library's marking
// (check's follow-through): told that it may (scanconvHost, once its page has loaded and
// reported its height), it sends the steps typed so far (a list of short texts); the worker
// judges them on the question the frame shows.
function judgeRequest(frame, ask) {
  if (!ask || typeof ask.id !== "string" || !Array.isArray(ask.steps) || ask.steps.length > 1000) return;
  const steps = ask.steps.map((s) =>
    Object.fromEntries(Object.entries(Object(s)).map(([k, v]) => [String(k).slice(0, 20), String(v).slice(0, 200)])),
  );
  const id = "judge" + nextId++;
  judging.set(id, [frame.contentWindow, ask.id.slice(0, 40)]);
  worker.postMessage({ id, question: shownQuestion, steps });
}

window.addEventListener("message", (event) => {
  const frame = $("answer");
  if (event.source !== frame.contentWindow || !event.data) return;
  if (event.data.scanconvHeight && !frame.dataset.host) {
    frame.dataset.host = "1";
    frame.contentWindow.postMessage({ scanconvHost: "judge" }, "*");
  }
  if (event.data.scanconvJudge && ready && shownQuestion !== null) judgeRequest(frame, event.data.scanconvJudge);
  const height = Number(event.data.scanconvHeight);
  if (Number.isFinite(height) && height > 0) {
    frame.style.height = Math.min(Math.ceil(height) + 4, 1e6) + "px"; // and its borders
    if (scrollPending) {
      scrollPending = false;
      intoView();
    }
  }
});

function showError(message, state) {
  $("error").textContent = message;
  $("error").hidden = false;
  for (const id of ["notes", "data", "answer"]) $(id).hidden = true;
  setStatus(state, "error");
}

// the words that choose a format or a file, and their values: the page shows the answer in
// its own formats (as the Python side drops them), so a shared link leaves them out
const OUTPUT_FLAGS = ["--format", "-f", "--output", "-o", "--svg", "--png"];

function shareable(question) {
  const words = question.split(/\s+/).filter((w) => w);
  if (words[0] === "scanconv") words.shift();
  const kept = [];
  for (let i = 0; i < words.length; i++) {
    if (OUTPUT_FLAGS.includes(words[i])) {
      i++; // and its value
    } else if (!OUTPUT_FLAGS.some((f) => words[i].startsWith(f + "="))) {
      kept.push(words[i]);
    }
  }
  return kept.join(" ");
}

function ask(question) {
  question = question.trim();
  if (!question) return;
  box.value = question;
  const url = "#q=" + encodeURIComponent(shareable(question));
  if (location.hash !== url) history.replaceState(null, "", url);
  $("share").href = url;
  $("share-row").hidden = false;
  asked = { id: nextId++, question, at: performance.now() };
  if (ready) {
    worker.postMessage({ id: asked.id, question });
    setStatus("Working… (a large question can take a while)", "working");
  }
}

function fromHash() {
  const m = location.hash.match(/^#q=(.*)$/s);
  if (!m) return;
  let question;
  try {
    question = decodeURIComponent(m[1]);
  } catch {
    // a link cut short or mistyped (#q=%E0%A4%A): say so, instead of an uncaught URIError
    showError(
      "This link is malformed: the question after #q= is not valid percent-encoded text " +
        "(was the link cut short when it was copied?).",
      "That link has an error.",
    );
    $("share-row").hidden = true; // the link shown was another question's
    return;
  }
  ask(question);
}

// --- the forms ------------------------------------------------------------------------------
const SAFE = /^[A-Za-z0-9_.,:\/+=@%^-]+$/;
const quote = (w) => (SAFE.test(w) ? w : "'" + w.replace(/'/g, `'"'"'`) + "'");

function formQuestion(fieldset) {
  const words = fieldset.dataset.command.split(" ");
  for (const field of fieldset.querySelectorAll("input, select")) {
    const flag = field.dataset.flag;
    if (field.type === "checkbox") {
      const given = field.checked !== field.hasAttribute("data-default");
      if (given) words.push(field.checked ? flag : field.dataset.off);
      continue;
    }
    const value = field.value.trim();
    if (!value) continue;
    const parts = "split" in field.dataset ? value.split(/\s+/) : [value];
    if ("repeat" in field.dataset) {
      for (const p of parts) words.push(flag, p);
    } else {
      if (flag) words.push(flag);
      words.push(...parts);
    }
  }
  return words.map(quote).join(" ");
}

function chooseForm() {
  const wanted = $("sc-command").value;
  for (const f of document.querySelectorAll(".sc-form")) f.hidden = f.dataset.command !== wanted;
}

$("sc-command").addEventListener("change", chooseForm);
$("form-go").addEventListener("click", () => {
  const fieldset = document.querySelector(".sc-form:not([hidden])");
  if (fieldset) ask(formQuestion(fieldset));
});
$("ask").addEventListener("submit", (event) => {
  event.preventDefault();
  ask(box.value);
});
for (const a of document.querySelectorAll("a.sc-example")) {
  a.addEventListener("click", (event) => {
    event.preventDefault();
    ask(a.textContent);
  });
}
$("copy").addEventListener("click", async () => {
  try {
    await navigator.clipboard.writeText(location.href);
    $("copy").textContent = "Copied";
  } catch {
    $("copy").textContent = "Copy the address bar";
  }
});
window.addEventListener("hashchange", fromHash);

chooseForm();
startWorker();
fromHash();
