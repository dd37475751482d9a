//! A running implementation process of an `exec:`-style backend: its stdin written by a thread
//! of its own (so a child that stops reading never blocks the runner), its stdout read line by
//! line by another, the last lines of its stderr kept for the reason of a crash. Both readers
//! hold a bounded amount of what the child writes: an answer line over [`MAX_ANSWER_LINE`] is a
//! protocol error, a stderr line is kept up to [`STDERR_LINE_KEPT`] bytes (saying how much was
//! cut), so a child writing without end costs the runner neither memory nor report size.

use super::command::ProcessCommand;
use shadowcheck_protocol::Request;
use std::collections::VecDeque;
use std::io::{BufRead, BufReader, BufWriter, Write};
use std::process::{Child, ChildStdin, Stdio};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// The writer thread: writes queued messages to the child's stdin, flushing whenever the queue is
/// empty; ends when the queue is closed (stdin is then closed) or the child stops reading.
fn write_loop(stdin: ChildStdin, queue: Receiver<Vec<u8>>) {
    let mut w = BufWriter::with_capacity(1 << 16, stdin);
    while let Ok(msg) = queue.recv() {
        if w.write_all(&msg).is_err() {
            return;
        }
        while let Ok(more) = queue.try_recv() {
            if w.write_all(&more).is_err() {
                return;
            }
        }
        if w.flush().is_err() {
            return;
        }
    }
    let _ = w.flush();
}

/// The longest answer line read (PROTOCOL.md answers are one JSON object of a few KiB, a sweep
/// of many points included); a longer one is read past and reported as a protocol error.
pub(super) const MAX_ANSWER_LINE: usize = 16 << 20;
/// The bytes kept of one stderr line, its first and last halves (the rest is counted and
/// said, not kept).
pub(super) const STDERR_LINE_KEPT: usize = 512;
/// The stderr lines kept for the reason of a crash: at most `TAIL_LINES` x `STDERR_LINE_KEPT`
/// bytes.
const TAIL_LINES: usize = 8;
/// Diagnostic lines (stderr shown with `-v`) held between two reads by the run.
const MAX_DIAGS: usize = 10_000;

/// The last lines a process wrote to stderr, each cut to [`STDERR_LINE_KEPT`] bytes, and how
/// many lines it wrote in all.
#[derive(Default)]
struct StderrTail {
    lines: VecDeque<String>,
    total: u64,
}
type Tail = Arc<Mutex<StderrTail>>;

/// A line read from the child's stdout: its text, or why it is not a line of the protocol (not
/// UTF-8, too long).
pub(super) type Line = Result<String, String>;

/// Reads one line (without its `\n` or `\r\n`) into `buf`, keeping at most `max` bytes of it:
/// its first and its last `max / 2` bytes when it is longer. Returns `(at, cut)`: `cut` bytes
/// of the line were left out at offset `at` of `buf` (0 when the line was kept whole); `None` at
/// the end of the stream. The memory held is `max` bytes plus the reader's buffer, whatever
/// the line's length.
fn read_line_bounded(
    r: &mut impl BufRead,
    max: usize,
    buf: &mut Vec<u8>,
) -> std::io::Result<Option<(usize, u64)>> {
    buf.clear();
    let head = max - max / 2;
    let mut tail: VecDeque<u8> = VecDeque::new();
    let mut cut = 0u64;
    let mut any = false;
    let end = loop {
        let chunk = match r.fill_buf() {
            Ok(c) => c,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if chunk.is_empty() {
            if !any {
                return Ok(None);
            }
            break false;
        }
        any = true;
        let (part, end) = match chunk.iter().position(|&b| b == b'\n') {
            Some(i) => (&chunk[..i], Some(i + 1)),
            None => (chunk, None),
        };
        let into_head = part.len().min(head.saturating_sub(buf.len()));
        buf.extend_from_slice(&part[..into_head]);
        // The rest goes to the tail window; what falls out of it is cut.
        let rest = &part[into_head..];
        let keep = max / 2;
        let skip = rest.len().saturating_sub(keep);
        cut += skip as u64;
        tail.extend(&rest[skip..]);
        while tail.len() > keep {
            tail.pop_front();
            cut += 1;
        }
        let used = end.unwrap_or(chunk.len());
        r.consume(used);
        if end.is_some() {
            break true;
        }
    };
    let at = buf.len();
    buf.extend(tail);
    if end && cut == 0 && buf.last() == Some(&b'\r') {
        buf.pop();
    }
    Ok(Some((at.min(buf.len()), cut)))
}

/// An answer line as the protocol reads it: UTF-8 text of at most [`MAX_ANSWER_LINE`] bytes.
fn answer_line(bytes: Vec<u8>, cut: u64) -> Line {
    if cut > 0 {
        return Err(format!(
            "a line of {} bytes, longer than the {} MiB an answer may have",
            bytes.len() as u64 + cut,
            MAX_ANSWER_LINE >> 20
        ));
    }
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        format!(
            "not UTF-8 (byte 0x{:02X} at offset {at}): {}",
            bytes.get(at).copied().unwrap_or(0),
            super::exec::clip(&String::from_utf8_lossy(bytes))
        )
    })
}

