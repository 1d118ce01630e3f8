#!/usr/bin/env bash
# Compiles every `--format latex` output of the texts' claims (`prove --explain ID`, one per
# claim the binary reports) and one `eval --scheme` with pdflatex, one document per fragment;
# checks that nothing outside ASCII is left outside the CJK environments, that no character
# was left unmapped (`[U+....]`), that no equation is set in `\texttt` and that no command-line
# text (`--explain`) is left. Lists overfull lines (text past the margin) as warnings.
#
#   scripts/latex.sh [BINARY [OUT_DIR]]      (defaults: a fresh release build, target/latex/)
#
# Installs Debian's LaTeX (texlive-latex-base, and latex-cjk-japanese with its wadalab fonts
# for the Japanese statements through CJKutf8) with apt-get when pdflatex or CJKutf8 is
# missing (needs root). Prints one line per failure and ends with the one-line summary
# "latex: N of M compiled with pdflatex ..."; exits 1 if any fragment fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-}
out=${2:-target/latex}

if ! command -v pdflatex >/dev/null || ! kpsewhich CJKutf8.sty >/dev/null 2>&1; then
  echo "latex: installing texlive-latex-base and latex-cjk-japanese (apt-get)" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    texlive-latex-base latex-cjk-japanese latex-cjk-japanese-wadalab >/dev/null
fi

if [[ -z $bin ]]; then
  cargo build --release --quiet
  bin=${CARGO_TARGET_DIR:-target}/release/casteljau
fi
[[ -x $bin ]] || { echo "latex: $bin is not an executable" >&2; exit 2; }
mkdir -p "$out"
rm -f "$out"/*.frag "$out"/*.tex "$out"/*.pdf "$out"/*.log "$out"/*.out "$out"/*.aux

# `prove` exits 1 when a verdict differs from the claim files; the ids are wanted regardless
"$bin" prove --format json >"$out/prove.json" || true
ids=$(python3 -c 'import json, sys; print("\n".join(c["id"] for c in json.load(open(sys.argv[1]))["claims"]))' "$out/prove.json")
[[ -n $ids ]] || { echo "latex: $bin prove --format json listed no claims" >&2; exit 2; }

compile() { # NAME FRAGMENT_FILE
  local name=$1 fragment=$2
  if [[ ! -s $fragment ]]; then
    echo "latex: $name: empty fragment"
    return 1
  fi
  # outside \begin{CJK}...\end{CJK}, ASCII only
  if sed 's/\\begin{CJK}{UTF8}{min}[^\\]*\\end{CJK}//g' "$fragment" | LC_ALL=C grep -q '[^ -~]'; then
    echo "latex: $name: non-ASCII outside a CJK environment"
    return 1
  fi
  # an equation is typeset as math, never as typewriter text
  if grep -q '\\texttt{[^}]*=' "$fragment"; then
    echo "latex: $name: an equation in \\texttt: $(grep -o '\\texttt{[^}]*=[^}]*}' "$fragment" | head -1)"
    return 1
  fi
  if grep -v '^%' "$fragment" | grep -q -e '--explain' -e '-{}-explain'; then
    echo "latex: $name: command-line text in the fragment"
    return 1
  fi
  if grep -q '\[U+[0-9A-F]*\]' "$fragment"; then
    echo "latex: $name: a character with no LaTeX form: $(grep -o '\[U+[0-9A-F]*\]' "$fragment" | sort -u | tr '\n' ' ')"
    return 1
  fi
  {
    printf '%s\n' '\documentclass{article}' '\usepackage{CJKutf8}' '\sloppy' '\begin{document}'
    cat "$fragment"
    printf '%s\n' '\end{document}'
  } >"$out/$name.tex"
  if ! (cd "$out" && pdflatex -interaction=nonstopmode -halt-on-error "$name.tex" >"$name.out" 2>&1); then
    echo "latex: $name: pdflatex failed, see $out/$name.log"
    return 1
  fi
  if grep -q '^Overfull \\hbox' "$out/$name.log"; then
    echo "latex: $name: warning: $(grep -c '^Overfull \\hbox' "$out/$name.log") overfull line(s), see $out/$name.log"
    overfull=$((overfull + 1))
  fi
}

total=0 failed=0 overfull=0
for id in $ids; do
  "$bin" --format latex prove --explain "$id" >"$out/$id.frag" || true
  total=$((total + 1))
  compile "$id" "$out/$id.frag" || failed=$((failed + 1))
done
"$bin" --format latex eval --scheme "0,0; 4/3,-4/3; 4/3,4/3; 0,0" --t 1/3 >"$out/scheme.frag" || true
total=$((total + 1))
compile scheme "$out/scheme.frag" || failed=$((failed + 1))

echo "latex: $((total - failed)) of $total compiled with pdflatex ($((total - 1)) claims' --explain and one scheme; $overfull with overfull lines; $out/)"
[[ $failed -eq 0 ]]
