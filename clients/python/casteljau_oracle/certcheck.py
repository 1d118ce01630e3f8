"""`python -m casteljau_oracle.certcheck [--symbolic] FILE|DIR …`: re-checks `casteljau prove
--certificates` files independently of the program (standard library only: `fractions`).
`--symbolic` also proves each re-checked goal as an identity of rational functions with
SymPy (the extra `casteljau-oracle[check]`).

Prints one line per certificate — `re-checked`, `refused` (the first failing obligation) or
`not re-checked` (why) — then a summary. Exit status 1 when a file is refused, else 0.
"""

import sys

from _casteljau_oracle.cert_check import NOT_RECHECKED, RECHECKED, REFUSED, Outcome, check_certificate, check_path

__all__ = ["check_certificate", "check_path", "Outcome", "main"]


def main(argv=None):
    args = sys.argv[1:] if argv is None else argv
    if not args or args[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if args else 2
    symbolic = "--symbolic" in args
    args = [a for a in args if a != "--symbolic"]
    if symbolic:
        try:
            import sympy  # noqa: F401
        except ImportError:
            print("certcheck: --symbolic needs SymPy: pip install 'casteljau-oracle[check]'", file=sys.stderr)
            return 2
    outcomes = []
    for path in args:
        try:
            outcomes.extend(check_path(path, symbolic))
        except (OSError, ValueError) as e:
            print(f"certcheck: {e}", file=sys.stderr)
            return 2
    for o in outcomes:
        print(o.line())
    counts = {s: sum(o.status == s for o in outcomes) for s in (RECHECKED, REFUSED, NOT_RECHECKED)}
    proved = [o for o in outcomes if o.verdict in ("proved", "proved_in_range")]
    fails = [o for o in outcomes if o.verdict == "fails"]
    print(
        f"summary: {len(outcomes)} certificates: {counts[RECHECKED]} re-checked, {counts[REFUSED]} refused, "
        f"{counts[NOT_RECHECKED]} not re-checked; proved and proved in range: "
        f"{sum(o.status == RECHECKED for o in proved)}/{len(proved)} re-checked; fails: "
        f"{sum(o.status == RECHECKED for o in fails)}/{len(fails)} re-checked"
    )
    return 1 if counts[REFUSED] else 0


if __name__ == "__main__":
    sys.exit(main())