/// A stderr line as it is kept: lossy UTF-8, saying where and how much was cut.
fn stderr_line(bytes: &[u8], at: usize, cut: u64) -> String {
    if cut == 0 {
        return String::from_utf8_lossy(bytes).into_owned();
    }
    let (head, tail) = bytes.split_at(at.min(bytes.len()));
    format!(
        "{} [... {cut} bytes of this line not kept ...] {}",
        String::from_utf8_lossy(head),
        String::from_utf8_lossy(tail)
    )
}

/// One running implementation process.
pub(super) struct Proc {
    pub(super) child: Child,
    /// Messages for the writer thread, which owns the child's stdin (so a child that stops
    /// reading can never block the runner: the answer deadline still fires).
    input: Option<Sender<Vec<u8>>>,
    /// The child's stdout, line by line (read by a thread of its own).
    pub(super) lines: Receiver<Line>,
    tail: Tail,
    stderr_thread: Option<JoinHandle<()>>,
}

impl Proc {
    pub(super) fn spawn(
        cmd: &ProcessCommand,
        diags: &Arc<Mutex<Vec<String>>>,
    ) -> Result<Proc, String> {
        let mut child = cmd
            .to_command()
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start `{}`: {e}", cmd.program.display()))?;
        let (Some(stdin), Some(stdout), Some(stderr)) =
            (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            let _ = child.kill();
            return Err("child pipes missing".to_string());
        };
        let (tx, lines) = mpsc::channel();
        std::thread::spawn(move || {
            let mut r = BufReader::new(stdout);
            let mut buf = Vec::new();
            // A line that is not UTF-8 is passed on as such (the protocol error it is); only the
            // end of the stream or a read error ends the reader.
            while let Ok(Some((_, cut))) = read_line_bounded(&mut r, MAX_ANSWER_LINE, &mut buf) {
                if tx.send(answer_line(std::mem::take(&mut buf), cut)).is_err() {
                    break;
                }
            }
        });
        let tail: Tail = Arc::new(Mutex::new(StderrTail::default()));
        let (t2, d2) = (tail.clone(), diags.clone());
        let stderr_thread = std::thread::spawn(move || {
            let mut r = BufReader::new(stderr);
            let mut buf = Vec::new();
            while let Ok(Some((at, cut))) = read_line_bounded(&mut r, STDERR_LINE_KEPT, &mut buf) {
                let line = stderr_line(&buf, at, cut);
                if let Ok(mut t) = t2.lock() {
                    if t.lines.len() == TAIL_LINES {
                        t.lines.pop_front();
                    }
                    t.lines.push_back(line.clone());
                    t.total += 1;
                }
                if let Ok(mut d) = d2.lock() {
                    if d.len() < MAX_DIAGS {
                        d.push(line);
                    }
                }
            }
        });
        let (input, queue) = mpsc::channel::<Vec<u8>>();
        std::thread::spawn(move || write_loop(stdin, queue));
        Ok(Proc {
            child,
            input: Some(input),
            lines,
            tail,
            stderr_thread: Some(stderr_thread),
        })
    }

