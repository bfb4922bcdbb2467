// web/app.js: the page's logic: calls scalcal's WebAssembly core (scalcal_core.js, web/wasm/binding.cpp) with
// JSON, shows each result with the CLI command that reproduces it, draws the sphere and the residuals, and keeps
// every result and timing in window.scalcalPage for the browser test (web/test/browser_test.py).
'use strict';

const page = { results: {}, timings: {}, ready: false, log: null, calibrationFile: null, exportFile: null };
window.scalcalPage = page;
const $ = (id) => document.getElementById(id);
let core = null;

// One call into the core. The request goes through malloc, not ccall's stack copy: a 50,000-row log is
// several MB, more than the stack emscripten gives (5 MB).
function call(request) {
  const text = JSON.stringify(request);
  const size = core.lengthBytesUTF8(text) + 1;
  const input = core._malloc(size);
  core.stringToUTF8(text, input, size);
  const output = core._scalcal_call(input);
  core._free(input);
  const reply = JSON.parse(core.UTF8ToString(output));
  core._scalcal_free(output);
  if (!reply.ok) throw new Error(reply.error);
  return reply;
}

// C's %.Ng (6 digits: %g), as the CLI's text prints: 33123.9, 4.64e-05.
function g6(x, digits = 6) {
  if (x === null || x === undefined || !isFinite(x)) return String(x);
  if (x === 0) return '0';
  const e = Math.floor(Math.log10(Math.abs(Number(x.toPrecision(digits)))));
  let s = e < -4 || e >= digits ? x.toExponential(digits - 1) : x.toPrecision(digits);
  if (s.includes('e')) {
    let [m, p] = s.split('e');
    if (m.includes('.')) m = m.replace(/0+$/, '').replace(/\.$/, '');
    const n = Math.abs(Number(p));
    return m + 'e' + (p.startsWith('-') ? '-' : '+') + (n < 10 ? '0' : '') + n;
  }
  return s.includes('.') ? s.replace(/0+$/, '').replace(/\.$/, '') : s;
}

// The library's warnings, as the CLI prints them on stderr ("scalcal COMMAND: SUBJECT: warning: MESSAGE").
function showWarnings(command, warnings) {
  const list = $('warnings');
  list.replaceChildren();
  for (const w of warnings || []) {
    const li = document.createElement('li');
    li.textContent = `scalcal ${command}: ${w.subject ? w.subject + ': ' : ''}warning: ${w.message}`;
    list.appendChild(li);
  }
}

// Long work runs after the status line is painted, so a screen reader and the eye both hear "working".
function run(what, work) {
  $('error').textContent = '';
  $('status').textContent = what + '…';
  return new Promise((resolve) => setTimeout(() => {
    try {
      work();
      $('status').textContent = what + ': done.';
    } catch (e) {
      $('error').textContent = what + ' failed: ' + e.message;
      $('status').textContent = what + ' failed.';
    }
    resolve();
  }, 30));
}

function download(name, text) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type: 'text/plain' }));
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

function row(cells, header) {
  const tr = document.createElement('tr');
  cells.forEach((c, i) => {
    const td = document.createElement(i === 0 && header ? 'th' : 'td');
    if (i === 0 && header) td.scope = 'row';
    td.textContent = c;
    tr.appendChild(td);
  });
  return tr;
}

// ---- 1. Design -----------------------------------------------------------------------------------------
function showProgram(evaluation, cli) {
  page.results.evaluate = evaluation;
  $('design-cli').textContent = cli;
  const rows = $('criteria-rows');
  rows.replaceChildren();
  for (const c of ['D', 'A', 'E', 'S']) {
    const limit = evaluation.limits[c];
    rows.appendChild(row([c, g6(evaluation[c]), limit ? g6(limit.value) + ' (' + limit.exact + ')' : '—',
                          limit ? g6(evaluation.efficiency[c]) : '—'], true));
  }
  $('criteria-note').textContent = evaluation.region === 'sphere' ? '' :
    `The program lies on ${evaluation.region}: the limits there need Ipopt, so the page gives no efficiency; ` +
    '`scalcal evaluate design.csv` gives it.';
  const positions = $('position-rows');
  positions.replaceChildren();
  evaluation.csv.split('\n').filter((l) => /^[-0-9]/.test(l)).forEach((l, i) =>
    positions.appendChild(row([String(i + 1), ...l.split(',').map((v) => g6(Number(v)))], true)));
  drawSphere(designView, evaluation.program);
  $('design-out').hidden = false;
  $('plan-part').hidden = false;
  $('plan-out').hidden = true;  // a plan of the program before is gone with it
  page.results.plan = null;
}

