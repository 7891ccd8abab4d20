#!/usr/bin/env python3
"""Mutation check of the core's kernels (issue 16).

Applies the one-token mutations listed in mutants.txt one at a time to a
private copy of the sources (never the working tree), rebuilds the gtest
executable RadiosityCoreTests, runs it with the mutant's --gtest_filter and
records whether a test failed (the mutant is killed), all passed (it
survived), the run hung past the timeout (killed: a hang is a failure) or the
mutant did not compile (invalid, not counted).

Usage:
  run_mutants.py [--source DIR] [--build DIR] [--only ID[,ID...]] [--check]
                 [--results FILE] [--jobs N] [--timeout S]

--source  the private copy (default: a detached git worktree of this
          repository's HEAD at /work/mutation-src, created when missing)
--build   its build directory (default /work/mutation-build, configured when
          it has no CMakeCache.txt)
--only    mutant ids (M01,M07) or 1-based positions in the list (1,7)
--check   only verify that every mutant applies (its line is found, the token
          occurs once in it); builds nothing
--results the JSON-lines log of the outcomes (default <build>/mutation-results.jsonl);
          a Markdown table of the same run is written beside it (.md)

mutants.txt holds blocks of `key: value` lines separated by blank lines:
  id:      M01
  kernel:  the kernel it belongs to (free text)
  file:    path relative to the source root
  line:    a fragment that identifies the line (exact substring)
  nth:     which of the lines holding the fragment (1-based, default: it must be unique)
  from:    the original token(s), occurring exactly once in that line
  to:      the replacement (may be empty: a dropped term)
  filter:  the --gtest_filter to run
  why:     what the mutation breaks (free text)
Lines starting with '#' are comments.
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
TARGET = "RadiosityCoreTests"
KEYS = {"id", "kernel", "file", "line", "nth", "from", "to", "filter", "why"}


def parse_mutants(path):
    mutants, current = [], {}
    with open(path, encoding="utf-8") as f:
        for number, raw in enumerate(f, 1):
            line = raw.rstrip("\n")
            if line.startswith("#"):
                continue
            if not line.strip():
                if current:
                    mutants.append(current)
                    current = {}
                continue
            key, sep, value = line.partition(":")
            key = key.strip()
            if not sep or key not in KEYS:
                sys.exit(f"{path}:{number}: expected 'key: value' with key in {sorted(KEYS)}")
            # One space after the colon is the separator; the rest is verbatim.
            current[key] = value[1:] if value.startswith(" ") else value
    if current:
        mutants.append(current)
    for m in mutants:
        for key in ("id", "file", "line", "from", "filter"):
            if key not in m:
                sys.exit(f"mutant {m.get('id', '?')}: missing '{key}'")
        m.setdefault("to", "")
        m.setdefault("kernel", "")
        m.setdefault("why", "")
    ids = [m["id"] for m in mutants]
    if len(ids) != len(set(ids)):
        sys.exit("mutants.txt: duplicate ids")
    return mutants


def mutate(text, m):
    """The mutated text of a file, or raises ValueError saying why not."""
    lines = text.split("\n")
    hits = [i for i, l in enumerate(lines) if m["line"] in l]
    if "nth" in m:
        k = int(m["nth"])
        if not 1 <= k <= len(hits):
            raise ValueError(f"{len(hits)} lines hold {m['line']!r}, nth={k}")
        index = hits[k - 1]
    else:
        if len(hits) != 1:
            raise ValueError(f"{len(hits)} lines hold {m['line']!r} (give nth)")
        index = hits[0]
    line = lines[index]
    if line.count(m["from"]) != 1:
        raise ValueError(f"line {index + 1} holds {m['from']!r} {line.count(m['from'])} times: {line.strip()}")
    lines[index] = line.replace(m["from"], m["to"])
    return "\n".join(lines), index + 1, line.strip(), lines[index].strip()


def run(cmd, timeout=None, log=None, env=None):
    """(returncode or None on timeout, output, seconds)."""
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           errors="replace", timeout=timeout, env=env, start_new_session=True)
        rc, out = p.returncode, p.stdout
    except subprocess.TimeoutExpired as e:
        rc = None
        out = e.stdout if isinstance(e.stdout, str) else (e.stdout or b"").decode("utf-8", "replace")
    seconds = time.monotonic() - start
    if log:
        log.write(f"$ {' '.join(cmd)}  [{seconds:.0f} s, rc {rc}]\n")
        log.write(out[-4000:] + "\n")
        log.flush()
    return rc, out, seconds


def ensure_source(source):
    if os.path.isdir(source):
        return
    subprocess.run(["git", "-C", REPO, "worktree", "add", "--detach", source, "HEAD"], check=True)


def cache_option(name):
    """An option of the lead's build, when there is one, for configuring alike."""
    cache = os.path.join(REPO, "build-lead", "CMakeCache.txt")
    if not os.path.isfile(cache):
        return None
    with open(cache, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith(name + ":"):
                return line.split("=", 1)[1].strip()
    return None


def ensure_build(source, build, log):
    if os.path.isfile(os.path.join(build, "CMakeCache.txt")):
        return
    cmd = ["nice", "cmake", "-S", source, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
           "-DBUILD_TESTING=ON", "-DRADIOSITY_BUILD_BENCH=OFF", "-DRADIOSITY_BUILD_PARAVIEW_PLUGIN=OFF"]
    if shutil.which("ccache"):
        cmd.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    vtk = cache_option("VTK_DIR")
    if vtk:
        cmd.append("-DVTK_DIR=" + vtk)
    rc, out, _ = run(cmd, log=log)
    if rc != 0:
        sys.exit("configure failed:\n" + out[-3000:])


def build_target(build, jobs, log):
    rc, out, seconds = run(["nice", "cmake", "--build", build, "-j", str(jobs), "--target", TARGET], log=log)
    return rc == 0, out, seconds


def run_tests(build, gtest_filter, timeout, log):
    exe = os.path.join(build, "bin", TARGET)
    rc, out, seconds = run(["nice", exe, "--gtest_filter=" + gtest_filter, "--gtest_color=no"],
                           timeout=timeout, log=log)
    failed = sorted(set(re.findall(r"^\[  FAILED  \] (\S+)(?: \(| with|$)", out, re.M)))
    failed = [t for t in failed if "." in t]
    return rc, failed, seconds, out


def markdown(records):
    valid = [r for r in records if r["status"] != "invalid"]
    killed = [r for r in valid if r["status"] in ("killed", "hang")]
    rows = ["| id | kernel | mutation | status | failing tests |", "|---|---|---|---|---|"]
    for r in records:
        mutation = f"`{r['file']}:{r['line_number']}` `{r['from']}` → `{r['to']}`".replace("|", "\\|")
        tests = ", ".join(r["failed"][:4]) + (" …" if len(r["failed"]) > 4 else "")
        rows.append(f"| {r['id']} | {r['kernel']} | {mutation} | {r['status']} | {tests.replace('|', '/')} |")
    ratio = f"{len(killed)}/{len(valid)}" + (f" = {100.0 * len(killed) / len(valid):.0f}%" if valid else "")
    return "\n".join([f"Killed {ratio} of the valid mutants "
                      f"({len(records) - len(valid)} invalid).", ""] + rows) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--source", default="/work/mutation-src")
    ap.add_argument("--build", default="/work/mutation-build")
    ap.add_argument("--list", default=os.path.join(HERE, "mutants.txt"))
    ap.add_argument("--only", default="")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--results", default="")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=0.0,
                    help="seconds per test run (default: 5x the unmutated run, at least 120)")
    args = ap.parse_args()

    mutants = parse_mutants(args.list)
    if args.only:
        wanted = [w.strip() for w in args.only.split(",") if w.strip()]
        chosen = []
        for w in wanted:
            if w.isdigit():
                chosen.append(mutants[int(w) - 1])
            else:
                match = [m for m in mutants if m["id"] == w]
                if not match:
                    sys.exit(f"no mutant {w}")
                chosen.append(match[0])
        mutants = chosen

    ensure_source(args.source)
    problems = 0
    for m in mutants:
        path = os.path.join(args.source, m["file"])
        try:
            with open(path, encoding="utf-8") as f:
                _, number, before, after = mutate(f.read(), m)
            m["line_number"] = number
            if args.check:
                print(f"{m['id']}: {m['file']}:{number}\n  - {before}\n  + {after}")
        except (OSError, ValueError) as e:
            problems += 1
            print(f"{m['id']}: does not apply: {e}", file=sys.stderr)
    if problems:
        sys.exit(f"{problems} mutants do not apply")
    if args.check:
        print(f"{len(mutants)} mutants apply")
        return

    os.makedirs(args.build, exist_ok=True)
    results = args.results or os.path.join(args.build, "mutation-results.jsonl")
    log = open(os.path.join(args.build, "mutation-build.log"), "a", encoding="utf-8")
    ensure_build(args.source, args.build, log)
    head = subprocess.run(["git", "-C", args.source, "rev-parse", "--short", "HEAD"],
                          stdout=subprocess.PIPE, text=True).stdout.strip()
    print(f"source {args.source} at {head}; build {args.build}; {len(mutants)} mutants", flush=True)

    ok, out, seconds = build_target(args.build, args.jobs, log)
    if not ok:
        sys.exit("the unmutated sources do not build:\n" + out[-3000:])
    baseline = {}
    for f in sorted({m["filter"] for m in mutants}):
        rc, failed, seconds, out = run_tests(args.build, f, None, log)
        if rc != 0:
            sys.exit(f"the unmutated tests fail for {f}: {failed or out[-2000:]}")
        baseline[f] = seconds
        print(f"baseline {f}: passes in {seconds:.0f} s", flush=True)

    records = []
    with open(results, "a", encoding="utf-8") as out_file:
        for m in mutants:
            path = os.path.join(args.source, m["file"])
            with open(path, encoding="utf-8") as f:
                original = f.read()
            mutated, number, before, after = mutate(original, m)
            record = {k: m.get(k, "") for k in ("id", "kernel", "file", "from", "to", "filter")}
            record.update(line_number=number, before=before, after=after, head=head, failed=[])
            try:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(mutated)
                built, build_out, build_seconds = build_target(args.build, args.jobs, log)
                record["build_seconds"] = round(build_seconds)
                if not built:
                    record["status"] = "invalid"
                    errors = [l for l in build_out.splitlines() if "error" in l]
                    record["error"] = errors[0][:300] if errors else build_out[-300:]
                else:
                    timeout = args.timeout or max(120.0, 5.0 * baseline[m["filter"]])
                    rc, failed, test_seconds, _ = run_tests(args.build, m["filter"], timeout, log)
                    record["test_seconds"] = round(test_seconds)
                    record["failed"] = failed
                    if rc is None:
                        record["status"] = "hang"
                    elif rc != 0:
                        record["status"] = "killed"
                        if not failed:
                            record["failed"] = [f"exit status {rc}"]
                    else:
                        record["status"] = "survived"
            finally:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(original)
            records.append(record)
            out_file.write(json.dumps(record) + "\n")
            out_file.flush()
            with open(os.path.splitext(results)[0] + ".md", "w", encoding="utf-8") as md:
                md.write(markdown(records))
            print(f"{m['id']} [{m['kernel']}] {record['status']}"
                  f" {' '.join(record['failed'][:3])}"
                  f" (build {record.get('build_seconds', 0)} s, test {record.get('test_seconds', 0)} s)", flush=True)

    # Leave the copy built from the unmutated sources.
    build_target(args.build, args.jobs, log)
    valid = [r for r in records if r["status"] != "invalid"]
    killed = [r for r in valid if r["status"] in ("killed", "hang")]
    print(f"killed {len(killed)} of {len(valid)} valid mutants"
          + (f" ({100.0 * len(killed) / len(valid):.0f}%)" if valid else "")
          + f"; {len(records) - len(valid)} invalid; survivors: "
          + (", ".join(r["id"] for r in valid if r not in killed) or "none"), flush=True)


if __name__ == "__main__":
    main()
