// The strun live monitor: talks only to the server that served it (the
// HTTP API of docs/live.md). Values arrive as Server-Sent Events (read
// through fetch, so that a token can go in the Authorization header); the
// state, tasks, forces and diagnostics are polled; DOM updates are batched
// into animation frames so that 10 000 variables stay responsive.
"use strict";
(() => {
  const $ = (id) => document.getElementById(id);
  let token = "";
  const hash = new URLSearchParams(location.hash.slice(1));
  if (hash.get("token")) token = hash.get("token");
  else if (sessionStorage.getItem("strun-token")) token = sessionStorage.getItem("strun-token");

  const rows = new Map();      // path -> {tr, value, type, scope}
  const values = new Map();    // path -> last value
  const pending = new Map();   // path -> value, applied at the next frame
  const trends = new Map();    // path -> {color, points: [[t_ns, number]]}
  const palette = ["#1f6feb", "#cf222e", "#1a7f37", "#8250df", "#bf8700", "#0a7c86", "#d1242f", "#57606a"];
  let forced = new Set();
  let lastTimeNs = 0;
  let ended = false;
  let tasks = [];

  function headers(json) {
    const h = {};
    if (token) h["Authorization"] = "Bearer " + token;
    if (json) h["Content-Type"] = "application/json";
    return h;
  }

  async function api(path, body) {
    const init = body === undefined ? { headers: headers(false) } : { method: "POST", headers: headers(true), body: JSON.stringify(body) };
    const res = await fetch(path, init);
    if (res.status === 401) {
      const given = prompt("This strun server needs its token (--serve-token):");
      if (given) { token = given; sessionStorage.setItem("strun-token", given); return api(path, body); }
    }
    const data = await res.json().catch(() => ({}));
    if (!res.ok) throw new Error(data.error || res.statusText);
    return data;
  }

  function say(text, error) {
    const m = $("message");
    m.textContent = text;
    m.className = "show" + (error ? " error" : "");
    clearTimeout(say.timer);
    say.timer = setTimeout(() => (m.className = ""), error ? 5000 : 1600);
  }

  // "T#1s500ms" -> ns (for the plots); the API's time strings are IEC literals.
  function parseTime(text) {
    const m = /^T#(-)?(.*)$/.exec(text || "");
    if (!m) return 0;
    const units = { d: 864e11, h: 36e11, m: 6e10, s: 1e9, ms: 1e6, us: 1e3, ns: 1 };
    let total = 0;
    for (const [, n, u] of m[2].matchAll(/([\d.]+)(ms|us|ns|d|h|m|s)/g)) total += parseFloat(n) * units[u];
    return m[1] ? -total : total;
  }

  function show(value) {
    if (typeof value === "string") return value;
    if (Array.isArray(value) || (value && typeof value === "object")) return JSON.stringify(value);
    if (value === true) return "TRUE";
    if (value === false) return "FALSE";
    return String(value);
  }

  // Splits a path at the dots outside brackets: "Main.a[1].b" -> ["Main", "a[1]", "b"].
  function parts(path) {
    const out = [];
    let depth = 0, cur = "";
    for (const c of path) {
      if (c === "[") depth++;
      if (c === "]") depth--;
      if (c === "." && depth === 0) { out.push(cur); cur = ""; } else cur += c;
    }
    out.push(cur);
    return out;
  }

  const esc = (s) => s.replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" }[c]));

  // ---------------------------------------------------------------- the tree
  // A virtual list: `items` is the whole tree (scopes and variables, in
  // order), `shown` what the filter and the folds leave, and only the rows
  // around the viewport exist in the page, so 10 000 variables cost the
  // browser no more layout than fifty.
  const ROW = 22;
  const items = [];        // {isScope: true, path, label, depth} or {path, label, depth, type, scope}
  let shown = [];
  const folded = new Set(); // scope paths folded
  const rendered = new Map(); // path -> {tr, value, edit, trend} for the rows in the page now
  let editing = null, editText = "";

  function buildTree(list) {
    let open = [];
    for (const v of list) {
      const p = parts(v.path);
      const scopes = p.length > 1 ? p.slice(0, -1) : ["Globals"];
      const scopePaths = scopes.map((_, i) => scopes.slice(0, i + 1).join("."));
      let same = 0;
      while (same < open.length && same < scopePaths.length && open[same] === scopePaths[same]) same++;
      for (let i = same; i < scopePaths.length; i++) items.push({ isScope: true, path: scopePaths[i], label: scopes[i], depth: i });
      open = scopePaths;
      const item = { path: v.path, label: p[p.length - 1], depth: scopePaths.length, type: v.type, scope: scopePaths[scopePaths.length - 1] };
      items.push(item);
      rows.set(v.path, item);
    }
    applyFilter();
  }

  function rowHtml(it) {
    if (it.isScope)
      return `<div class="scope${folded.has(it.path) ? " collapsed" : ""}" data-scope="${esc(it.path)}" style="padding-left:${6 + 14 * it.depth}px">${esc(it.label)}</div>`;
    const t = trends.get(it.path);
    return `<div class="row var${forced.has(it.path) ? " forced" : ""}" data-path="${esc(it.path)}">` +
      `<span class="name" style="padding-left:${6 + 14 * it.depth}px" title="${esc(it.path)}">${esc(it.label)}</span><span class="type">${esc(it.type)}</span>` +
      `<span class="value">${values.has(it.path) ? esc(show(values.get(it.path))) : ""}</span>` +
      `<span class="edit">${it.path === editing ? editorHtml(it.path) : '<button type="button" class="btn-edit" title="write or force">✎</button>'}</span>` +
      `<span class="trend">${t ? `<span style="color:${t.color}">●</span>` : ""}</span></div>`;
  }

  let firstShown = -1, lastShown = -1;
  function render(force) {
    const body = $("vars-body");
    body.style.height = shown.length * ROW + "px";
    const top = body.getBoundingClientRect().top;
    const first = Math.max(0, Math.floor(-top / ROW) - 20);
    const last = Math.min(shown.length, Math.ceil((innerHeight - top) / ROW) + 20);
    if (!force && first === firstShown && last === lastShown) return;
    firstShown = first; lastShown = last;
    const html = [];
    for (let i = first; i < last; i++) html.push(rowHtml(shown[i]).replace(/^<div /, `<div style="top:${i * ROW}px" `));
    body.innerHTML = html.join("");
    rendered.clear();
    for (const tr of body.querySelectorAll(".var"))
      rendered.set(tr.dataset.path, { tr, value: tr.querySelector(".value"), edit: tr.querySelector(".edit"), trend: tr.querySelector(".trend") });
    const input = body.querySelector(".edit-value");
    if (input) { input.value = editText; input.addEventListener("input", () => (editText = input.value)); }
  }
  let renderQueued = false;
  const queueRender = () => { if (!renderQueued) { renderQueued = true; requestAnimationFrame(() => { renderQueued = false; render(false); }); } };
  addEventListener("scroll", queueRender, { passive: true });
  addEventListener("resize", queueRender);

  $("vars-body").addEventListener("click", (e) => {
    const scopeRow = e.target.closest(".scope");
    if (scopeRow) { toggleScope(scopeRow.dataset.scope); return; }
    const tr = e.target.closest(".var");
    if (!tr) return;
    const path = tr.dataset.path;
    if (e.target.classList.contains("btn-edit")) openEditor(path);
    else if (e.target.classList.contains("btn-write")) send("/api/write", path, tr);
    else if (e.target.classList.contains("btn-force")) send("/api/force", path, tr);
    else if (e.target.classList.contains("btn-release")) release(path);
    else if (e.target.classList.contains("btn-trend")) toggleTrend(path);
  });
  $("vars-body").addEventListener("keydown", (e) => {
    if (e.key === "Enter" && e.target.classList.contains("edit-value")) send("/api/write", e.target.closest(".var").dataset.path, e.target.closest(".var"));
  });

  function toggleScope(scope) {
    if (folded.has(scope)) folded.delete(scope); else folded.add(scope);
    applyFilter();
  }

  function editorHtml(path) {
    return `<input class="edit-value" aria-label="value for ${esc(path)}">` +
      `<button type="button" class="btn-write" title="write once">W</button>` +
      `<button type="button" class="btn-force" title="force (hold)">F</button>` +
      `<button type="button" class="btn-release" title="release the force">U</button>` +
      `<button type="button" class="btn-trend" title="show in the trend plot">~</button>`;
  }

  function openEditor(path) {
    editing = path;
    editText = values.has(path) ? show(values.get(path)) : "";
    render(true);
    const input = $("vars-body").querySelector(".edit-value");
    if (input) input.focus();
  }

  async function send(path, name, tr) {
    const input = tr.querySelector(".edit-value");
    if (!input) return;
    try {
      await api(path, { name, value: input.value });
      say((path.endsWith("force") ? "forced " : "written ") + name + " := " + input.value);
      if (path.endsWith("force")) { forced.add(name); markForces(); }
    } catch (err) { say(err.message, true); }
  }

  async function release(name) {
    try { await api("/api/unforce", { name }); forced.delete(name); markForces(); say("released " + name); }
    catch (err) { say(err.message, true); }
  }

  // Marks the rows in the page; the others get their mark when they are drawn.
  function markForces() {
    for (const [path, r] of rendered) r.tr.classList.toggle("forced", forced.has(path));
  }

  // ---------------------------------------------------------------- filter
  function applyFilter() {
    const text = $("filter").value.trim().toLowerCase();
    let re = null;
    if (text.includes("*")) re = new RegExp("^" + text.split("*").map((s) => s.replace(/[.+?^${}()|[\]\\]/g, "\\$&")).join(".*") + "$");
    const matchingScopes = new Set();
    let count = 0;
    const match = new Set();
    for (const it of items) {
      if (it.isScope) continue;
      const p = it.path.toLowerCase();
      if (text && !(re ? re.test(p) : p.includes(text))) continue;
      match.add(it);
      count++;
      const sp = parts(it.scope);
      for (let i = 1; i <= sp.length; i++) matchingScopes.add(sp.slice(0, i).join("."));
    }
    const isFolded = (scopePath, self) => {
      const sp = parts(scopePath);
      for (let i = 1; i <= sp.length - (self ? 1 : 0); i++) if (folded.has(sp.slice(0, i).join("."))) return true;
      return false;
    };
    shown = items.filter((it) => (it.isScope ? matchingScopes.has(it.path) && !isFolded(it.path, true) : match.has(it) && !isFolded(it.scope, false)));
    $("var-count").textContent = (text ? count + " of " : "") + rows.size + " variables";
    render(true);
  }
  let filterTimer = 0;
  $("filter").addEventListener("input", () => { clearTimeout(filterTimer); filterTimer = setTimeout(applyFilter, 150); });

  // ---------------------------------------------------------------- values
  function queueValues(map, timeNs) {
    for (const path in map) {
      pending.set(path, map[path]);
      const t = trends.get(path);
      if (t) {
        const v = map[path];
        const n = v === true ? 1 : v === false ? 0 : typeof v === "number" ? v : parseFloat(v);
        if (!Number.isNaN(n)) { t.points.push([timeNs, n]); if (t.points.length > 4000) t.points.splice(0, 1000); }
      }
    }
    if (!queueValues.frame) queueValues.frame = requestAnimationFrame(flushValues);
  }
  function flushValues() {
    queueValues.frame = 0;
    for (const [path, value] of pending) {
      values.set(path, value);
      const row = rendered.get(path);
      if (row) row.value.textContent = show(value);
    }
    pending.clear();
  }

  async function streamEvents() {
    while (!ended) {
      try {
        // Large projects get fewer, larger events: parsing dominates then.
        const every = rows.size > 2000 ? "500ms" : "200ms";
        const res = await fetch("/api/events?every=" + every, { headers: headers(false) });
        if (!res.ok || !res.body) throw new Error("events: " + res.status);
        $("connection").textContent = "live";
        const reader = res.body.getReader();
        const decoder = new TextDecoder();
        let buffer = "";
        for (;;) {
          const { value, done } = await reader.read();
          if (done) break;
          buffer += decoder.decode(value, { stream: true });
          let cut;
          while ((cut = buffer.indexOf("\n\n")) >= 0) {
            const block = buffer.slice(0, cut);
            buffer = buffer.slice(cut + 2);
            let kind = "message", data = "";
            for (const line of block.split("\n")) {
              if (line.startsWith("event:")) kind = line.slice(6).trim();
              else if (line.startsWith("data:")) data += line.slice(5).trim();
            }
            if (!data) continue;
            const msg = JSON.parse(data);
            if (kind === "state") showState(msg);
            else { lastTimeNs = parseTime(msg.time); $("plc-time").textContent = msg.time; queueValues(msg.values, lastTimeNs); }
          }
        }
      } catch (err) { $("connection").textContent = "disconnected"; }
      if (!ended) await new Promise((r) => setTimeout(r, 1000));
    }
  }

  // ---------------------------------------------------------------- state
  function showState(s) {
    $("plc-state").textContent = s.state;
    $("plc-state").dataset.state = s.state;
    $("plc-paused").hidden = !s.paused;
  }

  function showFullState(s) {
    showState(s);
    $("plc-time").textContent = s.time;
    $("plc-cycle").textContent = s.cycle;
    lastTimeNs = Math.max(lastTimeNs, parseTime(s.time));
    forced = new Set(Object.keys(s.forces));
    markForces();
    const list = $("forces");
    list.innerHTML = Object.entries(s.forces).map(([k, v]) => `<li>${esc(k)} = ${esc(show(v))}<button type="button" data-name="${esc(k)}">release</button></li>`).join("") || "<li><i>none</i></li>";
    tasks = s.tasks;
    const sel = $("step-task");
    if (sel.options.length !== s.tasks.length) sel.innerHTML = s.tasks.map((t) => `<option>${esc(t.name)}</option>`).join("");
    $("tasks").tBodies[0].innerHTML = s.tasks.map((t) =>
      `<tr><td>${esc(t.name)}</td><td>${t.kind}</td><td>${t.priority}</td><td>${t.cycles}</td><td>${t.overruns}</td><td>${t.last_exec_us}</td><td>${t.avg_exec_us}</td><td>${t.max_exec_us}</td><td>${t.max_latency_us}</td></tr>`).join("");
    const diags = s.diagnostics.slice(-200);
    $("diag-count").textContent = s.diagnostics.length + (s.diagnostics_dropped ? " (+" + s.diagnostics_dropped + " dropped)" : "");
    $("diagnostics").innerHTML = diags.map((d) => `<li>${esc(d.time)} <b>${esc(d.code)}</b> ${esc(d.task)} ${esc(d.pou)}${d.line ? ":" + d.line : ""} — ${esc(d.message)}</li>`).join("");
    if (s.ended) { ended = true; $("connection").textContent = "the run has ended"; }
  }
  $("forces").addEventListener("click", (e) => { if (e.target.dataset.name) release(e.target.dataset.name); });

  async function pollState() {
    try { showFullState(await api("/api/state")); } catch (err) { $("connection").textContent = "disconnected"; }
    if (!ended) setTimeout(pollState, 500);
  }

  $("btn-pause").onclick = () => api("/api/pause", {}).then(() => say("pause requested"), (e) => say(e.message, true));
  $("btn-resume").onclick = () => api("/api/resume", {}).then(() => say("resumed"), (e) => say(e.message, true));
  $("btn-step").onclick = async () => {
    try {
      const s = await api("/api/step", { task: $("step-task").value || undefined, cycles: Math.max(1, parseInt($("step-cycles").value, 10) || 1) });
      showFullState(s);
      say("stepped");
    } catch (e) { say(e.message, true); }
  };
  $("btn-unforce-all").onclick = () => api("/api/unforce", { all: true }).then(() => { forced.clear(); markForces(); say("all forces released"); }, (e) => say(e.message, true));

  // ---------------------------------------------------------------- timeline
  let timelineNext = 0;
  const lanes = [];  // per task: [[start_ns, end_ns]]
  const open = [];   // per task: start of the current run, or null
  async function pollTimeline() {
    try {
      const t = await api("/api/timeline?since=" + timelineNext);
      timelineNext = t.next;
      for (const [, time, task, running] of t.events) {
        while (lanes.length <= task) { lanes.push([]); open.push(null); }
        if (running) open[task] = time;
        else if (open[task] !== null) { lanes[task].push([open[task], time]); open[task] = null; if (lanes[task].length > 6000) lanes[task].splice(0, 2000); }
      }
      drawTimeline(t.tasks, t.time_ns);
    } catch (err) { /* shown by the state poll */ }
    if (!ended) setTimeout(pollTimeline, 500);
  }

  function drawTimeline(names, now) {
    const c = $("timeline");
    const ctx = c.getContext("2d");
    const laneH = 22, left = 90;
    c.height = Math.max(40, names.length * laneH + 18);
    ctx.clearRect(0, 0, c.width, c.height);
    const span = 2e9 > now ? Math.max(now, 1e6) : 2e9;  // the last 2 s of PLC time
    const from = now - span;
    $("timeline-span").textContent = "(last " + (span >= 1e9 ? (span / 1e9).toFixed(1) + " s" : (span / 1e6).toFixed(1) + " ms") + " of PLC time)";
    const x = (t) => left + ((t - from) / span) * (c.width - left - 4);
    ctx.font = "11px system-ui";
    names.forEach((name, i) => {
      const y = i * laneH + 4;
      ctx.fillStyle = "#6b7685";
      ctx.fillText(name, 4, y + 13);
      ctx.fillStyle = palette[i % palette.length];
      const segs = (lanes[i] || []).concat(open[i] !== null && open[i] !== undefined ? [[open[i], now]] : []);
      for (const [a, b] of segs) {
        if (b < from) continue;
        const xa = Math.max(left, x(a)), xb = Math.max(xa + 1, x(b));
        ctx.fillRect(xa, y, xb - xa, laneH - 8);
      }
    });
  }

  // ---------------------------------------------------------------- trend
  function toggleTrend(path) {
    const row = rendered.get(path);
    if (trends.has(path)) { trends.delete(path); if (row) row.trend.textContent = ""; }
    else {
      const color = palette[trends.size % palette.length];
      const v = values.get(path);
      const n = v === true ? 1 : v === false ? 0 : typeof v === "number" ? v : parseFloat(v);
      trends.set(path, { color, points: Number.isNaN(n) ? [] : [[lastTimeNs, n]] });
      if (row) row.trend.innerHTML = `<span style="color:${color}">●</span>`;
    }
    $("trend-legend").innerHTML = [...trends].map(([p, t]) => `<span style="color:${t.color}">● ${esc(p)}</span>`).join("");
  }

  function drawTrend() {
    const c = $("trend");
    const ctx = c.getContext("2d");
    ctx.clearRect(0, 0, c.width, c.height);
    if (trends.size) {
      const span = 20e9, now = lastTimeNs, from = now - span;
      let lo = Infinity, hi = -Infinity;
      for (const t of trends.values()) for (const [, v] of t.points) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
      if (lo === hi) { lo -= 1; hi += 1; }
      const pad = 24;
      const x = (t) => pad + ((t - from) / span) * (c.width - pad - 4);
      const y = (v) => c.height - 14 - ((v - lo) / (hi - lo)) * (c.height - 24);
      ctx.fillStyle = "#6b7685";
      ctx.font = "10px system-ui";
      ctx.fillText(String(+hi.toPrecision(4)), 2, 10);
      ctx.fillText(String(+lo.toPrecision(4)), 2, c.height - 4);
      for (const t of trends.values()) {
        ctx.strokeStyle = t.color;
        ctx.beginPath();
        let prev = null;
        for (const [tn, v] of t.points) {
          const px = Math.max(pad, x(tn));
          if (prev === null) ctx.moveTo(px, y(v)); else { ctx.lineTo(px, y(prev)); ctx.lineTo(px, y(v)); }
          prev = v;
        }
        if (prev !== null) ctx.lineTo(x(now), y(prev));
        ctx.stroke();
      }
    }
    requestAnimationFrame(() => setTimeout(drawTrend, 250));
  }

  // ---------------------------------------------------------------- start
  (async () => {
    try {
      buildTree(await api("/api/variables"));
      const all = await api("/api/vars");
      lastTimeNs = parseTime(all.time);
      queueValues(all.values, lastTimeNs);
    } catch (err) { say(err.message, true); }
    pollState();
    pollTimeline();
    streamEvents();
    drawTrend();
  })();
})();
