//! The statuses of a test, as results.jsonl, the CSV files and the baselines write them.
//!
//! Two layers, as in deqp-runner:
//! - [`Outcome`]: the raw result of one test on one backend (Pass, Warn, Fail, Skip, Crash, Timeout);
//! - [`Status`]: the outcome after the baseline, the flake list and the flake re-run
//!   (ExpectedFail, UnexpectedImprovement(outcome), Flake, KnownFlake, or the outcome itself).
//!
//! How an observation becomes an [`Outcome`] is the runner's `verdict` module; how an outcome
//! becomes a [`Status`] is its `baseline` module.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// The raw result of one test (`<case id>@<api>`) on one backend.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Outcome {
    /// Inside the strict acceptance set.
    Pass,
    /// Inside quality, outside strict.
    Warn,
    /// Outside quality, or the implementation reported an error for a lookup it claims to support.
    Fail,
    /// Not run (with a reason).
    Skip,
    /// The implementation's process died on this case (found by bisection).
    Crash,
    /// The implementation did not answer this case in time (found by bisection).
    Timeout,
}

impl Outcome {
    /// Fail, Crash and Timeout: the outcomes a baseline may excuse.
    pub fn is_failure(self) -> bool {
        matches!(self, Outcome::Fail | Outcome::Crash | Outcome::Timeout)
    }
    pub fn as_str(self) -> &'static str {
        match self {
            Outcome::Pass => "Pass",
            Outcome::Warn => "Warn",
            Outcome::Fail => "Fail",
            Outcome::Skip => "Skip",
            Outcome::Crash => "Crash",
            Outcome::Timeout => "Timeout",
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for Outcome {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Ok(match s {
            "Pass" => Outcome::Pass,
            "Warn" => Outcome::Warn,
            "Fail" => Outcome::Fail,
            "Skip" => Outcome::Skip,
            "Crash" => Outcome::Crash,
            "Timeout" => Outcome::Timeout,
            _ => {
                return Err(format!(
                    "unknown outcome `{s}` (Pass, Warn, Fail, Skip, Crash, Timeout)"
                ))
            }
        })
    }
}

/// The final status of a test, written as deqp-runner writes it (`Fail`, `ExpectedFail`,
/// `UnexpectedImprovement(Pass)`, ...).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Status {
    /// The raw outcome, not changed by any list.
    Plain(Outcome),
    /// A failure listed in the baseline with this very status.
    ExpectedFail,
    /// Listed in the baseline as failing, but now passes (or is skipped): update the baseline.
    UnexpectedImprovement(Outcome),
    /// A failure whose re-run gave a different outcome.
    Flake,
    /// A failure of a test matching the flakes list.
    KnownFlake,
}

impl Status {
    /// Fail, Crash, Timeout not excused by the baseline: the run is a regression (exit code 100).
    pub fn is_regression(self) -> bool {
        matches!(self, Status::Plain(o) if o.is_failure())
    }
    pub fn is_improvement(self) -> bool {
        matches!(self, Status::UnexpectedImprovement(_))
    }
    /// Short column name for summaries.
    pub fn column(self) -> &'static str {
        match self {
            Status::Plain(o) => o.as_str(),
            Status::ExpectedFail => "ExpectedFail",
            Status::UnexpectedImprovement(_) => "UnexpectedImprovement",
            Status::Flake => "Flake",
            Status::KnownFlake => "KnownFlake",
        }
    }
}

impl From<Outcome> for Status {
    fn from(o: Outcome) -> Status {
        Status::Plain(o)
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Status::UnexpectedImprovement(o) => write!(f, "UnexpectedImprovement({o})"),
            s => f.write_str(s.column()),
        }
    }
}

impl FromStr for Status {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Ok(match s {
            "ExpectedFail" => Status::ExpectedFail,
            "Flake" => Status::Flake,
            "KnownFlake" => Status::KnownFlake,
            _ => match s
                .strip_prefix("UnexpectedImprovement(")
                .and_then(|r| r.strip_suffix(')'))
            {
                Some(inner) => Status::UnexpectedImprovement(inner.parse()?),
                None => Status::Plain(s.parse()?),
            },
        })
    }
}

impl Serialize for Status {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for Status {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        s.parse().map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn status_text_round_trips_like_deqp_runner() {
        for s in [
            Status::Plain(Outcome::Fail),
            Status::Plain(Outcome::Crash),
            Status::ExpectedFail,
            Status::UnexpectedImprovement(Outcome::Pass),
            Status::Flake,
            Status::KnownFlake,
        ] {
            assert_eq!(s.to_string().parse::<Status>().unwrap(), s);
        }
        assert_eq!(
            Status::UnexpectedImprovement(Outcome::Warn).to_string(),
            "UnexpectedImprovement(Warn)"
        );
        assert!("Failed".parse::<Status>().is_err());
        assert!("UnexpectedImprovement(Bogus)".parse::<Status>().is_err());
    }

    #[test]
    fn only_unexcused_failures_are_regressions() {
        assert!(Status::Plain(Outcome::Timeout).is_regression());
        assert!(!Status::Plain(Outcome::Warn).is_regression());
        assert!(!Status::ExpectedFail.is_regression());
        assert!(!Status::Flake.is_regression());
        assert!(Status::UnexpectedImprovement(Outcome::Pass).is_improvement());
    }
}
