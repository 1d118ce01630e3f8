#!/usr/bin/env bash
# The interactive figures (`casteljau figure KIND --interactive`) in a real browser: installs
# Debian's Chromium and playwright-core (npm) if absent, then scripts/browser_test.mjs loads each
# page headless, moves its sliders and drags its points to POSITIONS random positions (default 60)
# and compares every value the page shows with `casteljau oracle`'s, byte for byte; it also
# checks that nothing is wider than the viewport at 1280 and 390 px.
#
#   bash scripts/browser_test.sh                       # SEED=… to replay a run
#   UPDATE_SCREENSHOTS=1 bash scripts/browser_test.sh  # also rewrite docs/screenshots/*.png
set -euo pipefail
cd "$(dirname "$0")/.."
target_dir="${CARGO_TARGET_DIR:-target}"
case "$target_dir" in /*) ;; *) target_dir="$PWD/$target_dir" ;; esac

# Only what is missing: a machine whose Node.js comes from elsewhere (NodeSource's bundles npm)
# cannot take Debian's npm beside it.
missing=()
[ -x /usr/bin/chromium ] || missing+=(chromium chromium-driver)
command -v node >/dev/null || missing+=(nodejs)
command -v npm >/dev/null || missing+=(npm)
if [ "${#missing[@]}" -gt 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi
pw="$target_dir/browser-test"
if [ ! -f "$pw/node_modules/playwright-core/package.json" ]; then
    # the driver library alone: it downloads no browser of its own
    npm install --no-save --no-audit --no-fund --silent --prefix "$pw" playwright-core@1.65.2
fi
[ -x "$target_dir/release/casteljau" ] || cargo build --release

seed="${SEED:-$(date +%s)}"
shots="$pw/screenshots"
echo "browser test: Chromium $(/usr/bin/chromium --version 2>/dev/null | awk '{print $2}'), seed $seed"
node scripts/browser_test.mjs --bin "$target_dir/release/casteljau" --pw "$pw" \
    --positions "${POSITIONS:-60}" --seed "$seed" --shots "$shots"
if [ -n "${UPDATE_SCREENSHOTS:-}" ]; then
    mkdir -p docs/screenshots
    cp "$shots"/*.png docs/screenshots/
fi