function design() {
  const regions = $('region').value.trim().split(/\s+/).filter((x) => x);
  const q = { positions: Number($('positions').value), count: Number($('count').value),
              seed: Number($('seed').value), criterion: $('criterion').value, regions };
  const t0 = performance.now();
  const best = call({ op: 'random', ...q });
  const evaluation = call({ op: 'evaluate', csv: best.csv, name: 'design.csv' });
  page.timings.design = (performance.now() - t0) / 1000;
  page.results.random = best;
  page.design = best.csv;
  page.planSource = { name: 'design.csv', request: { csv: best.csv, name: 'design.csv' } };
  const region = regions.map((r) => ` --region ${r}`).join('');
  showProgram(evaluation, `scalcal random --positions ${q.positions} --count ${q.count} --seed ${q.seed} ` +
              `--criterion ${q.criterion}${region} --out design.csv\nscalcal evaluate design.csv` +
              (regions.length ? '' : ' --region sphere'));
}

function evaluateNamed() {
  const name = $('program').value;
  const evaluation = call({ op: 'evaluate', program: name });
  page.design = evaluation.csv;
  page.planSource = { name, request: { program: name } };
  showProgram(evaluation, `scalcal evaluate ${name} --region sphere`);
}

// A sphere turned by yaw and pitch, drawn orthographically: enough to see where the positions are. One view
// for the design, one for the log's poses.
const designView = { canvas: 'sphere', what: 'positions of the program', points: [], yaw: 0.6, pitch: 0.4 };
const posesView = { canvas: 'poses', what: "poses found in the log", points: [], yaw: 0.6, pitch: 0.4 };
function drawSphere(view, points) {
  if (points) view.points = points;
  const cv = $(view.canvas), ctx = cv.getContext('2d'), r = cv.width * 0.42, cx = cv.width / 2, cy = cv.height / 2;
  ctx.clearRect(0, 0, cv.width, cv.height);
  ctx.strokeStyle = '#666';
  ctx.beginPath(); ctx.arc(cx, cy, r, 0, 2 * Math.PI); ctx.stroke();
  const [c1, s1, c2, s2] = [Math.cos(view.yaw), Math.sin(view.yaw), Math.cos(view.pitch), Math.sin(view.pitch)];
  const project = (p) => { const x = c1 * p[0] - s1 * p[1], y = s1 * p[0] + c1 * p[1];
                           return [x, c2 * p[2] - s2 * y, s2 * p[2] + c2 * y]; };
  for (const p of view.points) {
    const [u, v, depth] = project(p);
    ctx.beginPath(); ctx.arc(cx + r * u, cy - r * v, 5, 0, 2 * Math.PI);
    ctx.fillStyle = '#0057b8'; ctx.strokeStyle = '#0057b8';
    depth >= 0 ? ctx.fill() : ctx.stroke();
  }
  if (view.next) {  // the Guide's next pose: a red ring, dashed when behind
    const [u, v, depth] = project(view.next);
    ctx.strokeStyle = '#c00000'; ctx.lineWidth = 3; ctx.setLineDash(depth >= 0 ? [] : [4, 3]);
    ctx.beginPath(); ctx.arc(cx + r * u, cy - r * v, 10, 0, 2 * Math.PI); ctx.stroke();
    ctx.lineWidth = 1; ctx.setLineDash([]);
  }
  cv.setAttribute('aria-label', `${view.points.length} ${view.what} on the sphere, turned ` +
                  `${Math.round(view.yaw * 57.3)} degrees about z and ${Math.round(view.pitch * 57.3)} about x; ` +
                  'arrow keys turn it' + (view.next ? '; the ring is the next pose' : ''));
}
function turnable(view) {
  const cv = $(view.canvas);
  cv.addEventListener('keydown', (e) => {
    const step = { ArrowLeft: [-0.15, 0], ArrowRight: [0.15, 0], ArrowUp: [0, -0.15], ArrowDown: [0, 0.15] }[e.key];
    if (!step) return;
    e.preventDefault();
    view.yaw += step[0]; view.pitch += step[1];
    drawSphere(view);
  });
  let drag = null;
  cv.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; cv.setPointerCapture(e.pointerId); });
  cv.addEventListener('pointermove', (e) => {
    if (!drag) return;
    view.yaw += (e.clientX - drag[0]) / 100; view.pitch += (e.clientY - drag[1]) / 100;
    drag = [e.clientX, e.clientY]; drawSphere(view);
  });
  cv.addEventListener('pointerup', () => { drag = null; });
}

