#!/bin/bash
# Attacks on the run's contract with CI (runner/README.md, "What a run guarantees") against a
# release build, one line each:
#   attack | what was seen | exit code | OK (contract kept) or BROKEN
# Usage, from the repository root:  bash runner/tests/chaos.sh [path/to/shadowcheck]
# Needs python3; the GL attacks need Mesa (as installed by .ci/run) and are SKIPPED without it, the
# WebGL and WebGPU kills need Chromium and are SKIPPED without it; the full-disk attack needs a tmpfs mount
# (root) and is SKIPPED without one. Takes a few minutes.
# It only reports: its exit status is the number of BROKEN lines.
set -u
SC=${1:-target/release/shadowcheck}
[ -x "$SC" ] || { echo "no binary at $SC (cargo build --release -p shadowcheck-runner)"; exit 2; }
SC=$(cd "$(dirname "$SC")" && pwd)/$(basename "$SC")
T=$(mktemp -d /tmp/shadowcheck-chaos.XXXXXX)
BROKEN=0
line() { # attack seen code verdict
  printf '%-44s | %-62s | %4s | %s\n' "$1" "$2" "$3" "$4"
  [ "$4" = BROKEN ] && BROKEN=$((BROKEN + 1))
}
ok_if() { if eval "$1"; then echo OK; else echo BROKEN; fi; }
panicked() { grep -q 'panicked' "$1" && echo "panic" || echo "no panic"; }

"$SC" gen --grid smoke -o "$T/fx" >/dev/null 2>&1
FX="$T/fx"
HAVE_GL=no
"$SC" run -b egl:llvmpipe:core --fixtures "$FX" --cases '^gl46/' -o "$T/glprobe" >/dev/null 2>&1
[ -f "$T/glprobe/results.csv" ] && grep -q ',Pass,' "$T/glprobe/results.csv" && HAVE_GL=yes

# An external implementation (PROTOCOL.md) that answers correctly (it asks for the expectation)
# and misbehaves as told: extra (one extra answer line after the 3rd case it ever saw), dup (two
# results for one API path of that case), empty (`results: []` for every case). "The 3rd case"
# is remembered in a file, so a restarted process (the runner restarts it after a protocol error)
# misbehaves on that same case and no other: exactly one case is at fault.
cat >"$T/impl.py" <<'EOF'
import json, os, sys
mode = sys.argv[1]
mark = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bad-" + mode)
n = 0
def guilty(case_id):
    if not os.path.exists(mark):
        if n < 3:
            return False
        with open(mark, "w") as f:
            f.write(case_id)
    with open(mark) as f:
        return f.read() == case_id
def value(case, api):
    e = case.get("expect") or {}
    r = e.get("spec_value")
    r = 0.0 if r is None else r
    out = []
    for ch in (e.get("layout") or {}).get(api, ["r", "r", "r", "r"]):
        out.append(r if ch == "r" else 1.0 if ch == "1" else 0.0)
    return out
for raw in sys.stdin:
    m = json.loads(raw) if raw.strip() else {}
    t = m.get("type")
    if t == "hello":
        print(json.dumps({"type": "hello", "protocol": 1, "name": "chaos-" + mode, "wants_expect": True,
                          "capabilities": {"specs": ["gl46"], "api": ["core"]}}))
    elif t == "case":
        c = m["case"]; n += 1
        res = [{"api": a, "rgba": value(c, a)} for a in c["api"]]
        if mode == "empty":
            res = []
        if mode == "dup" and guilty(c["id"]):
            res = res + [{"api": res[0]["api"], "rgba": [0.5, 0.5, 0.5, 0.5]}]
        print(json.dumps({"type": "observation", "case_id": c["id"], "results": res}))
        if mode == "extra" and guilty(c["id"]):
            print(json.dumps({"type": "observation", "case_id": c["id"], "results": res}))
    elif t == "flush":
        sys.stdout.flush()
    elif t == "bye":
        break
    sys.stdout.flush()
EOF
EXEC() { echo "exec:python3 $T/impl.py $1"; }
status_of() { grep -F "$2" "$1/results.csv" | cut -d, -f2 | sort | uniq -c | tr -s ' ' | tr '\n' ' '; }
count_status() { cut -d, -f2 "$1/results.csv" 2>/dev/null | grep -cx "$2"; }

# --- Panics and wrong exit codes ---------------------------------------------------------------
"$SC" run -b soft --fixtures "$FX" --timeout 1e19 -o "$T/a1" >"$T/a1.out" 2>&1; c=$?
line "run --timeout 1e19" "$(panicked "$T/a1.out")" $c "$(ok_if "[ $c = 96 ] && ! grep -q panicked $T/a1.out")"

bash -c "'$SC' explain --spec gl46 --filter linear --dt 0.2,0.4,0.6,0.8 2>'$T/a2.err' | head -1 >/dev/null; exit \${PIPESTATUS[0]}"; c=$?
line "explain ... | head" "$(panicked "$T/a2.err")" $c "$(ok_if "[ $c != 101 ] && ! grep -q panicked $T/a2.err")"

