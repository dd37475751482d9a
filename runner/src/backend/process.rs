//! A running implementation process of an `exec:`-style backend: its stdin written by a thread
//! of its own (so a child that stops reading never blocks the runner), its stdout read line by
//! line by another, the last lines of its stderr kept for the reason of a crash.

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

/// Keeps the last lines a process wrote to stderr.
type Tail = Arc<Mutex<VecDeque<String>>>;
const TAIL_LINES: usize = 8;

/// One running implementation process.
pub(super) struct Proc {
    pub(super) child: Child,
    /// Messages for the writer thread, which owns the child's stdin (so a child that stops
    /// reading can never block the runner: the answer deadline still fires).
    input: Option<Sender<Vec<u8>>>,
    /// The child's stdout, line by line (read by a thread of its own).
    pub(super) lines: Receiver<String>,
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
            for line in BufReader::new(stdout).lines() {
                match line {
                    Ok(l) => {
                        if tx.send(l).is_err() {
                            break;
                        }
                    }
                    Err(_) => break,
                }
            }
        });
        let tail: Tail = Arc::new(Mutex::new(VecDeque::new()));
        let (t2, d2) = (tail.clone(), diags.clone());
        let stderr_thread = std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines().map_while(Result::ok) {
                if let Ok(mut t) = t2.lock() {
                    if t.len() == TAIL_LINES {
                        t.pop_front();
                    }
                    t.push_back(line.clone());
                }
                if let Ok(mut d) = d2.lock() {
                    if d.len() < 10_000 {
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
        let tail: Vec<String> = self
            .tail
            .lock()
            .map(|t| t.iter().cloned().collect())
            .unwrap_or_default();
        if tail.is_empty() {
            status
        } else {
            format!("{status}; stderr: {}", tail.join(" | "))
        }
    }

    /// Ends the process politely (`bye`, stdin closed), killing it if it lingers.
    pub(super) fn finish(mut self) {
        let _ = self.send(Request::BYE_LINE.to_vec());
        drop(self.input.take());
        let t0 = Instant::now();
        while t0.elapsed() < Duration::from_secs(1) {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        self.kill();
    }
}
