#!/bin/sh
# shadowcheck reproducer for webgpu/cube/d24/linear/lequal/seamless/stage=compute/seamless=always/wrap=edge/x0=0.9/edge_s/ref=0.5@wgsl on webgpu:chromium: runs repro.html in headless Chromium
# with the backend's flags and prints what the page wrote (its console lines). Debian 12:
# apt-get install -y chromium
# Exit 1: the observation is outside the accepted set; 0: inside; 2: setup failed.
cd "$(dirname "$0")" || exit 2
browser=${SHADOWCHECK_CHROMIUM:-chromium}
command -v "$browser" >/dev/null 2>&1 || { echo "chromium not found: apt-get install -y chromium" >&2; exit 2; }
profile=$(mktemp -d)
log="$profile.log"
: >"$log"
"$browser" --headless --no-sandbox --enable-unsafe-webgpu --use-webgpu-adapter=swiftshader --enable-webgpu-developer-features --disable-gpu --no-first-run --disable-background-networking   --disable-component-update --disable-sync --user-data-dir="$profile" --enable-logging=stderr --v=0   "file://$(pwd)/repro.html" 2>"$log" &
pid=$!
i=0
while [ $i -lt 600 ] && ! grep -q '"shadowcheck-repro: end"' "$log" && kill -0 $pid 2>/dev/null; do
  sleep 0.1
  i=$((i + 1))
done
kill $pid 2>/dev/null
wait $pid 2>/dev/null
text=$(sed -n 's/^.*:INFO:CONSOLE[^]]*\] "\(.*\)", source: .*$/\1/p' "$log" | grep -v -e '^shadowcheck-repro: end$' -e '^\[\.WebGL-')
rm -rf "$profile" "$log"
printf '%s\n' "$text"
case "$text" in
*"verdict:   FAIL"*) exit 1 ;;
*"verdict:"*) exit 0 ;;
*) exit 2 ;;
esac
