#!/usr/bin/env bash
# Renders a page in headless Chromium to a PNG: the HTML player (viz/html_player.hpp) or an SVG.
# For the player it also prints the page's self-check line (<div id="status">: "ok frames=...
# nonblank=1 ..." or "error: ...") and exits 1 unless it starts with "ok".
#
#   scripts/headless_screenshot.sh INPUT.html|INPUT.svg OUTPUT.png [WIDTH,HEIGHT] [VIRTUAL_MS]
#
# Defaults: 1280,800 and 3000 ms of virtual time (the player animates meanwhile). Chromium is
# Debian's `chromium` package (apt-get install chromium); GAITSYNTH_CHROMIUM overrides the binary.
set -euo pipefail
if (($# < 2)); then
  sed -n '2,10p' "$0" >&2
  exit 2
fi
in=$1
out=$2
size=${3:-1280,800}
budget=${4:-3000}
chromium=${GAITSYNTH_CHROMIUM:-$(command -v chromium || command -v chromium-browser ||
  command -v google-chrome || true)}
if [[ -z "$chromium" ]]; then
  echo "headless_screenshot: chromium not found (apt-get install chromium)" >&2
  exit 2
fi
[[ -f "$in" ]] || { echo "headless_screenshot: no such file: $in" >&2; exit 2; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
url="file://$(realpath "$in")"
mkdir -p "$(dirname "$out")"
out_abs="$(realpath -m "$out")"
dom=$(timeout 180 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --enable-logging=stderr --v=0 --hide-scrollbars \
  --screenshot="$out_abs" --window-size="$size" --virtual-time-budget="$budget" \
  --dump-dom "$url" 2>"$profile/chromium.log")
if grep -q "Uncaught" "$profile/chromium.log"; then
  grep "Uncaught" "$profile/chromium.log" >&2
fi
[[ -s "$out_abs" ]] || { echo "headless_screenshot: no screenshot written" >&2; exit 1; }
echo "wrote $out"
status=$(grep -o '<div id="status"[^>]*>[^<]*' <<<"$dom" | sed 's/.*>//' || true)
if [[ "$in" == *.htm || "$in" == *.html ]]; then
  echo "status: ${status:-<none>}"
  [[ "$status" == ok* ]] || exit 1
fi
