#!/usr/bin/env bash
# Writes the HTML report and the students' handout afresh and prints every page to PDF (A4,
# as the print stylesheets ask) with headless Chromium, reports the page counts and how full
# each handout page is, and checks: text 000's report page prints to at most 14 pages; its
# handout to at most 8 pages, each but the last at least 60% full; text 003's handout to at
# most 10 pages.
#
#   scripts/print.sh [BINARY [OUT_DIR]]      (defaults: a fresh release build, target/print/)
#   scripts/print.sh REPORT_DIR [OUT_DIR]    (prints an existing report instead; no handout)
#
# The report goes to OUT_DIR/report/, its PDFs to OUT_DIR/NAME.pdf; the handout to
# OUT_DIR/handout/, its PDFs to OUT_DIR/handout-NAME.pdf. "Full" is measured on the PDF by
# scripts/page_fill.py: the lowest row with ink on the page as a fraction of the page's
# height (at most 96% with the 10 mm margins). Installs Debian's chromium, fonts-noto-cjk
# (the Japanese titles) and poppler-utils (pdfinfo; pdftoppm turns pages into images) with
# apt-get when missing (needs root). Ends with the one-line summaries "print: text 000
# prints to P A4 pages ..." and "print: handout ..."; exits 1 if a check fails or a page is
# not A4.
set -euo pipefail
cd "$(dirname "$0")/.."
arg=${1:-}
out=${2:-target/print}
max_pages_000=14
max_handout_000=8 min_fill_000=60 max_handout_003=10

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
  report=$out/report handout=$out/handout
  rm -rf "$report" "$handout"
  # `prove` exits 1 when a verdict differs from the claim files; the report is written anyway
  "$bin" prove --html "$report" --handout "$handout" >/dev/null || true
fi
[[ -f $report/index.html ]] || { echo "print: no $report/index.html" >&2; exit 2; }

profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
status=0 pages_000="" counts=""
print_pdf() { # HTML PDF: prints one page; sets $pages to its page count
  chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$profile" --no-pdf-header-footer \
    --print-to-pdf="$2" "file://$(realpath "$1")" >/dev/null 2>&1
  local size
  size=$(pdfinfo "$2" | awk -F': *' '/^Page size:/ {print $2}')
  [[ $size == *"(A4)"* ]] || { echo "print: $2 is not A4 ($size)"; status=1; }
  pages=$(pdfinfo "$2" | awk '/^Pages:/ {print $2}')
}
for page in "$report"/*.html; do
  name=$(basename "$page" .html)
  print_pdf "$page" "$out/$name.pdf"
  echo "$out/$name.pdf: $pages pages"
  [[ $name == 000_* ]] && pages_000=$pages
  counts+="${counts:+, }${name%%_*} $pages"
done
handout_line=""
if [[ -n ${handout:-} ]]; then
  hcounts="" h000="" h003="" fill000=""
  for page in "$handout"/*.html; do
    name=$(basename "$page" .html)
    [[ $name == index ]] && continue
    pdf=$out/handout-$name.pdf
    print_pdf "$page" "$pdf"
    fill=$(python3 scripts/page_fill.py "$pdf")
    echo "$pdf: $pages pages, filled $fill"
    hcounts+="${hcounts:+, }${name%%_*} $pages"
    case $name in
      000_*) h000=$pages fill000=$fill ;;
      003_*) h003=$pages ;;
    esac
  done
  if [[ -z $h000 || -z $h003 ]]; then
    echo "print: the handout has no page for text 000 or 003"
    status=1
  else
    ((h000 <= max_handout_000)) || { echo "print: text 000's handout prints to $h000 pages, more than $max_handout_000"; status=1; }
    ((h003 <= max_handout_003)) || { echo "print: text 003's handout prints to $h003 pages, more than $max_handout_003"; status=1; }
    # every page but the last at least min_fill_000 percent full
    read -r -a fills <<<"$fill000"
    for ((k = 0; k + 1 < ${#fills[@]}; k++)); do
      f=${fills[k]%\%}
      ((f >= min_fill_000)) || { echo "print: page $((k + 1)) of text 000's handout is only $f% full"; status=1; }
    done
    handout_line="print: handout: text 000 prints to $h000 A4 pages (at most $max_handout_000), filled $fill000 (each but the last at least $min_fill_000%); text 003 to $h003 (at most $max_handout_003); pages per file: $hcounts"
  fi
fi
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
[[ -z $handout_line ]] || echo "$handout_line"
exit $status
