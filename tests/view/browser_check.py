"""prt view in a real browser (Debian's chromium, headless, driven over the DevTools Protocol):
the page loads without a console error; a drag turns the light by the angle it should, shown at
interactive quality while it moves, and the still frame that follows is what `prt render` draws
from the command line the page gives, byte for byte; an lmax switch changes the picture as `prt
render --lmax` does; frames arrive in order on the stream; the page shows its frame rate. Run by tests/view/test_view_browser.cpp; exits 0 when every check holds, else 1 with the
failures on stderr.

    python3 browser_check.py PRT_BINARY MESH.obj SCRATCH_DIR
"""
import base64
import math
import os
import re
import shlex
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import cdp  # noqa: E402

# Degrees the light turns per pixel dragged (src/view/page/view.js, DEGREES_PER_PIXEL).
DEGREES_PER_PIXEL = 0.5
# The page's still picture and prt render's are drawn by the same code from the same numbers (the
# camera's floats go through the command line at 9 significant digits, which read back exactly).
SAME_FRAME = 0

failures = []


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def rotation(axis, degrees):
    """The matrix that turns by `degrees` about `axis` (right-handed), by Rodrigues' formula."""
    x, y, z = normalize(axis)
    t = math.radians(degrees)
    c, s, k = math.cos(t), math.sin(t), 1 - math.cos(t)
    return [[c + x * x * k, x * y * k - z * s, x * z * k + y * s],
            [y * x * k + z * s, c + y * y * k, y * z * k - x * s],
            [z * x * k - y * s, z * y * k + x * s, c + z * z * k]]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what, file=sys.stderr)
    if not ok:
        failures.append(what)


def max_difference(prt, a, b):
    run = subprocess.run([prt, "diff", a, b], capture_output=True, text=True)
    match = re.search(r"max_abs=(\d+)", run.stdout)
    if not match:
        raise RuntimeError("prt diff %s %s: %s" % (a, b, run.stderr))
    return int(match.group(1))


def canvas_png(page, path):
    data = page.evaluate("document.getElementById('frame').toDataURL('image/png')")
    with open(path, "wb") as f:
        f.write(base64.b64decode(data.split(",", 1)[1]))


def settled(page, drawn_before):
    """Waits until a frame newer than `drawn_before` is drawn and the picture is the still frame
    of the newest input."""
    page.wait_for("prtView.framesDrawn > %d && prtView.still && prtView.answered === prtView.input" % drawn_before)


def unexpected_errors(page, refused):
    """The page's console errors but the failed loads (400) of the paths in `refused`, at most as
    many of each as it says."""
    left = dict(refused)
    found = []
    for e in page.browser.events:
        entry = e.get("params", {}).get("entry", {})
        if e.get("sessionId") == page.session and e.get("method") == "Log.entryAdded" and "status of 400" in entry.get("text", ""):
            path = re.sub(r"^https?://[^/]+", "", entry.get("url", "")).split("?")[0]
            if left.get(path, 0) > 0:
                left[path] -= 1
                continue
            found.append("400 " + entry.get("url", ""))
    return found + [e for e in page.errors() if "status of 400" not in e]


