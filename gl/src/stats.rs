//! What a GL worker compiled and drew, as the last line it writes on stderr: the runner shows it
//! with `run -v`, the bench reads it (`shadowcheck_runner::bench`).

/// What a worker compiled and drew, as its last stderr line says it (`gl-worker stats: ...`,
/// [`WorkerStats::LINE_PREFIX`]): the bench and a reader of `run -v` learn from it how many
/// sampler states each program sampled (distinct sampling states, see
/// [`crate::renderer::RenderStats`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WorkerStats {
    /// Sampler states one program sampled at most.
    pub states_per_program: usize,
    /// Programs compiled (GLSL and ARB fragment programs).
    pub programs: usize,
    /// Distinct (lookup, sampling state) pairs drawn with programs: the variants one state per
    /// program compiles.
    pub states: usize,
    /// Distinct (program, sampling states bound together) sets drawn: the variants compiled when
    /// states share programs.
    pub sets: usize,
    /// The units of those sets, added up.
    pub units: usize,
}

impl WorkerStats {
    pub const LINE_PREFIX: &'static str = "gl-worker stats:";

    /// The stats of a line that ends with `gl-worker stats: ...` (a diagnostic line may carry
    /// the backend's name in front), or `None`.
    pub fn parse(line: &str) -> Option<WorkerStats> {
        let (_, rest) = line.split_once(Self::LINE_PREFIX)?;
        let mut st = WorkerStats::default();
        for part in rest.split_whitespace() {
            let (k, v) = part.split_once('=')?;
            let v: usize = v.parse().ok()?;
            match k {
                "states_per_program" => st.states_per_program = v,
                "programs" => st.programs = v,
                "states" => st.states = v,
                "sets" => st.sets = v,
                "units" => st.units = v,
                _ => return None,
            }
        }
        Some(st)
    }
}

impl std::fmt::Display for WorkerStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} states_per_program={} programs={} states={} sets={} units={}",
            Self::LINE_PREFIX,
            self.states_per_program,
            self.programs,
            self.states,
            self.sets,
            self.units
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stats_line_reads_back_as_written() {
        let st = WorkerStats {
            states_per_program: 16,
            programs: 12,
            states: 340,
            sets: 38,
            units: 401,
        };
        let line = st.to_string();
        assert_eq!(
            line,
            "gl-worker stats: states_per_program=16 programs=12 states=340 sets=38 units=401"
        );
        assert_eq!(WorkerStats::parse(&line), Some(st));
        assert_eq!(
            WorkerStats::parse(&format!("[egl:llvmpipe:core] {line}")),
            Some(st)
        );
        assert_eq!(WorkerStats::parse("gl-worker stats: programs=x"), None);
        assert_eq!(WorkerStats::parse("something else"), None);
    }
}
