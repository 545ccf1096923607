#!/usr/bin/env python3
"""Growth of the spatial contact-mode tree in the contacts k (docs/bench.md, "Contact modes in space").

    bench/spatial_growth.py BUILD-BENCH/bench/spatial_bench BUILD/cli/contactcert [OTHER/contactcert] [--time-limit 60]

Runs bench/spatial_bench (box on a plane and peg in a hole, k = 4, 8, 16, 32: the walk and its certificate text in
process with the checker's time; strong stability under gravity with its certificate text and the checker's time) and prints its counters
as Markdown tables, each with the exponent of its values fitted over k (least squares of log value on log k, over
k = 8 to 32 where the tree is past its start). Then the command line end to end on the same scenes (written by
`spatial_bench --scenes DIR`): `contactcert modes SCENE --json --certificate FILE` and
`contactcert stability SCENE --wrench 0,0,-1,0,0,0 --json --certificate FILE`, as the child's CPU seconds (user +
sys), its peak resident memory (ru_maxrss of that child alone, from wait4) and the certificate's size, then
`contactcert check FILE` on the stability certificate; with OTHER (an older build) its CPU seconds and peak memory and
the ratio of CPU OTHER / ours side by side. A run stopped by --time-limit or a budget shows its
exit code (3).
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

KS = [4, 8, 16, 32]
VERDICTS = ["strongly stable", "weakly stable", "unstable"]  # StabilityVerdict's order


def fit(ks, values):
    """The exponent b of value ~ a k^b, least squares of log value on log k."""
    xs, ys = [math.log(k) for k in ks], [math.log(v) for v in values]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


GRAVITY = ["--wrench", "0,0,-1,0,0,0"]


def timed(argv, peak=None):
    """(child CPU seconds, exit code) of one run; its peak resident memory in MB appended to `peak` if given."""
    p = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if peak is not None:
        peak.append(usage.ru_maxrss / 1024)  # KB on Linux
    return usage.ru_utime + usage.ru_stime, p.returncode


def cli(binary, command, scene, cert, limit, peak=None):
    """(child CPU seconds, certificate bytes or None, exit code, check CPU seconds or None) of one `modes` or
    `stability` run (the latter's certificate then checked by the same binary); its peak memory into `peak`."""
    extra = GRAVITY if command == "stability" else []
    cpu, rc = timed([binary, command, scene, *extra, "--json", "--certificate", cert, "--time-limit", str(limit)],
                    peak)
    size = os.path.getsize(cert) if rc == 0 and os.path.exists(cert) else None
    check = None
    if size and command == "stability":
        check, crc = timed([binary, "check", cert])
        check = check if crc == 0 else None
    if os.path.exists(cert):
        os.remove(cert)
    return cpu, size, rc, check


def table(rows, name, columns, fitted):
    """One Markdown table of a benchmark's counters per case, then the fitted exponents of `fitted`."""
    print("| scene | k | " + " | ".join(columns.values()) + " |")
    print("|---" * (len(columns) + 2) + "|")
    for (bench, shape, k), b in sorted(rows.items()):
        if bench == name:
            cells = [VERDICTS[int(b[c])] if c == "verdict" else f"{b[c]:.0f}" for c in columns]
            print(f"| {shape} | {k} | " + " | ".join(cells) + " |")
    print("\nexponent b of value ~ k^b over k = 8, 16, 32:\n")
    print("| scene | " + " | ".join(columns[c] for c in fitted) + " |")
    print("|---" * (len(fitted) + 1) + "|")
    for shape in sorted({s for n, s, _ in rows if n == name}):
        cells = []
        for c in fitted:  # over the cases measured (check_ms is 0 where the certificate was not checked)
            ks = [k for k in KS[1:] if (name, shape, k) in rows and rows[(name, shape, k)][c] > 0]
            cells.append(f"{fit(ks, [rows[(name, shape, k)][c] for k in ks]):.2f}" if len(ks) > 1 else "")
        print(f"| {shape} | " + " | ".join(cells) + " |")
    print()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bench")
    ap.add_argument("contactcert")
    ap.add_argument("other", nargs="?")
    ap.add_argument("--time-limit", type=float, default=60)
    a = ap.parse_args()
    out = subprocess.run([a.bench, "--benchmark_format=json"], capture_output=True, text=True, check=True).stdout
    rows = {}
    for b in json.loads(out)["benchmarks"]:
        shape, k = b["label"].split(" k=")
        rows[(b["name"].split("/")[0], shape, int(k))] = b
    table(rows, "BM_SpatialModes", {"modes": "modes", "nodes": "nodes", "lps": "LPs", "cert_bytes": "certificate bytes",
                                    "cpu_time": "CPU ms (walk + certificate text)", "check_ms": "check CPU ms"},
          ["modes", "nodes", "lps", "cert_bytes", "cpu_time", "check_ms"])
    table(rows, "BM_SpatialStability",
          {"verdict": "verdict under gravity", "lps": "LPs", "modes_decided": "moving modes decided",
           "by_reuse": "of them by a moved vector", "cert_bytes": "certificate bytes",
           "cpu_time": "CPU ms (verdict + certificate text)", "check_ms": "check CPU ms"},
          ["lps", "modes_decided", "cert_bytes", "cpu_time", "check_ms"])
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([a.bench, "--scenes", d], check=True)
        for command in ("modes", "stability"):
            shown = f"contactcert {command} SCENE" + (" --wrench 0,0,-1,0,0,0" if command == "stability" else "")
            head = "| scene | k | CPU s | peak MB | certificate bytes |"
            head += " check CPU s |" if command == "stability" else ""
            head += " OTHER CPU s | OTHER peak MB | OTHER / ours |" if a.other else ""
            print(f"`{shown} --json --certificate FILE`, end to end:\n\n" + head)
            print("|---" * (head.count("|") - 1) + "|")
            for shape in ("box", "peg"):
                for k in KS:
                    scene, cert = f"{d}/{shape}_{k}.json", f"{d}/cert.json"
                    peak = []
                    cpu, size, rc, check = cli(a.contactcert, command, scene, cert, a.time_limit, peak)
                    line = f"| {shape} | {k} | {cpu:.2f} | {peak[0]:.0f} | {size if size else 'exit %d' % rc} |"
                    if command == "stability":
                        line += f" {check:.2f} |" if check is not None else " |"
                    if a.other:
                        ocpu, _, orc, _ = cli(a.other, command, scene, cert, a.time_limit, peak)
                        shown = f"{ocpu:.2f}" if orc == 0 else f"exit {orc} after {ocpu:.2f}"
                        line += f" {shown} | {peak[1]:.0f} |"
                        line += f" {ocpu / cpu:.1f} |" if orc == 0 else " |"
                    print(line)
            print()

if __name__ == "__main__":
    main()
