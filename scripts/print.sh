#!/usr/bin/env bash
# Prints every page of the HTML report to PDF (A4, as the print stylesheet asks) with headless
# Chromium and reports the page counts, so that the printed handout can be looked at.
#
#   scripts/print.sh [REPORT_DIR [OUT_DIR]]      (defaults: report/, target/print/)
#
# Installs Debian's chromium, fonts-noto-cjk (the Japanese titles) and poppler-utils (pdfinfo;
# pdftoppm turns pages into PNGs) with apt-get when missing (needs root).
set -euo pipefail
cd "$(dirname "$0")/.."
report=${1:-report}
out=${2:-target/print}

if ! command -v chromium >/dev/null || ! command -v pdfinfo >/dev/null; then
  echo "print: installing chromium, fonts-noto-cjk and poppler-utils (apt-get)" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium fonts-noto-cjk poppler-utils >/dev/null
fi
if [[ ! -f $report/index.html ]]; then
  cargo run --release --quiet -- prove --html "$report" >/dev/null || true
fi
[[ -f $report/index.html ]] || { echo "print: no $report/index.html" >&2; exit 2; }

mkdir -p "$out"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
for page in "$report"/*.html; do
  name=$(basename "$page" .html)
  chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$profile" --no-pdf-header-footer \
    --print-to-pdf="$out/$name.pdf" "file://$(realpath "$page")" >/dev/null 2>&1
  pages=$(pdfinfo "$out/$name.pdf" | awk '/^Pages:/ {print $2}')
  size=$(pdfinfo "$out/$name.pdf" | awk -F': *' '/^Page size:/ {print $2}')
  echo "$out/$name.pdf: $pages pages ($size)"
done
echo "print: look at the pages with: pdftoppm -r 60 -png $out/NAME.pdf $out/NAME"