// ---- 1b. Plan on a bench: `scalcal plan`, its sheet as the CLI's text prints it -----------------------------
// C's %.*f as the CLI's sheet prints: toFixed, but an exact half goes to the even digit as glibc rounds it.
function fixed(x, places) {
  if (x === null || x === undefined) return '—';  // an angle that does not matter (NaN in the CLI's JSON)
  const v = x === 0 ? 0 : x, s = v.toFixed(places);
  const exact = Math.abs(v).toFixed(Math.min(100, places + 40)), point = exact.indexOf('.');
  if (!/^50*$/.test(exact.slice(point + places + 1))) return s;
  const kept = exact.slice(0, places ? point + places + 1 : point);
  return Number(kept.slice(-1)) % 2 ? s : (v < 0 ? '-' : '') + kept;
}
// The decimals that show a resolution (0.1: one, 0.05: two), four for exact angles (experiments/cli/cmd_plan.cpp).
const resolutionDecimals = (r) => r <= 0 ? 4 : Math.min(6, Math.max(0, Math.ceil(-Math.log10(r) - 1e-9)));
// A share of efficiency; below 1e-12 it is the criteria's rounding and says so.
const percent = (share) => share === null ? 'nan %' : Math.abs(share) < 1e-12 ? '< 1e-10 %' : g6(100 * share, 3) + ' %';

function showPlan(reply, cli) {
  const r = reply.result, b = reply.bench, several = b.mountings.length > 1;
  page.results.plan = reply;
  $('plan-cli').textContent = cli;
  const places = resolutionDecimals(r.resolution_deg);
  $('plan-caption').textContent = `plan of ${r.program} on the bench ${r.bench} (order ${r.order}, resolution ` +
    (r.resolution_deg > 0 ? fixed(r.resolution_deg, places) + ' deg' : 'exact') +
    (r.region ? `, region ${r.region}` : '') + ')';
  const given = r.given_order, less = given.total_travel_deg > 0 && r.total_travel_deg < given.total_travel_deg;
  $('plan-totals').textContent = `${r.steps.length} steps, ${r.remounts} ${r.remounts === 1 ? 'remount' : 'remounts'}, ` +
    `the axes travel ${fixed(r.total_travel_deg, 1)} deg (the program's own order: ${given.remounts} remounts, ` +
    `${fixed(given.total_travel_deg, 1)} deg` +
    (less ? `; ${percent(1 - r.total_travel_deg / given.total_travel_deg)} less travel` : '') + ')';
  $('plan-lost').textContent = `as run (each position within ${fixed(r.max_rounding_deg, 4)} deg of the design):` +
    ['D', 'A', 'E', 'S'].map((c) => ` ${c} ${g6(r.criteria[c], 8)} (efficiency lost ${percent(r.efficiency_lost[c])})`)
      .join(',');
  const head = $('plan-head');
  head.replaceChildren();
  for (const name of ['step', 'position', ...(several ? [b.mounting_key] : []), ...b.axes, 'x', 'y', 'z',
                      'rounding (deg)']) {
    const th = document.createElement('th');
    th.scope = 'col';
    th.textContent = name;
    head.appendChild(th);
  }
  const rows = $('plan-rows'), label = (v) => (b.mountings.find((m) => m.value === v) || { label: v }).label;
  rows.replaceChildren();
  r.steps.forEach((s, k) => {
    const angles = s.angles_deg || b.axes.map((a) => s[a]);
    const tr = rows.appendChild(row([String(s.step), String(s.position), ...(several ? [label(s[b.mounting_key])] : []),
                                     ...angles.map((a) => fixed(a, places)), ...s.eta.map((e) => fixed(e, 4)),
                                     fixed(s.rounding_deg, 4)], true));
    if (several && k > 0 && s[b.mounting_key] !== r.steps[k - 1][b.mounting_key]) tr.className = 'remount';
  });
  $('plan-out').hidden = false;
}

