"""prt view's controls in a real browser (chromium, headless, over the DevTools Protocol), on the
small scene with a second environment, a file: the turn slider follows a touch drag; the orbit
stops short of the pole and at the ground, and the camera resets; the render command line
follows every setting or says it is stale; a basis and a mode chosen at once are computed and
drawn, and a refused computation is said; controls that would change nothing are disabled with
their reason; environments by file name; the error label's light terms and its caution within the
reference's noise; the statistics explained; size and supersampling drawn as prt render draws
them; the error figures of each environment its own. Run by tests/view/test_view_browser.cpp;
exits 0 when every check holds, else 1 with the failures on stderr.

    python3 browser_controls_check.py PRT_BINARY MESH.obj SCRATCH_DIR
"""
import math
import os
import struct
import subprocess
import sys
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import browser_check as b  # noqa: E402  (its helpers and its list of failures)
from browser_check import check, cdp  # noqa: E402

# The page's orbit limits (src/view/page/view.js, MAX_ELEVATION; the ground: elevation 0).
MAX_ELEVATION = 85.0
# Degrees of slack in the elevation read back from the page's camera (its eye's floats).
ELEVATION_SLACK = 1e-6


def write_png(path, width, height, pixel):
    """An 8-bit RGB PNG, written with Python's own zlib (no image library needed)."""
    raw = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def eventually(page, expression, timeout=20):
    """True once the expression is truthy within `timeout` seconds, else False."""
    try:
        page.wait_for(expression, timeout=timeout)
        return True
    except cdp.CdpError:
        return False


def set_control(page, id, value, event="input"):
    page.evaluate("(() => { const c = document.getElementById('%s'); c.value = '%s';"
                  " c.dispatchEvent(new Event('%s')); })()" % (id, value, event))


def camera_angles(page):
    """The page's camera as (elevation in degrees, the eye's unit direction across up)."""
    c = page.evaluate("prtView.camera")
    up = b.normalize(c["up"])
    offset = [e - t for e, t in zip(c["eye"], c["target"])]
    along = sum(o * u for o, u in zip(offset, up))
    across = b.normalize([o - along * u for o, u in zip(offset, up)])
    return math.degrees(math.asin(along / math.sqrt(sum(o * o for o in offset)))), across, c


def drag(page, x, y, dx, dy, steps, button="left", buttons=1):
    """A drag of `steps` moves of (dx, dy) pixels from (x, y); returns the camera after each move."""
    page.mouse("mousePressed", x, y, button=button, buttons=buttons)
    seen = []
    for step in range(1, steps + 1):
        page.mouse("mouseMoved", x + dx * step, y + dy * step, button=button, buttons=buttons)
        seen.append(camera_angles(page))
    page.mouse("mouseReleased", x + dx * steps, y + dy * steps, button=button)
    return seen


