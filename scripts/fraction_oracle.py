#!/usr/bin/env python3
"""The oracle's `split` and `elevate` in plain Python: fractions.Fraction, standard library only.

The peer of `casteljau oracle` for these two ops (scripts/oracle_vs_fractions.py times both
on one request file). It reads the same JSON lines and writes the same answers, byte for
byte, for well-formed requests:

  {"id":1,"op":"split","points":[["0","1/2"],[1,"0.25"]],"t":"1/3"}
  {"id":2,"op":"elevate","points":[[0,0],[1,2],[2,0]],"by":1}

A JSON string is exact (an integer, "p/q", or a decimal such as "0.25" or "1e-3"); a JSON
number is exactly the float it parses to. Answers are strings "p" or "p/q" in lowest terms.
The algorithms are the textbook ones on Fraction: de Casteljau's steps
b_i <- b_i + t (b_{i+1} - b_i) for split, the elevation step (7)
b'_i = (i b_{i-1} + (n+1-i) b_i) / (n+1), repeated `by` times, for elevate. Anything else
(another op, a malformed request) gets {"ok": false} with a short error: this is a peer for
timing, not a second oracle.

  python3 scripts/fraction_oracle.py < requests.jsonl > answers.jsonl
"""

import json
import sys
from fractions import Fraction


def number(v):
    """An exact number from JSON, as the oracle reads it."""
    if isinstance(v, bool):
        raise ValueError("expected a number")
    if isinstance(v, int):
        return Fraction(v)
    if isinstance(v, float):
        return Fraction(v)  # exactly the float
    if isinstance(v, str):
        s = v.strip()
        if "/" in s:
            p, q = s.split("/", 1)
            return Fraction(p.strip()) / Fraction(q.strip())
        return Fraction(s)  # integers, decimals and exponents, exactly
    raise ValueError("expected a number")


def text(x):
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def points_text(points):
    return [[text(c) for c in p] for p in points]


def split(points, t):
    """Left and right halves of the curve at t, by de Casteljau's steps (per coordinate)."""
    n = len(points) - 1
    dim = len(points[0])
    left = [[None] * dim for _ in range(n + 1)]
    right = [[None] * dim for _ in range(n + 1)]
    for k in range(dim):
        b = [p[k] for p in points]
        left[0][k] = b[0]
        right[n][k] = b[n]
        for r in range(1, n + 1):
            for i in range(n + 1 - r):
                b[i] = b[i] + t * (b[i + 1] - b[i])
            left[r][k] = b[0]
            right[n - r][k] = b[n - r]
    return left, right


def elevate(points, by):
    for _ in range(by):
        n = len(points) - 1
        out = [points[0]]
        for i in range(1, n + 1):
            a, b = points[i - 1], points[i]
            out.append([(i * x + (n + 1 - i) * y) / (n + 1) for x, y in zip(a, b)])
        out.append(points[n])
        points = out
    return points


def answer(request):
    op = request.get("op")
    points = [[number(c) for c in p] for p in request["points"]]
    if not points or any(len(p) != len(points[0]) for p in points):
        raise ValueError("points of one dimension expected")
    if op == "split":
        left, right = split(points, number(request["t"]))
        return {"left": points_text(left), "right": points_text(right)}
    if op == "elevate":
        by = request["by"]
        by = int(by) if isinstance(by, str) else by
        return {"points": points_text(elevate(points, by))}
    raise ValueError(f"op {op!r} is not served here")


def main():
    out = sys.stdout
    for line in sys.stdin:
        response = {}
        try:
            request = json.loads(line)
            if "id" in request:
                response["id"] = request["id"]
            response.update(answer(request))
            response["ok"] = True
        except (ValueError, KeyError, TypeError, ZeroDivisionError) as e:
            response = {"error": str(e), "ok": False}
        out.write(json.dumps(response, sort_keys=True, separators=(",", ":"), ensure_ascii=False))
        out.write("\n")


if __name__ == "__main__":
    main()
