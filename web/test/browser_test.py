#!/usr/bin/python3
# web/test/browser_test.py: drives the built page in Debian's headless chromium (selenium + chromedriver) through
# design, a real log, calibration and every export format, and compares every number with the CLI's for the same
# inputs and seed. Exit 1 on any difference; the last line is check.sh's summary.
#
# usage: browser_test.py PAGE_DIR SCALCAL_CLI LOG MAGNITUDE WORK_DIR HOST_RUN
# (HOST_RUN: embedded/tests/host_run.c built in double with gcc, the Guide's reference; check.sh builds it.)
import gzip
import json
import os
import subprocess
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

from compare import Comparison

PAGE, CLI, LOG, MAGNITUDE, WORK, HOST_RUN = sys.argv[1:7]
DESIGN = {"positions": "18", "criterion": "D", "count": "20000", "seed": "7"}
# The bench: a tilt table of 40 degrees on which the meter may be turned over (docs/bench.md).
CAP40 = ["cap:40", "cap:40:0,0,-1"]
# Why a JSON number may differ in its last digits: the wasm core has no x86 SIMD and musl's libm, so sums
# run in another order (seen: 2.6e-10 relative at most, on a p-value of 1e-110; 2e-11 on residuals that are
# differences of nearly equal moduli). Every number must agree to 9 significant digits, the most the CLI's
# text prints for any of them; how many agree exactly is reported.
RELATIVE = 1e-9


def cli(*args, check=True):
    """The CLI's stdout (its --json parsed when asked), with SOURCE_DATE_EPOCH so its files carry no clock."""
    env = dict(os.environ, SOURCE_DATE_EPOCH="0")
    p = subprocess.run([CLI, *args], capture_output=True, text=True, env=env, cwd=WORK)
    if check and p.returncode != 0:
        sys.exit(f"browser test: scalcal {' '.join(args)} failed ({p.returncode}): {p.stderr}")
    return p


def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1200,2400"):
        options.add_argument(a)
    options.add_experimental_option("prefs", {"download.default_directory": WORK, "download.prompt_for_download": False})
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def wait_status(d, word, timeout=120, allow_error=False):
    """Waits for the status line to say `word: done.` (or failed) and, unless allowed, fails on the page's error."""
    WebDriverWait(d, timeout).until(lambda d: d.find_element(By.ID, "status").text in (word + ": done.", word + " failed."))
    err = d.find_element(By.ID, "error").text
    if err and not allow_error:
        sys.exit(f"browser test: the page says: {err}")


def downloaded(name, timeout=20):
    path = os.path.join(WORK, name)
    end = time.time() + timeout
    while time.time() < end:
        if os.path.exists(path) and not os.path.exists(path + ".crdownload"):
            with open(path) as f:
                return f.read()
        time.sleep(0.1)
    sys.exit(f"browser test: {name} was not downloaded")


def csv_numbers(text):
    return [[float(v) for v in line.split(",")] for line in text.splitlines() if line[:1].isdigit() or line[:1] == "-"]


def csv_header(text):
    return "\n".join(line for line in text.splitlines() if not (line[:1].isdigit() or line[:1] == "-"))


def design(d, cmp, regions):
    """A seeded random design on the sphere or a region, against `scalcal random` and `scalcal evaluate`; on a
    region the efficiency is left out (its limits need Ipopt), the rest compared."""
    for k, v in {**DESIGN, "region": " ".join(regions)}.items():
        if k == "criterion":
            Select(d.find_element(By.ID, k)).select_by_value(v)
        else:
            e = d.find_element(By.ID, k)
            e.clear()
            e.send_keys(v)
    d.find_element(By.ID, "design").click()
    wait_status(d, "Design")
    page = d.execute_script("return window.scalcalPage")
    args = [f"--{k}={v}" for k, v in DESIGN.items()] + [f"--region={r}" for r in regions]
    ref = json.loads(cli("random", *args, "--json", "--out", "cli_design.csv").stdout)
    cmp.json("random", ref, page["results"]["random"], skip={"/seconds"}, strings=True)
    for n in ("design.csv",):
        if os.path.exists(os.path.join(WORK, n)):
            os.remove(os.path.join(WORK, n))
    d.find_element(By.ID, "download-design").click()
    mine = downloaded("design.csv")
    with open(os.path.join(WORK, "cli_design.csv")) as f:
        theirs = f.read()
    # The files: the same lines of text apart from the numbers (the region line too), the numbers as above.
    cmp.json("design.csv", csv_numbers(theirs), csv_numbers(mine))
    cmp.same_text("design.csv's header", csv_header(theirs), csv_header(mine))
    # The page's design file, evaluated by the CLI: the same program, the same criteria (and efficiencies).
    ref = json.loads(cli("evaluate", "design.csv", *([] if regions else ["--region", "sphere"]), "--json").stdout)
    left_out = {f"/{k}/{c}" for k in ("efficiency", "limits") for c in "DAES"} if regions else set()
    limit_keys = ("value", "lower_bound", "status", "exact", "theorem", "certified_by", "margin")
    left_out |= {f"/limits/{c}/{k}" for c in "DAES" for k in limit_keys} if regions else set()
    cmp.json("evaluate design.csv", ref, page["results"]["evaluate"], skip=left_out, strings=True)
    if not regions:
        cmp.shown(d, "criteria-rows", [[c, ref[c], ref["limits"][c]["value"], ref["efficiency"][c]] for c in "DAES"])
    d.save_screenshot(os.path.join(WORK, "design_cap40.png" if regions else "design.png"))
    return page["timings"]["design"]