function plan() {
  if (!page.planSource) throw new Error('design or evaluate a program first');
  const bench = $('bench').value.trim(), resolution = $('resolution').value.trim();
  const args = [['--bench', bench]].concat(resolution ? [['--resolution', resolution]] : []);
  $('plan-out').hidden = true;  // a refused plan leaves no sheet of another bench behind
  const reply = call({ op: 'plan', ...page.planSource.request, args });
  showWarnings('plan', reply.warnings);
  page.planFile = reply.csv;
  showPlan(reply, `scalcal plan ${page.planSource.name} --bench ${bench}` +
                  `${resolution ? ' --resolution ' + resolution : ''} --out plan.csv`);
}

// The sheet alone on paper (index.html's print stylesheet), for as long as the print dialog is open.
function printPlan() {
  document.body.classList.add('print-plan');
  window.print();
}

// ---- 2. Guide: the log ------------------------------------------------------------------------------------
function useLog(name, text) {
  page.log = { name, text };
  const rows = text.split('\n').filter((l) => l.trim() && !l.startsWith('#')).length;
  $('log-info').textContent = `${name}: ${rows} lines read. Calibrate it below.`;
}
function readFile(file) {
  const reader = new FileReader();
  reader.onload = () => useLog(file.name, reader.result);
  reader.readAsText(file);
}

