#!/usr/bin/env python3
"""Mutation check of the test suite: does every deliberate bug make some test fail?

    python3 scripts/mutants.py [NAME_FILTER ...]  all mutants of tests/mutants.txt, or those whose
                                                  name contains one of the NAME_FILTERs

Each mutant of tests/mutants.txt replaces one exact piece of a source file. The script copies
the project to build-mutants/src (never touching the checkout), builds it once, then for each
mutant: applies it, rebuilds, runs the test programs of every tier (unit, threads, e2e, readme: tests/README.md;
then any other prt_*_tests program, and the tests that are scripts, CTest label `script`)
as a fresh clone would (PRT_SHARED_DATA=none, so the course data cannot be what catches it; tests that
run with the data are a superset), stops at the first failure (its output is kept in build-mutants/log/), and restores the file. It prints CAUGHT or SURVIVED per mutant and
exits 1 if any survived. A mutant whose text is no longer in its file is an error: the list
must follow the code.

tests/mutants.txt holds blocks of the form
    === name
    path/of/file.cpp
    <<<
    exact text to find (once)
    >>>
    replacement
    ===
"""
import glob
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(ROOT, "build-mutants")
COPY = os.path.join(WORK, "src")
BUILD = os.path.join(WORK, "build")


def parse(path):
    mutants, lines, i = [], open(path).read().split("\n"), 0
    while i < len(lines):
        if not lines[i].startswith("=== "):
            i += 1
            continue
        name, file = lines[i][4:].strip(), lines[i + 1].strip()
        assert lines[i + 2] == "<<<", f"{name}: expected <<<"
        j = lines.index(">>>", i + 3)
        k = lines.index("===", j + 1)
        mutants.append((name, file, "\n".join(lines[i + 3:j]), "\n".join(lines[j + 1:k])))
        i = k + 1
    return mutants


def sync(source, target):
    """Makes `target` a copy of `source` (without build folders, out/ and .git). Only files whose
    bytes differ are written, and they get a fresh modification time, so the copy's build
    recompiles exactly what changed, including what an interrupted run left mutated."""
    skip = lambda name: name.startswith("build") or name in ("out", ".git")
    wanted = set()
    for folder, dirs, files in os.walk(source):
        dirs[:] = [d for d in dirs if not skip(d)]
        for name in files:
            rel = os.path.relpath(os.path.join(folder, name), source)
            wanted.add(rel)
            data = open(os.path.join(source, rel), "rb").read()
            dest = os.path.join(target, rel)
            if not os.path.exists(dest) or open(dest, "rb").read() != data:
                os.makedirs(os.path.dirname(dest), exist_ok=True)
                open(dest, "wb").write(data)
    for folder, dirs, files in os.walk(target):
        dirs[:] = [d for d in dirs if not skip(d)]
        for name in files:
            if os.path.relpath(os.path.join(folder, name), target) not in wanted:
                os.remove(os.path.join(folder, name))


def run(cmd, **kw):
    # A failing check may print raw bytes (two files compared byte for byte): never a crash here.
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, encoding="utf-8", errors="replace", **kw)


def main():
    wanted = sys.argv[1:] or [""]
    mutants = [m for m in parse(os.path.join(ROOT, "tests", "mutants.txt")) if any(w in m[0] for w in wanted)]
    os.makedirs(WORK, exist_ok=True)
    sync(ROOT, COPY)
    jobs = str(os.cpu_count() or 2)
    shared = os.path.join(os.path.dirname(ROOT), "shared")
    if os.path.isdir(shared) and not os.path.exists(os.path.join(WORK, "shared")):
        os.symlink(shared, os.path.join(WORK, "shared"))  # PRT_SHARED_DATA_DIR resolves beside the copy
    r = run(["cmake", "-S", COPY, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release"])
    if r.returncode:
        sys.exit(r.stdout)
    build = ["cmake", "--build", BUILD, "--parallel", jobs]
    r = run(build)
    if r.returncode:
        sys.exit(r.stdout[-3000:])
    env = dict(os.environ, PRT_SHARED_DATA="none")
    env.pop("PRT_REQUIRE_SHARED_DATA", None)
    programs = [os.path.join(BUILD, f"prt_{tier}_tests") for tier in ("unit", "threads", "e2e", "readme")]
    # Programs of a tier built with other sources (tests/basis: prt_stub_basis_tests), after those.
    programs += sorted(p for p in glob.glob(os.path.join(BUILD, "prt_*_tests")) if p not in programs)

    def test():
        """The programs in turn until one fails, then the tests that are scripts, not cases of a
        program (CTest label `script`): the first failure's output."""
        out = ""
        for program in programs:
            r = run([program, "--no-intro=true", "--abort-after=1", "--no-version=true"], env=env)
            out += r.stdout
            if r.returncode:
                return subprocess.CompletedProcess(r.args, r.returncode, out)
        r = run(["ctest", "--test-dir", BUILD, "-L", "^script$", "--output-on-failure"], env=env)
        out += r.stdout
        if r.returncode:
            return subprocess.CompletedProcess(r.args, r.returncode, out)
        return subprocess.CompletedProcess(programs, 0, out)

    r = test()
    if r.returncode:
        sys.exit("the unmutated suite fails:\n" + r.stdout[-3000:])
    survived = []
    os.makedirs(os.path.join(WORK, "log"), exist_ok=True)
    for number, (name, file, old, new) in enumerate(mutants):
        path = os.path.join(COPY, file)
        text = open(path).read()
        if text.count(old) != 1:
            sys.exit(f"{name}: its text is found {text.count(old)} times in {file}, not once")
        start = time.time()
        try:
            open(path, "w").write(text.replace(old, new))
            r = run(build)
            if r.returncode:
                print(f"NO BUILD  {name}\n{r.stdout[-2000:]}")
                survived.append(name)
                continue
            r = test()
            with open(os.path.join(WORK, "log", f"{number:02d}.txt"), "w") as log:
                log.write(f"{name}\n{r.stdout}")
            caught = r.returncode != 0
            where, case = "", ""
            for line in r.stdout.splitlines():
                if "TEST CASE:" in line:
                    case = line.split("TEST CASE:")[1].strip()
                if ("ERROR:" in line or "FATAL" in line) and case:
                    where = case
                    break
            print(f"{'CAUGHT  ' if caught else 'SURVIVED'}  {name}  ({time.time() - start:.0f} s){'  by: ' + where if where else ''}",
                  flush=True)
            if not caught:
                survived.append(name)
        finally:
            open(path, "w").write(text)  # a fresh modification time: the next build recompiles it
    run(build)
    print(f"{len(mutants) - len(survived)} of {len(mutants)} mutants caught")
    sys.exit(1 if survived else 0)


if __name__ == "__main__":
    main()