bash -c "'$SC' run -b 'mock:fail=lequal' --fixtures '$FX' -o '$T/a3' 2>'$T/a3.err' | head -1 >/dev/null; exit \${PIPESTATUS[0]}"; c=$?
line "run ... | head, with regressions" "exit $c (100 documented)" $c "$(ok_if "[ $c = 100 ]")"
bash -c "'$SC' run -b 'mock:fail=lequal' --fixtures '$FX' -o '$T/a3b' -v 2>&1 | head -1 >/dev/null; exit \${PIPESTATUS[0]}"; c=$?
line "run ... 2>&1 | head (stderr's reader gone)" "exit $c (100 documented; a panic is 101)" $c "$(ok_if "[ $c = 100 ]")"

mkdir -p "$T/full"
if mount -t tmpfs -o size=200k tmpfs "$T/full" 2>/dev/null; then
  "$SC" run -b 'mock:fail=lequal' --fixtures "$FX" -o "$T/full/o" >"$T/a4.out" 2>&1; c=$?
  said=$(grep -o 'exit code [0-9]*' "$T/a4.out" | tail -1 | grep -o '[0-9]*$')
  empty=$(find "$T/full/o" -type f -size 0 2>/dev/null | wc -l)
  line "full disk (tmpfs 200k), with regressions" "printed ${said:-none}, ${empty} empty files" $c "$(ok_if "[ $c = 100 ] && [ '${said:-x}' = $c ] && [ $empty = 0 ]")"
  umount "$T/full"
else
  line "full disk" "SKIPPED (cannot mount a tmpfs here)" - SKIPPED
fi

echo '.*' >"$T/skipall.txt"
"$SC" run -b soft --fixtures "$FX" --skips "$T/skipall.txt" -o "$T/a5" >"$T/a5.out" 2>&1; c=$?
line "skips file .* (everything skipped)" "$(grep -o '[0-9]* skip' "$T/a5.out" | tail -1)" $c "$(ok_if "[ $c != 0 ]")"

if [ $HAVE_GL = yes ]; then
  "$SC" run -b egl:llvmpipe:es2 --fixtures "$FX" -o "$T/a6" >"$T/a6.out" 2>&1; c=$?
  line "backend that skips everything (egl es2)" "$(grep -o '[0-9]* tests: [0-9]* pass' "$T/a6.out" | tail -1)" $c "$(ok_if "[ $c != 0 ]")"
  VK_ICD_FILENAMES=/nonexistent "$SC" run --fixtures "$FX" --cases '^gl46/2d/d16/nearest/lequal/' -o "$T/a7" >"$T/a7.out" 2>&1; c=$?
  zink=$(grep -c 'zink' "$T/a7.out")
  line "zink hidden (VK_ICD_FILENAMES), default run" "zink named $zink times; hint: $(grep -c 'apt-get' "$T/a7.out")" $c "$(ok_if "[ $c != 0 ]")"
else
  line "backend that skips everything (egl es2)" "SKIPPED (no Mesa)" - SKIPPED
  line "missing driver, default run" "SKIPPED (no Mesa)" - SKIPPED
fi

"$SC" run -b 'mock:crash=/texel=1_' --fixtures "$FX" --cases '^gl46/' -o "$T/a8" >"$T/a8.out" 2>&1; c=$?
cr=$(count_status "$T/a8" Crash); fl=$(count_status "$T/a8" Flake)
line "crash that recurs on re-run" "$cr Crash, $fl Flake" $c "$(ok_if "[ $c = 100 ] && [ $cr -gt 0 ] && [ $fl = 0 ]")"

s=$(date +%s)
timeout 300 "$SC" run -b 'mock:hang=.' --fixtures "$FX" --cases '^gl46/2d/' --timeout 0.2 -o "$T/a9" >"$T/a9.out" 2>&1; c=$?
w=$(( $(date +%s) - s )); n=$(count_status "$T/a9" Timeout)
line "hangs on every case (timeout 0.2 s, 10 s max)" "$n Timeout in ${w} s" $c "$(ok_if "[ $c = 100 ] && [ $w -le 10 ]")"

"$SC" run -b "$(EXEC extra)" --fixtures "$FX" --cases '^gl46/' --no-rerun -o "$T/a10" >"$T/a10.out" 2>&1; c=$?
bad=$(( $(count_status "$T/a10" Crash) + $(count_status "$T/a10" Flake) ))
line "one extra answer line" "$bad Crash/Flake; $(count_status "$T/a10" Pass) Pass" $c "$(ok_if "[ $c != 0 ] && [ $bad -le 1 ]")"

"$SC" run -b "$(EXEC dup)" --fixtures "$FX" --cases '^gl46/' -o "$T/a11" >"$T/a11.out" 2>&1; c=$?
line "two results for one API path" "$(count_status "$T/a11" Pass) Pass, $(count_status "$T/a11" Fail) Fail, $(count_status "$T/a11" Crash) Crash" $c "$(ok_if "[ $c != 0 ]")"

"$SC" run -b "$(EXEC empty)" --fixtures "$FX" --cases '^gl46/' -o "$T/a12" >"$T/a12.out" 2>&1; c=$?
line "results: [] for every case" "$(count_status "$T/a12" Skip) Skip" $c "$(ok_if "[ $c != 0 ]")"

