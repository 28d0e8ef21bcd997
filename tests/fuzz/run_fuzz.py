#!/usr/bin/env python3
"""The hostile-input suite of latmpm (docs/robustness.md): every tool run against malformed
and hostile inputs, and asserted for each case to

  - not crash     (no death by a signal it was not sent; no exit status 4, internal error)
  - not hang      (finishes within the case's timeout)
  - not inject    (no file PWNED appears: hostile names try `touch PWNED` every way we know)
  - leave nothing (no staging file .*.tmp.* anywhere, $TMPDIR empty, and on failure no
                   output at all unless the case allows one, e.g. a run directory)
  - exit as documented (the statuses the case allows) with exactly one line on stderr
    naming the tool, when it fails.

  python3 tests/fuzz/run_fuzz.py --bin build/bin [--subset] [--jobs N] [--keep] [-k NAME]

The cases are in fuzz_cases.py. `make fuzz` runs all of them; ctest runs the subset (a few
of each kind, under a minute). Exit status 0 when every case holds, 1 otherwise.
"""
import argparse
import concurrent.futures
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fuzz_cases  # noqa: E402

CRASH_SIGNALS = {signal.SIGSEGV, signal.SIGABRT, signal.SIGBUS, signal.SIGFPE, signal.SIGILL}


def file_set(root):
    """Every file and directory under root, relative."""
    found = set()
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            found.add(os.path.relpath(os.path.join(dirpath, name), root))
    return found


def is_staging(path):
    name = os.path.basename(path)
    return ".tmp." in name or ".tmp-" in name or name.startswith(".gnuplot-errors")


