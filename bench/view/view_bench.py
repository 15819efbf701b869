"""prt view through a real browser: frames a second drawn on the page while the light turns (SH
lmax 4, then wavelets), and the time from an input event to its picture, on the demo scene at
640x480 in Debian's headless chromium; beside it, in the same chromium without a GPU
(SwiftShader), a WebGL page that does a GAMES202-style viewer's per-vertex work at the same size
(bench/view/webgl_stand_in.html). Then both again with another process beside them taking half a
core (a loop busy whenever it has used less than half the time since it started). Prints key=value lines as `prt bench` does, the CPU first,
the load average before each measurement, and the cores each process used during it (CPU
seconds over wall seconds: prt, the browser with all its processes, the load).

While the light turns the page shows frames at interactive quality (src/view/frame_stream.h:
ssaa 1, the wavelet light from fewer cells) and the still frame, what prt render draws, once it
stops; the frame rates below are the interactive ones.

    python3 bench/view/view_bench.py build/prt [--seconds S] [--runs N] [--no-wavelet] [--no-load]
                                               [--no-stand-in] [--view-threads N]
"""
import argparse
import functools
import http.server
import os
import statistics
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import cdp  # noqa: E402
sys.path.insert(0, os.path.join(HERE, ".."))
from machine import cpu_model  # noqa: E402


def say(key, value):
    print("%s=%s" % (key, value), flush=True)


TICKS = os.sysconf("SC_CLK_TCK")


def tree_cpu_seconds(root):
    """CPU seconds used so far by process `root` and every process below it."""
    parent, cpu = {}, {}
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % name) as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        pid = int(name)
        parent[pid] = int(fields[1])
        cpu[pid] = (int(fields[11]) + int(fields[12])) / TICKS
    total = 0.0
    for pid, seconds in cpu.items():
        p = pid
        while p > 1 and p != root:
            p = parent.get(p, 1)
        if p == root:
            total += seconds
    return total


class Cores:
    """The cores each named process tree used between start and stop."""

    def __init__(self, pids):
        self.pids = {k: v for k, v in pids.items() if v}
        self.t0 = time.monotonic()
        self.c0 = {k: tree_cpu_seconds(v) for k, v in self.pids.items()}

    def line(self):
        wall = time.monotonic() - self.t0
        return " ".join("%s:%.2f" % (k, (tree_cpu_seconds(v) - self.c0[k]) / wall) for k, v in self.pids.items())


def load_average():
    return "%.2f" % os.getloadavg()[0]


def page_fps(page, seconds, counter="prtView.framesDrawn"):
    """Frames drawn on the page per second over `seconds`, counted by the page itself."""
    f0, t0 = page.evaluate("[%s, performance.now()]" % counter)
    time.sleep(seconds)
    f1, t1 = page.evaluate("[%s, performance.now()]" % counter)
    return (f1 - f0) * 1000.0 / (t1 - t0)


def measured_runs(name, page, a, pids, counter="prtView.framesDrawn"):
    """`a.runs` frame rates, each with the load before it and the cores used during it; says the
    runs and their median, returns the median."""
    runs = []
    for i in range(a.runs):
        say("%s_load_before_run%d" % (name, i + 1), load_average())
        cores = Cores(pids)
        runs.append(page_fps(page, a.seconds, counter))
        say("%s_cores_run%d" % (name, i + 1), cores.line())
    say(name + "_fps_runs", ",".join("%.1f" % r for r in runs))
    say(name + "_fps", "%.1f" % statistics.median(runs))
    return statistics.median(runs)


# Busy whenever it has used less than half of the time since it started, asleep otherwise: it
# takes half a core whenever the scheduler lets it, whatever else runs.
LOAD_SCRIPT = """import time
t0, c0 = time.monotonic(), time.process_time()
while True:
    if time.process_time() - c0 < 0.5 * (time.monotonic() - t0):
        t = time.perf_counter() + 0.001
        while time.perf_counter() < t: pass
    else:
        time.sleep(0.001)
"""


def start_load():
    """Another process taking half a core."""
    return subprocess.Popen([sys.executable, "-c", LOAD_SCRIPT])


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
    page.wait_for("prtView.answered === prtView.input")
    return statistics.median(page.evaluate("prtView.latencies"))


