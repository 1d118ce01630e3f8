#!/usr/bin/env bash
# Writes the HTML report afresh and prints every page to PDF (A4, as the print stylesheet
# asks) with headless Chromium, reports the page counts and checks that text 000's page
# prints to at most 14 pages.
#
#   scripts/print.sh [BINARY [OUT_DIR]]      (defaults: a fresh release build, target/print/)
#   scripts/print.sh REPORT_DIR [OUT_DIR]    (prints an existing report instead)
#
# The report goes to OUT_DIR/report/, the PDFs to OUT_DIR/NAME.pdf. Installs Debian's
# chromium, fonts-noto-cjk (the Japanese titles) and poppler-utils (pdfinfo; pdftoppm turns
# pages into PNGs) with apt-get when missing (needs root). Ends with the one-line summary
# "print: text 000 prints to P A4 pages ..."; exits 1 if it takes more than 14 pages or a
# page is not A4.
set -euo pipefail
cd "$(dirname "$0")/.."
arg=${1:-}
out=${2:-target/print}
max_pages_000=14

if ! command -v chromium >/dev/null || ! command -v pdfinfo >/dev/null || ! fc-list | grep -q "Noto Sans CJK"; then
  echo "print: installing chromium, fonts-noto-cjk and poppler-utils (apt-get)" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium fonts-noto-cjk poppler-utils >/dev/null
fi

mkdir -p "$out"
rm -f "$out"/*.pdf
if [[ -n $arg && -d $arg ]]; then
  report=$arg
else
  bin=$arg
  if [[ -z $bin ]]; then
    cargo build --release --quiet
    bin=${CARGO_TARGET_DIR:-target}/release/casteljau
  fi
  [[ -x $bin ]] || { echo "print: $bin is not an executable" >&2; exit 2; }
  report=$out/report
  rm -rf "$report"
  # `prove` exits 1 when a verdict differs from the claim files; the report is written anyway
  "$bin" prove --html "$report" >/dev/null || true
fi
[[ -f $report/index.html ]] || { echo "print: no $report/index.html" >&2; exit 2; }

profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
status=0 pages_000="" counts=""
for page in "$report"/*.html; do
  name=$(basename "$page" .html)
  chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$profile" --no-pdf-header-footer \
    --print-to-pdf="$out/$name.pdf" "file://$(realpath "$page")" >/dev/null 2>&1
  pages=$(pdfinfo "$out/$name.pdf" | awk '/^Pages:/ {print $2}')
  size=$(pdfinfo "$out/$name.pdf" | awk -F': *' '/^Page size:/ {print $2}')
  echo "$out/$name.pdf: $pages pages ($size)"
  [[ $size == *"(A4)"* ]] || { echo "print: $name is not A4"; status=1; }
  [[ $name == 000_* ]] && pages_000=$pages
  counts+="${counts:+, }${name%%_*} $pages"
done
echo "print: look at the pages with: pdftoppm -r 60 -png $out/NAME.pdf $out/NAME"
if [[ -z $pages_000 ]]; then
  echo "print: no page for text 000 in $report"
  exit 1
fi
if ((pages_000 > max_pages_000)); then
  echo "print: text 000 prints to $pages_000 pages, more than $max_pages_000"
  status=1
fi
echo "print: text 000 prints to $pages_000 A4 pages (at most $max_pages_000); pages per file: $counts; PDFs in $out/"
exit $status
