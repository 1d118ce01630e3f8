"""Tampered copies of a certificate: every number, coefficient, point, sign, range end and
degree bound changed one at a time, the goal's sides swapped, and the goal edited while its
data is kept. Each mutant is `(kind, where, doc)`."""

import copy
import json
import re
from fractions import Fraction

_NUM_IN_EXPR = re.compile(r"(?<![A-Za-z_0-9'.])\d+(?:\.\d+)?")
_SIGN_IN_EXPR = re.compile(r"(?<=\s)[+-](?=\s)")
_NUM_IN_RANGE = re.compile(r"\d+")


def _bump(s):
    v = Fraction(s)
    return str(v + 1)


def _paths(node, path=()):
    """Every (path, string) leaf of a JSON tree."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _paths(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _paths(v, path + (i,))
    else:
        yield path, node


def _set(doc, path, value):
    d = copy.deepcopy(doc)
    node = d
    for k in path[:-1]:
        node = node[k]
    node[path[-1]] = value
    return d


def _is_rational_path(path):
    return (
        path[:1] in (("sampling",), ("fails",))
        and any(k in path for k in ("points", "at", "lhs", "rhs"))
    )


def mutants(doc):
    out = []
    for path, val in list(_paths(doc)):
        where = "/".join(str(k) for k in path)
        if isinstance(val, str) and _is_rational_path(path):
            # the exact numbers of the data: values, points, counterexample coordinates
            out.append(("number", where, _set(doc, path, _bump(val))))
            if Fraction(val) != 0:
                out.append(("sign", where, _set(doc, path, str(-Fraction(val)))))
        elif path[:1] == ("goal",) and path[-1] in ("lhs", "rhs") and isinstance(val, str):
            for m in _NUM_IN_EXPR.finditer(val):
                new = val[: m.start()] + _bump(m.group()) + val[m.end():]
                out.append(("coefficient", f"{where}@{m.start()}", _set(doc, path, new)))
            for m in _SIGN_IN_EXPR.finditer(val):
                flip = "-" if m.group() == "+" else "+"
                out.append(("sign", f"{where}@{m.start()}", _set(doc, path, val[: m.start()] + flip + val[m.end():])))
            # an edited goal, its data kept
            out.append(("edited goal", f"{where}+t", _set(doc, path, f"({val}) + 1/1000")))
        elif path[:1] == ("goal",) and "ints" in path and isinstance(val, str):
            out.append(("range end", where, _set(doc, path, str(int(val) + 1))))
        elif path == ("range",) and isinstance(val, str):
            for m in _NUM_IN_RANGE.finditer(val):
                new = val[: m.start()] + str(int(m.group()) + 1) + val[m.end():]
                out.append(("range end", f"range@{m.start()}", _set(doc, path, new)))
        elif path[-1] == "degree" and isinstance(val, int):
            out.append(("degree bound", where, _set(doc, path, val + 1)))
            if val > 0:
                out.append(("degree bound", where, _set(doc, path, val - 1)))
        elif path[-1] in ("lhs_degree", "rhs_degree") and isinstance(val, str):
            n = val.split("/")
            out.append(("degree bound", where, _set(doc, path, "/".join([str(int(n[0]) + 1)] + n[1:]))))
        elif path[-1] == "points" and isinstance(val, list):
            pass
    # a point dropped (its grid rows kept), and a point repeated
    for k, eq in enumerate((doc.get("sampling") or {}).get("equalities") or []):
        for j, p in enumerate(eq.get("params") or []):
            if len(p["points"]) >= 2:
                d = copy.deepcopy(doc)
                d["sampling"]["equalities"][k]["params"][j]["points"] = p["points"][:-1]
                out.append(("point", f"equality {k} {p['name']} dropped", d))
                d = copy.deepcopy(doc)
                pts = d["sampling"]["equalities"][k]["params"][j]["points"]
                pts[-1] = pts[0]
                out.append(("point", f"equality {k} {p['name']} repeated", d))
    goal = doc.get("goal")
    if goal:
        for k, eq in enumerate(goal["equalities"]):
            if eq["lhs"] != eq["rhs"]:
                d = copy.deepcopy(doc)
                e = d["goal"]["equalities"][k]
                e["lhs"], e["rhs"] = e["rhs"], e["lhs"]
                out.append(("swapped sides", f"equality {k}", d))
    out.extend(_vanishing_edits(doc))
    other = {"proved": "proved_in_range", "proved_in_range": "proved", "fails": "proved"}.get(doc.get("verdict"))
    if other:
        out.append(("verdict", f"{doc['verdict']} -> {other}", _set(doc, ("verdict",), other)))
    if doc.get("verdict") == "proved_in_range":
        d = copy.deepcopy(doc)
        d["goal"]["equalities"] = d["goal"]["equalities"][:-1] or d["goal"]["equalities"]
        if len(d["goal"]["equalities"]) < len(doc["goal"]["equalities"]):
            d["sampling"]["equalities"] = d["sampling"]["equalities"][:-1]
            out.append(("range end", "last case dropped", d))
    return out


def key(doc):
    return json.dumps(doc, sort_keys=True)


def _vanishing_edits(doc):
    """The goal's lhs plus a polynomial that vanishes at every sample point of a param: the
    listed values still match, so only the degree obligations can refuse it. Once with the
    file's degree fields kept, once with them re-derived for the edited side."""
    from _casteljau_oracle.cert_check import _derive_bounds, _fmt
    from _casteljau_oracle.cert_expr import parse

    out = []
    eqs = (doc.get("sampling") or {}).get("equalities") or []
    for k, data in enumerate(eqs):
        for j, p in enumerate(data.get("params") or []):
            extra = "*".join(f"({p['name']} - {x})" for x in p["points"])
            d = copy.deepcopy(doc)
            e = d["goal"]["equalities"][k]
            e["lhs"] = f"{e['lhs']} + {extra}" if not e["lhs"].startswith("(") else f"({e['lhs']}) + {extra}"
            if "," in doc["goal"]["equalities"][k]["lhs"]:
                continue  # a vector side: a scalar added would change its shape
            out.append(("edited goal", f"equality {k} + a product vanishing at the {p['name']} points", d))
            d2 = copy.deepcopy(d)
            e2 = d2["goal"]["equalities"][k]
            ints = {v: int(x) for v, x in e2["ints"].items()}
            names = [s["name"] for s in d2["goal"]["symbols"]]
            for q in d2["sampling"]["equalities"][k]["params"]:
                lb, rb, deg = _derive_bounds(parse(e2["lhs"], names, True), parse(e2["rhs"], names, True), q["name"], ints)
                q["lhs_degree"], q["rhs_degree"], q["degree"] = _fmt(lb), _fmt(rb), deg
            out.append(("edited goal", f"equality {k} + a product vanishing at the {p['name']} points, degrees re-derived", d2))
    return out