# --- Data loss ---------------------------------------------------------------------------------
"$SC" run -b 'mock:slow=50' --fixtures "$FX" -o "$T/a13" >"$T/a13a.out" 2>&1 & p1=$!
sleep 0.5
"$SC" run -b 'mock:slow=50' --fixtures "$FX" -o "$T/a13" >"$T/a13b.out" 2>&1; c2=$?
wait $p1; c1=$?
"$SC" run -b 'mock:slow=50' --fixtures "$FX" -o "$T/a13" --resume >"$T/a13c.out" 2>&1; c3=$?
line "two runs into one --out" "exits $c1 and $c2; resume after: $c3" "$c2" "$(ok_if "[ $c2 = 96 ] && [ $c1 = 0 ] && [ $c3 = 0 ]")"

zero=0
for d in 0.3 0.5 0.7 0.9 1.1 1.3; do
  rm -rf "$T/a14"
  "$SC" run -b 'mock:fail=.' --fixtures "$FX" --no-rerun -o "$T/a14" >/dev/null 2>&1 & p=$!
  sleep $d; kill -9 $p 2>/dev/null; wait $p 2>/dev/null
  for f in failures.csv results.csv junit.xml report.json report.md; do
    [ -f "$T/a14/$f" ] && [ ! -s "$T/a14/$f" ] && zero=$((zero + 1))
  done
done
line "kill -9 at 6 moments (reports half-written?)" "$zero empty report files" - "$(ok_if "[ $zero = 0 ]")"

# A background job of a script ignores SIGINT; python puts the default action back before exec.
python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
  "$SC" run -b 'mock:slow=200' --fixtures "$FX" -o "$T/a15" >"$T/a15.out" 2>&1 & p=$!
sleep 2; kill -INT $p; wait $p; c=$?
line "Ctrl-C mid-run" "resume hint: $(grep -c -- '--resume' "$T/a15.out"); report.md: $([ -f "$T/a15/report.md" ] && echo yes || echo no)" $c "$(ok_if "grep -q -- --resume $T/a15.out && [ -f $T/a15/report.md ]")"

# --- Noise a CI user trips over ----------------------------------------------------------------
"$SC" run -b soft:gl46 --fixtures "$FX" -o "$T/a16" >"$T/a16.out" 2>&1; c=$?
na=$(grep -o '[0-9]* not applicable' "$T/a16.out" | tail -1); sk=$(count_status "$T/a16" Skip)
line "cases a backend cannot run (soft:gl46)" "${na:-no not-applicable count}; $sk Skip in results.csv" $c "$(ok_if "[ -n '$na' ] && [ $sk = 0 ]")"

"$SC" run -b soft -o "$T/a17" >/dev/null 2>&1; c=$?
# results.csv is deqp-runner's format: a line per test, its length the test name's. What the run
# adds beside it (results.jsonl, reports) is held to 100 bytes per test.
tests=$(wc -l <"$T/a17/results.csv"); bytes=$(du -sb "$T/a17" | cut -f1); csv=$(stat -c %s "$T/a17/results.csv")
line "output size, run -b soft (default fixtures)" "$bytes bytes for $tests tests: $(((bytes - csv) / tests)) B/test beside results.csv" $c "$(ok_if "[ $(((bytes - csv) / tests)) -le 100 ]")"

"$SC" run -b 'mock:fail=lequal' -b 'mock:fail=gequal' --fixtures "$FX" -o "$T/a18" >/dev/null 2>&1; c=$?
quoted=$(grep -c '^"' "$T/a18/results.csv"); dups=$(cut -d, -f1 "$T/a18/results.csv" | sort | uniq -d | wc -l)
fails=$(( $(count_status "$T/a18" Fail) )); flines=$(wc -l <"$T/a18/failures.csv")
fdups=$(cut -d, -f1 "$T/a18/failures.csv" | sort | uniq -d | wc -l)
line "deqp-runner CSV: 2 backends" "$quoted quoted, $dups repeated names; $fails Fail, failures.csv $flines lines" $c "$(ok_if "[ $quoted = 0 ] && [ $dups = 0 ] && [ $fails = $flines ] && [ $fdups = 0 ]")"

for k in 1 2 3; do "$SC" run -b mock: --fixtures "$FX" --shard $k/4 -o "$T/a19/s$k" >/dev/null 2>&1; done
"$SC" merge -o "$T/a19/m" "$T"/a19/s* >"$T/a19.out" 2>&1; c=$?
line "merge 3 of 4 shards" "$(grep -o 'shard(s) [^ ]* missing' "$T/a19.out" || echo 'no word')" $c "$(ok_if "[ $c != 0 ]")"
"$SC" run -b mock: --fixtures "$FX" --cases lequal -o "$T/a19/other" >/dev/null 2>&1
"$SC" merge -o "$T/a19/m2" "$T/a19/s1" "$T/a19/other" >"$T/a19b.out" 2>&1; c=$?
line "merge of unrelated runs" "$(grep -o 'unrelated runs' "$T/a19b.out" || echo 'no word')" $c "$(ok_if "[ $c != 0 ]")"