// ---- 2b. Guide: embedded/'s streaming detector, fit and guidance (web/wasm/guide.c) ----------------------
const guideView = { canvas: 'guide-sphere', what: 'poses found so far', points: [], next: null, yaw: 0.6, pitch: 0.4 };
const guide = { running: false, stop: false };
const streamStates = ['no noise floor yet', 'moving', 'still: a pose is being summed'];
// Rows "t ix iy iz" (spaces, commas or semicolons); a header or a short line is skipped.
function samplesOf(text) {
  const t = [], x = [];
  for (const line of text.split('\n')) {
    if (!line.trim() || line.startsWith('#')) continue;
    const f = line.trim().split(/[\s,;]+/).map(Number);
    if (f.length < 4 || isNaN(f[0])) continue;
    t.push(f[0]); x.push(f[1], f[2], f[3]);
  }
  return { t, x };
}
function guideStart(t) {
  const m = $('guide-magnitude').value.trim(), given = Number($('guide-rate').value);
  const magnitude = m === 'auto' ? 0 : Number(m);
  if (!(magnitude > 0) && m !== 'auto') throw new Error(`|I| must be a positive number or auto, not "${m}"`);
  // The log's mean rate, as embedded/tests/host_run.c takes it.
  const rate = given > 0 ? given : 1 / ((t[t.length - 1] - t[0]) / (t.length - 1));
  if (!(rate > 0) || !isFinite(rate)) throw new Error('no sample rate: give one, or at least two rows with times');
  if (core._scalcal_guide_start(rate, magnitude) !== 0) throw new Error('the detector refused the rate ' + rate);
  guide.rate = rate;
  return rate;
}
function guidePush(x, from, to) {  // samples from..to-1 of the interleaved array x
  const n = to - from;
  if (n <= 0) return;
  const p = core._malloc(24 * n);
  core.HEAPF64.set(x.slice(3 * from, 3 * to), p >> 3);
  core._scalcal_guide_push(p, n);
  core._free(p);
}
const fixedFields = 16;
function guideShow() {
  const criterion = Number($('guide-criterion').value), p = core._scalcal_guide_report(criterion) >> 3;
  const h = core.HEAPF64, n = h[p];
  const r = { poses: n, state: h[p + 1], samples: h[p + 2], fit_status: h[p + 3], model: h[p + 4],
              efficiency: Array.from(h.subarray(p + 5, p + 9)), next: h[p + 9],
              next_direction: Array.from(h.subarray(p + 10, p + 13)), after: h[p + 13], floor: h[p + 14],
              directions: [] };
  for (let i = 0; i < n; ++i) r.directions.push(Array.from(h.subarray(p + fixedFields + 3 * i, p + fixedFields + 3 * i + 3)));
  guideView.next = r.next >= 0 ? r.next_direction : null;
  drawSphere(guideView, r.directions);
  const name = 'DAES'[criterion], fitted = r.fit_status === 0;
  $('guide-state').textContent = `${r.samples} samples, ${n} poses; the stream: ${streamStates[r.state]}; ` +
    (fitted ? `fitted (model with ${r.model} parameters).` : 'not fitted yet: directions through a rough offset.');
  $('guide-efficiency').textContent = isFinite(r.efficiency[criterion])
    ? `Efficiency against the sphere's proven limit: ${name} ${g6(r.efficiency[criterion], 3)} ` +
      `(D ${g6(r.efficiency[0], 3)}, A ${g6(r.efficiency[1], 3)}, E ${g6(r.efficiency[2], 3)}, S ${g6(r.efficiency[3], 3)}; 1 is the limit).`
    : 'Efficiency: not yet (the poses cannot identify the model).';
  const next = r.next >= 0 ? `Turn to (${r.next_direction.map((v) => g6(v, 3)).join(', ')}) next.` : 'No next pose yet.';
  if ($('guide-next').textContent !== next) $('guide-next').textContent = next;  // read out only when it changes
  page.results.guide = r;
  return r;
}
// The chosen log, fed in chunks of `speed` seconds of samples, one chunk per animation frame.
function guideLog() {
  if (!page.log) throw new Error('no log: choose, drop or paste one first');
  if (guide.running) throw new Error('the Guide is running: stop it first');
  const { t, x } = samplesOf(page.log.text);
  const rate = guideStart(t), chunk = Math.max(1, Math.round(rate * Number($('guide-speed').value)));
  const start = performance.now();
  let at = 0;
  guide.running = true; guide.stop = false; page.results.guide = null; page.guideDone = false;
  page.guideFrames = [];  // [samples pushed, poses shown] after each frame, for the browser test
  const step = () => {
    const to = Math.min(t.length, at + chunk);
    guidePush(x, at, to);
    at = to;
    if (at >= t.length || guide.stop) core._scalcal_guide_finish();
    const r = guideShow();
    page.guideFrames.push([r.samples, r.poses]);
    if (at < t.length && !guide.stop) return requestAnimationFrame(step);
    guide.running = false;
    page.timings.guide = (performance.now() - start) / 1000;
    page.guideDone = true;
    $('status').textContent = `Guide: ${guide.stop ? 'stopped' : 'done'}.`;
  };
  $('status').textContent = 'Guide: reading the log…';
  requestAnimationFrame(step);
}
// A board on a serial port (Chromium's Web Serial: only where navigator.serial exists; not tested in CI).
async function guideSerial() {
  const port = await navigator.serial.requestPort();
  await port.open({ baudRate: 115200 });
  const reader = port.readable.pipeThrough(new TextDecoderStream()).getReader();
  let rest = '', head = null, shown = 0;
  guide.running = true; guide.stop = false;
  $('status').textContent = 'Guide: reading the board…';
  try {
    while (!guide.stop) {
      const { value, done } = await reader.read();
      if (done) break;
      const lines = (rest + value).split('\n');
      rest = lines.pop();
      const { t, x } = samplesOf(lines.join('\n'));
      if (!head) { head = { t: [], x: [] }; }
      if (head.t !== null) {  // the first 100 rows give the rate when none is given
        head.t.push(...t); head.x.push(...x);
        if (head.t.length < 100) continue;
        guideStart(head.t);
        guidePush(head.x, 0, head.t.length);
        head.t = null;
      } else guidePush(x, 0, t.length);
      if (performance.now() - shown > 250) { guideShow(); shown = performance.now(); }
    }
  } finally {
    reader.cancel().catch(() => {});
    await port.close().catch(() => {});
    if (head && head.t === null) { core._scalcal_guide_finish(); guideShow(); }
    guide.running = false;
    $('status').textContent = 'Guide: the board is disconnected.';
  }
}