def sheet(text, axes):
    """The CLI's text of a plan, split as the page shows it: the caption (its first line), the totals (the second),
    the as-run line, and each step's cells (step, position, the mounting's label when the bench has several, the
    angles, x, y, z as printed); the label comes from the mounting's own column or the last "(re)mount" heading."""
    lines = text.splitlines()
    rows, heading = [], None
    for line in lines[2:]:
        if line.startswith(("mount the meter: ", "remount the meter: ")):
            heading = line.split(": ", 1)[1]
        f = line.split("(")
        if len(f) == 2 and line.startswith("  ") and line.split()[0].isdigit():
            words = f[0].split()
            label = " ".join(words[2:len(words) - axes]) or heading
            rows.append([words[0], words[1], label, *words[len(words) - axes:], *f[1].rstrip(")").split(", ")])
    return lines[0], lines[1], next(x for x in lines if x.startswith("as run (")), rows


def plan(d, cmp, source, bench, resolution, keyboard=False):
    """The plan part after a design: the bench and resolution typed, Plan pressed (or Enter in the resolution
    field), against `scalcal plan` run as the page's CLI line says, on the page's own design file: the JSON
    (--json), the plan file (--out plan.csv), the warnings, the sheet (caption, totals, every cell of the table
    against the CLI's text), and the print stylesheet (only the table on paper). Returns how many numbers, of them
    equal to the last bit, and strings, texts and cells it compared."""
    before = (cmp.numbers, cmp.exact, cmp.texts)
    for field, value in (("bench", bench), ("resolution", resolution)):
        e = d.find_element(By.ID, field)
        e.clear()
        e.send_keys(value)
    if keyboard:
        d.find_element(By.ID, "resolution").send_keys(Keys.ENTER)
    else:
        d.find_element(By.ID, "plan").click()
    wait_status(d, "Plan")
    page = d.execute_script("return window.scalcalPage.results.plan")
    line = d.find_element(By.ID, "plan-cli").text
    want = f"scalcal plan {source} --bench {bench}{' --resolution ' + resolution if resolution else ''} --out plan.csv"
    cmp.same_text("plan's CLI line", want, line)
    if os.path.exists(os.path.join(WORK, "plan.csv")):
        os.remove(os.path.join(WORK, "plan.csv"))
    d.find_element(By.ID, "download-plan").click()
    mine = downloaded("plan.csv")
    os.replace(os.path.join(WORK, "plan.csv"), os.path.join(WORK, "page_plan.csv"))
    run = cli(*line.split()[1:], "--json")  # the page's line as it is, with --json: writes plan.csv
    ref = json.loads(run.stdout)
    what = f"plan {source} --bench {bench}" + (f" --resolution {resolution}" if resolution else "")
    cmp.json(what, ref, page["result"], strings=True)
    with open(os.path.join(WORK, "plan.csv")) as f:
        theirs = f.read()
    cmp.json(f"{what}: plan.csv", csv_numbers(theirs), csv_numbers(mine))
    cmp.same_text(f"{what}: plan.csv's header", csv_header(theirs), csv_header(mine))
    shown = [li.text for li in d.find_elements(By.CSS_SELECTOR, "#warnings li")]
    cmp.same_text(f"{what}'s warnings", run.stderr, "".join(w + "\n" for w in shown))
    # The sheet: the CLI's text lines and cells, as printed (fixed decimals), the step's rounding as %.4f.
    caption, totals, lost, rows = sheet(cli(*line.split()[1:-2]).stdout, len(page["bench"]["axes"]))
    cmp.same_text(f"{what}: caption", caption, d.find_element(By.ID, "plan-caption").text)
    cmp.same_text(f"{what}: totals", totals, d.find_element(By.ID, "plan-totals").text)
    cmp.same_text(f"{what}: as run", lost, d.find_element(By.ID, "plan-lost").text)
    several = len(page["bench"]["mountings"]) > 1
    cells = [[c.text for c in tr.find_elements(By.CSS_SELECTOR, "th, td")]
             for tr in d.find_elements(By.CSS_SELECTOR, "#plan-rows tr")]
    if len(cells) != len(rows) or len(rows) != len(ref["steps"]):
        cmp.fail(f"{what}: {len(cells)} steps shown, the CLI's sheet has {len(rows)}")
    for got, want, step in zip(cells, rows, ref["steps"]):
        expected = want[:2] + (want[2:3] if several else []) + want[3:] + ["%.4f" % step["rounding_deg"]]
        cmp.texts += len(expected)
        if got != expected:
            cmp.fail(f"{what}: step {want[0]} shown {got}, the CLI's {expected}")
    headers = [th.get_attribute("scope") for th in d.find_elements(By.CSS_SELECTOR, "#plan-table th")]
    cmp.texts += 1
    if set(headers) != {"col", "row"} or not d.find_element(By.ID, "plan-caption").text:
        cmp.fail(f"{what}: the plan's table needs a caption and scoped headers, has {set(headers)}")
    printed(d, cmp)
    return [cmp.numbers - before[0], cmp.exact - before[1], cmp.texts - before[2]]