def render_command(prt, page, out):
    """The page's `prt render` line, run into `out` for one frame; returns frame 0's path."""
    page.evaluate("document.getElementById('command').value = ''")
    page.evaluate("document.getElementById('showcommand').click()")
    line = page.wait_for("(() => { const c = document.getElementById('command');"
                         " return !c.classList.contains('stale') && c.value; })()")
    words = shlex.split(line)
    assert words[:2] == ["prt", "render"], line
    words = [prt] + words[1:]
    at = words.index("--out")
    words[at + 1] = out
    words[words.index("--frames") + 1] = "1"
    run = subprocess.run(words + ["--quiet"], capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError("%s: %s" % (line, run.stderr))
    return os.path.join(out, "frame_0000.png"), line


def main():
    prt, mesh, scratch = sys.argv[1:4]
    view = subprocess.Popen([prt, "view", "--mesh", mesh, "--lmax", "3", "--samples", "256", "--size", "320x240",
                             "--start-angle", "10", "--port", "0"], stdout=subprocess.PIPE, stderr=open(os.path.join(scratch, "view.txt"), "w"),
                            text=True)
    try:
        address = view.stdout.readline().strip()
        check(address.startswith("http://127.0.0.1:"), "prt view printed its address: " + address)
        with cdp.Browser() as browser:
            page = browser.open(address)
            page.wait_for("window.prtView && prtView.framesDrawn >= 1", timeout=120)
            page.wait_for("prtView.still && prtView.answered === prtView.input")
            browser.pump(0.5)
            check(page.errors() == [], "the page loads and draws with no console error: %s" % page.errors())
            first = page.evaluate("prtView.lastQuery")
            state = page.evaluate("prtView.state.defaults")
            check("angle=10&" in first and "axis=0%2C1%2C0&" in first,
                  "the first frame is the command line's light, --start-angle 10: " + first)
            check(("exposure=%s&" % state["exposure"]) in first or ("exposure=%g&" % state["exposure"]) in first,
                  "the first frame has the measured exposure %s: %s" % (state["exposure"], first))

            # A drag: 90 px to the right over the canvas, in steps, as a hand does.
            box = page.evaluate("(() => { const r = document.getElementById('frame').getBoundingClientRect();"
                                " return [r.left, r.top, r.width, r.height]; })()")
            x0, y0 = box[0] + box[2] / 2, box[1] + box[3] / 2
            drawn = page.evaluate("prtView.framesDrawn")
            interactive = page.evaluate("prtView.interactiveFrames")
            page.mouse("mousePressed", x0, y0)
            for step in range(1, 10):
                page.mouse("mouseMoved", x0 + 10 * step, y0)
                time.sleep(0.03)
            page.mouse("mouseReleased", x0 + 90, y0)
            settled(page, drawn)
            check(page.evaluate("prtView.interactiveFrames") > interactive,
                  "the drag was shown at interactive quality while it moved, then the still frame")
            turn = page.evaluate("axisAngle()")
            check(abs(turn["angle"] - (10 + 90 * DEGREES_PER_PIXEL)) < 1e-9 and
                  max(abs(a - b) for a, b in zip(turn["axis"], [0, 1, 0])) < 1e-12,
                  "a 90 px drag turned the light by 45 degrees about the camera's up, from 10 to 55: %s" % turn)
            query = page.evaluate("prtView.lastQuery")
            check("angle=55&" in query and "axis=0%2C1%2C0&" in query, "the frame drawn is that turn's: " + query)
            canvas_png(page, os.path.join(scratch, "page_turned.png"))
            frame, line = render_command(prt, page, os.path.join(scratch, "render_turned"))
            check("--start-angle 55 " in line and "--axis 0,1,0 " in line, "the command line says the turn: " + line)
            diff = max_difference(prt, os.path.join(scratch, "page_turned.png"), frame)
            check(diff <= SAME_FRAME, "the page's picture is prt render's of the same light (max_abs %d)" % diff)

            # A vertical drag as well: a turn about another axis, still render's picture.
            drawn = page.evaluate("prtView.framesDrawn")
            page.mouse("mousePressed", x0, y0)
            for step in range(1, 5):
                page.mouse("mouseMoved", x0, y0 + 10 * step)
            page.mouse("mouseReleased", x0, y0 + 40)
            settled(page, drawn)
            turn = page.evaluate("axisAngle()")
            check(abs(turn["axis"][1]) < 0.999, "a vertical drag turned the light about another axis: %s" % turn)
            # The two drags compose as rotations: 45 degrees about up, then 20 about the camera's
            # right, computed here with matrices, independently of the page's quaternions.
            cam = page.evaluate("prtView.camera")
            forward = normalize([t - e for t, e in zip(cam["target"], cam["eye"])])
            right = normalize(cross(forward, cam["up"]))
            expected = matmul(rotation(right, 40 * DEGREES_PER_PIXEL), rotation([0, 1, 0], 10 + 90 * DEGREES_PER_PIXEL))
            got = rotation(turn["axis"], turn["angle"])
            worst = max(abs(expected[i][j] - got[i][j]) for i in range(3) for j in range(3))
            check(worst < 1e-9, "the drags composed: the page's rotation is up 55 then right 20 (off by %.2g)" % worst)
            canvas_png(page, os.path.join(scratch, "page_tilted.png"))
            frame, line = render_command(prt, page, os.path.join(scratch, "render_tilted"))
            diff = max_difference(prt, os.path.join(scratch, "page_tilted.png"), frame)
            check(diff <= SAME_FRAME, "after a drag about another axis, still render's picture (max_abs %d)" % diff)

            # lmax 3 -> 1: the picture changes, as prt render --lmax 1 draws it.
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("(() => { const s = document.getElementById('lmax'); s.value = '1';"
                          " s.dispatchEvent(new Event('input')); })()")
            settled(page, drawn)
            check("lmax=1&" in page.evaluate("prtView.lastQuery"), "the frame drawn asks for lmax 1")
            check(page.evaluate("document.getElementById('lmaxtext').textContent") == "1", "the page says lmax 1")
            canvas_png(page, os.path.join(scratch, "page_lmax1.png"))
            frame, line = render_command(prt, page, os.path.join(scratch, "render_lmax1"))
            check(" --lmax 1 " in line, "the command line says --lmax 1: " + line)
            diff = max_difference(prt, os.path.join(scratch, "page_lmax1.png"), frame)
            check(diff <= SAME_FRAME, "lmax 1 on the page is prt render --lmax 1 (max_abs %d)" % diff)
            changed = max_difference(prt, os.path.join(scratch, "page_lmax1.png"),
                                     os.path.join(scratch, "page_tilted.png"))
            check(changed > 5, "the lmax switch changed the picture (max_abs %d against lmax 3)" % changed)

            # The transport view, coefficient 5, chosen on the page: render's --view transport:5.
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("(() => { document.getElementById('coef').value = '5'; const v = document.getElementById('view');"
                          " v.value = 'transport'; v.dispatchEvent(new Event('input')); })()")
            settled(page, drawn)
            canvas_png(page, os.path.join(scratch, "page_transport5.png"))
            frame, line = render_command(prt, page, os.path.join(scratch, "render_transport5"))
            check(" --view transport:5 " in line, "the command line says --view transport:5: " + line)
            diff = max_difference(prt, os.path.join(scratch, "page_transport5.png"), frame)
            check(diff <= SAME_FRAME, "the transport view on the page is prt render's (max_abs %d)" % diff)
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("(() => { const v = document.getElementById('view'); v.value = 'radiance';"
                          " v.dispatchEvent(new Event('input')); })()")
            settled(page, drawn)

            # Input to picture is timed from the oldest input a frame answers: five inputs 60 ms
            # apart in one task of the page (no frame can be shown meanwhile; the first is posted
            # at once, the newest after it), answered by two frames shown after the task: the
            # first input's, counted from it (240 ms before the task ended), then the fifth's,
            # which answers inputs 2 to 5 and counts from the second (180 ms before the fifth).
            page.evaluate("prtView.latencies.length = 0; for (let i = 0; i < 5; ++i) {"
                          " changed(); const t = performance.now() + 60; while (performance.now() < t) {} }")
            page.wait_for("prtView.latencies.length >= 2")
            first_latency, second_latency = page.evaluate("prtView.latencies.slice(0, 2)")
            check(first_latency >= 240 and second_latency >= 170,
                  "input to picture counts from the oldest input (%.0f and %.0f ms)" % (first_latency, second_latency))

            # The error figures: measured against prt reference on request, less error at more bands.
            page.evaluate("document.getElementById('measure').click()")
            page.wait_for("prtView.error && prtView.error.lmax === 1", timeout=120)
            low = page.evaluate("prtView.error.error")
            text = page.evaluate("document.getElementById('error').textContent")
            check(("%.2f %% RMS" % (100 * low)) in text, "the page shows the error at lmax 1: " + text)
            page.evaluate("(() => { const s = document.getElementById('lmax'); s.value = '3';"
                          " s.dispatchEvent(new Event('input')); })()")
            page.wait_for("prtView.error.lmax === 3")
            high = page.evaluate("prtView.error.error")
            check(high < low, "more bands, less error on the page: lmax 3 %.4f < lmax 1 %.4f" % (high, low))

            # Playing: the light turns on its own and the page shows the frame rate.
            page.evaluate("document.getElementById('play').click()")
            time.sleep(2.0)
            fps = page.evaluate("document.getElementById('fps').textContent")
            drawn = page.evaluate("prtView.framesDrawn")
            check(re.fullmatch(r"\d+\.\d", fps or "") is not None and float(fps) > 0,
                  "the page shows its frame rate while the light turns: '%s' fps" % fps)
            check(re.fullmatch(r"\d+\.\d", page.evaluate("document.getElementById('drawms').textContent")) is not None,
                  "the page shows the frame's draw time")
            page.evaluate("document.getElementById('play').click()")
            check(drawn >= 5, "frames kept coming while playing (%d drawn)" % drawn)
            check(page.evaluate("prtView.outOfOrder") == 0 and page.evaluate("prtView.streams") == 1,
                  "every frame came in order, on one stream")

            # Another mode chosen: computed in the background while the page goes on drawing the
            # mode it shows, saying which; then that mode.
            page.evaluate("(() => { const m = document.getElementById('mode'); m.value = 'interreflection';"
                          " m.dispatchEvent(new Event('change')); })()")
            page.wait_for("document.getElementById('status').textContent.includes('(showing sh shadowed)')")
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("view.turn = { axis: view.turn.axis, angle: 77 }; changed()")
            page.wait_for("prtView.framesDrawn > %d && prtView.answered === prtView.input" % drawn)
            shown_meanwhile = page.evaluate("prtView.lastQuery")
            check("angle=77&" in shown_meanwhile and "mode=shadowed&" in shown_meanwhile,
                  "while another mode computes, the page draws the mode it shows and says which: " + shown_meanwhile)
            page.wait_for("prtView.lastQuery.includes('mode=interreflection&') && prtView.still", timeout=120)
            check(page.evaluate("document.getElementById('status').textContent") == "",
                  "then it draws the new mode, and says nothing more")
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("(() => { const m = document.getElementById('mode'); m.value = 'shadowed';"
                          " m.dispatchEvent(new Event('change')); })()")
            page.wait_for("prtView.lastQuery.includes('mode=shadowed&') && prtView.still", timeout=60)

            # An input the scene cannot draw (a mode never computed, asked for by hand): the
            # stream's error record shows on the page, and the stream goes on.
            page.evaluate("view.transport = { basis: 'sh', mode: 'unshadowed' }; changed()")
            page.wait_for("document.getElementById('status').textContent.includes('not computed')")
            check(True, "an input the scene cannot draw shows the stream's reason on the page")
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("view.transport = { basis: 'sh', mode: 'shadowed' }; changed()")
            settled(page, drawn)

            # Two choices in a row, the first still asking for its transport when the second (a
            # ready one) is drawn: the first gives way, and says nothing more. Its /compute is
            # held back 0.5 s here, so that the second comes while the first waits for it.
            page.evaluate("(() => { const f = window.fetch; window.computeAsked = false;"
                          " window.fetch = (u, o) => { if (String(u).startsWith('/compute')) { window.computeAsked = true;"
                          " return new Promise((r) => setTimeout(() => r(f(u, o)), 500)); } return f(u, o); };"
                          " const m = document.getElementById('mode'); m.value = 'unshadowed'; m.dispatchEvent(new Event('change')); })()")
            page.wait_for("window.computeAsked")
            page.evaluate("(() => { const m = document.getElementById('mode'); m.value = 'shadowed';"
                          " m.dispatchEvent(new Event('change')); })()")
            time.sleep(1.5)
            status_after = page.evaluate("document.getElementById('status').textContent")
            check(status_after == "" and page.evaluate("view.transport.mode") == "shadowed",
                  "a choice overtaken by a later one gives way and says nothing more: '%s'" % status_after)

            # An input the server refuses (a basis the run does not offer, set by hand): the page
            # says why, does not post it in a loop, and sends the input again with its next
            # message (here an acknowledgement), once it can be drawn.
            posts = "performance.getEntriesByType('resource').filter((e) => e.name.includes('/input?')).length"
            page.evaluate("view.transport = { basis: 'nosuch', mode: 'shadowed' }; changed()")
            page.wait_for("document.getElementById('status').textContent.includes('basis=nosuch')")
            before = page.evaluate(posts)
            time.sleep(0.5)
            check(page.evaluate(posts) - before <= 1, "a refused input is not posted again and again (%d posts in 0.5 s)"
                  % (page.evaluate(posts) - before))
            page.evaluate("view.transport = { basis: 'sh', mode: 'shadowed' }; sendInput()")
            page.wait_for("prtView.answered === prtView.input", timeout=30)
            check(True, "a refused input is sent again with the next message, and answered")

            # The stream ends under the page (another request takes its name, so the server ends
            # it): the page opens one new stream, and frames go on from where the light is.
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("(() => { const c = new AbortController();"
                          " fetch(api('/stream?stream=' + prtView.stream), { headers: { 'X-Prt-Stream': '1' }, signal: c.signal })"
                          ".then(() => c.abort(), () => {}); })()")
            page.wait_for("prtView.streams === 2 && prtView.stream !== null", timeout=30)
            page.evaluate("view.turn = { axis: view.turn.axis, angle: 123 }; changed()")
            settled(page, drawn)
            time.sleep(2.5)  # longer than a keep-alive: a second stream would have been opened by now
            check(page.evaluate("prtView.streams") == 2 and "angle=123&" in page.evaluate("prtView.lastQuery"),
                  "the page reopened one stream when its stream ended, and drew the newest input (%d streams)"
                  % page.evaluate("prtView.streams"))
            check(page.evaluate("prtView.outOfOrder") == 0, "frames came in order on the new stream too")
            # Told twice that the same stream ended (its reader's end and a late 404 of an input
            # sent to it): one new stream, not two.
            page.evaluate("(() => { const n = prtView.stream; reopenStream(n); reopenStream(n); })()")
            page.wait_for("prtView.streams >= 3 && prtView.stream !== null", timeout=30)
            time.sleep(2.5)
            check(page.evaluate("prtView.streams") == 3,
                  "an end said twice opens one stream (%d streams in all)" % page.evaluate("prtView.streams"))
            browser.pump(0.2)
            # The one refused input above is logged by the browser as a failed load of /input, and
            # of the command line the page asks for with it (/command), once each.
            errors = unexpected_errors(page, {"/input": 1, "/command": 1})
            check(errors == [], "no console error over the whole session but the refused input's: %s" % errors)
    finally:
        view.terminate()
        view.wait(timeout=30)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