def run_case(case, env_base, workdir):
    """Runs one case in a fresh directory; returns (case, problems, seconds, status, stderr)."""
    case_dir = os.path.join(workdir, "case-%04d" % case.index)
    os.makedirs(case_dir)
    tmp_dir = os.path.join(case_dir, ".tmpdir")
    os.makedirs(tmp_dir)
    if case.setup:
        try:
            case.setup(case_dir)
        except Exception as e:  # a bug of the suite, not of the tool: reported as a failure
            return case, ["setup failed: %s" % e], 0.0, None, ""
    before = file_set(case_dir)
    env = dict(env_base, TMPDIR=tmp_dir)

    def limits():
        os.setpgrp()
        if case.fsize_kb is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write beyond the limit fails (EFBIG)
            resource.setrlimit(resource.RLIMIT_FSIZE, (case.fsize_kb * 1024, case.fsize_kb * 1024))

    start = time.monotonic()
    problems = []
    proc = subprocess.Popen(case.command, cwd=case_dir, env=env, stdin=subprocess.PIPE if case.stdin is not None
                            else subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            preexec_fn=limits, shell=isinstance(case.command, str))
    try:
        if case.send_signal is not None:
            signo, trigger = case.send_signal
            deadline = time.monotonic() + case.timeout
            while not trigger(case_dir) and proc.poll() is None and time.monotonic() < deadline:
                time.sleep(0.01)
            if proc.poll() is None:
                os.killpg(proc.pid, signo) if case.signal_group else proc.send_signal(signo)
            else:
                problems.append("finished before the signal could be sent (case too short)")
        if case.head_bytes is not None:
            proc.stdout.read(case.head_bytes)
            proc.stdout.close()
            _, err = proc.communicate(timeout=case.timeout)
            out = b""
        else:
            out, err = proc.communicate(input=case.stdin, timeout=case.timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return case, ["hang: no exit within %g s" % case.timeout], time.monotonic() - start, None, ""
    seconds = time.monotonic() - start
    status = proc.returncode
    text = err.decode("utf-8", "replace")
    lines = [l for l in text.splitlines() if l.strip()]
    if case.send_signal is not None and status == -case.send_signal[0]:
        # Ended by the signal's default action, before the tool had installed its handler: as
        # documented (128+N), with nothing written yet and so nothing to say.
        status = 128 + case.send_signal[0]
        lines = [case.tool + ": (the signal's default action)"]

    if status < 0:
        if -status in CRASH_SIGNALS:
            problems.append("crash: killed by signal %d" % -status)
        else:
            problems.append("died of signal %d instead of exiting" % -status)
    elif status == 4:
        problems.append("internal error (status 4)")
    if status is not None and status >= 0 and status not in case.expect:
        problems.append("exit status %d, expected %s" % (status, sorted(case.expect)))
    if status not in (None, 0):
        tool = case.tool
        own = [l for l in lines if l.startswith(tool + ":")]
        if len(lines) != 1 or len(own) != 1:
            problems.append("%d lines on stderr, expected one naming %s" % (len(lines), tool))
    after = file_set(case_dir)
    if any(os.path.basename(p).upper().startswith("PWNED") for p in after) or \
            os.path.exists(os.path.join(workdir, "PWNED")):
        problems.append("INJECTION: a hostile name ran a command")
    staging = [p for p in after if is_staging(p) and not p.startswith(".tmpdir")]
    if staging:
        problems.append("staging files left: " + ", ".join(sorted(staging)[:3]))
    leftover_tmp = file_set(tmp_dir)
    if leftover_tmp:
        problems.append("files left in TMPDIR: " + ", ".join(sorted(leftover_tmp)[:3]))
    if status not in (None, 0):
        new = sorted(p for p in after - before if not p.startswith(".tmpdir") and not is_staging(p)
                     and not any(p == a or p.startswith(a + os.sep) for a in case.allowed_outputs))
        if new:
            problems.append("outputs left after a failure: " + ", ".join(new[:3]))
    if not problems and case.verify:
        problem = case.verify(case_dir, status, out.decode("utf-8", "replace"), text)
        if problem:
            problems.append(problem)
    return case, problems, seconds, status, lines[0] if lines else ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", required=True, help="directory of the built tools (build/bin)")
    parser.add_argument("--source", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    parser.add_argument("--subset", action="store_true", help="the fast representative subset (ctest)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--keep", action="store_true", help="keep the scratch directory")
    parser.add_argument("-k", dest="pattern", default="", help="only cases whose name contains this")
    parser.add_argument("-v", "--verbose", action="store_true", help="print every case")
    args = parser.parse_args()
    bin_dir = os.path.abspath(args.bin)
    workdir = tempfile.mkdtemp(prefix="latmpm-fuzz-")
    env_base = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""), LC_ALL="C")
    env_base.pop("TMPDIR", None)
    try:
        inputs = fuzz_cases.BaseInputs(os.path.join(workdir, "inputs"), bin_dir, os.path.abspath(args.source), env_base)
        cases = fuzz_cases.all_cases(inputs)
        for i, c in enumerate(cases):
            c.index = i
        if args.subset:
            cases = [c for c in cases if c.subset and c.name not in fuzz_cases.KNOWN]
        if args.pattern:
            cases = [c for c in cases if args.pattern in c.name or args.pattern == c.category]
        failures, known, by_category, counts = [], [], {}, {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for case, problems, seconds, status, first in pool.map(lambda c: run_case(c, env_base, workdir), cases):
                by_category.setdefault(case.category, [0, 0])[0] += 1
                counts[case.tool] = counts.get(case.tool, 0) + 1
                if problems and case.name in fuzz_cases.KNOWN:
                    known.append((case, fuzz_cases.KNOWN[case.name]))
                    problems = ["known, fixed on branch " + fuzz_cases.KNOWN[case.name] + ": " + "; ".join(problems)]
                elif problems:
                    by_category[case.category][1] += 1
                    failures.append((case, problems, status, first))
                if args.verbose or problems:
                    print("%s %-60s status %-4s %5.2fs  %s" % ("FAIL" if problems else "ok  ", case.name[:60], status,
                                                             seconds, "; ".join(problems) or first[:90]), flush=True)
        print("\nlatmpm hostile-input suite%s: %d cases, %d failed" % (" (subset)" if args.subset else "",
                                                                       len(cases), len(failures)))
        for category in sorted(by_category):
            total, failed = by_category[category]
            print("  %-22s %4d cases  %3d failed" % (category, total, failed))
        print("  per tool: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
        kinds = {}
        for _, problems, _, _ in failures:
            for p in problems:
                kind = p.split(":")[0].split(" ")[0]
                kinds[kind] = kinds.get(kind, 0) + 1
        if kinds:
            print("  problems: " + ", ".join("%s %d" % kv for kv in sorted(kinds.items())))
        if known:
            print("  %d known failures, fixed on another branch of issue 20 (fuzz_cases.KNOWN):" % len(known))
            for case, where in known:
                print("    %s -- %s" % (case.name, where))
        return 1 if failures or known else 0
    finally:
        if args.keep:
            print("scratch kept in " + workdir)
        else:
            shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