def printed(d, cmp):
    """Print the plan: window.print called with the print stylesheet's class set, and in print media only the
    plan's table (with its caption) is laid out; the class goes when the print dialog closes (afterprint)."""
    d.execute_script("window.print = () => { window.scalcalPage.printClass = document.body.className; }")
    d.find_element(By.ID, "print-plan").click()
    d.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": "print"})
    seen = d.execute_script("""
        const shown = (id) => { const e = document.getElementById(id); return !!e && e.getClientRects().length > 0; };
        return ['plan-table', 'plan-caption', 'plan-rows', 'design-form', 'plan-form', 'plan-cli', 'plan-totals',
                'download-plan', 'criteria-rows', 'cal-form', 'status'].filter(shown);""")
    d.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
    d.execute_script("window.dispatchEvent(new Event('afterprint'))")
    after = d.execute_script("return document.body.className")
    cmp.texts += 3
    if d.execute_script("return window.scalcalPage.printClass") != "print-plan":
        cmp.fail("print the plan: window.print was not called with the print-plan stylesheet")
    if seen != ["plan-table", "plan-caption", "plan-rows"]:
        cmp.fail(f"print the plan: on paper {seen}, not the plan's table alone")
    if after:
        cmp.fail(f"print the plan: the body keeps the class '{after}' after printing")


def catalogue(d, cmp):
    """Named programs (one from the paper's Table 1, read from the embedded data) against `scalcal evaluate`."""
    for name in ("icosahedral-20", "table1-A"):
        Select(d.find_element(By.ID, "program")).select_by_value(name)
        d.find_element(By.ID, "evaluate").click()
        wait_status(d, "Evaluation")
        ref = json.loads(cli("evaluate", name, "--region", "sphere", "--json").stdout)
        cmp.json(f"evaluate {name}", ref, d.execute_script("return window.scalcalPage.results.evaluate"), strings=True)


