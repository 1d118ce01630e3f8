"""Tampered copies of a certificate: every number, coefficient, point, sign, range end and
degree bound changed one at a time, the goal's sides swapped, and the goal edited while its
data is kept. Each mutant is `(kind, where, make)`, `make()` building the tampered copy (so
that a sample of a large file's mutants costs only what is sampled)."""

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
    def make():
        d = copy.deepcopy(doc)
        node = d
        for k in path[:-1]:
            node = node[k]
        node[path[-1]] = value
        return d

    return make


def _is_rational_path(path):
    return (
        path[:1] in (("sampling",), ("fails",))
        and any(k in path for k in ("points", "at", "lhs", "rhs", "premise"))
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
        elif path[:1] == ("goal",) and path[-1] in ("lhs", "rhs", "premise") and isinstance(val, str):
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
        elif path[-1] == "polygon" and isinstance(val, int):
            # the basis polygon a row belongs to
            out.append(("polygon", where, _set(doc, path, val + 1)))
            if val > 0:
                out.append(("polygon", where, _set(doc, path, val - 1)))
        elif len(path) >= 2 and path[-2] == "index" and isinstance(val, int):
            out.append(("control point", where, _set(doc, path, val + 1)))
    out.extend(_pieces_edits(doc))
    out.extend(_expansion_edits(doc))
    out.extend(_computation_edits(doc))
    out.extend(_convergence_edits(doc))
    # a point dropped (its grid rows kept), and a point repeated
    for k, eq in enumerate((doc.get("sampling") or {}).get("equalities") or []):
        for j, p in enumerate(eq.get("params") or []):
            if len(p["points"]) >= 2:
                at = ("sampling", "equalities", k, "params", j, "points")
                out.append(("point", f"equality {k} {p['name']} dropped", _set(doc, at, p["points"][:-1])))
                out.append(("point", f"equality {k} {p['name']} repeated", _set(doc, at, p["points"][:-1] + p["points"][:1])))
    goal = doc.get("goal")
    for k, eq in enumerate((goal or {}).get("equalities") or []):
        listed = eq.get("control_points") or []
        if len(listed) >= 2:
            at = ("goal", "equalities", k, "control_points")
            out.append(("control point", f"equality {k}: the last dropped", _set(doc, at, listed[:-1])))
            out.append(("control point", f"equality {k}: two swapped", _set(doc, at, [listed[1], listed[0]] + listed[2:])))
    if goal and "inequality" in goal:
        flipped = {">=": "<=", "<=": ">="}.get(goal.get("relation"), ">=")
        out.append(("swapped sides", "the inequality flipped", _set(doc, ("goal", "relation"), flipped)))
    if goal:
        for k, eq in enumerate(goal.get("equalities") or []):
            if eq["lhs"] != eq["rhs"]:
                swapped = {**eq, "lhs": eq["rhs"], "rhs": eq["lhs"]}
                out.append(("swapped sides", f"equality {k}", _set(doc, ("goal", "equalities", k), swapped)))
    out.extend(_vanishing_edits(doc))
    other = {"proved": "proved_in_range", "proved_in_range": "proved", "fails": "proved"}.get(doc.get("verdict"))
    if other:
        out.append(("verdict", f"{doc['verdict']} -> {other}", _set(doc, ("verdict",), other)))
    if doc.get("verdict") == "proved_in_range" and len(doc["goal"]["equalities"]) > 1:

        def drop_last():
            d = copy.deepcopy(doc)
            d["goal"]["equalities"].pop()
            d["sampling"]["equalities"].pop()
            return d

        out.append(("range end", "last case dropped", drop_last))
    return out


def _expansion_edits(doc):
    """An `expansion` file's data: every coefficient bumped and negated, every exponent
    raised and lowered, a term dropped, two variables exchanged, the two sides' data swapped."""
    out = []
    for k, eq in enumerate((doc.get("expansion") or {}).get("equalities") or []):
        base = ("expansion", "equalities", k)
        if len(eq["vars"]) >= 2:
            v = list(eq["vars"])
            v[0], v[-1] = v[-1], v[0]
            out.append(("variable", f"equality {k} vars exchanged", _set(doc, base + ("vars",), v)))
        for j, pair in enumerate(eq["entries"]):
            if pair["lhs"] != pair["rhs"]:
                out.append(("swapped sides", f"equality {k} entry {j} data", _set(doc, base + ("entries", j), {"lhs": pair["rhs"], "rhs": pair["lhs"]})))
            for side in ("lhs", "rhs"):
                for part in ("num", "den"):
                    poly = pair[side][part]
                    at = base + ("entries", j, side, part)
                    where = "/".join(str(x) for x in at)
                    out.append(("term", f"{where} last term dropped", _set(doc, at, poly[:-1])))
                    for t, (c, e) in enumerate(poly):
                        out.append(("coefficient", f"{where}/{t}", _set(doc, at + (t, 0), _bump(c))))
                        out.append(("sign", f"{where}/{t}", _set(doc, at + (t, 0), str(-Fraction(c)))))
                        for i, x in enumerate(e):
                            out.append(("exponent", f"{where}/{t}/{i}", _set(doc, at + (t, 1, i), x + 1)))
                            if x > 0:
                                out.append(("exponent", f"{where}/{t}/{i}", _set(doc, at + (t, 1, i), x - 1)))
    return out


def _computation_edits(doc):
    """A `computation` file's facts: every input number bumped and negated, the equation's
    numbers and signs edited, the result replaced by each other type."""
    out = []
    for k, fact in enumerate((doc.get("computation") or {}).get("facts") or []):
        base = ("computation", "facts", k)
        for path, val in _paths(fact, base):
            where = "/".join(str(x) for x in path)
            if path[-1] in ("lhs", "rhs"):
                for m in _NUM_IN_EXPR.finditer(val):
                    new = val[: m.start()] + _bump(m.group()) + val[m.end():]
                    out.append(("coefficient", f"{where}@{m.start()}", _set(doc, path, new)))
                for m in _SIGN_IN_EXPR.finditer(val):
                    flip = "-" if m.group() == "+" else "+"
                    out.append(("sign", f"{where}@{m.start()}", _set(doc, path, val[: m.start()] + flip + val[m.end():])))
            elif path[-1] == "kind":
                for other in ("ellipse", "parabola", "hyperbola", "degenerate"):
                    if other != val:
                        out.append(("result", f"{where} {other}", _set(doc, path, other)))
            elif path[-1] in ("nonnegative", "sum_one"):
                # a cited lemma's id: another claim's
                out.append(("lemma", where, _set(doc, path, "000-basis-recursion")))
            elif isinstance(val, str) and path[-1] != "computation":
                out.append(("number", where, _set(doc, path, _bump(val))))
                if Fraction(val) != 0:
                    out.append(("sign", where, _set(doc, path, str(-Fraction(val)))))
    return out


def _convergence_edits(doc):
    """Bounded evidence (`verified`): every control point and distance bumped and negated, the
    steps changed, a distance dropped."""
    data = doc.get("convergence")
    if not data:
        return []
    out = [("steps", "convergence/steps", _set(doc, ("convergence", "steps"), data["steps"] + d)) for d in (1, -1)]
    for path, val in _paths(data, ("convergence",)):
        if isinstance(val, str) and path[-1] != "name":
            where = "/".join(str(x) for x in path)
            out.append(("number", where, _set(doc, path, _bump(val))))
            if Fraction(val) != 0:
                out.append(("sign", where, _set(doc, path, str(-Fraction(val)))))
    for k, c in enumerate(data["curves"]):
        out.append(("distance", f"curve {k}: the last dropped", _set(doc, ("convergence", "curves", k, "distances"), c["distances"][:-1])))
    return out


def key(doc):
    return json.dumps(doc, sort_keys=True)


def _vanishing_edits(doc):
    """The goal's lhs plus a polynomial that vanishes at every sample point of a param: the
    listed values still match, so only the degree obligations can refuse it. Once with the
    file's degree fields kept, once with them re-derived for the edited side."""
    out = []
    eqs = (doc.get("sampling") or {}).get("equalities") or []
    for k, data in enumerate(eqs):
        if "," in doc["goal"]["equalities"][k]["lhs"]:
            continue  # a vector side: a scalar added would change its shape
        for p in data.get("params") or []:
            extra = "*".join(f"({p['name']} - {x})" for x in p["points"])
            where = f"equality {k} + a product vanishing at the {p['name']} points"
            out.append(("edited goal", where, _edit(doc, k, extra, False)))
            out.append(("edited goal", where + ", degrees re-derived", _edit(doc, k, extra, True)))
    return out


def _edit(doc, k, extra, rederive):
    from _casteljau_oracle.cert_check import _derive_bounds, _fmt
    from _casteljau_oracle.cert_expr import parse

    def make():
        d = copy.deepcopy(doc)
        e = d["goal"]["equalities"][k]
        e["lhs"] = f"{e['lhs']} + {extra}"
        if rederive:
            ints = {v: int(x) for v, x in e["ints"].items()}
            names = [s["name"] for s in d["goal"]["symbols"]]
            lhs, rhs = parse(e["lhs"], names, True), parse(e["rhs"], names, True)
            for q in d["sampling"]["equalities"][k]["params"]:
                lb, rb, deg = _derive_bounds(lhs, rhs, q["name"], ints)
                q["lhs_degree"], q["rhs_degree"], q["degree"] = _fmt(lb), _fmt(rb), deg
        return d

    return make


def _pieces_edits(doc):
    """A for-every file's data: every number of each WZ certificate `R` bumped, each sign of
    it flipped, `R` negated, and each range end of the goal's `for_all` moved by one."""
    out = []
    for k, r in enumerate((doc.get("pieces") or {}).get("certificates") or []):
        at = ("pieces", "certificates", k)
        for m in _NUM_IN_EXPR.finditer(r):
            out.append(("certificate", f"R{k}@{m.start()}", _set(doc, at, r[: m.start()] + _bump(m.group()) + r[m.end():])))
        for m in _SIGN_IN_EXPR.finditer(r):
            flip = "-" if m.group() == "+" else "+"
            out.append(("certificate", f"R{k} sign@{m.start()}", _set(doc, at, r[: m.start()] + flip + r[m.end():])))
        out.append(("certificate", f"R{k} negated", _set(doc, at, f"-({r})")))
    if "pieces" in doc:
        for k, r in enumerate(doc["goal"].get("for_all") or []):
            for key in ("from", "to"):
                if isinstance(r.get(key), str):
                    at = ("goal", "for_all", k, key)
                    out.append(("range end", f"for_all[{k}].{key} + 1", _set(doc, at, f"{r[key]} + 1")))
                    out.append(("range end", f"for_all[{k}].{key} - 1", _set(doc, at, f"{r[key]} - 1")))
    return out
