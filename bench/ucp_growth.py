#!/usr/bin/env python3
"""Growth of `contactcert ucp` with the number of contacts (docs/bench.md, "The UCP at scale").

    bench/ucp_growth.py BUILD/contactcert [OTHER/contactcert] [--nc 10,20,40,80,120,160] [--repeats 3]
                        [--arith float,verified,adaptive,exact] [--time-limit 60] [--max-seed 200]

For each nc: the first seed whose section 5 problem (`ucp --generate random --nc N --seed S`) is solvable and the
first that is jammed (classified by the float path), then `ucp FILE --json` on each arith (exact paths also write
their certificate), timed as the child's CPU seconds (user + sys), median of the repeats. Prints a Markdown table
with LPs, nodes, the phases of the JSON (CPU ms), the end-to-end CPU ms, and with OTHER (an older build) its
end-to-end CPU ms and the ratio OTHER / ours; then the exponent of each phase fitted over nc (least squares of
log time on log nc).
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile

PHASES = ["parse", "build", "solve", "recover", "check", "certificate"]


def run(binary, args, time_limit):
    """(JSON or None, child CPU seconds) of one `binary args` run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run([binary] + args + ["--time-limit", str(time_limit)], capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    try:
        return json.loads(p.stdout.strip().splitlines()[-1]), cpu
    except (ValueError, IndexError):
        return None, cpu


def find_problems(binary, nc, work, time_limit, max_seed):
    """{kind: file} for the first solvable and the first jammed seed below max_seed (float classification)."""
    found = {}
    for seed in range(1, max_seed):
        if len(found) == 2:
            break
        f = os.path.join(work, f"nc{nc}_seed{seed}.json")
        subprocess.run([binary, "ucp", "--generate", "random", "--nc", str(nc), "--seed", str(seed), "--out", f],
                       check=True)
        j, _ = run(binary, ["ucp", f, "--arith", "float", "--json"], time_limit)
        status = j["status"] if j else "unknown"
        if status in ("solvable", "jammed") and status not in found:
            found[status] = (seed, f)
    return found


def median(v):
    v = sorted(v)
    return v[len(v) // 2]


def measure(binary, f, arith, repeats, time_limit, work):
    args = ["ucp", f, "--arith", arith, "--json"]
    if arith != "float":
        args += ["--certificate", os.path.join(work, "cert.json")]
    runs = [run(binary, args, time_limit) for _ in range(repeats)]
    runs.sort(key=lambda r: r[1])
    return runs[len(runs) // 2]


def slope(points):
    pts = [(math.log(n), math.log(t)) for n, t in points if t > 2e-5]
    if len(pts) < 3:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ours")
    ap.add_argument("other", nargs="?")
    ap.add_argument("--nc", default="10,20,40,80,120,160")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--arith", default="float,verified,adaptive,exact")
    ap.add_argument("--time-limit", type=float, default=60)
    ap.add_argument("--max-seed", type=int, default=200)
    a = ap.parse_args()
    ncs = [int(x) for x in a.nc.split(",")]
    ariths = a.arith.split(",")
    work = tempfile.mkdtemp(prefix="ucp_growth_")
    rows = []
    print("| nc | kind | seed | arith | verdict | LPs | nodes | " + " | ".join(PHASES) +
          " | end to end | " + ("other | other/ours |" if a.other else ""))
    print("|" + "---|" * (14 + (2 if a.other else 0)))
    for nc in ncs:
        problems = find_problems(a.ours, nc, work, a.time_limit, a.max_seed)
        for kind in ("solvable", "jammed"):
            if kind not in problems:
                print(f"| {nc} | {kind} | - | no {kind} seed below {a.max_seed} |")
                continue
            seed, f = problems[kind]
            for arith in ariths:
                repeats = a.repeats if nc <= 40 else 1
                j, cpu = measure(a.ours, f, arith, repeats, a.time_limit, work)
                ph = j.get("phases", {}) if j else {}
                row = {"nc": nc, "kind": kind, "arith": arith, "cpu": cpu, "phases": ph}
                cells = [str(nc), kind, str(seed), arith, j["status"] if j else "error", str(j.get("lps", "")) if j else "",
                         str(j.get("nodes", "")) if j else ""]
                cells += [f"{1e3 * ph.get(p, 0):.2f}" for p in PHASES]
                cells.append(f"**{1e3 * cpu:.1f}**")
                if a.other:
                    jo, cpu_o = measure(a.other, f, arith, repeats, a.time_limit, work)
                    verdict_o = jo["status"] if jo else "error"
                    cells.append(f"{1e3 * cpu_o:.1f}" + ("" if verdict_o == (j or {}).get("status") else f" ({verdict_o})"))
                    cells.append(f"{cpu_o / cpu:.1f}x")
                rows.append(row)
                print("| " + " | ".join(cells) + " |")
                sys.stdout.flush()
    print("\nFitted exponent of each phase (CPU time ~ nc^k, least squares over the nc values; - = too small to fit)\n")
    print("| kind | arith | " + " | ".join(PHASES) + " | end to end |")
    print("|" + "---|" * (3 + len(PHASES)))
    for kind in ("solvable", "jammed"):
        for arith in ariths:
            sel = [r for r in rows if r["kind"] == kind and r["arith"] == arith]
            cells = [kind, arith]
            for p in PHASES:
                k = slope([(r["nc"], r["phases"].get(p, 0)) for r in sel])
                cells.append("-" if k is None else f"{k:.1f}")
            k = slope([(r["nc"], r["cpu"]) for r in sel])
            cells.append("-" if k is None else f"{k:.1f}")
            print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