def calibrate(d, cmp, log, magnitude, rate=""):
    """A real log through the file input, calibrated, against `scalcal calibrate` run in the folder holding it
    under the same name (so the messages that name the file read alike): the result, the warnings, the shown
    parameters and the calibration file."""
    name = os.path.basename(log)
    if not os.path.exists(os.path.join(WORK, name)):
        os.symlink(log, os.path.join(WORK, name))
    d.find_element(By.ID, "log-file").send_keys(log)
    WebDriverWait(d, 30).until(lambda d: d.find_element(By.ID, "log-info").text.startswith(name + ":"))
    for field, value in (("magnitude", magnitude), ("rate", rate)):
        e = d.find_element(By.ID, field)
        e.clear()
        e.send_keys(value)
    d.find_element(By.ID, "calibrate").click()
    wait_status(d, "Calibration")
    page = d.execute_script("return window.scalcalPage")
    for n in ("cal.json", "cli_cal.json"):
        if os.path.exists(os.path.join(WORK, n)):
            os.remove(os.path.join(WORK, n))
    args = ["--measurements", name, "--magnitude", magnitude] + (["--rate", rate] if rate else [])
    run = cli("calibrate", *args, "--suggest", "0", "--json", "--out", "cli_cal.json")
    r = json.loads(run.stdout)
    # --json prints the calibration file; the page's result is its fit, the file's header (when, by what, the units)
    # being the downloaded cal.json's, compared with the CLI's --out below.
    header = {"format_version", "created", "tool", "sensor", "units", "units_reason", "region"}
    fit = {k: v for k, v in r.items() if k not in header}
    cmp.json(f"calibrate {name}", fit, page["results"]["calibrate"], strings=True)
    shown = [li.text for li in d.find_elements(By.CSS_SELECTOR, "#warnings li")]
    cmp.same_text(f"calibrate {name}'s warnings", run.stderr, "".join(w + "\n" for w in shown))
    d.find_element(By.ID, "download-cal").click()
    mine = json.loads(downloaded("cal.json"))
    with open(os.path.join(WORK, "cli_cal.json")) as f:
        ref = json.load(f)
    # created is the clock (the CLI's SOURCE_DATE_EPOCH), tool.commit the build's.
    cmp.json(f"{name}'s cal.json", ref, mine, skip={"/created", "/tool/commit"}, strings=True)
    cmp.shown(d, "param-rows", [[k, v, None] for k, v in r["parameters"].items()], columns=2)
    d.save_screenshot(os.path.join(WORK, f"calibrate_{name.split('.')[0]}.png"))
    return page["timings"]["calibrate"]


def export_all(d, cmp):
    """Every registered format, the page's against `scalcal export` on the page's own cal.json: the same bytes,
    or the same refusal; once as it is, once with a driver's scale (the Xsens log is in counts, about 4057 a g:
    its nominal gain 413.7 per m/s^2) and --force, so the firmware formats are written too."""
    formats = d.execute_script("return window.scalcalPage.formats")
    outcomes = {"written": 0, "refused": 0}
    last = None  # the CLI's text of the last format written
    for scale, force in (("", False), ("1/4057g", True)):
        e = d.find_element(By.ID, "raw-scale")
        e.clear()
        e.send_keys(scale)
        if d.find_element(By.ID, "force").is_selected() != force:
            d.find_element(By.ID, "force").click()
        extra = (["--raw-scale", scale] if scale else []) + (["--force"] if force else [])
        for f in formats:
            Select(d.find_element(By.ID, "format")).select_by_value(f)
            d.execute_script("window.scalcalPage.results.export = null")
            d.find_element(By.ID, "export").click()
            wait_status(d, "Export", allow_error=True)
            error = d.find_element(By.ID, "error").text
            what = f"export --format {f} {' '.join(extra)}".strip()
            ref = cli("export", "cal.json", "--format", f, *extra, check=False)
            if ref.returncode == 0:
                text = d.execute_script("return window.scalcalPage.results.export.text") if not error else error
                cmp.same_text(what, ref.stdout, text)
                outcomes["written"] += 1
                last = ref.stdout
            else:
                outcomes["refused"] += 1
                message = ref.stderr.strip().splitlines()[-1].removeprefix("scalcal export: ")
                cmp.same_text(what + " (refused)", message, error.removeprefix("Export failed: "))
    # The last file as the page hands it over (a download), byte for byte the CLI's output.
    name = d.execute_script("return window.scalcalPage.exportFile.name")
    d.find_element(By.ID, "download-export").click()
    cmp.same_text(f"downloaded {name}", last, downloaded(name))
    return outcomes