mkdir -p "$T/a20"; cp -r "$T/a18" "$T/a20/r1"
"$SC" report "$T"/a20/* -o "$T/a20/html" --fixtures "$FX" >/dev/null 2>&1
"$SC" report "$T"/a20/* -o "$T/a20/html" --fixtures "$FX" >"$T/a20.out" 2>&1; c=$?
line "report out/* -o out/html, second time" "$(tail -1 "$T/a20.out" | cut -c1-60)" $c "$(ok_if "[ $c = 0 ]")"

printf '%s\n' "gl46/no/such/test@core,Fail" "$(head -1 "$T/a18/results.csv" | cut -d, -f1 | sed 's|^[^/]*/||'),Pass" >"$T/base.csv"
"$SC" run -b mock: --fixtures "$FX" --baseline "$T/base.csv" -o "$T/a21" >"$T/a21.out" 2>&1; c=$?
line "baseline: Pass entry + entry matching nothing" "$(grep -c 'warning: baseline entry' "$T/a21.out") warnings" $c "$(ok_if "[ \$(grep -c 'warning: baseline entry' $T/a21.out) = 2 ]")"

mkdir -p "$T/badfx"
sed -n '1p;2p' "$FX/gl46.json" >"$T/badfx/x.json"
python3 - "$T/badfx/x.json" <<'EOF'
import json, sys
p = sys.argv[1]
head, case = open(p).read().splitlines()[:2]
c = json.loads(case.rstrip(','))
c1 = dict(c, id=c["id"] + "/dt=0.2,0.4")
c2 = dict(c, id=c["id"] + "/dup", api=c["api"] + c["api"][:1])
open(p, "w").write(head + "\n" + json.dumps(c1) + ",\n" + json.dumps(c2) + "\n]}\n")
EOF
"$SC" run -b soft --fixtures "$T/badfx" -o "$T/a22" >"$T/a22.out" 2>&1; c=$?
line "fixture: id with a comma, API path twice" "$(grep -c "in the id" "$T/a22.out") comma error, $(grep -c 'duplicate API path' "$T/a22.out") duplicate error" $c "$(ok_if "[ $c = 96 ] && grep -q 'in the id' $T/a22.out && grep -q 'duplicate API path' $T/a22.out")"

# WebGL backend (webgl:chromium): Chromium's GPU process and the page's renderer killed by PID
# during a run, a browser that cannot start, one that ignores Browser.close, a worker killed with
# SIGKILL (its profile folder). The kills need Chromium and are SKIPPED without it.
descendants() { # pid: every descendant's "pid args"
  local k
  for k in $(ps -o pid= --ppid "$1" 2>/dev/null); do
    ps -o pid=,args= -p "$k" 2>/dev/null; descendants "$k"
  done
}
# kill_in_run DIR WHAT: `run -v -b webgl:chromium` on the GLES 3.2 2D fixtures into DIR (the
# clean run's failures as baseline); once its first batch is written, SIGKILL every descendant
# process whose arguments match WHAT (once).
kill_in_run() {
  "$SC" run -v -b webgl:chromium --fixtures cases/fixtures/gles32/2d --baseline "$T/w0/failures.csv" \
    -o "$1" >"$1.out" 2>&1 &
  local p=$! i victims=""
  for i in $(seq 600); do
    [ "$(cat "$1/results.jsonl" 2>/dev/null | wc -l)" -gt 1 ] && break
    sleep 0.05
  done
  victims=$(descendants $p | grep -- "$2" | grep -v -- '--top-chrome' | awk '{print $1}')
  [ -n "$victims" ] && kill -9 $victims
  wait $p; echo "$? $(echo $victims | wc -w)"
}
statuses() { cut -d, -f1,2 "$1/results.csv" | sed 's/,ExpectedFail$/,Fail/' | sort; }
if "$SC" webgl-worker --probe >/dev/null 2>&1; then
  "$SC" run -b webgl:chromium --fixtures cases/fixtures/gles32/2d -o "$T/w0" >/dev/null 2>&1
  read -r c n <<<"$(kill_in_run "$T/w1" '--type=gpu-process')"
  lost=$(grep -c 'the WebGL context was lost' "$T/w1.out")
  same=$(cmp -s <(statuses "$T/w0") <(statuses "$T/w1") && echo same || echo different)
  line "webgl: kill -9 Chromium's GPU process" "$n killed, $lost context-lost exits, verdicts $same as a clean run's" $c "$(ok_if "[ $c = 0 ] && [ $n -ge 1 ] && [ $lost -ge 1 ] && [ $same = same ]")"
  read -r c n <<<"$(kill_in_run "$T/w2" '--type=renderer')"
  died=$(grep -c "the page's renderer process died" "$T/w2.out")
  same=$(cmp -s <(statuses "$T/w0") <(statuses "$T/w2") && echo same || echo different)
  line "webgl: kill -9 the page's renderer" "$n killed, $died renderer-died exits, verdicts $same, $(grep -c ',Timeout,' "$T/w2/results.csv") Timeout" $c "$(ok_if "[ $c = 0 ] && [ $n -ge 1 ] && [ $died -ge 1 ] && [ $same = same ]")"
  # The worker killed once its first batch is answered: the runner restarts it, and the next
  # worker's start removes the killed one's profile folder.
  mkdir -p "$T/w3tmp"
  TMPDIR="$T/w3tmp" "$SC" run -b webgl:chromium --fixtures cases/fixtures/gles32/2d --baseline "$T/w0/failures.csv" \
    -o "$T/w3" >"$T/w3.out" 2>&1 &
  p=$!; w=""
  for i in $(seq 600); do
    [ "$(cat "$T/w3/results.jsonl" 2>/dev/null | wc -l)" -gt 1 ] && break
    sleep 0.05
  done
  w=$(descendants $p | grep -- 'webgl-worker' | awk '{print $1}' | head -1)
  had=$(ls "$T/w3tmp" | grep -c "^shadowcheck-chromium-$w-")
  [ -n "$w" ] && kill -9 "$w"; wait $p; c=$?
  left=$(ls "$T/w3tmp" | grep -c '^shadowcheck-chromium-')
  line "webgl: kill -9 the worker (profile folder)" "worker ${w:-not found} killed with $had folder, $left folders left" $c "$(ok_if "[ -n '$w' ] && [ $had = 1 ] && [ $left = 0 ]")"
