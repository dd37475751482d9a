#!/bin/sh
# Runs repro.html in headless Chromium and prints its lines. Debian 12: apt-get install -y chromium
# sh run.sh          Dawn's Vulkan backend on SwiftShader (shadowcheck's webgpu:chromium flags)
# sh run.sh compat   Dawn's OpenGL ES backend on ANGLE on SwiftShader, compatibility mode
# Exit 1: a lookup differs from the expected value; 0: none does; 2: the page printed no verdict.
cd "$(dirname "$0")" || exit 2
browser=${SHADOWCHECK_CHROMIUM:-chromium}
if [ "$1" = compat ]; then
  flags="--enable-unsafe-webgpu --use-webgpu-adapter=opengles --enable-webgpu-developer-features --use-angle=swiftshader --enable-unsafe-swiftshader"
  query="?compat"
else
  flags="--enable-unsafe-webgpu --use-webgpu-adapter=swiftshader --enable-webgpu-developer-features --disable-gpu"
  query=""
fi
profile=$(mktemp -d)
log="$profile.log"
"$browser" --headless --no-sandbox $flags --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$profile" --enable-logging=stderr --v=0 \
  "file://$(pwd)/repro.html$query" 2>"$log" &
pid=$!
i=0
while [ $i -lt 600 ] && ! grep -q '"repro: end"' "$log" && kill -0 $pid 2>/dev/null; do
  sleep 0.1
  i=$((i + 1))
done
kill $pid 2>/dev/null
wait $pid 2>/dev/null
text=$(sed -n 's/^.*:INFO:CONSOLE[^]]*\] "\(.*\)", source: .*$/\1/p' "$log" | grep -v '^repro: end$')
rm -rf "$profile" "$log"
printf '%s\n' "$text"
case "$text" in
*"verdict: FAIL"*) exit 1 ;;
*"verdict:"*) exit 0 ;;
*) exit 2 ;;
esac