def view_phase(a, load):
    """prt view in chromium: SH (and wavelets) turning, and input to picture; with `load`,
    another process takes half a core throughout. Returns the SH frame rate."""
    suffix = "_loaded" if load else ""
    threads = ["--threads", str(a.view_threads)] if a.view_threads else []
    view = subprocess.Popen([a.prt, "view", "--port", "0", "--size", "640x480", "--quiet"] + threads,
                            stdout=subprocess.PIPE, text=True)
    loader = None
    try:
        address = view.stdout.readline().strip()
        say("view_address", address)
        with cdp.Browser() as browser:
            page = browser.open(address)
            page.wait_for("window.prtView && prtView.framesDrawn >= 1", timeout=300)
            if load:
                loader = start_load()
            pids = {"prt": view.pid, "browser": browser.process.pid, "load": loader.pid if loader else None}
            playing(page, True)
            time.sleep(1.0)
            sh = measured_runs("view_sh_lmax4" + suffix, page, a, pids)
            playing(page, False)
            say("view_sh_draw_ms" + suffix, page.evaluate("document.getElementById('drawms').textContent"))
            say("view_sh_input_to_picture_ms" + suffix, "%.1f" % input_latency(page, 30))
            say("view_sh_out_of_order_frames" + suffix, page.evaluate("prtView.outOfOrder"))
            # The page idle (the light still, its still frame shown): what it costs the machine.
            page.wait_for("prtView.still && prtView.answered === prtView.input")
            idle = Cores(pids)
            time.sleep(a.seconds)
            say("view_idle_cores" + suffix, idle.line())
            if not a.no_wavelet and not load:
                t0 = time.monotonic()
                page.evaluate("(() => { const b = document.getElementById('basis'); b.value = 'wavelet';"
                              " b.dispatchEvent(new Event('change')); })()")
                page.wait_for("document.getElementById('status').textContent === '' && prtView.lastQuery.includes('basis=wavelet')",
                              timeout=1800, interval=0.5)
                say("view_wavelet_precompute_s", "%.1f" % (time.monotonic() - t0))
                playing(page, True)
                time.sleep(1.0)
                measured_runs("view_wavelet", page, a, pids)
                playing(page, False)
                say("view_wavelet_draw_ms", page.evaluate("document.getElementById('drawms').textContent"))
                say("view_wavelet_input_to_picture_ms", "%.1f" % input_latency(page, 30))
    finally:
        if loader:
            loader.kill()
            loader.wait()
        view.terminate()
        view.wait()
    return sh


def stand_in_phase(a, load):
    """The WebGL stand-in, served from this folder, in chromium with SwiftShader for WebGL."""
    suffix = "_loaded" if load else ""
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=HERE)
    handler.log_message = lambda *args: None
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    loader = None
    try:
        with cdp.Browser(extra_args=["--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                                     "--ignore-gpu-blocklist"]) as browser:
            page = browser.open("http://127.0.0.1:%d/webgl_stand_in.html" % server.server_address[1])
            page.wait_for("window.bench && bench.frames >= 2", timeout=120)
            if not load:
                say("webgl_renderer", page.evaluate(
                    "(() => { const gl = document.createElement('canvas').getContext('webgl');"
                    " const e = gl.getExtension('WEBGL_debug_renderer_info');"
                    " return e ? gl.getParameter(e.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER); })()"))
                say("webgl_mesh", page.evaluate("meshInfo.vertices + ' vertices, ' + meshInfo.triangles + ' triangles'"))
            if load:
                loader = start_load()
            time.sleep(1.0)
            pids = {"browser": browser.process.pid, "load": loader.pid if loader else None}
            return measured_runs("webgl_stand_in" + suffix, page, a, pids, "bench.frames")
    finally:
        if loader:
            loader.kill()
            loader.wait()
        server.shutdown()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("prt")
    ap.add_argument("--seconds", type=float, default=3.0)
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--no-wavelet", action="store_true")
    ap.add_argument("--no-load", action="store_true")
    ap.add_argument("--no-stand-in", action="store_true")
    ap.add_argument("--view-threads", type=int, default=0, help="prt view --threads N (0: its default, every core)")
    a = ap.parse_args()
    say("cpu_model", cpu_model())
    say("cpu_count", os.cpu_count())
    say("browser", cdp.find_chromium())
    say("note", "frame rates while the light turns are at interactive quality (ssaa 1; wavelets: fewer light "
                "cells), the still frame follows when it stops; webgl_stand_in is the stand-in for the course's "
                "viewer, which does less per frame than the course's own (38 against 31 fps when measured), "
                "so a target met against it is met against the course's")
    say("view_threads", a.view_threads or "default (every core)")
    sh = view_phase(a, False)
    if not a.no_stand_in:
        stand_in = stand_in_phase(a, False)
        say("view_sh_over_stand_in", "%.2f" % (sh / stand_in))
    if not a.no_load:
        sh = view_phase(a, True)
        if not a.no_stand_in:
            stand_in = stand_in_phase(a, True)
            say("view_sh_over_stand_in_loaded", "%.2f" % (sh / stand_in))
    return 0


if __name__ == "__main__":
    sys.exit(main())
