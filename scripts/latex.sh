#!/usr/bin/env bash
# Compiles every `--format latex` output of the texts' claims with pdflatex, one document per
# fragment, and checks that nothing outside ASCII is left outside the CJK environments.
#
#   scripts/latex.sh [OUT_DIR]      (default target/latex/)
#
# Installs Debian's LaTeX (texlive-latex-base, and latex-cjk-japanese with its wadalab fonts
# for the Japanese statements through CJKutf8) with apt-get when pdflatex or CJKutf8 is
# missing (needs root). Prints one line per failure and a count; exits 1 if any fails.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-target/latex}

if ! command -v pdflatex >/dev/null || ! kpsewhich CJKutf8.sty >/dev/null 2>&1; then
  echo "latex: installing texlive-latex-base and latex-cjk-japanese (apt-get)" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    texlive-latex-base latex-cjk-japanese latex-cjk-japanese-wadalab >/dev/null
fi

cargo build --release --quiet
bin=${CARGO_TARGET_DIR:-target}/release/casteljau
mkdir -p "$out"

ids=$("$bin" prove --format json | python3 -c 'import json, sys; print("\n".join(c["id"] for c in json.load(sys.stdin)["claims"]))')

compile() { # NAME FRAGMENT_FILE
  local name=$1 fragment=$2
  # outside \begin{CJK}...\end{CJK}, ASCII only
  if sed 's/\\begin{CJK}{UTF8}{min}[^\\]*\\end{CJK}//g' "$fragment" | LC_ALL=C grep -q '[^ -~]'; then
    echo "latex: $name: non-ASCII outside a CJK environment"
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
}

total=0 failed=0
for id in $ids; do
  "$bin" --format latex prove --explain "$id" >"$out/$id.frag"
  total=$((total + 1))
  compile "$id" "$out/$id.frag" || failed=$((failed + 1))
done
"$bin" --format latex eval --scheme "0,0; 4/3,-4/3; 4/3,4/3; 0,0" --t 1/3 >"$out/scheme.frag"
total=$((total + 1))
compile scheme "$out/scheme.frag" || failed=$((failed + 1))

echo "latex: $((total - failed)) of $total fragments compile with pdflatex ($out/)"
[[ $failed -eq 0 ]]