// ---- 3. Calibrate -----------------------------------------------------------------------------------------
const stdKeys = { bias: 'bias_std', scale: 'scale_deviation_std', nonorth: 'nonorthogonality_std' };
function calibrate() {
  if (!page.log) throw new Error('no log: choose, drop or paste one first');
  const magnitude = $('magnitude').value.trim(), rate = $('rate').value.trim();
  const args = [['--magnitude', magnitude]].concat(rate ? [['--rate', rate]] : [], [['--suggest', '0']]);
  const t0 = performance.now();
  const reply = call({ op: 'calibrate', name: page.log.name, log: page.log.text, args });
  page.timings.calibrate = (performance.now() - t0) / 1000;
  const r = reply.result;
  page.results.calibrate = r;
  showWarnings('calibrate', reply.warnings);
  page.calibrationFile = reply.calibration_file;
  $('cal-cli').textContent = `scalcal calibrate --measurements ${page.log.name} --magnitude ${magnitude} ` +
                             `${rate ? '--rate ' + rate + ' ' : ''}--suggest 0 --out cal.json`;
  $('cal-summary').textContent = `model ${r.model}: ${r.positions} positions, ${r.samples} samples, ` +
    `${r.dof} degrees of freedom, ${r.iterations} iterations, converged ${r.converged ? 'yes' : 'no'}; ` +
    `residual rms ${g6(r.residual_rms)}, noise ${g6(r.noise)}`;
  const rows = $('param-rows');
  rows.replaceChildren();
  for (const [name, value] of Object.entries(r.parameters)) {
    const [group, axis] = name.split('_');
    const stds = r[stdKeys[group]];
    const i = { x: 0, y: 1, z: 2, xy: 0, yz: 1, zx: 2 }[axis];
    // Standard errors to 3 digits, as the CLI's text gives them.
    rows.appendChild(row([name, g6(value), stds && stds[i] !== null && i !== undefined ? g6(stds[i], 3) : '—'], true));
  }
  const p = r.program;
  $('program-quality').textContent = `The poses as a program: N = ${p.positions}, D ${g6(p.D)}, A ${g6(p.A)}, ` +
    `E ${g6(p.E)}, S ${g6(p.S)}; efficiency on the ${p.region}: ` +
    ['D', 'A', 'E', 'S'].map((c) => `${c} ${g6(p.efficiency[c])}`).join(' ');
  // A tumbling log (a magnetometer turned by hand) has no still poses: every sample is fitted.
  const poses = r.intervals.length > 0;
  $('poses').hidden = $('residuals').hidden = !poses;
  if (poses) {
    drawSphere(posesView, r.intervals.map((i) => i.direction));
    drawResiduals(r.intervals);
  }
  $('tumbling').textContent = r.tumbling ? `A log turned continuously: every sample fitted (${r.tumbling.samples_used} ` +
    `used); the directions cover ${g6(100 * r.tumbling.covered_share, 3)} % of the sphere, the largest gap ` +
    `${g6(r.tumbling.largest_gap_deg, 3)} degrees wide.` : '';
  $('cal-out').hidden = false;
  $('export').disabled = false;
}

function drawResiduals(intervals) {
  const cv = $('residuals'), ctx = cv.getContext('2d'), w = cv.width, h = cv.height;
  ctx.clearRect(0, 0, w, h);
  const big = Math.max(...intervals.map((i) => Math.abs(i.standardised_residual)), 3);
  ctx.strokeStyle = '#999'; ctx.beginPath(); ctx.moveTo(0, h / 2); ctx.lineTo(w, h / 2); ctx.stroke();
  ctx.fillStyle = '#b8002e';
  intervals.forEach((iv, k) => {
    const x = 10 + (w - 20) * (k + 0.5) / intervals.length, y = h / 2 - (h / 2 - 8) * iv.standardised_residual / big;
    ctx.fillRect(x - 3, Math.min(y, h / 2), 6, Math.abs(y - h / 2) || 1);
  });
  cv.setAttribute('aria-label', `standardised residual of each of ${intervals.length} poses, largest ` +
                  g6(Math.max(...intervals.map((i) => Math.abs(i.standardised_residual)))));
}

