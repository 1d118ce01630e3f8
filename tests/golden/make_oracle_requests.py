#!/usr/bin/env python3
"""Writes tests/golden/oracle_requests.jsonl: a fixed, seeded set of oracle requests covering
every op, exact and float inputs, the edges of f64 and malformed lines. The answers recorded
from the program (oracle_answers.jsonl) are the regression reference of tests/golden.rs.
Run once; the file is committed, so this script only documents how it was made."""
import json, random

rng = random.Random(20261202)
FLOATS = [0.0, -0.0, 0.1, 0.5, 1.0, -1.0, 1e308, -1e308, 5e-324, 2.2250738585072014e-308,
          1.7976931348623157e308, 0.7500001, 1e-15, 3.0, -2.5]

def exact():
    k = rng.randrange(4)
    if k == 0:
        return rng.randrange(-9, 10)
    if k == 1:
        return f"{rng.randrange(-10**6, 10**6)}/{rng.randrange(1, 10**6)}"
    if k == 2:
        return f"{rng.randrange(-10**30, 10**30)}/{rng.randrange(1, 10**30)}"
    return rng.choice(FLOATS[:5] + [0.25, 0.375])

def fl():
    return rng.choice(FLOATS) if rng.random() < 0.3 else rng.uniform(-4, 4)

def pts(n, dim, num):
    return [[num() for _ in range(dim)] for _ in range(n + 1)]

def param(num):
    return rng.choice([num(), "1/2", "1/3", 0, 1, 0.3])

lines = []
def add(req):
    lines.append(json.dumps(req, separators=(",", ":")))

i = 0
for _ in range(12):
    for num in (exact, fl):
        i += 1
        n, d = rng.randrange(0, 8), rng.randrange(1, 4)
        add({"id": i, "op": "eval", "points": pts(n, d, num), "t": param(num)})
        i += 1
        p = pts(n, d, fl)
        add({"id": i, "op": "eval", "points": p, "t": fl(), "approx": [fl() for _ in range(d)]})
        i += 1
        add({"id": i, "op": "eval", "points": p, "t": fl(), "approx": [fl() for _ in range(d)],
             "method": rng.choice(["de_casteljau", "lerp", "horner", "bernstein", "compensated"])})
        i += 1
        add({"id": i, "op": "elevate", "points": pts(n, d, num), "by": rng.randrange(0, 4)})
        i += 1
        add({"id": i, "op": "split", "points": pts(n, d, num), "t": param(num)})
        i += 1
        add({"id": i, "op": "derivative", "points": pts(n, d, num), "order": rng.randrange(0, 4)})
        i += 1
        add({"id": i, "op": "derivative", "points": pts(n, d, num), "order": rng.randrange(0, 3), "t": param(num)})
        i += 1
        add({"id": i, "op": "to_bezier", "power": [[num() for _ in range(n + 1)] for _ in range(d)]})
        i += 1
        add({"id": i, "op": "rational_eval", "points": pts(2, 2, num), "weights": [1, rng.choice([1, "1/2", 2, 0.5]), 1], "t": param(num)})
        i += 1
        add({"id": i, "op": "conic", "points": pts(2, 2, num), "weights": [1, rng.choice([1, "1/2", 2, "-1", 0]), 1]})
        i += 1
        m, k = rng.randrange(0, 3), rng.randrange(0, 3)
        add({"id": i, "op": "surface_eval", "net": [pts(k, 3, num) for _ in range(m + 1)], "u": param(num), "v": param(num)})
        i += 1
        add({"id": i, "op": "fit_cubic", "x0": [num() for _ in range(3)], "x1": [num() for _ in range(3)],
             "xh": [num() for _ in range(3)], "d0": [num() for _ in range(3)], "d1": [num() for _ in range(3)]})
        i += 1
        add({"id": i, "op": "float_eval", "points": pts(n, 1, fl), "t": rng.uniform(0, 1),
             "method": rng.choice(["de_casteljau", "compensated", "interval", "lerp", "horner", "bernstein"])})
        i += 1
        add({"id": i, "op": "eval", "points": pts(n, 1, fl), "t": [rng.uniform(0, 1) for _ in range(3)]})

raw = [
    '{"id":"a","op":"eval","points":[[0]],"t":"1/0"}',
    '{"id":"b","op":"elevate","points":[[0],[1]],"by":1000000000000}',
    '{"id":"c","op":"eval","points":[[0,0],[1]],"t":0}',
    '{"id":"d","op":"frobnicate"}',
    '{"id":"e","op":"eval","points":[[1e308],[1e308]],"t":0.5,"approx":[1e308]}',
    '{"id":"f","op":"eval","points":[["inf"]],"t":0}',
    '{"id":"g","op":"eval","points":[[0]],"t":0,"t":1}',
    '{"id":"h","op":"eval","points":[[0]],"t":0,"extra":1}',
    '{"id":123456789012345678901234567890,"op":"eval","points":[[0]],"t":0,"approx":[1e-15]}',
    '',
    'not json',
    '{"op":"eval"}',
    '{"id":"i","op":"eval","points":[],"t":0}',
    '{"id":"j","op":"derivative","points":[[0],[1],[3]],"order":5}',
    '{"id":"k","op":"eval","points":[[5e-324],[-5e-324]],"t":0.5,"approx":[0]}',
    '{"id":"l","op":"float_eval","points":[[0.1],[0.2],[0.7]],"t":0.3,"method":"interval"}',
    '{"id":"m","op":"eval","points":[[0],[1]],"t":["1/2",0.25,1]}',
    '{"id":"n","op":"conic","points":[[0,0],[1,1],[2,2]],"weights":[1,1,1]}',
]
lines.extend(raw)
with open("oracle_requests.jsonl", "w") as f:
    f.write("\n".join(lines) + "\n")
print(len(lines), "requests")
