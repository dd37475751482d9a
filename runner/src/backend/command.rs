//! The command line of a child-process backend: the program, its arguments and environment, and
//! the shell-like splitting of an `exec:` command line (no shell runs it).

use std::path::PathBuf;
use std::process::Command;

/// The program to start, with its arguments and extra environment (for a GL worker: the driver
/// selection, set before the driver loads).
#[derive(Debug, Clone, PartialEq)]
pub struct ProcessCommand {
    pub program: PathBuf,
    pub args: Vec<String>,
    pub env: Vec<(String, String)>,
}

impl ProcessCommand {
    /// A `std::process::Command` ready to spawn (stdio not configured).
    pub fn to_command(&self) -> Command {
        let mut c = Command::new(&self.program);
        c.args(&self.args);
        for (k, v) in &self.env {
            c.env(k, v);
        }
        c
    }
}

/// Splits a command line on whitespace, honouring '...' and "..." quoting and backslash escapes.
/// No shell is involved (so killing the process kills the implementation itself).
pub fn split_command(s: &str) -> Result<Vec<String>, String> {
    let mut out = vec![];
    let mut cur = String::new();
    let mut in_word = false;
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        match c {
            '\'' => {
                in_word = true;
                loop {
                    match chars.next() {
                        Some('\'') => break,
                        Some(ch) => cur.push(ch),
                        None => return Err(format!("unclosed ' in `{s}`")),
                    }
                }
            }
            '"' => {
                in_word = true;
                loop {
                    match chars.next() {
                        Some('"') => break,
                        Some('\\') => cur.push(
                            chars
                                .next()
                                .ok_or_else(|| format!("trailing \\ in `{s}`"))?,
                        ),
                        Some(ch) => cur.push(ch),
                        None => return Err(format!("unclosed \" in `{s}`")),
                    }
                }
            }
            '\\' => {
                in_word = true;
                cur.push(
                    chars
                        .next()
                        .ok_or_else(|| format!("trailing \\ in `{s}`"))?,
                );
            }
            c if c.is_whitespace() => {
                if in_word {
                    out.push(std::mem::take(&mut cur));
                    in_word = false;
                }
            }
            c => {
                in_word = true;
                cur.push(c);
            }
        }
    }
    if in_word {
        out.push(cur);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_command_quotes_like_a_shell() {
        assert_eq!(
            split_command("python3 a.py --x").unwrap(),
            ["python3", "a.py", "--x"]
        );
        assert_eq!(
            split_command(" 'a b' \"c \\\" d\" e\\ f ").unwrap(),
            ["a b", "c \" d", "e f"]
        );
        assert_eq!(split_command("''").unwrap(), [""]);
        assert!(split_command("'open").is_err());
    }
}