def keyboard_and_labels(d, cmp):
    """Every control has a name a screen reader reads (a label, aria-label or text; canvases role=img with a
    label), and the keyboard alone designs a program and turns the sphere."""
    unnamed = d.execute_script("""
        const out = [];
        for (const e of document.querySelectorAll('input, select, textarea, button, canvas')) {
          const named = e.tagName === 'BUTTON' ? e.textContent.trim() !== ''
            : e.tagName === 'CANVAS' ? e.getAttribute('role') === 'img' && !!e.getAttribute('aria-label')
            : e.labels.length > 0 || !!e.getAttribute('aria-label');
          if (!named) out.push(e.tagName + '#' + e.id);
        }
        return out;""")
    cmp.texts += 1
    if unnamed:
        cmp.fail(f"controls without an accessible name: {unnamed}")
    e = d.find_element(By.ID, "positions")
    e.send_keys(Keys.CONTROL, "a")
    e.send_keys("12", Keys.ENTER)  # Enter in a field submits its form, as in any form
    wait_status(d, "Design")
    n = d.execute_script("return window.scalcalPage.results.random.program.length")
    cmp.texts += 1
    if n != 12:
        cmp.fail(f"the keyboard's design has {n} positions, not 12")
    sphere = d.find_element(By.ID, "sphere")
    before = sphere.get_attribute("aria-label")
    sphere.send_keys(Keys.ARROW_RIGHT)
    cmp.texts += 1
    if sphere.get_attribute("aria-label") == before:
        cmp.fail("the arrow keys do not turn the sphere")


def phone(d, cmp):
    """The filled page on a phone's width (390 CSS pixels): nothing may stick out sideways."""
    d.set_window_size(390, 844)
    time.sleep(0.5)
    wide = d.execute_script("return [document.documentElement.scrollWidth, window.innerWidth]")
    cmp.texts += 1
    if wide[0] > wide[1]:
        cmp.fail(f"on a phone's width the page is {wide[0]} pixels wide in a {wide[1]}-pixel window")
    d.save_screenshot(os.path.join(WORK, "phone.png"))


def host_run(log, magnitude):
    """embedded/'s own host driver on the log (its streaming detector, fit and guidance): `key value...` lines."""
    p = subprocess.run([HOST_RUN, log, "--detect", "--magnitude", magnitude], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"browser test: host_run {log} failed ({p.returncode}): {p.stderr}")
    out = {}
    for line in p.stdout.splitlines():
        key, *rest = line.split()
        out.setdefault(key, []).append(rest)
    return out


def live(cmp, ref, frames):
    """Poses appear as the samples arrive: after each frame, the poses shown are the host's poses that ended
    before the samples pushed and no more, give or take the two windows the detector needs to close one."""
    ends = sorted(int(p[2]) for p in ref["pose"])
    window = int(ref["detector_window"][0][0])
    for samples, poses in frames[:-1]:  # (the last frame also closes the pose being summed)
        low = sum(e + 2 * window < samples for e in ends)
        high = sum(e < samples for e in ends)
        cmp.texts += 1
        if not low <= poses <= high:
            cmp.fail(f"guide: {poses} poses shown after {samples} samples, the host's end between {low} and {high}")
            return


def guide(d, cmp, log, magnitude):
    """The chosen log through the Guide (the detector fed chunk by chunk, one chunk per animation frame), once
    per criterion and at two speeds, against embedded/tests/host_run.c --detect on the same log (the whole log
    pushed at once, then fitted): the poses, the fit's status and model, the four efficiencies against the
    sphere's limit, and the next pose among the 26 with its criterion once added. Returns (poses, efficiency D,
    the next pose by D, seconds, frames) of the run at 1 s per frame."""
    ref = host_run(log, magnitude)
    status = int(ref["status"][0][0])
    expected = {"poses": int(ref["poses"][0][0]), "fit_status": status}
    if status == 0:
        expected["model"] = int(ref["model"][0][0])
        expected["efficiency"] = [float(v) for v in ref["program_efficiency"][0]]
    nexts = {int(c): (int(b), float(a)) for c, b, a in ref.get("next_pose", [])}
    field = d.find_element(By.ID, "guide-magnitude")
    field.clear()
    field.send_keys(magnitude)
    summary, compared, times = None, 0, []
    for criterion, speed in ((0, "1"), (1, "60"), (2, "10"), (3, "60")):
        Select(d.find_element(By.ID, "guide-criterion")).select_by_value(str(criterion))
        Select(d.find_element(By.ID, "guide-speed")).select_by_value(speed)
        d.execute_script("window.scalcalPage.guideDone = false")
        d.find_element(By.ID, "guide-run").send_keys(Keys.ENTER)  # the keyboard alone starts it
        WebDriverWait(d, 300).until(lambda d: d.execute_script("return window.scalcalPage.guideDone === true"))
        page = d.execute_script("return window.scalcalPage")
        err = d.find_element(By.ID, "error").text
        if err:
            cmp.fail(f"guide: the page says {err}")
            continue
        mine = page["results"]["guide"]
        frames = page["guideFrames"]
        times.append(f"{len(frames)} frames of {speed} s in {page['timings']['guide']:.2f} s")
        if criterion == 0:
            live(cmp, ref, frames)
        want = dict(expected)
        if criterion in nexts:
            want["next"], want["after"] = nexts[criterion]
        before = cmp.numbers
        cmp.json(f"guide {'DAES'[criterion]} at {speed} s per frame", want, mine, source="host_run")
        compared += cmp.numbers - before
        if criterion in nexts:
            said = d.find_element(By.ID, "guide-next").text
            xyz = ", ".join("%.3g" % v for v in mine["next_direction"])
            cmp.same_text("guide's spoken next pose", f"Turn to ({xyz}) next.", said)
        if criterion == 0:
            d.save_screenshot(os.path.join(WORK, "guide.png"))
            summary = (mine["poses"], (mine["efficiency"] or [None])[0], mine["next"], page["timings"]["guide"],
                       len(frames))
    return summary + (compared, times) if summary else None


