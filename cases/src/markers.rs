//! Generated sections of hand-written Markdown files: the text between a begin and an end marker
//! line is rewritten by a command (`gen --update-readme`, `mutants --update-readme`), the rest of
//! the file is kept as written.

/// The text between `begin` and the next `end` in `doc`, without surrounding newlines.
pub fn section<'a>(doc: &'a str, begin: &str, end: &str) -> Option<&'a str> {
    let a = doc.find(begin)? + begin.len();
    let b = doc[a..].find(end)? + a;
    Some(doc[a..b].trim_matches('\n'))
}

/// `doc` with the text between `begin` and the next `end` replaced by `body` (one newline on
/// each side); `None` when a marker is missing.
pub fn replace(doc: &str, begin: &str, end: &str, body: &str) -> Option<String> {
    let a = doc.find(begin)? + begin.len();
    let b = doc[a..].find(end)? + a;
    Some(format!(
        "{}\n{}\n{}",
        &doc[..a],
        body.trim_matches('\n'),
        &doc[b..]
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn replaces_only_between_the_markers() {
        let doc = "head\n<!-- b -->\nold\n<!-- e -->\ntail\n";
        let new = replace(doc, "<!-- b -->", "<!-- e -->", "\nnew 1\nnew 2\n").unwrap();
        assert_eq!(new, "head\n<!-- b -->\nnew 1\nnew 2\n<!-- e -->\ntail\n");
        assert_eq!(
            section(&new, "<!-- b -->", "<!-- e -->"),
            Some("new 1\nnew 2")
        );
        assert_eq!(
            replace(&new, "<!-- b -->", "<!-- e -->", "new 1\nnew 2").unwrap(),
            new
        );
        assert!(replace("no markers", "<!-- b -->", "<!-- e -->", "x").is_none());
        assert!(replace("<!-- e --> <!-- b -->", "<!-- b -->", "<!-- e -->", "x").is_none());
    }
}
