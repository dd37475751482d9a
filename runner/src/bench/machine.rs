//! The machine a bench ran on: cores, CPU model, memory, Mesa version, load, date.

use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Machine {
    /// Logical CPUs available to this process.
    pub nproc: usize,
    /// `model name` of /proc/cpuinfo.
    pub cpu: String,
    /// MemTotal of /proc/meminfo, MiB.
    pub memory_mib: u64,
    /// Mesa version (from a GL_VERSION string, else the libgl1-mesa-dri package), or "unknown".
    pub mesa: String,
    /// 1-minute load average when the bench started (other work on the machine skews timings).
    pub load_average: f64,
    pub kernel: String,
    /// UTC, ISO 8601.
    pub date: String,
}

fn read(path: &str) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}

/// `Mesa 22.3.6` from a GL_VERSION string such as `4.5 (Core Profile) Mesa 22.3.6`.
pub fn mesa_from_gl_version(v: &str) -> Option<String> {
    let i = v.find("Mesa ")?;
    Some(
        v[i..]
            .split_whitespace()
            .take(2)
            .collect::<Vec<_>>()
            .join(" "),
    )
}

fn mesa_package() -> Option<String> {
    let o = std::process::Command::new("dpkg-query")
        .args(["-W", "-f", "${Version}", "libgl1-mesa-dri"])
        .output()
        .ok()?;
    let v = String::from_utf8_lossy(&o.stdout).trim().to_string();
    (o.status.success() && !v.is_empty()).then(|| format!("Mesa {v} (libgl1-mesa-dri)"))
}

/// Days since 1970-01-01 to (year, month, day) in the proleptic Gregorian calendar.
fn civil(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

/// Seconds since the epoch as `YYYY-MM-DDTHH:MM:SSZ`.
pub fn iso8601(secs: u64) -> String {
    let (y, m, d) = civil((secs / 86_400) as i64);
    let s = secs % 86_400;
    format!(
        "{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z",
        s / 3600,
        s / 60 % 60,
        s % 60
    )
}

impl Machine {
    /// Describes this machine; `gl_version`: a GL_VERSION string seen by a floor child, if any.
    pub fn describe(gl_version: Option<&str>) -> Machine {
        let cpuinfo = read("/proc/cpuinfo");
        let cpu = cpuinfo
            .lines()
            .find(|l| l.starts_with("model name"))
            .and_then(|l| l.split_once(':'))
            .map(|(_, v)| v.trim().to_string())
            .unwrap_or_else(|| "unknown".into());
        let memory_mib = read("/proc/meminfo")
            .lines()
            .find(|l| l.starts_with("MemTotal:"))
            .and_then(|l| l.split_whitespace().nth(1))
            .and_then(|k| k.parse::<u64>().ok())
            .map_or(0, |k| k / 1024);
        let load_average = read("/proc/loadavg")
            .split_whitespace()
            .next()
            .and_then(|v| v.parse().ok())
            .unwrap_or(0.0);
        let kernel = read("/proc/sys/kernel/osrelease").trim().to_string();
        let mesa = gl_version
            .and_then(mesa_from_gl_version)
            .or_else(mesa_package)
            .unwrap_or_else(|| "unknown".into());
        let now = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs());
        Machine {
            nproc: std::thread::available_parallelism().map_or(1, |n| n.get()),
            cpu,
            memory_mib,
            mesa,
            load_average,
            kernel,
            date: iso8601(now),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_are_utc_iso8601() {
        assert_eq!(iso8601(0), "1970-01-01T00:00:00Z");
        // 2000-03-01 is day 11017 (leap-year handling across February 2000).
        assert_eq!(iso8601(11_017 * 86_400 + 3661), "2000-03-01T01:01:01Z");
        assert_eq!(iso8601(951_782_400), "2000-02-29T00:00:00Z");
    }

    #[test]
    fn mesa_version_comes_from_gl_version() {
        assert_eq!(
            mesa_from_gl_version("4.5 (Core Profile) Mesa 22.3.6").as_deref(),
            Some("Mesa 22.3.6")
        );
        assert_eq!(
            mesa_from_gl_version("OpenGL ES 3.2 Mesa 22.3.6").as_deref(),
            Some("Mesa 22.3.6")
        );
        assert_eq!(mesa_from_gl_version("4.6 NVIDIA"), None);
    }
}
