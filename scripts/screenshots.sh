#!/usr/bin/env bash
# Screenshots of the HTML report (and of SVG figures) in headless Chromium, to look at them
# as a reader does.
#
#   scripts/screenshots.sh [REPORT_DIR [OUT_DIR]] [-- FILE.svg ...]
#
# REPORT_DIR (default report/) is written by `casteljau prove --html` when it has no
# index.html; PNGs go to OUT_DIR (default target/screenshots/): one per page, taken at two
# widths (a laptop screen, 1280 px, and a narrow one, 800 px) and tall enough for the page.
# Installs Debian's `chromium` with apt-get when it is missing (needs root). Chromium runs
# offline with a fresh profile: no network, no first-run, no sync.
set -euo pipefail
cd "$(dirname "$0")/.."

report=${1:-report}
out=${2:-target/screenshots}
shift $(( $# > 2 ? 2 : $# )) || true
[[ ${1:-} == -- ]] && shift
extra=("$@")

browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $browser ]]; then
  echo "screenshots: installing chromium (apt-get)" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium fonts-dejavu-core fonts-noto-cjk >/dev/null
  browser=$(command -v chromium)
fi

if [[ ! -f $report/index.html ]]; then
  cargo run --release --quiet -- prove --html "$report" >/dev/null || true
fi
[[ -f $report/index.html ]] || { echo "screenshots: no $report/index.html" >&2; exit 2; }

mkdir -p "$out"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT

shoot() { # URL PNG WIDTH HEIGHT
  "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile" --hide-scrollbars --window-size="$3,$4" \
    --screenshot="$2" "$1" >/dev/null 2>&1
  echo "$2"
}

for page in "$report"/*.html; do
  name=$(basename "$page" .html)
  url="file://$(realpath "$page")"
  # tall enough for the longest page: about 900 px per claim section at most
  shoot "$url" "$out/$name-1280.png" 1280 "${SCREENSHOT_HEIGHT:-2400}"
  shoot "$url" "$out/$name-800.png" 800 "${SCREENSHOT_HEIGHT:-2400}"
done
for svg in "${extra[@]}"; do
  shoot "file://$(realpath "$svg")" "$out/$(basename "$svg" .svg).png" 1000 760
done
