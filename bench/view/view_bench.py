"""prt view through a real browser: frames a second drawn on the page while the light turns (SH
lmax 4, then wavelets), and the time from an input event to its picture, on the demo scene at
640x480 in Debian's headless chromium; beside it, in the same chromium without a GPU
(SwiftShader), a WebGL page that does a GAMES202-style viewer's per-vertex work at the same size
(bench/view/webgl_stand_in.html). Prints key=value lines as `prt bench` does, the CPU first.

    python3 bench/view/view_bench.py build/prt [--seconds S] [--runs N] [--no-wavelet]
"""
import argparse
import functools
import http.server
import os
import platform
import statistics
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import cdp  # noqa: E402


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def say(key, value):
    print("%s=%s" % (key, value), flush=True)


def page_fps(page, seconds, counter="prtView.framesDrawn"):
    """Frames drawn on the page per second over `seconds`, counted by the page itself."""
    f0, t0 = page.evaluate("[%s, performance.now()]" % counter)
    time.sleep(seconds)
    f1, t1 = page.evaluate("[%s, performance.now()]" % counter)
    return (f1 - f0) * 1000.0 / (t1 - t0)


def playing(page, on):
    if page.evaluate("prtView.playing") != on:
        page.evaluate("document.getElementById('play').click()")


def input_latency(page, moves):
    """Median ms from a mouse move (a drag turning the light) to its frame drawn on the page, the
    moves 150 ms apart so that each is answered by a frame of its own."""
    box = page.evaluate("(() => { const r = document.getElementById('frame').getBoundingClientRect();"
                        " return [r.left + r.width / 2, r.top + r.height / 2]; })()")
    page.evaluate("prtView.latencies.length = 0")
    page.mouse("mousePressed", box[0], box[1])
    for i in range(moves):
        page.mouse("mouseMoved", box[0] + 2 * (i + 1), box[1])
        time.sleep(0.15)
    page.mouse("mouseReleased", box[0] + 2 * moves, box[1])
    page.wait_for("!prtView.dirty && !prtView.inflight")
    return statistics.median(page.evaluate("prtView.latencies"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("prt")
    ap.add_argument("--seconds", type=float, default=3.0)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--no-wavelet", action="store_true")
    a = ap.parse_args()
    say("cpu_model", cpu_model())
    say("cpu_count", os.cpu_count())
    say("browser", cdp.find_chromium())

    view = subprocess.Popen([a.prt, "view", "--port", "0", "--size", "640x480", "--quiet"], stdout=subprocess.PIPE,
                            text=True)
    try:
        address = view.stdout.readline().strip()
        say("view_address", address)
        with cdp.Browser() as browser:
            page = browser.open(address)
            page.wait_for("window.prtView && prtView.framesDrawn >= 1", timeout=300)
            playing(page, True)
            time.sleep(1.0)
            runs = [page_fps(page, a.seconds) for _ in range(a.runs)]
            playing(page, False)
            say("view_sh_lmax4_fps_runs", ",".join("%.1f" % r for r in runs))
            say("view_sh_lmax4_fps", "%.1f" % statistics.median(runs))
            say("view_sh_draw_ms", page.evaluate("document.getElementById('drawms').textContent"))
            latency = input_latency(page, 30)
            say("view_sh_input_to_picture_ms", "%.1f" % latency)
            if not a.no_wavelet:
                t0 = time.monotonic()
                page.evaluate("(() => { const b = document.getElementById('basis'); b.value = 'wavelet';"
                              " b.dispatchEvent(new Event('change')); })()")
                page.wait_for("document.getElementById('status').textContent === '' && prtView.lastQuery.includes('basis=wavelet')",
                              timeout=1800, interval=0.5)
                say("view_wavelet_precompute_s", "%.1f" % (time.monotonic() - t0))
                playing(page, True)
                time.sleep(1.0)
                runs = [page_fps(page, a.seconds) for _ in range(a.runs)]
                playing(page, False)
                say("view_wavelet_fps_runs", ",".join("%.1f" % r for r in runs))
                say("view_wavelet_fps", "%.1f" % statistics.median(runs))
                say("view_wavelet_draw_ms", page.evaluate("document.getElementById('drawms').textContent"))
                say("view_wavelet_input_to_picture_ms", "%.1f" % input_latency(page, 30))
    finally:
        view.terminate()
        view.wait()

    # The WebGL stand-in, served from this folder, in chromium with SwiftShader for WebGL.
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=HERE)
    handler.log_message = lambda *args: None
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        with cdp.Browser(extra_args=["--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                                     "--ignore-gpu-blocklist"]) as browser:
            page = browser.open("http://127.0.0.1:%d/webgl_stand_in.html" % server.server_address[1])
            page.wait_for("window.bench && bench.frames >= 2", timeout=120)
            say("webgl_renderer", page.evaluate(
                "(() => { const gl = document.createElement('canvas').getContext('webgl');"
                " const e = gl.getExtension('WEBGL_debug_renderer_info');"
                " return e ? gl.getParameter(e.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER); })()"))
            say("webgl_mesh", page.evaluate("meshInfo.vertices + ' vertices, ' + meshInfo.triangles + ' triangles'"))
            time.sleep(1.0)
            runs = [page_fps(page, a.seconds, "bench.frames") for _ in range(a.runs)]
            say("webgl_stand_in_fps_runs", ",".join("%.1f" % r for r in runs))
            say("webgl_stand_in_fps", "%.1f" % statistics.median(runs))
    finally:
        server.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