    /// Queues bytes (whole lines) for the child's stdin. Fails once the writer has stopped (the
    /// child closed its stdin or died).
    pub(super) fn send(&mut self, bytes: Vec<u8>) -> std::io::Result<()> {
        let tx = self.input.as_ref().ok_or(std::io::ErrorKind::BrokenPipe)?;
        tx.send(bytes)
            .map_err(|_| std::io::Error::from(std::io::ErrorKind::BrokenPipe))
    }

    /// Kills the process and says how it ended, with its last stderr lines.
    pub(super) fn kill(mut self) -> String {
        let _ = self.child.kill();
        let status = self
            .child
            .wait()
            .map(|s| s.to_string())
            .unwrap_or_else(|e| e.to_string());
        // Give the stderr reader a moment to drain what the process wrote before dying.
        if let Some(h) = self.stderr_thread.take() {
            let t0 = Instant::now();
            while !h.is_finished() && t0.elapsed() < Duration::from_millis(300) {
                std::thread::sleep(Duration::from_millis(5));
            }
        }
        let (tail, total) = self
            .tail
            .lock()
            .map(|t| (t.lines.iter().cloned().collect::<Vec<_>>(), t.total))
            .unwrap_or_default();
        let shown = tail.len() as u64;
        match (tail.is_empty(), total > shown) {
            (true, _) => status,
            (false, false) => format!("{status}; stderr: {}", tail.join(" | ")),
            (false, true) => format!(
                "{status}; stderr (last {shown} of {total} lines): {}",
                tail.join(" | ")
            ),
        }
    }

    /// Ends the process politely (`bye`, stdin closed), killing it if it lingers. After a clean
    /// exit the stderr reader is given a moment to pass on the last lines (diagnostics).
    pub(super) fn finish(mut self) {
        let _ = self.send(Request::BYE_LINE.to_vec());
        drop(self.input.take());
        let t0 = Instant::now();
        while t0.elapsed() < Duration::from_secs(1) {
            if let Ok(Some(_)) = self.child.try_wait() {
                if let Some(h) = self.stderr_thread.take() {
                    let t1 = Instant::now();
                    while !h.is_finished() && t1.elapsed() < Duration::from_millis(300) {
                        std::thread::sleep(Duration::from_millis(5));
                    }
                }
                return;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        self.kill();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(input: &[u8], max: usize) -> Vec<(Vec<u8>, usize, u64)> {
        // A small reader buffer, so a line spans many reads.
        let mut r = BufReader::with_capacity(7, input);
        let mut buf = Vec::new();
        let mut out = vec![];
        while let Some((at, cut)) = read_line_bounded(&mut r, max, &mut buf).unwrap() {
            out.push((buf.clone(), at, cut));
        }
        out
    }

    #[test]
    fn a_long_line_keeps_its_two_ends_and_counts_the_rest() {
        let mut input = b"short\r\n".to_vec();
        input.extend(std::iter::repeat_n(b'x', 3 << 20));
        input.extend(b"THE END\nlast");
        let got = lines(&input, 16);
        assert_eq!(got.len(), 3);
        assert_eq!(got[0], (b"short".to_vec(), 5, 0));
        let (bytes, at, cut) = &got[1];
        assert_eq!(bytes.len(), 16);
        assert_eq!(*at, 8);
        assert_eq!(*cut, (3 << 20) + 7 - 16);
        assert_eq!(&bytes[..8], b"xxxxxxxx");
        assert_eq!(&bytes[8..], b"xTHE END");
        assert_eq!(
            stderr_line(bytes, *at, *cut),
            format!("xxxxxxxx [... {cut} bytes of this line not kept ...] xTHE END")
        );
        // The last line, without a newline, is a line too.
        assert_eq!(got[2], (b"last".to_vec(), 4, 0));
    }

    #[test]
    fn answer_lines_that_are_not_utf8_or_too_long_say_so() {
        let why = answer_line(b"{\"a\":\"\xff\"}".to_vec(), 0).unwrap_err();
        assert!(
            why.starts_with("not UTF-8 (byte 0xFF at offset 6)"),
            "{why}"
        );
        let why = answer_line(vec![b'x'; 10], 5).unwrap_err();
        assert!(why.starts_with("a line of 15 bytes"), "{why}");
        assert_eq!(answer_line(b"ok".to_vec(), 0), Ok("ok".to_string()));
    }
}