// ---- 4. Export ------------------------------------------------------------------------------------------
function exportCalibration() {
  if (!page.calibrationFile) throw new Error('calibrate first');
  const format = $('format').value, scale = $('raw-scale').value.trim();
  const force = $('force').checked;
  const args = [['--format', format]].concat(scale ? [['--raw-scale', scale]] : [], force ? [['--force']] : []);
  const reply = call({ op: 'export', name: 'cal.json', calibration: page.calibrationFile, args });
  page.results.export = reply;
  showWarnings('export', reply.warnings);
  page.exportFile = { name: `cal.${format === 'c' ? 'h' : format === 'json' ? 'export.json' : format + '.txt'}`,
                      text: reply.text };
  $('export-cli').textContent = `scalcal export cal.json --format ${format}${scale ? ' --raw-scale ' + scale : ''}${force ? ' --force' : ''}`;
  $('export-text').textContent = reply.text;
  $('export-out').hidden = false;
}

// ---- wiring ----------------------------------------------------------------------------------------------
function wire() {
  $('design-form').addEventListener('submit', (e) => { e.preventDefault(); run('Design', design); });
  $('catalogue-form').addEventListener('submit', (e) => { e.preventDefault(); run('Evaluation', evaluateNamed); });
  $('cal-form').addEventListener('submit', (e) => { e.preventDefault(); run('Calibration', calibrate); });
  $('export-form').addEventListener('submit', (e) => { e.preventDefault(); run('Export', exportCalibration); });
  $('download-design').addEventListener('click', () => download('design.csv', page.design));
  $('plan-form').addEventListener('submit', (e) => { e.preventDefault(); run('Plan', plan); });
  $('print-plan').addEventListener('click', printPlan);
  window.addEventListener('afterprint', () => document.body.classList.remove('print-plan'));
  $('download-plan').addEventListener('click', () => download('plan.csv', page.planFile));
  $('download-cal').addEventListener('click', () => download('cal.json', page.calibrationFile));
  $('download-export').addEventListener('click', () => download(page.exportFile.name, page.exportFile.text));
  $('log-file').addEventListener('change', (e) => e.target.files[0] && readFile(e.target.files[0]));
  $('use-pasted').addEventListener('click', () => useLog('pasted.txt', $('log-text').value));
  const drop = $('drop');
  drop.addEventListener('dragover', (e) => e.preventDefault());
  drop.addEventListener('drop', (e) => { e.preventDefault(); if (e.dataTransfer.files[0]) readFile(e.dataTransfer.files[0]); });
  $('guide-form').addEventListener('submit', (e) => { e.preventDefault(); run('Guide start', guideLog); });
  $('guide-stop').addEventListener('click', () => { guide.stop = true; });
  if ('serial' in navigator) {
    $('guide-connect').hidden = false;
    $('guide-connect').addEventListener('click', () => guideSerial().catch((e) => { $('error').textContent = String(e); }));
  }
  turnable(guideView);
  turnable(designView);
  turnable(posesView);
}

function fill(select, items) {
  for (const it of items) {
    const o = document.createElement('option');
    o.value = it.name; o.textContent = it.label;
    select.appendChild(o);
  }
}

wire();
const loadStart = performance.now();
ScalcalCore().then((m) => {
  core = m;
  const about = call({ op: 'about' });
  fill($('program'), about.programs.map((p) => ({ name: p.name, label: `${p.name} (N = ${p.positions})` })));
  fill($('format'), about.formats.map((f) => ({ name: f.name, label: `${f.name}: ${f.what}` })));
  page.formats = about.formats.map((f) => f.name);
  $('bench-syntaxes').textContent = about.benches;
  page.timings.load = (performance.now() - loadStart) / 1000;
  page.ready = true;
  $('status').textContent = 'Ready.';
}, (e) => { $('error').textContent = 'The numeric core did not load: ' + e; });
