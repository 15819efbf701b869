"""What the farm benchmarks share: a prt process measured by wait4, a folder's files as bytes, and
the mesh they run on."""
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def measured(argv, env=None):
    """Runs argv; returns (cpu seconds, wall seconds, peak MB), exiting on failure."""
    t0 = time.monotonic()
    child = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - t0
    err = child.stderr.read().decode(errors="replace")
    child.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("%s: failed: %s\n%s" % (os.path.basename(sys.argv[0]), " ".join(argv), err))
    return usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss / 1024.0


def files(folder):
    """The plain files of `folder`, name -> bytes."""
    out = {}
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            with open(path, "rb") as f:
                out[name] = f.read()
    return out


def default_mesh(prt, work):
    """The course's mary (../shared/data), or else prt sample-files' scene written into `work`."""
    mary = os.path.join(HERE, "..", "..", "..", "shared", "data", "games202", "mary", "mary.obj")
    if os.path.exists(mary):
        return os.path.abspath(mary)
    subprocess.run([prt, "sample-files", "--out", os.path.join(work, "samples"), "--quiet"], check=True)
    return os.path.join(work, "samples", "scene.obj")
