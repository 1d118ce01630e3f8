"""The lemmas a for-every certificate cites (`lemmas`, docs/certificates.md "Lemmas and
induction"): each lemma's file among the files checked together, stating the very goal the
proof assumes, itself not refused, and no cycle in the references. The proof itself, with the
lemmas' goals assumed, is re-derived in `cert_lemmas`; it is re-checked only when every
lemma's file is re-checked here too."""


class LinkRefused(Exception):
    """A lemma reference that cannot hold (malformed, another goal, a cycle)."""


def lemma_refs(doc):
    """The `(id, goal)` pairs of `doc`'s lemmas (`[]` without the field); raises `LinkRefused`
    for a malformed list."""
    refs = doc.get("lemmas", [])
    if not isinstance(refs, list):
        raise LinkRefused("lemmas: not a list")
    out = []
    for i, r in enumerate(refs):
        if not isinstance(r, dict) or not isinstance(r.get("id"), str) or not isinstance(r.get("goal"), dict):
            raise LinkRefused(f"lemmas[{i}]: not an object with a string id and a goal object")
        if any(r["id"] == seen for seen, _ in out):
            raise LinkRefused(f"lemmas[{i}]: lemma {r['id']} is listed twice")
        out.append((r["id"], r["goal"]))
    return out


def rests_on(doc):
    """What a `pieces` file's proof rests on beyond its goal, as a phrase; `None` for a proof
    by pieces alone."""
    refs = lemma_refs(doc)
    var = doc["pieces"].get("induction")
    parts = []
    if var is not None:
        if not isinstance(var, str):
            raise LinkRefused("pieces.induction: not a string")
        parts.append(f"an induction on {var}")
    if refs:
        parts.append("the lemmas " + ", ".join(i for i, _ in refs) + " (their goals assumed)")
    return " and ".join(parts) or None


def resolve(outcomes, docs, refused, not_rechecked, rechecked="re-checked"):
    """Rewrites the `outcomes` (one per doc, same order) of the files checked together: a file
    citing a lemma is refused when the lemma's file states another goal, is refused, is given
    twice or closes a cycle. A proof re-derived with its lemmas' goals assumed (its outcome's
    `assumes`) is re-checked only when every lemma's file is given and itself re-checked;
    otherwise it is not re-checked, its detail naming the lemma missing or not re-checked."""
    by_id = {}
    for k, d in enumerate(docs):
        if isinstance(d, dict) and isinstance(d.get("id"), str):
            by_id.setdefault(d["id"], []).append(k)
    state = {}

    def visit(k, path):
        if k in state:
            return state[k]
        o, d = outcomes[k], docs[k]
        try:
            refs = lemma_refs(d) if isinstance(d, dict) and ("pieces" in d or "computation" in d) else []
        except LinkRefused:
            refs = []  # already refused by the file's own check
        if o.status == refused or not refs:
            state[k] = (o.status, None)
            return state[k]
        path = path + [d["id"]]
        result = None
        missing, pending = [], []
        for lid, goal in refs:
            files = by_id.get(lid, [])
            if not files:
                missing.append(lid)
                continue
            if len(files) > 1:
                result = (refused, f"lemma {lid}: {len(files)} files state it")
                break
            j = files[0]
            if lid in path:
                cycle = path[path.index(lid):] + [lid]
                result = (refused, "the lemmas form a cycle: " + " → ".join(cycle))
                break
            if docs[j].get("goal") != goal:
                result = (refused, f"lemma {lid}: its file states another goal than the one this proof assumes")
                break
            status, why = visit(j, path)
            if status == refused:
                result = (refused, f"rests on lemma {lid}, which is refused" + (f" ({why})" if why else ""))
                break
            if status != rechecked:
                pending.append(lid)
        else:
            gaps = [f"rests on lemma {m}, whose file was not given" for m in missing]
            gaps += [f"rests on lemma {m}, whose file is not re-checked here" for m in pending]
            if gaps:
                result = (not_rechecked, "; lemma references: " + "; ".join(gaps))
            elif o.assumes:
                ids = ", ".join(i for i, _ in refs)
                result = (rechecked, f"; its lemmas {ids} re-checked here in their own files, with the goals it assumes")
            else:
                note = "; lemma references: every lemma's file given, with the goal assumed, none refused, no cycle"
                result = (o.status, note)
        state[k] = result
        return result

    for k in range(len(outcomes)):
        status, why = visit(k, [])
        o = outcomes[k]
        if why is None:
            continue
        if status == refused and o.status != refused:
            o.status, o.detail = refused, why
        elif status != refused:
            o.status = status
            o.detail += why
    return outcomes