else
  line "webgl: kill -9 Chromium's GPU process" "SKIPPED (no Chromium)" - SKIPPED
  line "webgl: kill -9 the page's renderer" "SKIPPED (no Chromium)" - SKIPPED
  line "webgl: kill -9 the worker (profile folder)" "SKIPPED (no Chromium)" - SKIPPED
fi
# WebGPU backend (webgpu:chromium): Chromium's GPU process (Dawn's device) and the page's renderer
# killed by PID during a run: the worker ends without answering what was in flight, the runner
# re-runs it in a fresh browser, and the verdicts are a clean run's. SKIPPED without an adapter.
kill_in_webgpu_run() { # DIR WHAT, as kill_in_run
  "$SC" run -v -b webgpu:chromium --fixtures cases/fixtures/webgpu/2d --baseline "$T/g0/failures.csv" \
    -o "$1" >"$1.out" 2>&1 &
  local p=$! i victims=""
  for i in $(seq 600); do
    [ "$(cat "$1/results.jsonl" 2>/dev/null | wc -l)" -gt 1 ] && break
    sleep 0.05
  done
  victims=$(descendants $p | grep -- "$2" | grep -v -- '--top-chrome' | awk '{print $1}')
  [ -n "$victims" ] && kill -9 $victims
  wait $p; echo "$? $(echo $victims | wc -w)"
}
if "$SC" webgpu-worker --probe >/dev/null 2>&1; then
  "$SC" run -b webgpu:chromium --fixtures cases/fixtures/webgpu/2d -o "$T/g0" >/dev/null 2>&1
  read -r c n <<<"$(kill_in_webgpu_run "$T/g1" '--type=gpu-process')"
  lost=$(grep -c -e 'the WebGPU device is gone' -e "renderer process died" -e 'closed the DevTools pipe' "$T/g1.out")
  same=$(cmp -s <(statuses "$T/g0") <(statuses "$T/g1") && echo same || echo different)
  line "webgpu: kill -9 Chromium's GPU process" "$n killed, $lost device-gone exits, verdicts $same as a clean run's" $c "$(ok_if "[ $c = 0 ] && [ $n -ge 1 ] && [ $lost -ge 1 ] && [ $same = same ]")"
  read -r c n <<<"$(kill_in_webgpu_run "$T/g2" '--type=renderer')"
  died=$(grep -c "the page's renderer process died" "$T/g2.out")
  same=$(cmp -s <(statuses "$T/g0") <(statuses "$T/g2") && echo same || echo different)
  line "webgpu: kill -9 the page's renderer" "$n killed, $died renderer-died exits, verdicts $same" $c "$(ok_if "[ $c = 0 ] && [ $n -ge 1 ] && [ $died -ge 1 ] && [ $same = same ]")"
else
  line "webgpu: kill -9 Chromium's GPU process" "SKIPPED (no Chromium or no WebGPU adapter)" - SKIPPED
  line "webgpu: kill -9 the page's renderer" "SKIPPED (no Chromium or no WebGPU adapter)" - SKIPPED
fi
printf '#!/bin/sh\necho "chaos-chromium: error while loading shared libraries" >&2\nsleep 40 &\nexit 127\n' >"$T/nochrome"
chmod +x "$T/nochrome"
s0=$(date +%s)
SHADOWCHECK_CHROMIUM="$T/nochrome" "$SC" run -b webgl:chromium --fixtures "$FX" -o "$T/w4" >"$T/w4.out" 2>&1; c=$?
line "webgl: browser exits at start (pipe kept)" "$(( $(date +%s) - s0 )) s, $(grep -o 'exit status: 127' "$T/w4.out" | head -1), $(grep -c 'no hello within' "$T/w4.out") 'no hello'" $c "$(ok_if "[ $c = 96 ] && grep -q 'exit status: 127; its last stderr lines: chaos-chromium' $T/w4.out && ! grep -q 'no hello within' $T/w4.out")"
printf '#!/bin/sh\nexec python3 %s hang-close "$@"\n' "$(pwd)/webgl/tests/fake_chromium.py" >"$T/hangclose"
chmod +x "$T/hangclose"
s0=$(date +%s)
printf '{"type":"hello","protocol":2}\n{"type":"bye"}\n' | SHADOWCHECK_CHROMIUM="$T/hangclose" timeout 60 "$SC" webgl-worker >/dev/null 2>&1; c=$?
line "webgl: browser ignores Browser.close" "worker ended after $(( $(date +%s) - s0 )) s" $c "$(ok_if "[ $c = 0 ] && [ $(( $(date +%s) - s0 )) -lt 10 ]")"

