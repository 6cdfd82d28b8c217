#!/usr/bin/env python3
"""The adversarial run of the command line: what a hostile or careless user types.

    python3 scripts/adversarial.py [--seconds N] [--binary PATH]

1. Every numeric flag of every subcommand with bad and extreme values (NaN, ±inf, ±1e308,
   1e-320, −1, 0, empty, words, wrong list lengths, huge lists).
2. The reproducers of the issue "No silent wrong answers", each with the answer it must give.
3. For N seconds (default 60): scenario, simulation and mechanism files mutated at random from
   the fuzz corpus (numbers replaced by extremes, lines dropped or repeated, keys renamed).
4. The explorer's server: an oversized request head, a POST with a body, garbage; it must
   answer each properly and stay up.

Every invocation must keep the command line's contract (crates/impax-cli/src/contract.rs):
exit 0 or 2 (never a panic, never a hang: 60 s), on exit 2 nothing on stdout and one
`error: ` line on stderr, on success no NaN or infinity shown as a number and, in JSON, no null
where a number is documented. Prints the counts tried and the failures; exits 1 on any.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import re
import socket
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NULLABLE = {
    "detail", "inconsistency", "breakdown", "compression_impulse", "slip_halt",
    "second_compression", "switch_impulse", "other_body_velocity_after", "hodograph",
    "energy_change_from_velocities",
}
BAD = ["nan", "inf", "-inf", "1e308", "-1e308", "1e-320", "-1", "0", "", "abc", "1e999",
       "0x10", "1,2", "--", "5e-324"]


def nulls(v, key="", path="$"):
    if v is None:
        # Brach's ratio is null when the impulse that stops the slip is not compressive.
        return [] if key in NULLABLE or path.endswith("detail.ratio") else [path]
    if isinstance(v, list):
        return [p for i, x in enumerate(v) for p in nulls(x, key, f"{path}[{i}]")]
    if isinstance(v, dict):
        verdict = v.get("verdict")
        if isinstance(verdict, dict):
            verdict = verdict.get("id")
        if verdict in ("breakdown", "no-reference") or v.get("breakdown") not in (None,):
            return []
        return [p for k, x in v.items() for p in nulls(x, k, f"{path}.{k}")]
    return []


class Run:
    def __init__(self, binary: str):
        self.binary = binary
        self.tried = 0
        self.failures: list[str] = []
        self.lock = threading.Lock()

    def call(self, args: list[str], timeout: float = 60.0):
        with self.lock:
            self.tried += 1
        try:
            p = subprocess.run([self.binary, *args], capture_output=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            self.fail(args, f"no answer within {timeout} s")
            return None
        return p

    def fail(self, args, why: str):
        with self.lock:
            self.failures.append(f"impax {' '.join(args)}: {why}")

    def contract(self, args: list[str], timeout: float = 60.0):
        p = self.call(args, timeout)
        if p is None:
            return None
        out, err = p.stdout.decode(errors="replace"), p.stderr.decode(errors="replace")
        if p.returncode == 2:
            lines = [l for l in err.splitlines() if l.strip()]
            if out or len(lines) != 1 or not lines[0].startswith("error: "):
                self.fail(args, f"exit 2 without exactly one error line: {err!r}")
        elif p.returncode == 0:
            try:
                bad = nulls(json.loads(out))
                if bad:
                    self.fail(args, f"null numbers at {bad[:3]}")
            except ValueError:
                if re.search(r"(^|[\s(=,])[+-]?(NaN|inf)\b", out):
                    self.fail(args, "NaN or inf shown as a number")
        else:
            self.fail(args, f"exit code {p.returncode}: {err[-400:]!r}")
        return p

    def expect(self, args: list[str], check, what: str):
        p = self.contract(args)
        if p is not None and not check(p):
            self.fail(args, f"expected {what}; got exit {p.returncode}: "
                      f"{(p.stdout + p.stderr).decode(errors='replace')[-400:]!r}")


# (base arguments, flag, how many comma-separated numbers the flag takes)
FLAGS = [
    (["compare"], f, 1) for f in ["--alpha-deg", "--restitution", "--friction", "--spin-ratio",
                                  "--mass", "--radius", "--speed"]
] + [
    (["compare", "double-pendulum"], f, n) for f, n in [("--masses", 2), ("--lengths", 2),
                                                      ("--angles-deg", 2), ("--rates", 2),
                                                      ("--gravity", 1)]
] + [
    (["resolve", "--v", "0.5,-1", "--friction", "0.4", "--restitution", "0.5"], "--w", 3),
    (["resolve", "--w", "3.5,0,1", "--friction", "0.4", "--restitution", "0.5"], "--v", 2),
    (["resolve", "--w", "3.5,0,1", "--v", "0.5,-1", "--restitution", "0.5"], "--friction", 1),
    (["resolve", "--w", "3.5,0,1", "--v", "0.5,-1", "--friction", "0.4"], "--restitution", 1),
    (["resolve", "--v", "0.5,0.2,-1", "--friction", "0.4", "--restitution", "0.5"], "--w", 6),
    (["resolve", "--w", "3.5,0,0,3.5,0,1", "--friction", "0.4", "--restitution", "0.5"],
     "--v", 3),
    (["sweep", "--format", "summary", "--grid", "alpha-deg=0:60:3"], "--threads", 1),
    (["sweep", "--format", "summary", "--random", "alpha-deg=0:60"], "--samples", 1),
    (["sweep", "--format", "summary", "--grid", "alpha-deg=0:60:3", "--set"], "friction=", 1),
    (["sweep", "--format", "summary", "--grid"], "speed=1:", 1),
    (["conserved", "ring-pendulum", "--samples", "10"], "--duration", 1),
    (["conserved", "ring-pendulum", "--duration", "0.1"], "--about", 2),
    (["conserved", "ring-pendulum", "--duration", "0.1"], "--tolerance", 1),
] + [
    (["simulate", "bouncing-ball", "--until", "0.5"], f, 1)
    for f in ["--friction", "--restitution", "--until", "--gravity", "--mass", "--radius",
              "--height", "--speed", "--alpha-deg", "--spin-ratio", "--samples"]
] + [
    (["simulate", "rod-drop", "--until", "0.5"], f, 1)
    for f in ["--length", "--angle-deg", "--height", "--mass"]
] + [
    (["simulate", "double-pendulum-drop", "--until", "0.5"], f, n)
    for f, n in [("--masses", 2), ("--lengths", 2), ("--angles-deg", 2), ("--rates", 2),
                 ("--floor", 1)]
] + [
    (["simulate", "rocking-block", "--until", "0.5"], f, 1)
    for f in ["--half-width", "--half-height", "--angle-deg", "--omega", "--mass"]
] + [
    (["simulate", "cradle", "--until", "0.5"], f, 1)
    for f in ["--balls", "--v0", "--gap", "--mass", "--radius"]
] + [
    (["audit", "rod"], f, 1) for f in ["--friction", "--restitution", "--gravity"]
] + [
    (["compare", "examples/mechanisms/double-pendulum.toml"], f, n)
    for f, n in [("--q", 2), ("--u", 2), ("--friction", 1), ("--gravity", 1)]
] + [
    (["compare", "examples/mechanisms/arm-3d.toml"], f, n)
    for f, n in [("--q", 3), ("--u", 3), ("--floor", 1), ("--restitution", 1)]
] + [
    (["compare", "crates/impax/tests/data/urdf/solo12.urdf", "--floating-base", "--contact",
      "FL_FOOT"], f, n) for f, n in [("--q", 19), ("--u", 18), ("--floor", 1)]
] + [
    (["sweep", "examples/mechanisms/arm-3d.toml", "--quiet", "--grid"], "q.elbow=-1:", 1),
    (["simulate", "examples/mechanisms/rod.toml", "--until", "0.3"], "--q", 3),
] + [
    (["simulate", "examples/mechanisms/hopper-3d.toml", "--until", "0.5"], f, n)
    for f, n in [("--q", 8), ("--u", 7), ("--floor", 1), ("--gravity", 1), ("--friction", 1),
                 ("--restitution", 1), ("--until", 1), ("--samples", 1)]
] + [
    (["simulate", "crates/impax/tests/data/urdf/solo12.urdf", "--floating-base", "--contact",
      "FL_FOOT", "--contact", "HR_FOOT", "--floor", "-0.5", "--until", "0.5"], f, n)
    for f, n in [("--q", 19), ("--u", 18), ("--floor", 1)]
] + [
    (["conserved", "examples/mechanisms/hopper-3d.toml", "--duration", "0.2"], f, n)
    for f, n in [("--q", 8), ("--u", 7), ("--about", 3), ("--gravity", 1), ("--duration", 1)]
] + [
    (["conserved", "crates/impax/tests/data/urdf/solo12.urdf", "--floating-base",
      "--duration", "0.2"], f, n) for f, n in [("--q", 19), ("--u", 18)]
]


def bad_values(n: int, rng: random.Random):
    good = ["1"] * n
    for b in BAD:
        for i in range(n):
            v = list(good)
            v[i] = b
            yield ",".join(v)
    yield ",".join(["1"] * (n + 1))
    yield ",".join(["1"] * max(n - 1, 0))
    yield ",".join(["1e-300"] * n)
    yield ",".join(["1e300"] * n)
    yield ",".join(str(rng.choice([-1, 1]) * 10 ** rng.uniform(-300, 300)) for _ in range(n))
    yield ",".join(["1"] * 10000)


def flags(run: Run, rng: random.Random):
    # The invocations are drawn first (the same for a seed), then run on every core.
    cases = []
    for base, flag, n in FLAGS:
        for value in bad_values(n, rng):
            if flag.endswith("=") or flag.endswith(":"):
                args = base + [f"{flag.split('=')[0]}={value}" if flag.endswith("=")
                               else f"{flag}{value}:3"]
                if "--set" in base:
                    args = base[:-1] + ["--set", f"{flag}{value}"]
                elif "--grid" in base:
                    args = base + [f"{flag}{value}:3"]
            else:
                args = base + [flag, value]
            if "--json" not in args and args[0] in ("compare", "resolve", "conserved", "simulate",
                                                    "audit"):
                args.append("--json")
            cases.append(args)
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        list(pool.map(run.contract, cases))


def reproducers(run: Run):
    def js(p):
        return json.loads(p.stdout)

    def law(doc, name):
        return next(r for r in doc["results"] if r["law"] == name)

    # 1. Simulations stay above the floor and name their stop.
    for angle in ["30", "0"]:
        run.expect(["simulate", "rod-drop", "--angle-deg", angle, "--json"],
                   lambda p: js(p)["stop"]["id"] != "time-limit", "a named stop before 3 s")
    run.expect(["simulate", "double-pendulum-drop", "--angles-deg", "90,0", "--floor", "-1.0",
                "--json"], lambda p: js(p)["stop"]["id"] == "rest", "rest at t = 0")
    # 2. smith at μ = 1e30 does not gain energy on a sphere.
    run.expect(["resolve", "--w", "3.5,0,1", "--v", "0.5,-0.866", "--friction", "1e30",
                "--restitution", "0.7", "--law", "smith", "--json"],
               lambda p: js(p)["verdict"] != "energy-gained", "no energy gained")
    # 3. A grazing impact keeps its restitution; a tiny speed prints no NaN.
    run.expect(["resolve", "--w", "3.5,0,1", "--v", "0.5,-1e-300", "--friction", "0.4",
                "--restitution", "0.7", "--law", "energetic", "--json"],
               lambda p: abs(js(p)["velocity_after"]["n"] - 7e-301) < 1e-315, "v_n⁺ = 7e-301")
    run.contract(["compare", "--speed", "1e-300"])
    # 4. Spatial poisson does not end approaching.
    run.expect(["resolve", "--w", "1.2008324287749725,0.7591989489860935,0.403401879441061,"
                "1.4497343144842805,0.22396419839288853,1.1040311283093813", "--v",
                "-0.3175701672458717,-0.9220617217576841,-0.1422905376691409", "--friction",
                "19.512088227010317", "--restitution", "1", "--law", "poisson", "--json"],
               lambda p: js(p)["verdict"] != "consistent" or js(p)["velocity_after"]["n"] >= 0,
               "v_n⁺ ≥ 0 or a flagged verdict")
    # 5. A well-conditioned rotated W (eigenvalues 1e8, 1, 1) is accepted.
    run.expect(["resolve", "--w", "33333334,33333333,33333333,33333334,33333333,33333334",
                "--v", "0.1,0.2,-1", "--friction", "0.5", "--restitution", "0.5", "--json"],
               lambda p: p.returncode == 0, "accepted")
    # 6. A tiny slip gives the zero-slip result.
    tiny = run.contract(["resolve", "--w", "1,0,0,1,0,1", "--v", "0,1e-200,-1", "--friction",
                         "0.5", "--restitution", "0.6", "--json"])
    zero = run.contract(["resolve", "--w", "1,0,0,1,0,1", "--v", "0,0,-1", "--friction", "0.5",
                         "--restitution", "0.6", "--json"])
    if tiny is not None and zero is not None and tiny.returncode == 0:
        for a, b in zip(js(tiny)["results"], js(zero)["results"]):
            if a.get("verdict") == "breakdown" or abs(
                    a["impulse"]["n"] - b["impulse"]["n"]) > 1e-12:
                run.fail(["resolve", "--v", "0,1e-200,-1"], f"{a['law']}: not the zero-slip one")
    # 7. Spatial lcp finds the solution.
    run.expect(["resolve", "--w", "614327.3694481789,341336.2451532919,347013.5943548623,"
                "189656.59358945338,192810.08142403685,196018.03696236789", "--v",
                "1,0.12097437381250864,-1e-9", "--friction", "1.0598928366735887",
                "--restitution", "0.9615509061531089", "--law", "lcp", "--json"],
               lambda p: js(p).get("verdict") != "breakdown", "a solution")
    # 8. A small true gain (exactly 5.67e-14, 1e-13 of the approach energy) is a gain.
    run.expect(["resolve", "--w", "3.5,0,1", "--v", "0.5,-1", "--friction", "0.4182061896726541",
                "--restitution", "0.5", "--law", "whittaker", "--json"],
               lambda p: js(p)["verdict"] == "energy-gained", "energy-gained")
    # 10. Threads are bounded.
    run.expect(["sweep", "--grid", "alpha-deg=0:60:3", "--threads", "100000"],
               lambda p: p.returncode == 2, "exit 2")
    # 12. A singular W names w.
    run.expect(["resolve", "--w", "1e308,1e308,1e308", "--v", "0.5,-1", "--friction", "0.4",
                "--restitution", "0.5"], lambda p: p.stderr.startswith(b"error: w:"),
               "an error naming w")


NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?(e-?\d+)?(?![\w.])")
EXTREMES = ["0", "-0.0", "-1", "1e308", "-1e308", "1e-320", "1e-300", "1e300", "nan", "inf",
            "1e999", "2", "0.5", "720", "-720", "1e20", "10000000"]


def mutate(text: str, rng: random.Random) -> str:
    lines = text.splitlines()
    for _ in range(rng.randint(1, 4)):
        kind = rng.random()
        if kind < 0.6:
            spots = [m for m in NUMBER.finditer(text)]
            if spots:
                m = rng.choice(spots)
                text = text[:m.start()] + rng.choice(EXTREMES) + text[m.end():]
                lines = text.splitlines()
        elif kind < 0.7 and lines:
            del lines[rng.randrange(len(lines))]
            text = "\n".join(lines)
        elif kind < 0.8 and lines:
            lines.insert(rng.randrange(len(lines)), rng.choice(lines))
            text = "\n".join(lines)
        elif kind < 0.9 and lines:
            i = rng.randrange(len(lines))
            lines[i] = lines[i].replace("_", "-", 1) if rng.random() < 0.5 else "[" + lines[i]
            text = "\n".join(lines)
        else:
            i = rng.randrange(len(text) + 1)
            text = text[:i] + rng.choice(["\"", "]", "=", "\x00", "é", "[[body]]\n", "{"]) + text[i:]
    return text


def files(run: Run, rng: random.Random, seconds: float):
    seeds = []
    for d in ["scenario_toml", "mechanism_toml"]:
        for p in sorted((ROOT / "fuzz" / "corpus" / d).glob("*")):
            seeds.append(p.read_text())
    tmp = Path(tempfile.mkdtemp(prefix="impax-adversarial-"))
    end = time.monotonic() + seconds
    n = 0
    while time.monotonic() < end:
        text = mutate(rng.choice(seeds), rng)
        path = tmp / f"case-{n % 8}.toml"
        path.write_text(text)
        cmd = rng.choice([["compare", str(path), "--json"], ["audit", str(path), "--json"],
                          ["simulate", str(path), "--json", "--until", "0.3"],
                          ["conserved", str(path), "--json", "--duration", "0.1"]])
        before = len(run.failures)
        run.contract(cmd)
        if len(run.failures) > before:
            keep = tmp / f"failing-{n}.toml"
            keep.write_text(text)
            run.failures[-1] += f" (file kept: {keep})"
        n += 1
    return n


def explorer(run: Run):
    p = subprocess.Popen([run.binary, "explore", "--port", "0"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    try:
        line = p.stdout.readline().decode()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        if not m:
            run.fail(["explore"], f"no address: {line!r}")
            return
        port = int(m.group(1))

        def exchange(data: bytes, read_all=True) -> bytes:
            run.tried += 1
            with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
                try:
                    s.sendall(data)
                except OSError:
                    pass
                chunks = []
                try:
                    while True:
                        c = s.recv(65536)
                        if not c:
                            break
                        chunks.append(c)
                        if not read_all:
                            break
                except OSError:
                    pass
                return b"".join(chunks)

        big = b"GET /" + b"a" * (50 * 1024 * 1024) + b" HTTP/1.1\r\n\r\n"
        r = exchange(big)
        if not re.match(rb"HTTP/1\.[01] 4\d\d", r):
            run.fail(["explore"], f"oversized request line: {r[:60]!r}")
        r = exchange(b"POST / HTTP/1.1\r\nContent-Length: 18\r\n\r\nGET / HTTP/1.1\r\n\r\n")
        if r.count(b"HTTP/1.1 ") != 1 or b" 405 " not in r:
            run.fail(["explore"], f"POST with a body: {r[:120]!r}")
        for junk in [b"\x00\xff\r\n\r\n", b"GET\r\n\r\n", b"GET / HTTP/1.1\r\n" + b"X: y\r\n" * 20000]:
            r = exchange(junk)
            if r and not re.match(rb"HTTP/1\.[01] [45]\d\d", r):
                run.fail(["explore"], f"garbage {junk[:20]!r}: {r[:60]!r}")
        r = exchange(b"GET / HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
        if not r.startswith(b"HTTP/1.1 200"):
            run.fail(["explore"], f"the server did not survive: {r[:60]!r}")
    finally:
        p.kill()
        p.wait()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seconds", type=float, default=60.0, help="time for mutated files")
    ap.add_argument("--binary", help="the impax binary (default: build it with cargo)")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    binary = a.binary
    if binary is None:
        subprocess.run(["cargo", "build", "--release", "--quiet", "--bin", "impax"], cwd=ROOT,
                       check=True)
        target = Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
        binary = str((ROOT / target).resolve() / "release" / "impax")
    run = Run(binary)
    rng = random.Random(a.seed)
    t0 = time.monotonic()
    flags(run, rng)
    n_flags = run.tried
    reproducers(run)
    n_repro = run.tried - n_flags
    explorer(run)
    n_files = files(run, rng, a.seconds)
    print(f"adversarial: {run.tried} invocations in {time.monotonic() - t0:.0f} s: "
          f"{n_flags} bad flag values, {n_repro} reproducers, {n_files} mutated files, "
          f"the explorer's server; {len(run.failures)} failures")
    for f in run.failures[:50]:
        print("  FAIL", f)
    sys.exit(1 if run.failures else 0)


if __name__ == "__main__":
    main()