def main():
    os.makedirs(WORK, exist_ok=True)
    for n in ("design.csv", "cal.json"):
        if os.path.exists(os.path.join(WORK, n)):
            os.remove(os.path.join(WORK, n))
    cmp = Comparison(RELATIVE)
    d = browser()
    try:
        d.get("file://" + os.path.join(PAGE, "index.html"))
        WebDriverWait(d, 60).until(lambda d: d.execute_script("return window.scalcalPage && window.scalcalPage.ready"))
        t_load = d.execute_script("return window.scalcalPage.timings.load")
        keyboard_and_labels(d, cmp)
        catalogue(d, cmp)
        design(d, cmp, [])
        planned = plan(d, cmp, "design.csv", "gimbal:x,y", "0.5", keyboard=True)
        t_design = design(d, cmp, CAP40)
        planned = [a + b for a, b in zip(planned, plan(d, cmp, "design.csv", "tilt:40:flip", "0.1"))]
        part = d.find_element(By.ID, "plan-part")
        d.execute_script("arguments[0].scrollIntoView(true)", part)
        part.screenshot(os.path.join(WORK, "plan.png"))
        # Three real logs of ../shared/data (README there): a magnetometer turned by hand (every sample fitted,
        # the field's strength unknown), an MPU-6050 accelerometer in g without a time column, and last the
        # Xsens accelerometer (51,175 rows, timed, exported below).
        data = os.path.dirname(LOG)
        for other, m, rate in (("qmc5883l_mag.csv", "auto", "50"), ("mpu6050_acc.csv", "1", "100")):
            if os.path.exists(os.path.join(data, other)):
                calibrate(d, cmp, os.path.join(data, other), m, rate)
            else:
                print(f"browser test: {other} is not beside {LOG}: not calibrated")
        t_cal = calibrate(d, cmp, LOG, MAGNITUDE)
        g = guide(d, cmp, LOG, MAGNITUDE)
        n = export_all(d, cmp)
        phone(d, cmp)
    finally:
        d.quit()
    print(cmp.report())
    print(f"browser test: the core loaded and listed its programs and formats in {t_load:.2f} s")
    print(f"browser test: every registered format exported twice: {n['written']} written, the same bytes as the CLI's; "
          f"{n['refused']} refused with the CLI's message")
    print(f"browser test: two plans (gimbal:x,y at 0.5 deg on the sphere's design, tilt:40:flip at 0.1 deg on the "
          f"caps'): {planned[0]} numbers ({planned[1]} equal to the last bit) and {planned[2]} strings, texts and "
          f"cells against scalcal plan --json, --out plan.csv and its sheet")
    if g:
        print(f"browser test: the Guide on {os.path.basename(LOG)}: {g[0]} poses, D-efficiency {g[1]:.6g}, next pose "
              f"{g[2]} of the 26, as embedded/'s host_run ({g[5]} numbers over four runs; {', '.join(g[6])})")
    size = sum(len(gzip.compress(open(os.path.join(PAGE, f), "rb").read(), 9)) for f in os.listdir(PAGE))
    print(f"page {size} bytes compressed, design {t_design:.2f} s, calibrate {t_cal:.2f} s")
    return 1 if cmp.failures else 0


if __name__ == "__main__":
    sys.exit(main())