# --- Run pipeline: state phase, give-up, stderr, unreadable answers, Ctrl-C count -----------------
ONE='^gl46/1d/d16/nearest/none/texel1/read/'
"$SC" run -b 'mock:extra=compare_mode/set=0x0205$' --fixtures "$FX" --cases '^state/gl46/core/' -o "$T/b1" >"$T/b1.out" 2>&1; c=$?
line "second answer to a state case" "$(count_status "$T/b1" Crash) Crash, $(count_status "$T/b1" Pass) Pass" $c "$(ok_if "[ $c = 100 ] && [ $(count_status "$T/b1" Crash) = 1 ]")"

"$SC" run -b 'mock:previous=compare_mode/set=0x0207$' --fixtures "$FX" --cases '^state/gl46/core/' -o "$T/b2" >"$T/b2.out" 2>&1; c=$?
line "state answer naming the previous case" "$(count_status "$T/b2" Crash) Crash ($(grep -c 'set=0x0206@core,Crash' "$T/b2/results.csv") the named one)" $c "$(ok_if "[ $c = 100 ] && grep -q 'set=0x0206@core,Crash' $T/b2/results.csv")"

"$SC" run -b "mock:late=$ONE" --fixtures "$FX" --cases "$ONE|^state/gl46/core/" -o "$T/b3" >"$T/b3.out" 2>&1; c=$?
line "lookup's extra answer read with state cases" "$(count_status "$T/b3" Crash) Crash, $(count_status "$T/b3" Pass) Pass" $c "$(ok_if "[ $c = 100 ] && [ $(count_status "$T/b3" Crash) = 4 ]")"

s=$(date +%s)
timeout 300 "$SC" run -b 'mock:hang=^gl46/1d/d16/nearest/never/texel1/ref=0\.3/' --fixtures "$FX" --cases '^gl46/1d/' --timeout 0.2 --no-rerun -o "$T/b4" >"$T/b4.out" 2>&1; c=$?
w=$(( $(date +%s) - s ))
line "hang on one case of 28 sweep points" "$(count_status "$T/b4" Timeout) Timeout, $(count_status "$T/b4" Pass) Pass in ${w} s" $c "$(ok_if "[ $c = 100 ] && [ $(count_status "$T/b4" Timeout) = 4 ] && [ $(count_status "$T/b4" Pass) -gt 0 ] && [ $w -le 20 ]")"

"$SC" run -b "mock:spew=$ONE" --fixtures "$FX" --cases '^gl46/1d/' --no-rerun -o "$T/b5" >"$T/b5.out" 2>&1; c=$?
bytes=$(du -sb "$T/b5" | cut -f1)
line "4 MiB stderr line, then a crash" "$(count_status "$T/b5" Crash) Crash; $bytes bytes of reports" $c "$(ok_if "[ $c = 100 ] && [ $bytes -lt 1000000 ] && grep -q 'bytes of this line not kept' $T/b5/report.json")"

"$SC" run -b "mock:notutf8=$ONE" --fixtures "$FX" --cases '^gl46/1d/' -o "$T/b6" >"$T/b6.out" 2>&1; c=$?
line "answer line not UTF-8" "$(grep -c 'bad answer line: not UTF-8' "$T/b6/report.json") reasons say not UTF-8; $(grep -c SIGKILL "$T/b6/report.json") SIGKILL" $c "$(ok_if "[ $c = 100 ] && grep -q 'not UTF-8' $T/b6/report.json && ! grep -q SIGKILL $T/b6/report.json")"

"$SC" run -b mock: --fixtures "$FX" --cases '^gl46/1d/' -o "$T/b7n" >/dev/null 2>&1
n=$(wc -l <"$T/b7n/results.csv")
SHADOWCHECK_MOCK_INTERRUPT_RUNNER='^gl46/1d/d16/nearest/greater/texel1/ref=0\.3/dt=0\.2_0\.4_0\.6_0\.8$' \
  "$SC" run -b mock: -b soft:sgix --fixtures "$FX" --cases '^gl46/1d/' -o "$T/b7" >"$T/b7.out" 2>&1; c=$?
said=$(grep -o 'of [0-9]* tests finished' "$T/b7.out")
line "Ctrl-C count, soft:sgix has no test of gl46" "said '${said:-nothing}' ($n tests)" $c "$(ok_if "[ $c = 130 ] && [ '$said' = 'of $n tests finished' ]")"

SHADOWCHECK_MOCK_SEEN="$T/b8.seen" "$SC" run -b "mock:once,extra=$ONE" --fixtures "$FX" --cases '^gl46/1d/' -o "$T/b8" >"$T/b8.out" 2>&1; c=$?
line "one-off extra answer line, re-run on" "$(count_status "$T/b8" Crash) Crash, $(count_status "$T/b8" Flake) Flake" $c "$(ok_if "[ $c = 100 ] && [ $(count_status "$T/b8" Flake) = 0 ]")"

mkdir -p "$T/noexpect"
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); [c.pop("expect", None) for c in d["state_cases"]]; json.dump(d, open(sys.argv[2], "w"))' "$FX/state/gl46.json" "$T/noexpect/state.json"
"$SC" run -b soft --fixtures "$T/noexpect" -o "$T/b9" >"$T/b9.out" 2>&1; c=$?
line "state cases without expect, correct impl" "$(count_status "$T/b9" Pass) Pass, $(count_status "$T/b9" Fail) Fail" $c "$(ok_if "[ $c = 0 ] && [ $(count_status "$T/b9" Fail) = 0 ]")"

