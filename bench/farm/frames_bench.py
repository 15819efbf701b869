"""prt render by frame range, on this machine: what splitting a sequence into ranges costs.

Runs `prt render` of F frames once (its transport from a warm cache, as a farm's frame tasks
find it after the merge; median of --runs), then the same sequence as M ranges (`--frame-range
auto` under a stand-in of Slurm's array variables), one range after another into one folder, each
its own process measured by wait4, for each M of --ranges, then `prt video` of the ranges'
frames. Prints key=value lines, the CPU first:

  one_run_cpu_s, one_run_wall_s, one_run_peak_mb   the whole sequence in one run (medians)
  ranges_cpu_s_M, range_peak_mb_M                  the M ranges summed, the largest range
  ratio_ranges_cpu_over_one_run_M=x                the M ranges and prt video over the one run
                                                   with --video: what the ranges add (each loads
                                                   the mesh, the light and the cache, and a range
                                                   after frame 0 draws frame 0 again for the
                                                   exposure) and the video's decoding of the PNGs
  video_cpu_s                                      prt video of the frames (an animated PNG)
  identical_M=1                                    the frames and the video are the one run's

    python3 bench/farm/frames_bench.py build/prt [--mesh PATH] [--frames F] [--size WxH] [--ranges 2,8,32] [--runs R]
The default mesh is the course's mary (../shared/data); without it, prt sample-files' scene.
"""
import argparse
import os
import shutil
import statistics
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
sys.path.insert(0, HERE)
from machine import cpu_model  # noqa: E402
from processes import default_mesh, files, measured  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("prt")
    ap.add_argument("--mesh")
    ap.add_argument("--frames", type=int, default=96)
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--ranges", default="2,8,32")
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    prt = os.path.abspath(a.prt)
    work = tempfile.mkdtemp(prefix="prt-frames-bench-")
    mesh = a.mesh or default_mesh(prt, work)
    cache = os.path.join(work, "transport.cache")
    options = ["--mesh", mesh, "--frames", str(a.frames), "--size", a.size, "--cache", cache, "--quiet"]

    print("cpu=%s" % cpu_model())
    print("cores=%d" % os.cpu_count())
    print("load_before=%.2f" % os.getloadavg()[0])
    print("mesh=%s" % mesh)
    print("frames=%d" % a.frames)
    print("size=%s" % a.size)

    warm = os.path.join(work, "warm")  # the cache, as a farm's merge leaves it
    measured([prt, "render", *options, "--out", warm, "--frame-range", "0-0"])
    one = []
    for _ in range(a.runs):
        out = os.path.join(work, "one")
        shutil.rmtree(out, ignore_errors=True)
        one.append(measured([prt, "render", *options, "--out", out, "--video", os.path.join(out, "turn.png")]))
    one_cpu = statistics.median(x[0] for x in one)
    print("one_run_cpu_s=%.3f" % one_cpu)
    print("one_run_wall_s=%.3f" % statistics.median(x[1] for x in one))
    print("one_run_peak_mb=%.1f" % statistics.median(x[2] for x in one))
    expected = files(os.path.join(work, "one"))

    video_cpu = []
    for m in [int(x) for x in a.ranges.split(",")]:
        out = os.path.join(work, "ranges%d" % m)
        shutil.rmtree(out, ignore_errors=True)
        cpu_sum = peak = 0.0
        for i in range(m):
            env = dict(os.environ, SLURM_ARRAY_TASK_ID=str(i), SLURM_ARRAY_TASK_COUNT=str(m))
            cpu, _, mb = measured([prt, "render", *options, "--out", out, "--frame-range", "auto"], env)
            cpu_sum += cpu
            peak = max(peak, mb)
        cpu, _, _ = measured([prt, "video", out, "--video", os.path.join(out, "turn.png"), "--quiet"])
        video_cpu.append(cpu)
        print("ranges_cpu_s_%d=%.3f" % (m, cpu_sum))
        print("range_peak_mb_%d=%.1f" % (m, peak))
        print("ratio_ranges_cpu_over_one_run_%d=%.3f" % (m, (cpu_sum + cpu) / one_cpu))
        print("identical_%d=%d" % (m, int(files(out) == expected)))
    print("video_cpu_s=%.3f" % statistics.median(video_cpu))
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
