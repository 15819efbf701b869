"""prt precompute as a farm job, on this machine: what the shards cost beside one run.

Runs `prt precompute` once on one machine (median of --runs), then as N shard tasks and their
merges (prt precompute --shard I/N, prt merge; interreflection: the direct pass and each bounce
as stages, docs/CLI.md "A farm job") for each N of --shards, one task after another, each its own
process measured by wait4: CPU seconds (user + system), wall seconds, peak resident memory.
Prints key=value lines as `prt bench` does, the CPU first:

  one_run_cpu_s, one_run_wall_s, one_run_peak_mb        the single run (medians)
  tasks_cpu_s_N, merges_cpu_s_N, task_peak_mb_N         the N tasks summed over every stage,
                                                        the merges summed, the largest task
  identical_N=1                                         the merged folder is the single run's, byte for byte
  ratio_tasks_cpu_over_one_run_N=x                      the shards' overhead (each task loads the
                                                        mesh, splits the senders, builds the BVH)
  ratio_merges_cpu_over_one_run_N=x                     what the merges add

Then a model, not a measurement, of the wall time on M machines like this one (M = N shards):
each stage's slowest task, from a fit of the measured task wall times against their block sizes
(t = a + b x vertices: a the fixed cost of a task, b its cost per vertex), plus the stage's merge
(measured at the largest N), plus the shared file system moving each stage's files at --fs-mb-s
MB/s (an assumption, printed): a task's part of the rows and of the hits, and the state, then the
merge's reading of every row. model_speedup_M = one run's wall / that.

    python3 bench/farm/farm_bench.py build/prt [--mesh PATH] [--transport MODE] [--bounces B] [--shards 2,4,16]
                                               [--runs R] [--model 16,64] [--fs-mb-s 100]
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


def folder_bytes(folder):
    return sum(os.path.getsize(os.path.join(folder, n)) for n in os.listdir(folder))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("prt")
    ap.add_argument("--mesh")
    ap.add_argument("--bounces", type=int, default=1)
    ap.add_argument("--transport", default="interreflection")
    ap.add_argument("--shards", default="2,4,16")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--model", default="16,64")
    ap.add_argument("--fs-mb-s", type=float, default=100.0)
    a = ap.parse_args()
    prt = os.path.abspath(a.prt)
    work = tempfile.mkdtemp(prefix="prt-farm-bench-")
    mesh = a.mesh or default_mesh(prt, work)
    bounced = a.transport == "interreflection"
    options = ["--mesh", mesh, "--transport", a.transport, "--quiet"] + (["--bounces", str(a.bounces)] if bounced else [])
    stages = a.bounces + 1 if bounced else 1

    print("cpu=%s" % cpu_model())
    print("cores=%d" % os.cpu_count())
    print("load_before=%.2f" % os.getloadavg()[0])
    print("mesh=%s" % mesh)
    print("transport=%s" % a.transport)
    if bounced:
        print("bounces=%d" % a.bounces)

    one = []
    for r in range(a.runs):
        out = os.path.join(work, "one")
        shutil.rmtree(out, ignore_errors=True)
        one.append(measured([prt, "precompute", *options, "--out", out]))
    one_cpu = statistics.median(x[0] for x in one)
    one_wall = statistics.median(x[1] for x in one)
    print("one_run_cpu_s=%.3f" % one_cpu)
    print("one_run_wall_s=%.3f" % one_wall)
    print("one_run_peak_mb=%.1f" % statistics.median(x[2] for x in one))
    expected = files(os.path.join(work, "one"))

    fit_points = {}  # stage -> [(block vertices, wall)]
    merge_wall = {}
    state_bytes = 0
    for n in [int(x) for x in a.shards.split(",")]:
        out = os.path.join(work, "farm%d" % n)
        shutil.rmtree(out, ignore_errors=True)
        tasks_cpu = merges_cpu = peak = 0.0
        for stage in range(stages):
            before = set(os.listdir(out)) if os.path.isdir(out) else set()
            for i in range(n):
                cpu, wall, mb = measured([prt, "precompute", *options, "--out", out, "--shard", "%d/%d" % (i, n)] +
                                         (["--bounce-stage", str(stage)] if bounced else []))
                tasks_cpu += cpu
                peak = max(peak, mb)
                new = [f for f in set(os.listdir(out)) - before if ".shard-%05d-of-" % i in f]
                size = lambda names: sum(os.path.getsize(os.path.join(out, f)) for f in names)
                # The rows, which the merge reads, and the hits, which only the task's own later
                # stages read.
                rows = size(f for f in new if ".hits." not in f)
                hits = size(f for f in new if ".hits." in f)
                fit_points.setdefault(stage, []).append((n, wall, rows, hits))
            cpu, wall, _ = measured([prt, "merge", out, "--quiet"] + (["--bounce-stage", str(stage)] if bounced else []))
            merges_cpu += cpu
            merge_wall.setdefault(stage, {})[n] = wall
            if os.path.exists(os.path.join(out, "transport.cache.bounces")):
                state_bytes = max(state_bytes, os.path.getsize(os.path.join(out, "transport.cache.bounces")))
        same = files(out) == expected
        print("tasks_cpu_s_%d=%.3f" % (n, tasks_cpu))
        print("merges_cpu_s_%d=%.3f" % (n, merges_cpu))
        print("task_peak_mb_%d=%.1f" % (n, peak))
        print("identical_%d=%d" % (n, 1 if same else 0))
        print("ratio_tasks_cpu_over_one_run_%d=%.3f" % (n, tasks_cpu / one_cpu))
        print("ratio_merges_cpu_over_one_run_%d=%.3f" % (n, merges_cpu / one_cpu))

    # The model: per stage, task wall = a + b / N of the whole (fit over the measured N).
    largest = max(int(x) for x in a.shards.split(","))
    print("model_note=a model from the measured task times, not a measurement; shared file system at %.0f MB/s a machine (assumed)" % a.fs_mb_s)
    for m in [int(x) for x in a.model.split(",")]:
        total = 0.0
        for stage in range(stages):
            pts = fit_points[stage]
            xs = [1.0 / n for n, _, _, _ in pts]
            ys = [w for _, w, _, _ in pts]
            mx, my = statistics.mean(xs), statistics.mean(ys)
            sxx = sum((x - mx) ** 2 for x in xs)
            b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx else 0.0
            fixed = my - b * mx
            # The stage's files, at the largest N measured: each machine writes its part of the
            # rows and of the hits (at stage 0; it reads its hits back at every later stage) and
            # reads the state; the merge reads every row and writes the state.
            rows_mb = sum(r for n, _, r, _ in pts if n == largest) / 1e6
            hits_mb = max(sum(h for n, _, _, h in fit_points[0] if n == largest) / 1e6, 0.0)
            fs = (rows_mb / m + hits_mb / m + state_bytes / 1e6) / a.fs_mb_s + (rows_mb + state_bytes / 1e6) / a.fs_mb_s
            total += fixed + b / m + fs + merge_wall[stage][largest]
            if m == int(a.model.split(",")[0]):
                print("model_stage%d_task_fixed_s=%.3f" % (stage, fixed))
                print("model_stage%d_work_s=%.3f" % (stage, b))
                print("model_stage%d_merge_s=%.3f" % (stage, merge_wall[stage][largest]))
        print("model_wall_s_%d=%.3f" % (m, total))
        print("model_speedup_%d=%.2f" % (m, one_wall / total))
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