def main():
    prt, mesh, scratch = sys.argv[1:4]
    warm = os.path.join(scratch, "warm_sky.png")  # a 32 x 16 equirect: a warm patch in a dark blue sky
    write_png(warm, 32, 16, lambda x, y: (255, 200, 120) if y < 5 and 4 < x < 12 else (20, 30, 60))
    view = subprocess.Popen([prt, "view", "--mesh", mesh, "--lmax", "3", "--samples", "256", "--size", "320x240",
                             "--port", "0", warm], stdout=subprocess.PIPE,
                            stderr=open(os.path.join(scratch, "view.txt"), "w"), text=True)
    try:
        address = view.stdout.readline().strip()
        with cdp.Browser() as browser:
            page = browser.open(address)
            page.wait_for("window.prtView && prtView.framesDrawn >= 1", timeout=120)
            page.wait_for("prtView.still && prtView.answered === prtView.input")
            box = page.evaluate("(() => { const r = document.getElementById('frame').getBoundingClientRect();"
                                " return [r.left, r.top, r.width, r.height]; })()")
            x0, y0 = box[0] + box[2] / 2, box[1] + box[3] / 2

            # The turn slider follows a touch drag on the picture, which leaves the focus on the
            # slider (a mouse press would take it away): clicked at its left end, then a 180 px
            # touch drag turns the light by 90 degrees, and the slider says 90 too.
            r = page.evaluate("(() => { const r = document.getElementById('angle').getBoundingClientRect();"
                              " return [r.left, r.top, r.width, r.height]; })()")
            page.mouse("mousePressed", r[0] + 1, r[1] + r[3] / 2)
            page.mouse("mouseReleased", r[0] + 1, r[1] + r[3] / 2)

            def touch(kind, x, y):
                page.send("Input.dispatchTouchEvent", {"type": kind, "touchPoints": [] if kind == "touchEnd" else [{"x": x, "y": y}]})
            touch("touchStart", x0, y0)
            for step in range(1, 10):
                touch("touchMove", x0 + 20 * step, y0)
                time.sleep(0.02)
            touch("touchEnd", x0 + 180, y0)
            angle = page.evaluate("axisAngle().angle")
            slider = float(page.evaluate("document.getElementById('angle').value"))
            check(page.evaluate("document.activeElement.id") == "angle" and abs(angle - 90) < 1e-9 and abs(slider - 90) <= 0.5,
                  "the turn slider follows a touch drag (the light at %.1f degrees, the slider at %g)" % (angle, slider))
            page.evaluate("document.getElementById('reset').click()")

            # The orbit: a right-drag down by 3 px moves, 180 degrees in all, raises the eye until
            # MAX_ELEVATION and stops there, never crossing the pole (the eye's direction across
            # up stays, so the picture never turns over); a drag up stops at the ground.
            before, across0, _ = camera_angles(page)
            seen = drag(page, x0, y0, 0, 3, 120, "right", 2)
            highest = max(e for e, _, _ in seen)
            turned = min(sum(a * c for a, c in zip(across, across0)) for _, across, _ in seen)
            check(abs(highest - MAX_ELEVATION) < ELEVATION_SLACK and abs(seen[-1][0] - MAX_ELEVATION) < ELEVATION_SLACK and
                  turned > 1 - 1e-9,
                  "an orbit past the pole stops %g degrees short of it, never turning over (from %.2f: highest %.4f, "
                  "last %.4f, across up %.9f)" % (90 - MAX_ELEVATION, before, highest, seen[-1][0], turned))
            seen = drag(page, x0, y0, 0, -3, 120, "right", 2)
            lowest = min(e for e, _, _ in seen)
            below = min(c["eye"][1] - c["target"][1] for _, _, c in seen)  # up is the y axis here
            check(abs(lowest) < ELEVATION_SLACK and abs(seen[-1][0]) < ELEVATION_SLACK and below > -1e-6,
                  "an orbit down stops at the ground, the target's level (lowest elevation %.6f, eye %.2g above the target)"
                  % (lowest, below))
            drag(page, x0, y0, 7, 2, 5, "right", 2)
            home = page.evaluate("prtView.home.camera")
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("document.getElementById('resetcamera').click()")
            b.settled(page, drawn)
            check(page.evaluate("prtView.camera") == home and
                  page.evaluate("prtView.lastQuery").find("eye=" + page.evaluate("fmt(prtView.home.camera.eye)").replace(",", "%2C")) >= 0,
                  "reset camera draws the first camera again")
            drag(page, x0, y0, -6, 3, 5, "right", 2)
            drawn = page.evaluate("prtView.framesDrawn")
            page.evaluate("document.getElementById('resetcamera').click()")
            b.settled(page, drawn)
            check(page.evaluate("prtView.camera") == home, "a second reset, after another orbit, draws the first camera again")

            # The render command line follows every setting: stale (and saying so) at once, then
            # the line of the new setting.
            page.evaluate("document.getElementById('showcommand').click()")
            fresh = "(() => { const c = document.getElementById('command'); return !c.classList.contains('stale') && %s; })()"
            page.wait_for(fresh % "true")
            for control, value, said in [("exposure", "1.5", " --exposure 1.5 "), ("tonemap", "reinhard", " --tonemap reinhard "),
                                         ("lmax", "2", " --lmax 2 ")]:
                set_control(page, control, value)
                stale = page.evaluate("document.getElementById('commandstate').textContent")
                ok = eventually(page, fresh % ("c.value.includes('%s')" % said), timeout=10)
                check(stale.startswith("stale") and ok,
                      "the command line follows %s=%s, stale until then ('%s')" % (control, value, stale))
            # Two changes in one go, the second while the first's line is still being asked
            # for: the box ends on the line of both.
            page.evaluate("(() => { for (const [id, v] of [['exposure', '2.5'], ['tonemap', 'aces']]) {"
                          " const c = document.getElementById(id); c.value = v; c.dispatchEvent(new Event('input'));"
                          " c.dispatchEvent(new Event('change')); } })()")
            ok = eventually(page, fresh % "c.value.includes(' --exposure 2.5 ') && c.value.includes(' --tonemap aces ')",
                            timeout=10)
            check(ok, "the command line follows a change made while the last one's line was being asked for")
            page.evaluate("window.lineBefore = document.getElementById('command').value")
            drag(page, x0, y0, 10, 0, 2, "right", 2)
            ok = eventually(page, fresh % "c.value !== window.lineBefore && c.value.includes(' --eye ')", timeout=10)
            check(ok, "the command line follows an orbit of the camera")
            page.evaluate("document.getElementById('resetcamera').click()")

            # Controls that would change nothing are disabled, saying why: the wavelet light
            # terms under SH, the glossy view of a diffuse scene.
            terms = page.evaluate("[document.getElementById('terms').disabled, document.getElementById('terms').title]")
            glossy = page.evaluate("(() => { const o = document.querySelector('#view option[value=glossy]');"
                                   " return [o.disabled, o.title]; })()")
            check(terms[0] and "wavelet" in terms[1] and glossy[0] and "diffuse" in glossy[1],
                  "under SH the light terms, and on a diffuse scene the glossy view, are disabled and say why: %s %s"
                  % (terms, glossy))

            # A basis and a mode chosen at once: that transport is computed and drawn, and the page
            # says nothing more (it waited for the key it asked for).
            page.evaluate("(() => { const b = document.getElementById('basis'); b.value = 'wavelet'; b.dispatchEvent(new Event('change'));"
                          " const m = document.getElementById('mode'); m.value = 'unshadowed'; m.dispatchEvent(new Event('change')); })()")
            ok = eventually(page, "prtView.lastQuery.includes('basis=wavelet&mode=unshadowed&') && prtView.still", timeout=60)
            time.sleep(1.0)
            status = page.evaluate("document.getElementById('status').textContent")
            check(ok and status == "", "a basis and a mode chosen at once: that transport drawn, nothing more said ('%s')" % status)
            lmax = page.evaluate("[document.getElementById('lmax').disabled, document.getElementById('lmax').closest('label').title]")
            transport = page.evaluate("document.querySelector('#view option[value=transport]').disabled")
            check(lmax[0] and "changes nothing" in lmax[1] and transport and not page.evaluate("document.getElementById('terms').disabled"),
                  "under wavelets lmax and the transport view are disabled, saying why, and the light terms enabled: %s" % lmax)

            # The error label of a wavelet setting names its light terms.
            page.evaluate("document.getElementById('measure').click()")
            ok = eventually(page, "prtView.error && document.getElementById('error').textContent.includes('% RMS')", timeout=120)
            text = page.evaluate("document.getElementById('error').textContent")
            check(ok and "light terms, unshadowed" in text, "the error label names the wavelet light's terms: " + text)
            near = page.evaluate("errorText({ error: 0.0136, reference_error: 0.0135, vertices: 9, samples: 1024, lmax: 3 },"
                                 " { basis: 'wavelet', mode: 'shadowed' }, 64)")
            far = page.evaluate("errorText({ error: 0.05, reference_error: 0.0135, vertices: 9, samples: 1024, lmax: 3 },"
                                " { basis: 'sh', mode: 'shadowed' }, 0)")
            check("within the reference's own noise" in near and "noise" not in far.split("the reference's own error")[1] and
                  "64 light terms" in near and "sh lmax 3, shadowed" in far,
                  "an error at the reference's own noise says so, one well above it does not: %s | %s" % (near, far))

            # A refused computation is said, not "computing" for ever.
            page.evaluate("(() => { const f = window.fetch; window.realFetch = f; window.fetch = (u, o) =>"
                          " String(u).startsWith('/compute') ? Promise.resolve(new Response('mode=interreflection: refused (a test)',"
                          " { status: 400 })) : f(u, o); })()")
            set_control(page, "mode", "interreflection", "change")
            ok = eventually(page, "document.getElementById('status').textContent.includes('refused (a test)')", timeout=10)
            time.sleep(0.6)
            status = page.evaluate("document.getElementById('status').textContent")
            check(ok and "computing" not in status, "a computation the server refuses is said, not waited for: '%s'" % status)
            page.evaluate("window.fetch = window.realFetch")
            page.evaluate("(() => { const b = document.getElementById('basis'); b.value = 'sh'; b.dispatchEvent(new Event('change'));"
                          " const m = document.getElementById('mode'); m.value = 'shadowed'; m.dispatchEvent(new Event('change')); })()")
            page.wait_for("prtView.lastQuery.includes('basis=sh&mode=shadowed&') && prtView.still", timeout=60)

            # Environments by file name, the whole path in the title; the statistics explained.
            env = page.evaluate("Array.from(document.getElementById('env').options).map((o) => [o.textContent, o.title])")
            check(env[1] == ["warm_sky.png", warm], "an environment is listed by its file name, its path in the title: %s" % env)
            titles = page.evaluate("Array.from(document.querySelectorAll('#stats [title]')).map((e) => e.title)")
            check(len(titles) == 4 and any("round trip" in t for t in titles) and all(len(t) > 40 for t in titles),
                  "the frame rate, draw, input to picture and quality are explained in their titles")

            # Size and supersampling: an ssaa over the frame's sample budget is disabled; 160 x 120
            # at 3 x 3 (not the command line's 2) is drawn, and is prt render's picture of the
            # command line the page gives.
            set_control(page, "size", "1280x960")
            over = page.evaluate("(() => { const o = document.querySelector('#ssaa option[value=\"4\"]'); return [o.disabled, o.title]; })()")
            check(over[0] and "4096 x 4096" in over[1], "at 1280 x 960, ssaa 4 is over the frame's samples, and says so: %s" % over)
            drawn = page.evaluate("prtView.framesDrawn")
            set_control(page, "size", "160x120")
            set_control(page, "ssaa", "3")
            b.settled(page, drawn)
            size = page.evaluate("[document.getElementById('frame').width, document.getElementById('frame').height]")
            b.canvas_png(page, os.path.join(scratch, "page_small.png"))
            frame, line = b.render_command(prt, page, os.path.join(scratch, "render_small"))
            diff = b.max_difference(prt, os.path.join(scratch, "page_small.png"), frame)
            check(size == [160, 120] and " --size 160x120 --ssaa 3 " in line and diff <= b.SAME_FRAME,
                  "160 x 120 at ssaa 3 is drawn as prt render draws it (%s, max_abs %d): %s" % (size, diff, line))

            # The error figures are each environment's own: measured under environment 0, then
            # environment 1 is not measured (not 0's figure); measured, its own figure; back
            # under 0, 0's again. And an answer for 0 that comes after the switch to 1 is dropped.
            set_control(page, "lmax", "3")
            page.evaluate("prtView.error = null; document.getElementById('measure').click()")
            page.wait_for("prtView.error && prtView.error.lmax === 3", timeout=120)
            first = page.evaluate("window.firstError = document.getElementById('error').textContent")
            set_control(page, "env", "1")
            ok = eventually(page, "document.getElementById('error').textContent.includes('not measured')", timeout=10)
            check(ok, "after switching the environment, the error is not the other one's: "
                  + page.evaluate("document.getElementById('error').textContent"))
            page.evaluate("prtView.error = null; document.getElementById('measure').click()")
            page.wait_for("prtView.error && prtView.error.lmax === 3", timeout=120)
            second = page.evaluate("document.getElementById('error').textContent")
            set_control(page, "env", "0")
            back = eventually(page, "document.getElementById('error').textContent === window.firstError", timeout=10)
            check(first != second and back, "each environment's error is its own: %s | %s" % (first, second))
            page.evaluate("(() => { const f = window.fetch; window.fetch = (u, o) => { if (String(u).startsWith('/error?') &&"
                          " String(u).includes('&env=0&')) { window.errorAsked = true;"
                          " return new Promise((r) => setTimeout(() => r(f(u, o)), 800)); } return f(u, o); }; })()")
            set_control(page, "lmax", "2")
            page.wait_for("window.errorAsked")  # environment 0's figure asked for, its answer held back
            set_control(page, "env", "1")
            time.sleep(1.6)
            shown = page.evaluate("document.getElementById('error').textContent")
            own = page.evaluate("fetch(api('/error?' + query())).then((r) => r.json()).then((e) => (100 * e.error).toFixed(2) + ' % RMS')")
            check(own in shown and "lmax 2" in shown,
                  "an error answer for the environment left behind is dropped: '%s' (its own: %s)" % (shown, own))

            # Every request the page made but its own files and /state carried the run's token.
            urls = page.evaluate("performance.getEntriesByType('resource').map((e) => e.name)")
            bare = [u for u in urls if "token=" not in u and not u.split("?")[0].endswith(("/view.js", "/state"))]
            check(len(urls) > 10 and bare == [], "every request of the page carries the run's token (%d requests): %s"
                  % (len(urls), bare[:3]))
            browser.pump(0.2)
            errors = b.unexpected_errors(page, {})
            check(errors == [], "no console error over the whole session: %s" % errors)
    finally:
        view.terminate()
        view.wait(timeout=30)
    return 1 if b.failures else 0


if __name__ == "__main__":
    sys.exit(main())