# --- shadowcheck gtest (googletest's interface for deqp-runner's [[gtest]] blocks) ------------
"$SC" gtest -b soft --fixtures "$FX" --gtest_list_tests >"$T/g1.out" 2>"$T/g1.err"; c=$?
dots=$(grep -v '\.$' "$T/g1.out" | grep -c '\.')
line "gtest: list of names holding '.'" "$(grep -c '^ ' "$T/g1.out") tests, $dots test lines with a '.'" $c "$(ok_if "[ $c = 0 ] && [ $dots = 0 ] && [ \$(grep -c '^ ' $T/g1.out) -gt 0 ]")"
"$SC" gtest -b 'mock:crash=^gles32/' --fixtures "$FX" --cases '^(gl46|gles32)/' >"$T/g2.out" 2>&1; c=$?
last=$(grep -v '^shadowcheck: ' "$T/g2.out" | tail -1 | cut -c1-14)
line "gtest: a crash mid-group" "last line '$last', $(grep -c 'OK \]' "$T/g2.out") OK before it" $c "$(ok_if "[ $c = 1 ] && [ '$last' = '[ RUN      ] g' ] && ! grep -q panicked $T/g2.out")"
env -u SHADOWCHECK_BACKEND "$SC" gtest --fixtures "$FX" --gtest_list_tests >"$T/g3.out" 2>&1; c=$?
line "gtest: no backend named" "$(grep -o 'no backend[^:]*' "$T/g3.out" | head -1)" $c "$(ok_if "[ $c = 96 ]")"

# --- Records that are not whole, outputs that cannot be written: merge, summarize, repro, report ---
"$SC" run -b 'mock:fail=lequal' --fixtures "$FX" --shard 1/2 -o "$T/b1/s1" >/dev/null 2>&1
# The mock worker SIGKILLs the runner on the first gles32 case (the subshell keeps bash's "Killed" quiet).
(SHADOWCHECK_MOCK_KILL_RUNNER='gles32' "$SC" run -b 'mock:fail=lequal' --fixtures "$FX" --shard 2/2 --group 8 -o "$T/b1/s2" >/dev/null 2>&1; :) 2>/dev/null
"$SC" merge -o "$T/b1/m" "$T/b1/s1" "$T/b1/s2" >"$T/b1.out" 2>&1; c=$?
line "merge: a shard killed midway" "$(grep -o '[0-9]* of [0-9]* tests written' "$T/b1.out" || echo 'no word')" $c "$(ok_if "[ $c = 96 ] && grep -q 's2/results.jsonl: the run did not finish' $T/b1.out")"

"$SC" run -b 'mock:fail=lequal' --fixtures "$FX" --shard 2/2 --group 8 -o "$T/b1/s2" --resume >/dev/null 2>&1
mkdir -p "$T/b2"; head -c -10 "$T/b1/s2/results.jsonl" >"$T/b2/results.jsonl"
"$SC" merge -o "$T/b2/m" "$T/b1/s1" "$T/b2" >"$T/b2.out" 2>&1; c=$?
line "merge: results.jsonl cut in its last line" "$(grep -o 'last line is cut off' "$T/b2.out" || echo 'no word')" $c "$(ok_if "[ $c = 96 ] && grep -q 'b2/results.jsonl' $T/b2.out")"

mkdir -p "$T/b3"; sed '1s/"schema_version":1,/"schema_version":99,/' "$T/b1/s1/results.jsonl" >"$T/b3/results.jsonl"
"$SC" merge -o "$T/b3/m" "$T/b3" "$T/b1/s2" >"$T/b3.out" 2>&1; c=$?
line "merge: schema_version 99" "$(grep -o 'schema_version 99 is not one' "$T/b3.out" || echo 'no word')" $c "$(ok_if "[ $c = 96 ] && grep -q 'b3/results.jsonl:1:' $T/b3.out")"

mkdir -p "$T/b4"
if mount -t tmpfs -o size=64k tmpfs "$T/b4" 2>/dev/null; then how="tmpfs 64k"; else how="/dev/full"; ln -s /dev/full "$T/b4/results.jsonl"; fi
"$SC" merge -o "$T/b4" "$T/b1/s1" "$T/b1/s2" >"$T/b4.out" 2>&1; c=$?
said=$(grep -o 'exit code [0-9]* (regressions; also 96' "$T/b4.out" | tail -1)
line "merge onto a full disk ($how), regressions" "${said:-no word of both}" $c "$(ok_if "[ $c = 100 ] && [ -n '$said' ]")"
mountpoint -q "$T/b4" && umount "$T/b4"

if [ $HAVE_GL = yes ]; then
  t=$(grep ',Pass,' "$T/glprobe/results.csv" | head -1 | cut -d, -f1)
  bash -c "'$SC' repro -b egl:llvmpipe:core --case '$t' --fixtures '$FX' --allow-pass -o '$T/b5' 2>'$T/b5.err' | head -1 >/dev/null; exit \${PIPESTATUS[0]}"; c=$?
  line "repro ... | head -1" "$(panicked "$T/b5.err")" $c "$(ok_if "[ $c != 101 ] && ! grep -q panicked $T/b5.err")"
