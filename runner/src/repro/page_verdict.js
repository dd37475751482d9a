// The fixed part of a reproducer page (after the generated constants), shared by the WebGPU and
// the WebGL 2.0 pages: printing and the verdict. Each line goes to the page and to the console
// (build.sh reads the browser's console log); END is the last line.
const out = document.getElementById("out");
const END = "shadowcheck-repro: end";
function print(s) {
  out.textContent += s + "\n";
  for (const line of s.split("\n")) console.log(line);
}

function inSet(v, set) {
  return set.some(([lo, hi]) => v >= lo && v <= hi);
}

// Does channel value v meet the layout's rule for channel c under the given set (a gather
// component 'g0'..'g3': under its own set of `gather`)?
function channelOk(c, v, set, gather) {
  if (c[0] === "g") return gather !== null && inSet(v, gather[Number(c[1])]);
  switch (c) {
    case "r": return inSet(v, set);
    case "z": return v === 0 || inSet(v, set);
    case "0": return v === 0;
    case "1": return v === 1;
    default: return true;
  }
}

// Accepted when one reading of the layout accepts every channel (each tier on its own).
function judge(px) {
  let ok = false;
  let strictOk = false;
  for (const l of LAYOUTS) {
    ok ||= [0, 1, 2, 3].every((i) => channelOk(l[i], px[i], ACCEPTED, GATHER_ACCEPTED));
    strictOk ||= [0, 1, 2, 3].every((i) => channelOk(l[i], px[i], STRICT, GATHER_STRICT));
  }
  const g = (v) => Number(v.toPrecision(9)).toString();
  print("test:      " + TEST);
  print("expected:  " + SPEC_VALUE + " (spec value); accepted: r in " + ACCEPTED_TEXT + " (strict: " + STRICT_TEXT + ")");
  if (GATHER_ACCEPTED !== null) {
    const show = (sets) => sets.map((s) => "{" + s.map(([lo, hi]) => (lo === hi ? lo : "[" + lo + ", " + hi + "]")).join(", ") + "}").join(", ");
    print("gather:    components accepted in " + show(GATHER_ACCEPTED) + " (strict: " + show(GATHER_STRICT) + ")");
  }
  print("layout:    (" + LAYOUTS[0].join(", ") + ")  ('r' the result, '0'/'1' exactly, 'z' r or 0, '-' unused, 'gi' gather component i)");
  for (let k = 1; k < LAYOUTS.length; k++) {
    print("           (" + LAYOUTS[k].join(", ") + ")  also accepted: the other reading " + READINGS[k]);
  }
  print("observed:  (" + px.map(g).join(", ") + ")");
  if (!ok) {
    LAYOUTS.forEach((l, k) =>
      [0, 1, 2, 3].forEach((i) => {
        if (!channelOk(l[i], px[i], ACCEPTED, GATHER_ACCEPTED)) {
          print("           " + "rgba"[i] + " = " + g(px[i]) + " is outside what channel '" + l[i] + "' allows (" + READINGS[k] + " reading)");
        }
      }),
    );
  }
  print("verdict:   " + (!ok ? 'FAIL (outside the accepted set: a "shall" is violated)'
    : strictOk ? "pass" : "warn (inside the accepted set, outside the strict tier)"));
}

