#!/usr/bin/env bash
# Random statements made of TeX's special characters (\ { } ^ _ % # $ & ~), quotes, letters,
# digits and spaces, each rendered by `prove --explain ID --format latex` and compiled with
# pdflatex, one document per statement: each must compile (a statement is never refused: the
# renderer escapes what it cannot set). Also checks that no fragment holds TeX's `^^` notation.
#
#   scripts/latex_fuzz.sh [BINARY [COUNT [SEED]]]     (defaults: target/release/casteljau, 100, 1)
#
# Needs pdflatex (Debian: apt-get install texlive-latex-base). Prints one line per failure and
# ends with "latex fuzz: N of M compiled"; exits 1 if any fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-target/release/casteljau}
count=${2:-100}
seed=${3:-1}
command -v pdflatex >/dev/null || { echo "latex fuzz: pdflatex is missing (apt-get install texlive-latex-base)" >&2; exit 2; }
out=$(mktemp -d)
python3 - "$count" "$seed" >"$out/fuzz.toml" <<'PY'
import random, sys
count, seed = int(sys.argv[1]), int(sys.argv[2])
rng = random.Random(seed)
alphabet = list("\\{}^_%#$&~") * 3 + list("abxyt'() 12")
for k in range(count):
    s = "".join(rng.choice(alphabet) for _ in range(rng.randint(1, 40)))
    esc = s.replace("\\", "\\\\").replace('"', '\\"')
    print(f'[[claim]]\nid = "f{k}"\nsource = "x 1"\nstatement = "{esc}"\nkind = "identity"\nvars = ["t"]\nlhs = "t"\nrhs = "t"\n')
PY
failed=0
for ((k = 0; k < count; k++)); do
  frag="$out/f$k.tex"
  {
    printf '%s\n' '\documentclass{article}' '\begin{document}'
    "$bin" --format latex prove "$out/fuzz.toml" --explain "f$k"
    printf '%s\n' '\end{document}'
  } >"$frag"
  if grep -q '\^\^' "$frag"; then
    echo "latex fuzz: f$k: ^^ in $frag"
    failed=$((failed + 1))
  elif ! (cd "$out" && pdflatex -interaction=nonstopmode -halt-on-error -no-shell-escape "f$k.tex" >/dev/null 2>&1); then
    echo "latex fuzz: f$k: pdflatex failed on statement $(grep -A0 "^id = \"f$k\"" -A2 "$out/fuzz.toml" | tail -1); see $out/f$k.log"
    failed=$((failed + 1))
  fi
done
echo "latex fuzz: $((count - failed)) of $count compiled with pdflatex (seed $seed; $out/)"
[[ $failed -eq 0 ]]