else
  line "repro ... | head -1" "SKIPPED (no Mesa)" - SKIPPED
fi

bash -c "'$SC' report '$T/b1/s1' -o '$T/b6' 2>'$T/b6.err' | head -0; exit \${PIPESTATUS[0]}"; c=$?
line "report with a closed stdout" "$(panicked "$T/b6.err")" $c "$(ok_if "[ $c = 0 ] && ! grep -q panicked $T/b6.err")"

"$SC" run -b 'mock:fail=lequal' --fixtures "$FX" -o "$T/b7/r-egl-llvmpipe-core" >/dev/null 2>&1
"$SC" summarize -o "$T/b7/sum" "$T/b7/r-egl-llvmpipe-core" --platform chaos >"$T/b7.out" 2>&1; c=$?
line "summarize: folder named for another driver" "labels: $(grep -o '^| [^ ]* | core' "$T/b7/sum/SUMMARY.md" | cut -d' ' -f2 | sort -u | tr '\n' ' ')" $c "$(ok_if "[ $c = 0 ] && ! grep -q egl-llvmpipe-core $T/b7/sum/SUMMARY.md")"

cp -r "$T/b7/r-egl-llvmpipe-core" "$T/b8"; head -c -5 "$T/b7/r-egl-llvmpipe-core/results.jsonl" >"$T/b8/results.jsonl"
"$SC" summarize -o "$T/b8/sum" "$T/b8" --platform chaos >"$T/b8.out" 2>&1; c=$?
line "summarize: results.jsonl cut" "$(grep -o 'last line is cut off' "$T/b8.out" || echo 'no word')" $c "$(ok_if "[ $c = 96 ] && grep -q 'b8/results.jsonl' $T/b8.out")"

"$SC" repro --all-failures "$T/b7/r-egl-llvmpipe-core" -o "$T/b9" >"$T/b9.out" 2>&1; c=$?
dangling=0
for l in $(grep -o '](\([^)]*\)/)' "$T/b9/index.md" 2>/dev/null | sed 's/^](//; s/)$//'); do [ -d "$T/b9/$l" ] || dangling=$((dangling + 1)); done
line "repro --all-failures, none reproducible" "$dangling dangling links; $(grep -c 'no reproducer:' "$T/b9/index.md") classes without one" $c "$(ok_if "[ $c = 96 ] && [ $dangling = 0 ]")"

"$SC" run -b mock: --fixtures "$FX" -o "$T/b10" >/dev/null 2>&1
sed -i '/"kind":"meta"/d' "$T/b10/results.jsonl"
"$SC" run -b mock: --fixtures "$FX" -o "$T/b10" --resume >"$T/b10.out" 2>&1; c=$?
line "--resume of results.jsonl without meta" "$(grep -o 'has no meta line' "$T/b10.out" || echo 'no word')" $c "$(ok_if "[ $c = 96 ]")"

# Vulkan backends (vk:*): the vk-worker killed with SIGKILL mid-run (the runner re-sends what it
# had not answered to a fresh worker: the verdicts are a clean run's), and vk:native with a loader
# that finds no driver (a setup error naming it, exit 96, no panic). The kill needs lavapipe and
# glslangValidator and is SKIPPED without them.
if [ -f /usr/share/vulkan/icd.d/lvp_icd.x86_64.json ] && command -v glslangValidator >/dev/null 2>&1; then
  "$SC" run -b vk:lavapipe --fixtures cases/fixtures/vulkan -o "$T/v0" >/dev/null 2>&1
  "$SC" run -b vk:lavapipe --fixtures cases/fixtures/vulkan -o "$T/v1" >"$T/v1.out" 2>&1 & p=$!
  w=""
  for _ in $(seq 1 100); do
    w=$(descendants $p | grep -- 'vk-worker' | awk '{print $1}' | head -1)
    [ -n "$w" ] && break; sleep 0.1
  done
  sleep 2; [ -n "$w" ] && kill -9 "$w"; wait $p; c=$?
  same=$(cmp -s <(cut -d, -f1,2 "$T/v0/results.csv" | sort) <(cut -d, -f1,2 "$T/v1/results.csv" | sort) && echo same || echo differ)
  line "vk: kill -9 the vk-worker mid-run" "worker ${w:-not found} killed, verdicts $same as a clean run's" $c "$(ok_if "[ -n '$w' ] && [ $c = 0 ] && [ $same = same ]")"
else
  line "vk: kill -9 the vk-worker mid-run" "SKIPPED (no lavapipe or glslangValidator)" - SKIPPED
fi
VK_ICD_FILENAMES=/nonexistent/icd.json "$SC" run -b vk:native --fixtures "$FX" -o "$T/v2" >"$T/v2.out" 2>&1; c=$?
line "vk:native, the loader finds no driver" "$(grep -o 'Unable to find a Vulkan driver\|cannot start' "$T/v2.out" | head -1), $(panicked "$T/v2.out")" $c "$(ok_if "[ $c = 96 ] && ! grep -q panicked $T/v2.out")"

echo "($T kept; $BROKEN BROKEN)"
exit $BROKEN
