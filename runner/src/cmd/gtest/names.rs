//! googletest names and filters for `shadowcheck gtest`: the reversible mapping between a test name
//! (`<case id>@<api>`) and a gtest name `Suite.Test` (see the module comment of `cmd/gtest.rs`), and
//! `--gtest_filter`'s patterns.

use std::collections::HashSet;

/// Bytes a gtest name keeps as they are: none of them means anything to a gtest filter or to
/// deqp-runner's list parser.
fn plain(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b"/=_+^@".contains(&b)
}

/// Writes every byte that is not [`plain`] as `%XX`.
fn encode(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for &b in s.as_bytes() {
        if plain(b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

/// The inverse of [`encode`]; `None` for text `encode` never writes (a byte that should have been
/// escaped, an escape of a plain byte, a malformed escape, bytes that are not UTF-8).
fn decode(s: &str) -> Option<String> {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        if b == b'%' {
            let hex = bytes.get(i + 1..i + 3)?;
            if !hex
                .iter()
                .all(|h| h.is_ascii_digit() || (b'A'..=b'F').contains(h))
            {
                return None;
            }
            let v = u8::from_str_radix(std::str::from_utf8(hex).ok()?, 16).ok()?;
            if plain(v) {
                return None;
            }
            out.push(v);
            i += 3;
        } else if plain(b) {
            out.push(b);
            i += 1;
        } else {
            return None;
        }
    }
    String::from_utf8(out).ok()
}

/// The suite of a test name without `/` (a name with one never has this suite: its first part
/// holds no `/`, so its encoding holds no `%2F`).
const NO_SLASH_SUITE: &str = "%2F";

/// A test name (`<case id>@<api>`) as a gtest name `Suite.Test` (see the module comment).
pub fn to_gtest(test: &str) -> String {
    match test.split_once('/') {
        Some((suite, rest)) => format!("{}.{}", encode(suite), encode(rest)),
        None => format!("{NO_SLASH_SUITE}.{}", encode(test)),
    }
}

/// The test name a gtest name written by [`to_gtest`] stands for; `None` for any other text.
pub fn from_gtest(name: &str) -> Option<String> {
    let (suite, test) = name.split_once('.')?;
    let rest = decode(test)?;
    if suite == NO_SLASH_SUITE {
        return (!rest.contains('/')).then_some(rest);
    }
    let first = decode(suite)?;
    if first.contains('/') {
        return None;
    }
    Some(format!("{first}/{rest}"))
}

/// googletest's `--gtest_filter`: `POSITIVE[-NEGATIVE]`, each `:`-separated patterns with `*` (any
/// text) and `?` (one character); an empty positive part means `*`.
pub struct Filter {
    pub positive: Vec<String>,
    negative: Vec<String>,
}

impl Filter {
    pub fn parse(text: &str) -> Filter {
        let (pos, neg) = text.split_once('-').unwrap_or((text, ""));
        let split = |s: &str| -> Vec<String> {
            s.split(':')
                .filter(|p| !p.is_empty())
                .map(str::to_string)
                .collect()
        };
        let mut positive = split(pos);
        if positive.is_empty() {
            positive.push("*".into());
        }
        Filter {
            positive,
            negative: split(neg),
        }
    }

    /// The indices of `names` (gtest names) the filter selects, in the order of `names`.
    pub fn select(&self, names: &[String]) -> Vec<usize> {
        let wild = |p: &String| p.contains(['*', '?']);
        let exact: HashSet<&str> = self
            .positive
            .iter()
            .filter(|p| !wild(p))
            .map(String::as_str)
            .collect();
        let globs: Vec<&String> = self.positive.iter().filter(|p| wild(p)).collect();
        (0..names.len())
            .filter(|&i| {
                let n = names[i].as_str();
                (exact.contains(n) || globs.iter().any(|g| glob(g, n)))
                    && !self.negative.iter().any(|g| glob(g, n))
            })
            .collect()
    }
}

/// Whether `text` matches `pattern` (`*` any text, `?` one character), as googletest matches.
fn glob(pattern: &str, text: &str) -> bool {
    let p: Vec<char> = pattern.chars().collect();
    let t: Vec<char> = text.chars().collect();
    let (mut pi, mut ti) = (0, 0);
    let mut star: Option<(usize, usize)> = None;
    while ti < t.len() {
        if pi < p.len() && (p[pi] == '?' || p[pi] == t[ti]) {
            pi += 1;
            ti += 1;
        } else if pi < p.len() && p[pi] == '*' {
            star = Some((pi, ti));
            pi += 1;
        } else if let Some((sp, st)) = star {
            pi = sp + 1;
            ti = st + 1;
            star = Some((sp, st + 1));
        } else {
            return false;
        }
    }
    p[pi..].iter().all(|&c| c == '*')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_on_real_fixture_ids() {
        for name in [
            "gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25@core",
            "sgix_ambient/2d/d24/nearest/lequal_r_sgix/clamp/dt=0.5/ref=-inf@ff",
            "arb/rect/depth/linear/none/a=0.25_0.5/read/dt=0.2_0.4_0.6_0.8@glsl120",
            "gles32/2d/d24/linear/none/a=0.25_0.5/read/dt=0.2_0.4_0.6_0.8@es300",
            "sgix_ambient/1d/depth/nmn/lequal_r_sgix/lod=1/ref=0.5/levels=0.2_0.8_0.4@arbfp",
            "gl46/cube/d32f/linear/lequal/u=2.5/face=+x@core",
            "noslash@core",
            "/leading@core",
            "odd:chars*?%2E-%@x.y",
            "ünïcode/ok@core",
        ] {
            let g = to_gtest(name);
            // One `.`, the suite separator; nothing a gtest filter or list parser reads.
            assert_eq!(g.matches('.').count(), 1, "{g}");
            assert!(!g.contains([':', '-', '*', '?', ' ']), "{g}");
            assert_eq!(from_gtest(&g).as_deref(), Some(name), "{g}");
        }
        assert_eq!(
            to_gtest("gl46/2d/d16/nearest/lequal/ref=0.5/dt=0.25@core"),
            "gl46.2d/d16/nearest/lequal/ref=0%2E5/dt=0%2E25@core"
        );
        assert_eq!(
            to_gtest("sgix/2d/d16/nearest/lequal/dt=0/ref=-0.1@ff"),
            "sgix.2d/d16/nearest/lequal/dt=0/ref=%2D0%2E1@ff"
        );
    }

    #[test]
    fn names_round_trip_on_every_committed_fixture_id() {
        // The ids read from the files' text (loading the cases checks each against the oracle,
        // which takes minutes in a debug build); every API path key, since the name holds one.
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fixtures");
        let id = regex::Regex::new(r#""id": *"([^"]*)""#).unwrap();
        let mut n = 0;
        let mut seen = HashSet::new();
        for f in shadowcheck_cases::fixtures::fixture_paths(&root).unwrap() {
            let text = std::fs::read_to_string(&f).unwrap();
            for c in id.captures_iter(&text) {
                let name = format!("{}@core", &c[1]);
                let g = to_gtest(&name);
                assert_eq!(from_gtest(&g).as_deref(), Some(name.as_str()), "{g}");
                assert!(seen.insert(g), "{name}");
                n += 1;
            }
        }
        assert!(n > 10_000, "cases/fixtures holds {n} ids: missing?");
    }

    #[test]
    fn text_the_mapping_never_writes_is_refused() {
        for g in [
            "nodot",
            "a.b.c",
            "gl46.ref=0.5",
            "gl46.ref=%2e5",
            "gl46.a%41",
            "gl46.a%4",
            "gl46.ref=-1",
            "a/b.c",
            "%2F.a/b",
            "gl46.%FF",
        ] {
            assert_eq!(from_gtest(g), None, "{g}");
        }
    }

    #[test]
    fn filter_follows_googletest() {
        let names: Vec<String> = ["a.x1", "a.x2", "b.y", "b.yy"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let sel = |f: &str| Filter::parse(f).select(&names);
        assert_eq!(sel("a.x1:b.y"), vec![0, 2]);
        assert_eq!(sel("*"), vec![0, 1, 2, 3]);
        assert_eq!(sel(""), vec![0, 1, 2, 3]);
        assert_eq!(sel("a.*"), vec![0, 1]);
        assert_eq!(sel("b.y?"), vec![3]);
        assert_eq!(sel("*-a.x2:b.*"), vec![0]);
        assert_eq!(sel("-a.*"), vec![2, 3]);
        assert_eq!(sel("c.z"), Vec::<usize>::new());
        assert!(glob("*x*2", "a.x12"));
        assert!(!glob("a.x", "a.x1"));
    }
}
